// Reads a .gltf/.glb file into a tinygltf::Model under the loader's limits: the raw JSON is
// checked first (nesting, data: URIs), external files are confined to the scene's folder, and
// images are measured before they are decoded. tinygltf's errors become one-line Errors.
#include <stb/stb_image.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <climits>
#include <fstream>
#include <iterator>
#include <sstream>

#include "scene/gltf_internal.h"
#include "scene/gltf_json_checks.h"
#include "util/error.h"

namespace ontile::gltf {
namespace {

// tinygltf reports problems as several newline-terminated sentences; they become one line.
// Its messages may quote a whole data: URI; the line is cut after kMaxReasonChars.
std::string one_line(const std::string& text) {
  constexpr size_t kMaxReasonChars = 400;
  std::istringstream lines(text);
  std::string line, joined;
  while (std::getline(lines, line)) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const size_t last = line.find_last_not_of(" \t\r");
    if (!joined.empty()) joined += "; ";
    joined += line.substr(first, last - first + 1);
  }
  if (joined.size() > kMaxReasonChars) joined = joined.substr(0, kMaxReasonChars) + "...";
  return joined;
}

// The lines of tinygltf's text that mention `subject` (all of them when none does), as one line.
std::string lines_mentioning(const std::string& text, const std::string& subject) {
  std::istringstream lines(text);
  std::string line, matching;
  while (std::getline(lines, line)) {
    if (!subject.empty() && line.find(subject) != std::string::npos) matching += line + "\n";
  }
  return one_line(matching.empty() ? text : matching);
}

// Extensions that the loader understands well enough to draw the file correctly. Lights and
// emissive strength are applied; KHR_mesh_quantization needs only the integer attribute
// decoding every accessor gets; KHR_texture_transform is accepted but not applied (textures
// using it sample with untransformed UVs).
bool is_supported_required_extension(const std::string& name) {
  return name == "KHR_lights_punctual" || name == "KHR_materials_emissive_strength" ||
         name == "KHR_texture_transform" || name == "KHR_mesh_quantization";
}

// What the file-system and image callbacks share; the first refusal wins and becomes the
// load's error (tinygltf would report it as a warning or a generic failure).
struct ReadState {
  std::filesystem::path scene_folder;  // absolute, lexically normal
  const GltfLoadOptions* options = nullptr;
  uint64_t image_texels = 0;
  std::string refusal;
};

void refuse(ReadState& state, const std::string& problem) {
  if (state.refusal.empty()) state.refusal = problem;
}

// Lexical containment: ".." and absolute URIs that leave the folder are refused; symbolic
// links inside the folder are the user's own layout and are followed.
bool inside_folder(const std::filesystem::path& folder, const std::filesystem::path& file) {
  const std::filesystem::path relative =
      std::filesystem::absolute(file).lexically_normal().lexically_relative(folder);
  return !relative.empty() && *relative.begin() != ".." && !relative.is_absolute();
}

bool read_confined_file(std::vector<unsigned char>* out, std::string* err,
                        const std::string& filepath, void* user_data) {
  auto& state = *static_cast<ReadState*>(user_data);
  if (!state.options->allow_uris_outside_scene_folder &&
      !inside_folder(state.scene_folder, filepath)) {
    refuse(state, "URI '" + filepath + "' resolves outside the scene's folder " +
                      state.scene_folder.string() +
                      " (GltfLoadOptions::allow_uris_outside_scene_folder allows it)");
    if (err) *err = "outside the scene's folder";
    return false;
  }
  return tinygltf::ReadWholeFile(out, err, filepath, nullptr);
}

std::string image_label(const tinygltf::Image& image, int image_index) {
  return "image " + std::to_string(image_index) +
         (image.uri.empty() ? std::string() : " ('" + image.uri + "')");
}

// Measures the image from its header before tinygltf's stb_image decoder allocates pixels.
bool load_measured_image(tinygltf::Image* image, int image_index, std::string* err,
                         std::string* warn, int required_width, int required_height,
                         const unsigned char* bytes, int size, void* user_data) {
  auto& state = *static_cast<ReadState*>(user_data);
  const GltfLimits& limits = state.options->limits;
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
    refuse(state, image_label(*image, image_index) + " cannot be decoded: " +
                      stbi_failure_reason() + " (PNG and JPEG are supported)");
    return false;
  }
  const uint64_t texels = uint64_t(std::max(width, 0)) * uint64_t(std::max(height, 0));
  if (texels > limits.max_image_texels) {
    refuse(state, image_label(*image, image_index) + " declares " + std::to_string(width) + "x" +
                      std::to_string(height) + " texels, more than " +
                      std::to_string(limits.max_image_texels) +
                      " (GltfLimits::max_image_texels)");
    return false;
  }
  state.image_texels += texels;
  if (state.image_texels > limits.max_total_image_texels) {
    refuse(state, image_label(*image, image_index) + " brings the file's images to " +
                      std::to_string(state.image_texels) + " texels, more than " +
                      std::to_string(limits.max_total_image_texels) +
                      " (GltfLimits::max_total_image_texels)");
    return false;
  }
  // No option block: tinygltf's default, channels expanded to RGBA.
  if (!tinygltf::LoadImageData(image, image_index, err, warn, required_width, required_height,
                               bytes, size, nullptr)) {
    refuse(state, image_label(*image, image_index) + " cannot be decoded: " +
                      stbi_failure_reason());
    return false;
  }
  return true;
}

