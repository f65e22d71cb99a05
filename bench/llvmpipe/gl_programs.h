// The runner's GLSL ES 3.20 programs: ontile's Lit/Lambert functor (lambert_shader.h) as a
// fragment shader, and the primitive-id AOV. Variants are compiled per material keyword set,
// as ontile instantiates one functor template per keyword combination.
#pragma once
#include <map>
#include <tuple>

#include <GLES3/gl32.h>

namespace ontile::peer {

struct ProgramKey {
  bool primitive_ids = false;  // the AOV program instead of the colour one
  bool base_map = false;       // _BASEMAP
  bool alpha_test = false;     // _ALPHATEST_ON
  bool emission_map = false;   // _EMISSION
  auto tie() const { return std::tie(primitive_ids, base_map, alpha_test, emission_map); }
  bool operator<(const ProgramKey& o) const { return tie() < o.tie(); }
};

struct GlProgram {
  GLuint id = 0;
  GLint mvp = -1, normal_matrix = -1, base_color = -1, emission = -1, cutoff = -1;
  GLint to_light = -1, radiance = -1, ambient = -1, primitive_id_base = -1;
};

// Texture units of the samplers.
constexpr GLint kBaseMapUnit = 0, kEmissionMapUnit = 1;
// Vertex attribute locations.
constexpr GLuint kPositionAttribute = 0, kNormalAttribute = 1, kUvAttribute = 2;

class GlPrograms {
 public:
  GlPrograms() = default;
  GlPrograms(const GlPrograms&) = delete;
  GlPrograms& operator=(const GlPrograms&) = delete;
  ~GlPrograms();
  // Compiles the variant on first use; throws ontile::Error with the compiler's log.
  const GlProgram& get(const ProgramKey& key);

 private:
  std::map<ProgramKey, GlProgram> programs_;
};

}  // namespace ontile::peer
