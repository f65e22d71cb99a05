// ontile's `cartoon` frame on the GL side (src/pipelines/cartoon/cartoon_pipelines.cpp): one
// MRT pass writing colour (SRGB8_ALPHA8), view normals (RGB10_A2), border colour (RGBA8) and
// depth (DEPTH_COMPONENT32F) with ontile's toon materials and sky, then a full-screen Sobel
// pass that samples those targets as textures and writes the final SRGB8_ALPHA8 image.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include <GLES3/gl32.h>

#include "context/scene_renderers.h"
#include "gl_cartoon_programs.h"
#include "gl_scene.h"
#include "pipelines/cartoon/toon_shaders.h"
#include "pipelines/lit/lit_shader.h"

namespace ontile::peer {

class GlCartoonFrame {
 public:
  // gl_view_projection: the camera's view-projection with the runner's Y flip and depth
  // convention (llvmpipe_main.cpp). Throws ontile::Error for a material the runner cannot draw
  // as ontile does (a normal-mapped MatCap).
  GlCartoonFrame(const Scene& scene, GlScene& gl_scene, const CameraMatrices& camera,
                 const glm::dmat4& gl_view_projection, int width_px, int height_px);
  ~GlCartoonFrame();
  GlCartoonFrame(const GlCartoonFrame&) = delete;
  GlCartoonFrame& operator=(const GlCartoonFrame&) = delete;

  // Records one frame (both passes); returns the number of scene draws. The caller finishes.
  size_t render();
  // The final image's stored bytes, RGBA8 sRGB, rows top first.
  std::vector<uint8_t> read_color() const;
  // Runs the edge-mask variant of the Sobel pass on the current G-buffer and returns its R
  // channel: 255 where the Sobel test found an edge, 0 elsewhere.
  std::vector<uint8_t> edge_mask();

 private:
  struct ToonMaterial {
    ToonProgramKey key;
    glm::vec4 lit_color{1.0f}, shadow_color{0.5f}, base_color{1.0f}, border_color{0.0f};
    int steps = 1;
    float step_size = 1.0f;
    GLuint base_map = 0, base_sampler = 0, matcap = 0, matcap_sampler = 0;
    PassState state;
  };
  struct Target {
    GLuint texture = 0;
    GLenum internal_format = 0;
  };

  void draw_scene(size_t& draws);
  void draw_sky();
  void draw_edges(bool edge_mask);

  GlScene& gl_;
  CameraMatrices camera_;
  glm::dmat4 gl_view_projection_;
  int width_px_, height_px_;
  DirectionalLighting lighting_;
  ToonShaderLibrary library_;
  SceneRenderers renderers_;
  std::map<const RenderMaterial*, ToonMaterial> materials_;
  GlCartoonPrograms programs_;
  GLuint environment_ = 0, environment_sampler_ = 0, empty_vao_ = 0;
  Target color_, normals_, border_, depth_, final_, mask_;
  GLuint mrt_fbo_ = 0, final_fbo_ = 0, mask_fbo_ = 0;
  glm::vec3 sky_directions_[3];
};

}  // namespace ontile::peer
