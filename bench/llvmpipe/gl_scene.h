// The scene on the GL side: every mesh primitive in buffer objects, every texture the Lit
// materials sample (ontile's own mip chain, texel for texel), and the frame's draws recorded in
// the order and with the render state ontile's lambert pipeline uses.
#pragma once
#include <map>
#include <memory>
#include <vector>

#include <GLES3/gl32.h>

#include "context/scene_renderers.h"
#include "gl_programs.h"
#include "shaders_cpp/lambert_shader.h"

namespace ontile::peer {

class GlScene {
 public:
  // Uploads everything; the scene must outlive this object. Throws ontile::Error on GL errors.
  explicit GlScene(const Scene& scene);
  ~GlScene();
  GlScene(const GlScene&) = delete;
  GlScene& operator=(const GlScene&) = delete;

  // Records one lambert frame into the bound framebuffer (cleared by the caller): culling and
  // the opaque then transparent queues sorted as ontile's draw_renderers sorts them. Returns
  // the number of draws.
  size_t draw_lambert(const glm::dmat4& view_projection, const CameraMatrices& camera,
                      const DirectionalLighting& lighting, GlPrograms& programs);
  // Records ontile's primitive-id AOV pass: the opaque queue only, ids into an R32UI target.
  size_t draw_primitive_ids(const glm::dmat4& view_projection, const CameraMatrices& camera,
                            GlPrograms& programs);

 private:
  struct GlMesh {
    GLuint vao = 0;
    GLuint buffers[4] = {0, 0, 0, 0};  // positions, normals, uvs, indices
    GLsizei index_count = 0;
  };
  struct GlTextureSlot {
    GLuint texture = 0, sampler = 0;
  };
  struct GlMaterial {
    ProgramKey key;
    glm::vec4 base_color{1.0f};
    glm::vec3 emission{0.0f};
    float cutoff = 0.5f;
    GlTextureSlot base_map, emission_map;
    PassState state;
    int render_queue = 0;
  };

  GLuint upload_texture(const Texture2D& texture);
  GlTextureSlot texture_slot(const RenderMaterial& material, const char* property);
  // Visible renderers of the queue range in ontile's order (frame_executor.cpp, DrawRenderers).
  std::vector<uint32_t> sorted_draws(const CameraMatrices& camera, bool transparent) const;
  void draw(uint32_t renderer, const glm::dmat4& view_projection, const ProgramKey& key,
            const GlProgram& program, bool ids);

  std::unique_ptr<Shader> lit_shader_;
  SceneRenderers renderers_;
  std::map<const RenderMaterial*, GlMaterial> materials_;
  std::map<const MeshPrimitive*, GlMesh> meshes_;
  std::map<const Texture2D*, GLuint> textures_;
  std::vector<GLuint> samplers_;
};

// Throws ontile::Error naming `what` when GL reports an error.
void check_gl(const char* what);

}  // namespace ontile::peer
