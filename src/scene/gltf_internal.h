// Internal to the glTF loader: the state its parts share (meshes, materials, node tree) while
// converting one tinygltf::Model into an ontile::Scene. Not for use outside src/scene/gltf_*.
#pragma once
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
};

// Throws ontile::Error("FILE: problem").
[[noreturn]] void throw_error(const LoadContext& context, const std::string& problem);

// Converts glTF mesh `mesh_index`: triangle primitives become MeshPrimitive lists, point and
// line primitives are skipped and counted.
Mesh convert_mesh(const LoadContext& context, int mesh_index);

// Converts every material, building each (image, colour space) texture once.
std::vector<Material> convert_materials(const LoadContext& context);

}  // namespace ontile::gltf
