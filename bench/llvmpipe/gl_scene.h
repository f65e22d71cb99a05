// The scene on the GL side: every mesh primitive in buffer objects, every texture the materials
// sample (ontile's own mip chain, texel for texel), ontile's draw order, and the lambert frame's
// draws recorded in that order with the render state ontile's lambert pipeline uses.
#pragma once
#include <map>
#include <memory>
#include <vector>

#include <GLES3/gl32.h>

#include "context/drawing_settings.h"
#include "context/scene_renderers.h"
#include "gl_programs.h"
#include "shaders_cpp/lambert_shader.h"

namespace ontile::peer {

// The visible renderers (cull_renderers with default parameters) of `range` in the order of
// FrameExecutor's DrawRenderers with `sorting` (frame_executor.cpp: 64 distance buckets front to
// back, then materials in order of first appearance; or back to front), so equal depths resolve
// alike in both renderers.
std::vector<uint32_t> draw_order(const std::vector<Renderer>& renderers, const CameraMatrices& camera,
                                 RenderQueueRange range, SortingCriteria sorting);

class GlScene {
 public:
  struct GlMesh {
    GLuint vao = 0;  // attributes kPositionAttribute, kNormalAttribute, kUvAttribute
    GLuint buffers[4] = {0, 0, 0, 0};  // positions, normals, uvs, indices
    GLsizei index_count = 0;
  };

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

  // The buffers of a primitive of the scene.
  const GlMesh& mesh(const MeshPrimitive* primitive) const;
  // The GL texture holding every level of `texture` as stored (uploaded on first use).
  GLuint texture(const Texture2D& texture);
  // A 2D array texture of the base levels of `layers` (same size and encoding), e.g. the six
  // faces of a cube map in their Vulkan layer order; owned by this scene.
  GLuint texture_array(const std::vector<const Texture2D*>& layers);
  // A new sampler object with `sampler`'s filters and wrap modes, owned by this scene.
  GLuint sampler(const SamplerDesc& sampler);

 private:
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

  GlTextureSlot texture_slot(const RenderMaterial& material, const char* property);
  void draw(uint32_t renderer, const glm::dmat4& view_projection, const ProgramKey& key,
            const GlProgram& program, bool ids);

  std::unique_ptr<Shader> lit_shader_;
  SceneRenderers renderers_;
  std::map<const RenderMaterial*, GlMaterial> materials_;
  std::map<const MeshPrimitive*, GlMesh> meshes_;
  std::map<const Texture2D*, GLuint> textures_;
  std::vector<GLuint> array_textures_;
  std::vector<GLuint> samplers_;
};

}  // namespace ontile::peer
