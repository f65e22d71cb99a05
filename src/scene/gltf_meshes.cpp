// glTF 2.0 meshes to MeshPrimitive triangle lists: attribute decoding, strip/fan conversion
// (spec 3.7.2.1), index validation and flat normals for primitives without NORMAL.
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "scene/gltf_accessors.h"
#include "scene/gltf_internal.h"

namespace ontile::gltf {
namespace {

std::string primitive_label(int mesh_index, size_t primitive_index) {
  return "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(primitive_index);
}

// Decodes attribute `name` and checks its element width and count. Returns the flat floats.
std::vector<float> read_attribute(const LoadContext& context, int accessor_index,
                                  const std::string& where, const std::string& name,
                                  int min_components, int max_components, size_t expected_count) {
  if (accessor_index < 0 || static_cast<size_t>(accessor_index) >= context.model.accessors.size()) {
    throw_error(context, where + " attribute " + name + " refers to accessor " +
                             std::to_string(accessor_index) + ", which does not exist");
  }
  const tinygltf::Accessor& accessor = context.model.accessors[static_cast<size_t>(accessor_index)];
  const int components = component_count_of_type(accessor.type);
  if (components < min_components || components > max_components) {
    throw_error(context,
                "accessor " + std::to_string(accessor_index) + " (" + name + " of " + where +
                    ") has " + std::to_string(components) + " components per element, expected " +
                    std::to_string(min_components) +
                    (max_components != min_components ? " or " + std::to_string(max_components)
                                                      : std::string()));
  }
  if (expected_count != SIZE_MAX && accessor.count != expected_count) {
    throw_error(context, "accessor " + std::to_string(accessor_index) + " (" + name + " of " +
                             where + ") has " + std::to_string(accessor.count) +
                             " elements, POSITION has " + std::to_string(expected_count));
  }
  charge_geometry_bytes(context, uint64_t{accessor.count} * uint64_t(components) * sizeof(float),
                        where + " attribute " + name);
  return read_accessor_floats(context.model, accessor_index, context.file_label);
}

int find_attribute(const tinygltf::Primitive& primitive, const char* name) {
  const auto it = primitive.attributes.find(name);
  return it == primitive.attributes.end() ? -1 : it->second;
}

// Triangle lists from the vertex sequence of each mode (spec 3.7.2.1): strips alternate the
// winding so every triangle keeps the first triangle's orientation, fans share vertex 0.
std::vector<uint32_t> triangle_list(int mode, const std::vector<uint32_t>& sequence) {
  std::vector<uint32_t> list;
  const size_t n = sequence.size();
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    list.assign(sequence.begin(), sequence.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
    return list;
  }
  if (n < 3) return list;
  list.reserve((n - 2) * 3);
  for (size_t i = 0; i + 2 < n; ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
      // Triangle i = {v_i, v_(i+1+i%2), v_(i+2-i%2)}.
      list.push_back(sequence[i]);
      list.push_back(sequence[i + 1 + i % 2]);
      list.push_back(sequence[i + 2 - i % 2]);
    } else {
      // TRIANGLE_FAN: triangle i = {v_(i+1), v_(i+2), v_0}.
      list.push_back(sequence[i + 1]);
      list.push_back(sequence[i + 2]);
      list.push_back(sequence[0]);
    }
  }
  return list;
}

// Spec 3.7.2.1: without NORMAL, clients must use flat normals (and ignore TANGENT). Each
// triangle gets its own three vertices so the face normal is exact; only these primitives are
// de-indexed. Degenerate or non-finite triangles get +Z (they draw no pixels anyway).
void make_flat_normals(const LoadContext& context, const std::string& where,
                       MeshPrimitive& primitive) {
  const uint64_t bytes_per_corner = sizeof(glm::vec3) * 2 + sizeof(uint32_t) +
                                    (primitive.uv0.empty() ? 0 : sizeof(glm::vec2)) +
                                    (primitive.colors.empty() ? 0 : sizeof(glm::vec4));
  charge_geometry_bytes(context, primitive.indices.size() * bytes_per_corner,
                        where + " flat normals (one vertex per triangle corner)");
  MeshPrimitive flat;
  flat.material = primitive.material;
  const size_t corner_count = primitive.indices.size();
  flat.positions.resize(corner_count);
  flat.normals.resize(corner_count);
  flat.indices.resize(corner_count);
  if (!primitive.uv0.empty()) flat.uv0.resize(corner_count);
  if (!primitive.colors.empty()) flat.colors.resize(corner_count);
  for (size_t corner = 0; corner < corner_count; ++corner) {
    const uint32_t source = primitive.indices[corner];
    flat.indices[corner] = static_cast<uint32_t>(corner);
    flat.positions[corner] = primitive.positions[source];
    if (!flat.uv0.empty()) flat.uv0[corner] = primitive.uv0[source];
    if (!flat.colors.empty()) flat.colors[corner] = primitive.colors[source];
  }
  for (size_t corner = 0; corner < corner_count; corner += 3) {
    const glm::vec3 edge1 = flat.positions[corner + 1] - flat.positions[corner];
    const glm::vec3 edge2 = flat.positions[corner + 2] - flat.positions[corner];
    const glm::vec3 cross = glm::cross(edge1, edge2);
    const float length = glm::length(cross);
    const glm::vec3 normal =
        (length > 0.0f && std::isfinite(length)) ? cross / length : glm::vec3(0.0f, 0.0f, 1.0f);
    flat.normals[corner] = flat.normals[corner + 1] = flat.normals[corner + 2] = normal;
  }
  flat.bounds = primitive.bounds;
  primitive = std::move(flat);
}

MeshPrimitive convert_triangles(const LoadContext& context, int mesh_index, size_t primitive_index,
                                const tinygltf::Primitive& source) {
  const std::string where = primitive_label(mesh_index, primitive_index);
  MeshPrimitive primitive;
  primitive.material = source.material;
  if (source.material < -1 || source.material >= static_cast<int>(context.model.materials.size())) {
    throw_error(context, where + " refers to material " + std::to_string(source.material) +
                             ", which does not exist");
  }

  const int position_accessor = find_attribute(source, "POSITION");
  if (position_accessor < 0) throw_error(context, where + " has no POSITION attribute");
  const std::vector<float> positions =
      read_attribute(context, position_accessor, where, "POSITION", 3, 3, SIZE_MAX);
  const size_t vertex_count = positions.size() / 3;
  primitive.positions.resize(vertex_count);
  for (size_t v = 0; v < vertex_count; ++v) {
    const glm::vec3 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    primitive.positions[v] = p;
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      primitive.bounds.extend(p);
      continue;
    }
    if (context.options.reject_non_finite_positions) {
      throw_error(context, "accessor " + std::to_string(position_accessor) + " (POSITION of " +
                               where + ") element " + std::to_string(v) +
                               " is a non-finite position (NaN/Inf)");
    }
    ++context.stats.non_finite_positions;
  }

