#include "scene/gltf_uri_policy.h"

#include <cctype>

namespace vkp {
namespace {

int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Why the (already percent-decoded) path is refused, or "".
std::string pathRefusalReason(const std::string& path) {
    if (path.empty()) return "the URI is empty";
    for (const char c : path)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "the URI contains control characters";
    if (path[0] == '/' || path[0] == '\\') return "absolute paths are not allowed";
    if (path[0] == '~') return "'~' expansion is not allowed";
    if (path.find_first_of("$`") != std::string::npos) return "shell expansion characters ($ `) are not allowed";
    // A ':' before the first separator is a scheme ("http:", "file:") or a drive letter ("C:").
    const size_t colon = path.find(':');
    if (colon != std::string::npos && colon < path.find_first_of("/\\"))
        return "only relative paths and data: URIs are allowed (no schemes or drive letters)";
    size_t start = 0;
    while (true) {
        const size_t end = path.find_first_of("/\\", start);
        if (path.compare(start, end == std::string::npos ? std::string::npos : end - start, "..") == 0)
            return "'..' leaves the scene's folder";
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return {};
}

}  // namespace

bool isDataUri(const std::string& uri) { return uri.rfind("data:", 0) == 0; }

std::string uriToRelativePath(const std::string& uri) {
    std::string decoded;
    decoded.reserve(uri.size());
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hexValue(uri[i + 1]) >= 0 && hexValue(uri[i + 2]) >= 0) {
            decoded += static_cast<char>(hexValue(uri[i + 1]) * 16 + hexValue(uri[i + 2]));
            i += 2;
        } else {  // '+' included: a literal in URIs (RFC 3986), not a space
            decoded += uri[i];
        }
    }
    return decoded;
}

std::string uriRefusalReason(const std::string& uri) {
    if (isDataUri(uri)) return {};
    // tinygltf decodes every '%' without checking its digits: refuse what it would mis-decode.
    for (size_t i = 0; i < uri.size(); ++i)
        if (uri[i] == '%' && (i + 2 >= uri.size() || hexValue(uri[i + 1]) < 0 || hexValue(uri[i + 2]) < 0))
            return "malformed percent-escape";
    // Check both spellings: the raw one (what a shell or another tool might see) and the decoded
    // one (what is opened), so "%2e%2e/" and "%24HOME" are caught too.
    if (std::string reason = pathRefusalReason(uri); !reason.empty()) return reason;
    return pathRefusalReason(uriToRelativePath(uri));
}

}  // namespace vkp
