// The runner's GLSL ES 3.20 programs for ontile's `cartoon` frame: the toon MRT functors (Cel,
// MatCap, ToonEnv; src/shaders_cpp/toon/), the gradient sky (GradientSkyShader) and the
// full-screen Sobel edge pass (SobelEdgeShader), with an edge-mask variant of the latter.
#pragma once
#include <map>
#include <tuple>

#include <GLES3/gl32.h>

namespace ontile::peer {

enum class ToonKind { Cel, MatCap, Environment };

struct ToonProgramKey {
  ToonKind kind = ToonKind::Cel;
  bool base_map = false;  // _BASEMAP
  auto tie() const { return std::tie(kind, base_map); }
  bool operator<(const ToonProgramKey& o) const { return tie() < o.tie(); }
};

struct GlToonProgram {
  GLuint id = 0;
  GLint mvp = -1, normal_matrix = -1, view_normal_matrix = -1, to_light = -1, steps = -1, step_size = -1;
  GLint lit_color = -1, shadow_color = -1, base_color = -1, border_color = -1;
};

struct GlSkyProgram {
  GLuint id = 0;
  GLint directions = -1, zenith = -1, horizon = -1, ground = -1;
};

struct GlEdgeProgram {
  GLuint id = 0;
  GLint tap_step = -1, orthographic = -1, near_plane = -1, far_plane = -1, view_ray_scale = -1;
  GLint depth_limit_scale = -1, normal_threshold = -1, min_grazing_cosine = -1;
};

// Texture units of the toon samplers and of the edge pass's G-buffer.
constexpr GLint kToonBaseMapUnit = 0, kToonMatCapUnit = 1, kToonEnvironmentUnit = 2;
constexpr GLint kEdgeColorUnit = 0, kEdgeDepthUnit = 1, kEdgeNormalUnit = 2, kEdgeBorderUnit = 3;

class GlCartoonPrograms {
 public:
  GlCartoonPrograms();
  GlCartoonPrograms(const GlCartoonPrograms&) = delete;
  GlCartoonPrograms& operator=(const GlCartoonPrograms&) = delete;
  ~GlCartoonPrograms();
  // Compiles the variant on first use; throws ontile::Error with the compiler's log.
  const GlToonProgram& toon(const ToonProgramKey& key);
  const GlSkyProgram& sky() const { return sky_; }
  // edge_mask: the Sobel decision alone, 1 on an edge and 0 elsewhere in every channel but
  // alpha, instead of the composited colour.
  const GlEdgeProgram& edges(bool edge_mask) const { return edge_mask ? mask_ : edges_; }

 private:
  std::map<ToonProgramKey, GlToonProgram> toon_;
  GlSkyProgram sky_;
  GlEdgeProgram edges_, mask_;
};

}  // namespace ontile::peer
