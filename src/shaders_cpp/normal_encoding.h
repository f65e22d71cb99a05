// How a unit normal is stored in a colour target and read back: RGB10A2 (n * 0.5 + 0.5),
// RGBA16F (as is) or octahedral-encoded RG16 UNORM (Cigolle et al., "A Survey of Efficient
// Representations for Independent Unit Vectors", JCGT 2014).
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"

namespace ontile {

enum class NormalStorage { Rgb10a2, Rgba16f, OctRg16 };

// "rgb10a2", "rgba16f", "oct-rg16".
const char* normal_storage_name(NormalStorage storage);
std::optional<NormalStorage> parse_normal_storage(std::string_view name);
std::vector<NormalStorage> all_normal_storages();
PixelFormat normal_storage_format(NormalStorage storage);

// Octahedral map of a unit vector to [-1, 1]^2: project onto |x| + |y| + |z| = 1, fold the lower
// half (z < 0) over the diagonals. The zero vector maps to (0, 0).
glm::vec2 octahedral_encode(const glm::vec3& unit_normal);
// The inverse map, normalised; every point of [-1, 1]^2 gives a unit vector.
glm::vec3 octahedral_decode(const glm::vec2& encoded);

// The colour-target value to write for a unit normal (before the format quantises it).
glm::vec4 encode_normal(NormalStorage storage, const glm::vec3& unit_normal);
// The unit normal a stored (quantised) value stands for; (0, 0, 0) for an all-zero RGB10A2 or
// RGBA16F value (a cleared pixel).
glm::vec3 decode_normal(NormalStorage storage, const glm::vec4& stored);

}  // namespace ontile