std::string read_whole_file(const std::filesystem::path& path, const std::string& label) {
  std::ifstream file(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (file.bad()) throw Error(label + ": cannot read the file");
  return bytes;
}

}  // namespace

tinygltf::Model read_model(const std::filesystem::path& path, const std::string& label,
                           const GltfLoadOptions& options, GltfLoadStats& stats) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw Error(label + (std::filesystem::exists(path, error) ? ": not a regular file"
                                                              : ": file not found"));
  }
  const std::string bytes = read_whole_file(path, label);
  if (bytes.size() > UINT_MAX) throw Error(label + ": files over 4 GiB are not supported");
  const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  if (!binary && path.extension() == ".glb") {
    throw Error(label + ": not a GLB file (no 'glTF' magic at the start)");
  }
  check_json_text(binary ? glb_json_chunk(bytes) : std::string_view(bytes), label,
                  options.limits.max_json_nesting_depth, options.allow_uris_outside_scene_folder);

  ReadState state;
  state.scene_folder = std::filesystem::absolute(path).parent_path().lexically_normal();
  state.options = &options;
  tinygltf::TinyGLTF loader;
  tinygltf::FsCallbacks file_access{&tinygltf::FileExists, &tinygltf::ExpandFilePath,
                                    &read_confined_file, &tinygltf::WriteWholeFile, &state};
  loader.SetFsCallbacks(file_access);
  loader.SetImageLoader(&load_measured_image, &state);
  // tinygltf's own base folder rule (GetBaseDir): the path up to its last separator.
  const std::string path_text = path.string();
  const size_t separator = path_text.find_last_of("/\\");
  const std::string base_dir = separator == std::string::npos ? "" : path_text.substr(0, separator);
  tinygltf::Model model;
  std::string tiny_error, tiny_warning;
  const bool loaded =
      binary ? loader.LoadBinaryFromMemory(&model, &tiny_error, &tiny_warning,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned int>(bytes.size()), base_dir)
             : loader.LoadASCIIFromString(&model, &tiny_error, &tiny_warning, bytes.data(),
                                          static_cast<unsigned int>(bytes.size()), base_dir);
  if (!state.refusal.empty()) throw Error(label + ": " + state.refusal);
  if (!loaded) {
    const std::string reason = one_line(tiny_error + "\n" + tiny_warning);
    // tinygltf passes on the JSON parser's message; name the problem plainly in front of it.
    const bool json_syntax = reason.find("parse_error") != std::string::npos ||
                             reason.find("parse JSON") != std::string::npos;
    throw Error(label + (json_syntax ? ": invalid JSON: " : ": cannot load glTF: ") +
                (reason.empty() ? "unknown tinygltf error" : reason));
  }
  for (const std::string& extension : model.extensionsRequired) {
    if (!is_supported_required_extension(extension)) {
      throw Error(label + ": unsupported required extension " + extension);
    }
  }
  // tinygltf only warns when an external image is missing or unreadable; ontile refuses to
  // draw a model with a texture silently missing.
  for (size_t i = 0; i < model.images.size(); ++i) {
    const tinygltf::Image& image = model.images[i];
    if (image.image.empty()) {
      throw Error(label + ": " + image_label(image, static_cast<int>(i)) +
                  " could not be loaded: " + lines_mentioning(tiny_warning, image.uri));
    }
  }
  const std::string warnings = one_line(tiny_warning);
  if (!warnings.empty()) stats.warnings.push_back(warnings);
  return model;
}

}  // namespace ontile::gltf
