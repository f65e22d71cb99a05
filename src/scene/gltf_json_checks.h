// Checks on a glTF file's raw JSON text before tinygltf parses it: bracket nesting depth (the
// JSON parser recurses once per level) and strict base64 in "uri" data: URIs (tinygltf's
// decoder stops silently at the first bad character).
#pragma once
#include <string>
#include <string_view>

namespace ontile::gltf {

// The JSON chunk of a GLB file (GLB spec 4.4: 12-byte header, then chunk 0 of type JSON);
// empty when the header or the chunk length is malformed (tinygltf then reports it).
std::string_view glb_json_chunk(std::string_view file_bytes);

// Throws ontile::Error("LABEL: problem") when brackets outside strings nest deeper than
// max_nesting_depth, when the value of a "uri" key is a base64 data: URI whose payload is not
// valid base64 (RFC 4648 section 4: the 64-character alphabet, length a multiple of 4, at most
// two '=' and only at the end), or, unless allow_absolute_uris, when it is an absolute path
// ("/...", "\\...", "C:...") or a file: URI.
void check_json_text(std::string_view json, const std::string& label, int max_nesting_depth,
                     bool allow_absolute_uris);

}  // namespace ontile::gltf
