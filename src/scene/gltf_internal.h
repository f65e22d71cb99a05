// Internal to the glTF loader: the state its parts share (meshes, materials, node tree) while
// converting one tinygltf::Model into an ontile::Scene. Not for use outside src/scene/gltf_*.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/gltf_loader.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace ontile::gltf {

struct LoadContext {
  const tinygltf::Model& model;
  std::string file_label;  // the path as given; starts every error message
  const GltfLoadOptions& options;
  GltfLoadStats& stats;
  // Bytes of vertex attributes and indices decoded so far (GltfLimits::
  // max_decoded_geometry_bytes); charged before each allocation.
  uint64_t& decoded_geometry_bytes;
};

// Throws ontile::Error("FILE: problem").
[[noreturn]] void throw_error(const LoadContext& context, const std::string& problem);

// Charges `bytes` of decoded geometry for `what`; throws when the file's total would pass
// GltfLimits::max_decoded_geometry_bytes.
void charge_geometry_bytes(const LoadContext& context, uint64_t bytes, const std::string& what);

// Reads and parses the file (gltf_reader.cpp): raw JSON checks, URIs confined to the scene's
// folder, images measured before decoding, required extensions checked.
tinygltf::Model read_model(const std::filesystem::path& path, const std::string& label,
                           const GltfLoadOptions& options, GltfLoadStats& stats);

// Converts glTF mesh `mesh_index`: triangle primitives become MeshPrimitive lists, point and
// line primitives are skipped and counted.
Mesh convert_mesh(const LoadContext& context, int mesh_index);

// Converts every material, building each (image, colour space) texture once.
std::vector<Material> convert_materials(const LoadContext& context);

}  // namespace ontile::gltf
