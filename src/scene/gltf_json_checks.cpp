// Raw JSON checks before parsing (see gltf_json_checks.h): one linear pass that tracks
// strings, bracket depth and "uri" keys.
#include "scene/gltf_json_checks.h"

#include <cstdint>
#include <cstring>
#include <optional>

#include "util/error.h"

namespace ontile::gltf {
namespace {

uint32_t read_u32_le(std::string_view bytes, size_t offset) {
  uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4);
  return value;
}

bool is_base64_alphabet(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
         c == '/';
}

std::string describe_char(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x20 && byte < 0x7F) return std::string("'") + c + "'";
  static const char* kHex = "0123456789abcdef";
  return std::string("byte 0x") + kHex[byte >> 4] + kHex[byte & 15];
}

// The problem with the base64 payload of a data: URI given as raw JSON string content
// (between the quotes, escapes not yet decoded), or nullopt when it is valid. Only "\/" is
// accepted as an escape: it is how some writers store '/'.
std::optional<std::string> base64_problem(std::string_view raw) {
  size_t symbols = 0, padding = 0;
  for (size_t i = 0; i < raw.size(); ++i) {
    char c = raw[i];
    if (c == '\\') {
      if (i + 1 < raw.size() && raw[i + 1] == '/') {
        c = '/';
        ++i;
      } else {
        return "escape sequence at payload position " + std::to_string(symbols + padding);
      }
    }
    if (c == '=') {
      ++padding;
      continue;
    }
    if (!is_base64_alphabet(c)) {
      return describe_char(c) + " at payload position " + std::to_string(symbols + padding);
    }
    if (padding > 0) return "'=' padding before the end of the payload";
    ++symbols;
  }
  if (padding > 2) return std::to_string(padding) + " '=' padding characters (at most 2)";
  if ((symbols + padding) % 4 != 0) {
    return "payload length " + std::to_string(symbols + padding) + " is not a multiple of 4";
  }
  return std::nullopt;
}

bool is_absolute_reference(std::string_view raw_value) {
  if (raw_value.substr(0, 5) == "file:") return true;
  if (!raw_value.empty() && (raw_value[0] == '/' || raw_value[0] == '\\')) return true;
  return raw_value.size() >= 2 && raw_value[1] == ':' &&
         ((raw_value[0] >= 'A' && raw_value[0] <= 'Z') || (raw_value[0] >= 'a' && raw_value[0] <= 'z'));
}

void check_uri(std::string_view raw_value, size_t offset, const std::string& label,
               bool allow_absolute_uris) {
  if (!allow_absolute_uris && is_absolute_reference(raw_value)) {
    constexpr size_t kShownChars = 80;
    throw Error(label + ": URI '" + std::string(raw_value.substr(0, kShownChars)) +
                "' is an absolute path; URIs must name files inside the scene's folder "
                "(GltfLoadOptions::allow_uris_outside_scene_folder allows it)");
  }
  if (raw_value.substr(0, 5) != "data:") return;
  const size_t marker = raw_value.find(";base64,");
  if (marker == std::string_view::npos) return;  // not base64: tinygltf rejects it by name
  if (const auto problem = base64_problem(raw_value.substr(marker + 8))) {
    throw Error(label + ": data: URI at JSON byte " + std::to_string(offset) +
                " is not valid base64: " + *problem);
  }
}

}  // namespace

std::string_view glb_json_chunk(std::string_view file_bytes) {
  constexpr uint32_t kJsonChunkType = 0x4E4F534Au;  // "JSON"
  if (file_bytes.size() < 20) return {};
  const uint32_t length = read_u32_le(file_bytes, 12);
  if (read_u32_le(file_bytes, 16) != kJsonChunkType || length > file_bytes.size() - 20) return {};
  return file_bytes.substr(20, length);
}

void check_json_text(std::string_view json, const std::string& label, int max_nesting_depth,
                     bool allow_absolute_uris) {
  int depth = 0;
  // "uri" key tracking: after the string "uri" and a ':', the next string is a URI value.
  bool last_string_was_uri_key = false, expecting_uri_value = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (c == '"') {
      const size_t start = i + 1;
      size_t end = start;
      while (end < json.size() && json[end] != '"') end += json[end] == '\\' ? 2 : 1;
      if (end >= json.size()) return;  // unterminated string: the parser reports it
      const std::string_view content = json.substr(start, end - start);
      if (expecting_uri_value) check_uri(content, start, label, allow_absolute_uris);
      last_string_was_uri_key = !expecting_uri_value && content == "uri";
      expecting_uri_value = false;
      i = end;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
    expecting_uri_value = c == ':' && last_string_was_uri_key;
    last_string_was_uri_key = false;
    if (c == '{' || c == '[') {
      if (++depth > max_nesting_depth) {
        throw Error(label + ": JSON nesting deeper than " + std::to_string(max_nesting_depth) +
                    " levels at byte " + std::to_string(i) +
                    " (GltfLimits::max_json_nesting_depth)");
      }
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
}

}  // namespace ontile::gltf
