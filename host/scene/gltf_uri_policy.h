// Which external URIs a glTF file may reference: relative paths inside the file's folder only.
#pragma once

#include <filesystem>
#include <string>

namespace vkp {

// Returns an empty string when `uri` is acceptable, else the reason it is refused: absolute
// paths, ".." components, and anything a shell would expand ($, `, ~ at the start, ...).
// data: URIs are always acceptable.
std::string uriRefusalReason(const std::string& uri);

// Refuses (InputError naming `file` and `element`) every buffer and image URI of the glTF JSON
// (the JSON chunk for .glb) that uriRefusalReason() rejects; also reports malformed JSON.
void checkExternalUris(const std::filesystem::path& file);

}  // namespace vkp
