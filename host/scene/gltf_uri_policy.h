// Which external URIs a glTF file may reference: relative paths inside the file's folder only.
#pragma once

#include <string>

namespace vkp {

// Returns an empty string when `uri` is acceptable, else the reason it is refused: absolute
// paths, URI schemes other than data:, ".." components (also percent-encoded), control
// characters, and anything a shell would expand ($, `, ~ at the start). data: URIs are always
// acceptable here (their payload is checked where it is decoded).
std::string uriRefusalReason(const std::string& uri);

// The relative path an acceptable, non-data URI names: percent-escapes decoded, the way tinygltf
// decodes it before opening the file.
std::string uriToRelativePath(const std::string& uri);

bool isDataUri(const std::string& uri);

}  // namespace vkp
