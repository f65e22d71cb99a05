// glTF 2.0 loader (.gltf and .glb): decodes meshes, materials, textures, cameras and
// KHR_lights_punctual lights of one scene of the file into an ontile::Scene.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace ontile {

// Limits that make hostile or corrupt files fail fast with a clear error and bounded memory
// (docs/robustness.md, "Loader limits"). Each can be raised by the caller.
struct GltfLimits {
  // Bracket nesting of the JSON text (file or GLB JSON chunk). The JSON parser recurses per
  // level; 15,000 levels overflow the stack. glTF itself nests about 10 deep.
  int max_json_nesting_depth = 512;
  // Depth of the node tree (roots have depth 1); the flattening walk is iterative.
  int max_node_depth = 1024;
  // Mesh instances after flattening the node tree.
  uint64_t max_instances = 1'000'000;
  // Declared width x height of one image, checked before decoding (8192 x 8192).
  uint64_t max_image_texels = uint64_t{1} << 26;
  // Sum over all images of the file, checked before decoding each.
  uint64_t max_total_image_texels = uint64_t{1} << 28;
  // Bytes of decoded vertex attributes and indices over the whole file (4 GiB), checked
  // before each accessor is decoded.
  uint64_t max_decoded_geometry_bytes = uint64_t{1} << 32;
};

struct GltfLoadOptions {
  // Which entry of the file's "scenes" to flatten; -1 picks the file's "scene" field, else
  // scene 0, else (a file with no scenes) every root node.
  int scene_index = -1;
  // NaN/Inf in a POSITION accessor. true: the load fails with an error naming the accessor.
  // false: the file loads as it is (the rasterizer drops triangles with non-finite corners at
  // render time and counts them) and GltfLoadStats::non_finite_positions reports how many
  // vertices were affected, so the caller can warn.
  bool reject_non_finite_positions = true;
  // Buffer and image URIs must name files inside the scene file's folder (or below it);
  // true also allows absolute paths and ".." that leave it.
  bool allow_uris_outside_scene_folder = false;
  // Storage of the scene's images for the texture-cache model (--texture-compression): their
  // memory layout and bytes, never the texels sampled.
  TextureCompression texture_compression = TextureCompression::None;
  GltfLimits limits;
};

// What the loader met on the way that the Scene itself does not show.
struct GltfLoadStats {
  uint64_t skipped_point_primitives = 0;  // mode POINTS: not drawn by a triangle rasterizer
  uint64_t skipped_line_primitives = 0;   // modes LINES, LINE_LOOP, LINE_STRIP
  uint64_t non_finite_positions = 0;      // vertices whose POSITION has a NaN/Inf component
  // Primitives without NORMAL: they got flat normals (glTF 2.0 spec 3.7.2.1) and were
  // de-indexed so each triangle has its own three vertices.
  uint64_t primitives_with_generated_normals = 0;
  // Non-fatal notes: tinygltf warnings and things the loader ignored, one line each.
  std::vector<std::string> warnings;
};

// Loads `path` (binary when the file starts with the GLB magic "glTF", else JSON). Throws
// ontile::Error with a one-line message "PATH: problem" on any failure: unreadable or invalid
// file, missing buffer or image file, out-of-range accessor or index, unsupported required
// extension, scene index out of range, a node tree that is not a tree (glTF 2.0 3.5.2), a
// degenerate camera transform, a URI outside the scene's folder, invalid base64 in a data:
// URI, any GltfLimits exceeded, and (by default) non-finite positions.
Scene load_gltf(const std::filesystem::path& path, const GltfLoadOptions& options = {},
                GltfLoadStats* stats = nullptr);

}  // namespace ontile
