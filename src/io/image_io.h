// Image files in and out (OpenImageIO): atomic 8-bit PNG and float32 OpenEXR output with the
// same bytes on every run, reading of any format OpenImageIO knows. Every failure is an
// ontile::Error naming the file.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ontile {

class StagedOutputs;

struct ImageRGBA32F {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGBA, row-major, top row first; width * height * 4 values
  // Bits per channel of the integer format the values came from (read_image of an 8-bit PNG:
  // 8, the values being code / 255); 0 for a float format or values made in memory.
  int integer_bits = 0;
};

// Format by extension (case-insensitive): ".png" writes 8-bit RGBA, ".exr" writes float32 RGBA
// exactly as given (linear). For PNG, RGB is encoded linear -> sRGB (IEC 61966-2-1, rounded to
// nearest) when linear_to_srgb_for_8bit is true; otherwise the values are taken as already
// display-referred and quantized as UNORM (clamp, round to nearest). Alpha is always UNORM.
// Other extensions, size mismatches and write failures throw Error; the target is then left as it
// was and no temporary file remains (write_file_atomically).
// Every writer here: with `staged`, the file is only staged there (written to its temporary)
// and appears when the caller commits; without, it is written on its own, atomically. Files
// carry no timestamp: identical images give identical bytes.
void write_image(const std::filesystem::path& path, const ImageRGBA32F& image,
                 bool linear_to_srgb_for_8bit, StagedOutputs* staged = nullptr);

// Writes width x height RGBA bytes unchanged (e.g. attachments already quantized to RGBA8) as an
// 8-bit PNG; the extension must be ".png".
void write_png_rgba8(const std::filesystem::path& path, int width, int height,
                     const std::vector<uint8_t>& rgba, StagedOutputs* staged = nullptr);

// The same 8-bit RGBA PNG as write_png_rgba8 would write, as a "data:image/png;base64,..." URI for
// self-contained HTML pages (RFC 2397, RFC 4648 base64). Throws Error for a size mismatch.
std::string png_data_uri(int width, int height, const std::vector<uint8_t>& rgba);

// Writes a float32 OpenEXR with arbitrary channels (AOVs such as "Z" or "N.x", "N.y", "N.z"):
// interleaved holds width * height * channel_names.size() values. The extension must be ".exr".
void write_exr_channels(const std::filesystem::path& path, int width, int height,
                        const std::vector<std::string>& channel_names,
                        const std::vector<float>& interleaved, StagedOutputs* staged = nullptr);

// Reads the first subimage of any file OpenImageIO can read, as the values the file stores
// (8-bit files give code / 255, no colour-space conversion; integer_bits says which).
// Channels are expanded to RGBA:
// 1 channel -> (v, v, v, 1); 2 -> (v, v, v, a) when the second is alpha, else (r, g, 0, 1);
// 3 -> (r, g, b, 1); more than 4 -> the first 4.
ImageRGBA32F read_image(const std::filesystem::path& path);

// Reads a PNG as 8-bit RGBA (expanded as read_image does, alpha 255 when absent; 16-bit files are
// converted by OpenImageIO). Throws Error for files that are not PNG.
std::vector<uint8_t> read_png_rgba8(const std::filesystem::path& path, int& width, int& height);

}  // namespace ontile
