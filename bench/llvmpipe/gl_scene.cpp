// Scene upload and draw recording for the llvmpipe runner (see gl_scene.h).
#include "gl_scene.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "gl_state.h"
#include "pipelines/lit/lit_shader.h"
#include "raster/pixel_format.h"
#include "util/error.h"

namespace ontile::peer {
namespace {

template <class T>
GLuint upload_buffer(GLenum target, const std::vector<T>& data) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(target, buffer);
  glBufferData(target, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
  return buffer;
}

// The stored byte of a texel channel: Texture2D::fetch decodes to linear float, and the sRGB
// decode table is strictly increasing, so the byte is where the value sits in the table.
uint8_t srgb_byte(float linear) {
  const auto& table = srgb8_decode_table();
  const auto it = std::lower_bound(table.begin(), table.end(), linear);
  if (it == table.end()) return 255;
  if (it != table.begin() && linear - *(it - 1) < *it - linear) return static_cast<uint8_t>(it - table.begin() - 1);
  return static_cast<uint8_t>(it - table.begin());
}

uint8_t unorm_byte(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

struct GlTexelFormat {
  GLenum internal = GL_SRGB8_ALPHA8, type = GL_UNSIGNED_BYTE;
};

GlTexelFormat gl_texel_format(const Texture2D& t) {
  if (t.encoding() == TexelEncoding::Unorm8) return {GL_RGBA8, GL_UNSIGNED_BYTE};
  if (t.encoding() == TexelEncoding::Float32) return {GL_RGBA32F, GL_FLOAT};
  return {};
}

// One level's texels as stored (8-bit codes or floats), RGBA, rows top first.
class TexelData {
 public:
  TexelData(const Texture2D& t, int level, GlTexelFormat format) {
    for (int y = 0; y < t.height(level); ++y) {
      for (int x = 0; x < t.width(level); ++x) {
        const glm::vec4 v = t.fetch(level, x, y);
        if (format.type == GL_FLOAT) {
          floats_.insert(floats_.end(), {v.x, v.y, v.z, v.w});
        } else if (format.internal == GL_SRGB8_ALPHA8) {
          bytes_.insert(bytes_.end(), {srgb_byte(v.x), srgb_byte(v.y), srgb_byte(v.z), unorm_byte(v.w)});
        } else {
          bytes_.insert(bytes_.end(), {unorm_byte(v.x), unorm_byte(v.y), unorm_byte(v.z), unorm_byte(v.w)});
        }
      }
    }
  }
  const void* pointer() const { return floats_.empty() ? static_cast<const void*>(bytes_.data()) : floats_.data(); }

 private:
  std::vector<uint8_t> bytes_;
  std::vector<float> floats_;
};

}  // namespace

GlScene::GlScene(const Scene& scene) : lit_shader_(make_lit_shader()) {
  // ontile's own material mapping, so queue, culling, blending and keywords are the lambert
  // pipeline's, not a re-derivation from the glTF.
  renderers_ = make_scene_renderers(scene, [&](const Material& m) { return make_lit_material(*lit_shader_, m); });
  const ShaderPass* forward = lit_shader_->find_light_mode(lit::kForwardLit);
  for (const auto& material : renderers_.materials) {
    GlMaterial m;
    const PropertyBlock& p = material->properties;
    m.base_color = p.get_vector("_BaseColor", glm::vec4(1.0f));
    m.emission = glm::vec3(p.get_vector("_EmissionColor"));
    m.cutoff = p.get_float("_Cutoff", 0.5f);
    if (material->has_keyword("_BASEMAP")) m.base_map = texture_slot(*material, "_BaseMap");
    if (material->has_keyword("_EMISSION")) m.emission_map = texture_slot(*material, "_EmissionMap");
    m.key.base_map = m.base_map.texture != 0;
    m.key.alpha_test = material->has_keyword("_ALPHATEST_ON");
    m.key.emission_map = m.emission_map.texture != 0;
    m.state = material->state_for(*forward);
    m.render_queue = material->render_queue;
    materials_[material.get()] = m;
  }
  for (const Renderer& r : renderers_.renderers) {
    if (meshes_.count(r.mesh)) continue;
    const MeshPrimitive& prim = *r.mesh;
    GlMesh mesh;
    glGenVertexArrays(1, &mesh.vao);
    glBindVertexArray(mesh.vao);
    mesh.buffers[0] = upload_buffer(GL_ARRAY_BUFFER, prim.positions);
    glVertexAttribPointer(kPositionAttribute, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(kPositionAttribute);
    // Absent streams read the constant attribute values set below (MeshVertexShader's
    // defaults: normal (0, 0, 1), uv (0, 0)).
    if (!prim.normals.empty()) {
      mesh.buffers[1] = upload_buffer(GL_ARRAY_BUFFER, prim.normals);
      glVertexAttribPointer(kNormalAttribute, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(kNormalAttribute);
    }
    if (!prim.uv0.empty()) {
      mesh.buffers[2] = upload_buffer(GL_ARRAY_BUFFER, prim.uv0);
      glVertexAttribPointer(kUvAttribute, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
      glEnableVertexAttribArray(kUvAttribute);
    }
    mesh.buffers[3] = upload_buffer(GL_ELEMENT_ARRAY_BUFFER, prim.indices);
    mesh.index_count = static_cast<GLsizei>(prim.indices.size());
    glBindVertexArray(0);
    meshes_[r.mesh] = mesh;
  }
  glVertexAttrib3f(kNormalAttribute, 0.0f, 0.0f, 1.0f);
  glVertexAttrib2f(kUvAttribute, 0.0f, 0.0f);
  check_gl("scene upload");
}

GlScene::~GlScene() {
  for (auto& [prim, mesh] : meshes_) {
    glDeleteVertexArrays(1, &mesh.vao);
    for (GLuint b : mesh.buffers) {
      if (b) glDeleteBuffers(1, &b);
    }
  }
  for (auto& [texture, id] : textures_) glDeleteTextures(1, &id);
  for (GLuint id : array_textures_) glDeleteTextures(1, &id);
  if (!samplers_.empty()) glDeleteSamplers(static_cast<GLsizei>(samplers_.size()), samplers_.data());
}

GLuint GlScene::texture(const Texture2D& t) {
  const auto found = textures_.find(&t);
  if (found != textures_.end()) return found->second;
  const GlTexelFormat format = gl_texel_format(t);
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D, id);
  glTexStorage2D(GL_TEXTURE_2D, t.level_count(), format.internal, t.width(0), t.height(0));
  // Every level of ontile's chain as stored, rather than glGenerateMipmap, so both renderers
  // filter the same texels. Rows go top first: GL's t = 0 is then glTF's v = 0, the top row.
  for (int level = 0; level < t.level_count(); ++level) {
    const TexelData data(t, level, format);
    glTexSubImage2D(GL_TEXTURE_2D, level, 0, 0, t.width(level), t.height(level), GL_RGBA, format.type, data.pointer());
  }
  check_gl("texture upload");
  textures_[&t] = id;
  return id;
}

GLuint GlScene::texture_array(const std::vector<const Texture2D*>& layers) {
  const Texture2D& first = *layers.at(0);
  const GlTexelFormat format = gl_texel_format(first);
  GLuint id = 0;
  glGenTextures(1, &id);
  glBindTexture(GL_TEXTURE_2D_ARRAY, id);
  glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, format.internal, first.width(0), first.height(0),
                 static_cast<GLsizei>(layers.size()));
  for (size_t layer = 0; layer < layers.size(); ++layer) {
    const Texture2D& t = *layers[layer];
    if (t.width(0) != first.width(0) || t.height(0) != first.height(0) || gl_texel_format(t).internal != format.internal) {
      throw Error("llvmpipe runner: texture array layer '" + t.name() + "' differs from '" + first.name() + "'");
    }
    const TexelData data(t, 0, format);
    glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, static_cast<GLint>(layer), t.width(0), t.height(0), 1, GL_RGBA,
                    format.type, data.pointer());
  }
  check_gl("texture array upload");
  array_textures_.push_back(id);
  return id;
}

GLuint GlScene::sampler(const SamplerDesc& desc) {
  samplers_.push_back(make_gl_sampler(desc));
  return samplers_.back();
}

const GlScene::GlMesh& GlScene::mesh(const MeshPrimitive* primitive) const { return meshes_.at(primitive); }

GlScene::GlTextureSlot GlScene::texture_slot(const RenderMaterial& material, const char* property) {
  const TextureBinding* binding = material.properties.get_texture(property);
  if (!binding || !binding->texture) return {};
  GlTextureSlot slot;
  slot.texture = texture(*binding->texture);
  slot.sampler = sampler(binding->sampler);
  return slot;
}

std::vector<uint32_t> draw_order(const std::vector<Renderer>& all, const CameraMatrices& camera,
                                 RenderQueueRange range, SortingCriteria sorting) {
  const CullingResults culling = cull_renderers(all, camera, {});
  std::vector<uint32_t> list;
  for (uint32_t i : culling.visible) {
    const int queue = all[i].material->render_queue;
    if (queue >= range.lower && queue <= range.upper) list.push_back(i);
  }
  // The same keys as FrameExecutor's DrawRenderers: 64 distance buckets front to back and
  // materials in order of first appearance (opaque), back to front by distance (transparent).
  std::map<const RenderMaterial*, uint32_t> material_order;
  std::vector<double> distance(all.size(), 0.0);
  double max_distance = 0.0;
  for (uint32_t i : list) {
    material_order.emplace(all[i].material, static_cast<uint32_t>(material_order.size()));
    distance[i] = glm::length(glm::dvec3(all[i].world_bounds.center()) - camera.position);
    max_distance = std::max(max_distance, distance[i]);
  }
  auto bucket = [&](uint32_t i) {
    return max_distance > 0.0 ? static_cast<int>(distance[i] / max_distance * 63.0) : 0;
  };
  if (sorting == SortingCriteria::CommonOpaque) {
    std::stable_sort(list.begin(), list.end(), [&](uint32_t a, uint32_t b) {
      return std::tuple(all[a].material->render_queue, bucket(a), material_order[all[a].material]) <
             std::tuple(all[b].material->render_queue, bucket(b), material_order[all[b].material]);
    });
  } else if (sorting == SortingCriteria::CommonTransparent) {
    std::stable_sort(list.begin(), list.end(), [&](uint32_t a, uint32_t b) {
      if (all[a].material->render_queue != all[b].material->render_queue) {
        return all[a].material->render_queue < all[b].material->render_queue;
      }
      return distance[a] > distance[b];
    });
  }
  return list;
}

void GlScene::draw(uint32_t index, const glm::dmat4& view_projection, const ProgramKey& key,
                   const GlProgram& program, bool ids) {
  const Renderer& r = renderers_.renderers[index];
  const GlMaterial& m = materials_.at(r.material);
  const GlMesh& mesh = meshes_.at(r.mesh);
  const glm::mat4 mvp(view_projection * r.world);
  const glm::mat3 normal_matrix = r.mesh->normals.empty()
                                      ? glm::mat3(1.0f)
                                      : glm::mat3(glm::transpose(glm::inverse(glm::dmat3(r.world))));
  glUniformMatrix4fv(program.mvp, 1, GL_FALSE, &mvp[0][0]);
  glUniformMatrix3fv(program.normal_matrix, 1, GL_FALSE, &normal_matrix[0][0]);
  glUniform4fv(program.base_color, 1, &m.base_color[0]);
  glUniform1f(program.cutoff, m.cutoff);
  if (ids) {
    glUniform1ui(program.primitive_id_base, r.primitive_id_base);
  } else {
    glUniform3fv(program.emission, 1, &m.emission[0]);
  }
  if (key.base_map) {
    glActiveTexture(GL_TEXTURE0 + kBaseMapUnit);
    glBindTexture(GL_TEXTURE_2D, m.base_map.texture);
    glBindSampler(kBaseMapUnit, m.base_map.sampler);
  }
  if (key.emission_map) {
    glActiveTexture(GL_TEXTURE0 + kEmissionMapUnit);
    glBindTexture(GL_TEXTURE_2D, m.emission_map.texture);
    glBindSampler(kEmissionMapUnit, m.emission_map.sampler);
  }
  apply_cull(m.state.cull);
  apply_depth(m.state);
  if (!ids) apply_blend(m.state.blend);
  glBindVertexArray(mesh.vao);
  glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
}

size_t GlScene::draw_lambert(const glm::dmat4& view_projection, const CameraMatrices& camera,
                             const DirectionalLighting& lighting, GlPrograms& programs) {
  size_t draws = 0;
  const GlProgram* bound = nullptr;
  for (bool transparent : {false, true}) {
    const RenderQueueRange range = transparent ? RenderQueueRange::transparent() : RenderQueueRange::opaque();
    const SortingCriteria sorting = transparent ? SortingCriteria::CommonTransparent : SortingCriteria::CommonOpaque;
    for (uint32_t i : draw_order(renderers_.renderers, camera, range, sorting)) {
      const ProgramKey& key = materials_.at(renderers_.renderers[i].material).key;
      const GlProgram& program = programs.get(key);
      if (&program != bound) {
        glUseProgram(program.id);
        glUniform3fv(program.to_light, 1, &lighting.to_light[0]);
        glUniform3fv(program.radiance, 1, &lighting.radiance[0]);
        glUniform3fv(program.ambient, 1, &lighting.ambient[0]);
        bound = &program;
      }
      draw(i, view_projection, key, program, false);
      ++draws;
    }
  }
  glBindVertexArray(0);
  return draws;
}

size_t GlScene::draw_primitive_ids(const glm::dmat4& view_projection, const CameraMatrices& camera,
                                   GlPrograms& programs) {
  size_t draws = 0;
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (uint32_t i : draw_order(renderers_.renderers, camera, RenderQueueRange::opaque(), SortingCriteria::CommonOpaque)) {
    const GlMaterial& m = materials_.at(renderers_.renderers[i].material);
    // Only an alpha-tested material needs its base map: the AOV runs the material's functor
    // just for its discards.
    ProgramKey key;
    key.primitive_ids = true;
    key.alpha_test = m.key.alpha_test;
    key.base_map = m.key.alpha_test && m.key.base_map;
    const GlProgram& program = programs.get(key);
    glUseProgram(program.id);
    draw(i, view_projection, key, program, true);
    ++draws;
  }
  glBindVertexArray(0);
  return draws;
}

}  // namespace ontile::peer