  const int normal_accessor = find_attribute(source, "NORMAL");
  if (normal_accessor >= 0) {
    const auto values =
        read_attribute(context, normal_accessor, where, "NORMAL", 3, 3, vertex_count);
    primitive.normals.resize(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
      primitive.normals[v] = glm::vec3(values[3 * v], values[3 * v + 1], values[3 * v + 2]);
    }
    const int tangent_accessor = find_attribute(source, "TANGENT");
    if (tangent_accessor >= 0) {
      const auto t =
          read_attribute(context, tangent_accessor, where, "TANGENT", 4, 4, vertex_count);
      primitive.tangents.resize(vertex_count);
      for (size_t v = 0; v < vertex_count; ++v) {
        primitive.tangents[v] = glm::vec4(t[4 * v], t[4 * v + 1], t[4 * v + 2], t[4 * v + 3]);
      }
    }
  }
  const int uv_accessor = find_attribute(source, "TEXCOORD_0");
  if (uv_accessor >= 0) {
    const auto values =
        read_attribute(context, uv_accessor, where, "TEXCOORD_0", 2, 2, vertex_count);
    primitive.uv0.resize(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
      primitive.uv0[v] = glm::vec2(values[2 * v], values[2 * v + 1]);
    }
  }
  const int color_accessor = find_attribute(source, "COLOR_0");
  if (color_accessor >= 0) {
    const auto values =
        read_attribute(context, color_accessor, where, "COLOR_0", 3, 4, vertex_count);
    const size_t width = values.size() / std::max<size_t>(vertex_count, 1);
    primitive.colors.resize(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) {
      const float* c = values.data() + width * v;
      primitive.colors[v] = glm::vec4(c[0], c[1], c[2], width == 4 ? c[3] : 1.0f);
    }
  }

