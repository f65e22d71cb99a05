// glTF 2.0 accessor decoding (spec 3.6 "Binary Data Storage"): strides, offsets, sparse
// substitution, normalized integers, with a bounds check on every byte read.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace ontile::gltf {

// Number of components of an accessor "type" (SCALAR 1, VEC2 2, VEC3 3, VEC4 4); 0 for the
// matrix types, which no vertex attribute uses.
int component_count_of_type(int accessor_type);

// Decodes accessor `accessor_index` to floats, `count * components` values, element after
// element. Integer components convert by value, or by the spec 3.11 formulas when the
// accessor is normalized (e.g. BYTE: max(c / 127, -1), UNSIGNED_BYTE: c / 255).
// `file_label` starts every error message.
std::vector<float> read_accessor_floats(const tinygltf::Model& model, int accessor_index,
                                        const std::string& file_label);

// Decodes an index accessor (SCALAR, UNSIGNED_BYTE/UNSIGNED_SHORT/UNSIGNED_INT, not
// normalized) exactly.
std::vector<uint32_t> read_accessor_indices(const tinygltf::Model& model, int accessor_index,
                                            const std::string& file_label);

}  // namespace ontile::gltf
