// Image files as textures for the cartoon materials (MatCaps, cube-map faces, equirect skies):
// 8-bit-style files as sRGB RGBA8, HDR files (.exr, .hdr) as linear float.
#pragma once
#include <filesystem>
#include <memory>

#include "io/image_io.h"
#include "raster/texture.h"

namespace ontile {

// True for extensions whose values are linear radiance (.exr, .hdr; case-insensitive).
bool is_hdr_image_path(const std::filesystem::path& path);

// An image already read from `path` as a texture named after the file: HDR files keep their float
// values (linear); others are taken as sRGB-encoded colour, quantized to 8-bit codes
// (round to nearest, clamped) and decoded as sRGB when sampled.
std::shared_ptr<const Texture2D> texture_from_image(const ImageRGBA32F& image,
                                                    const std::filesystem::path& path);

// read_image + texture_from_image; every failure is an Error naming the file.
std::shared_ptr<const Texture2D> load_color_texture(const std::filesystem::path& path);

}  // namespace ontile