  std::vector<uint32_t> sequence;
  if (source.indices >= 0) {
    if (static_cast<size_t>(source.indices) < context.model.accessors.size()) {
      const auto& index_accessor = context.model.accessors[static_cast<size_t>(source.indices)];
      charge_geometry_bytes(context, uint64_t{index_accessor.count} * sizeof(uint32_t),
                            where + " indices");
    }
    sequence = read_accessor_indices(context.model, source.indices, context.file_label);
    for (uint32_t index : sequence) {
      if (index >= vertex_count) {
        throw_error(context, "accessor " + std::to_string(source.indices) + " index " +
                                 std::to_string(index) + " out of range (vertex count " +
                                 std::to_string(vertex_count) + ")");
      }
    }
  } else {
    charge_geometry_bytes(context, vertex_count * sizeof(uint32_t), where + " generated indices");
    sequence.resize(vertex_count);
    for (size_t v = 0; v < vertex_count; ++v) sequence[v] = static_cast<uint32_t>(v);
  }
  if (source.mode == TINYGLTF_MODE_TRIANGLES && sequence.size() % 3 != 0) {
    context.stats.warnings.push_back(where + ": " + std::to_string(sequence.size()) +
                                     " vertices is not a multiple of 3; the last " +
                                     std::to_string(sequence.size() % 3) + " ignored");
  }
  if (source.mode != TINYGLTF_MODE_TRIANGLES) {
    charge_geometry_bytes(context, 3 * sequence.size() * sizeof(uint32_t),
                          where + " strip or fan as a triangle list");
  }
  primitive.indices = triangle_list(source.mode, sequence);

  if (primitive.normals.empty()) {
    make_flat_normals(context, where, primitive);
    ++context.stats.primitives_with_generated_normals;
  }
  return primitive;
}

}  // namespace

Mesh convert_mesh(const LoadContext& context, int mesh_index) {
  const tinygltf::Mesh& source = context.model.meshes[static_cast<size_t>(mesh_index)];
  Mesh mesh;
  mesh.name = source.name;
  for (size_t p = 0; p < source.primitives.size(); ++p) {
    const tinygltf::Primitive& primitive = source.primitives[p];
    switch (primitive.mode) {
      case TINYGLTF_MODE_POINTS:
        ++context.stats.skipped_point_primitives;
        break;
      case TINYGLTF_MODE_LINE:
      case TINYGLTF_MODE_LINE_LOOP:
      case TINYGLTF_MODE_LINE_STRIP:
        ++context.stats.skipped_line_primitives;
        break;
      case TINYGLTF_MODE_TRIANGLES:
      case TINYGLTF_MODE_TRIANGLE_STRIP:
      case TINYGLTF_MODE_TRIANGLE_FAN:
        mesh.primitives.push_back(convert_triangles(context, mesh_index, p, primitive));
        break;
      default:
        throw_error(context, primitive_label(mesh_index, p) + " has invalid mode " +
                                 std::to_string(primitive.mode));
    }
  }
  return mesh;
}

}  // namespace ontile::gltf
