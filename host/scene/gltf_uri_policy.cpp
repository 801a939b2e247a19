#include "scene/gltf_uri_policy.h"

#include <cctype>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "util/errors.h"

namespace vkp {
namespace {

// The JSON text of a .gltf, or the JSON chunk of a .glb (header: magic, version, length; then
// chunk length, chunk type "JSON", data).
std::string jsonText(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(fmt::format("{}: cannot open the file", file.string()));
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
        if (bytes.size() < 20) throw InputError(fmt::format("{}: truncated GLB header", file.string()));
        uint32_t chunkLength = 0, chunkType = 0;
        std::memcpy(&chunkLength, bytes.data() + 12, 4);
        std::memcpy(&chunkType, bytes.data() + 16, 4);
        if (chunkType != 0x4E4F534Au || uint64_t(chunkLength) + 20 > bytes.size())
            throw InputError(fmt::format("{}: the GLB's first chunk is not a complete JSON chunk", file.string()));
        return bytes.substr(20, chunkLength);
    }
    return bytes;
}

}  // namespace

std::string uriRefusalReason(const std::string& uri) {
    if (uri.rfind("data:", 0) == 0) return {};
    if (uri.empty()) return "the URI is empty";
    if (uri.find('\0') != std::string::npos) return "the URI contains a NUL byte";
    if (uri.find("://") != std::string::npos) return "only relative file URIs and data: URIs are allowed";
    if (uri[0] == '/' || uri[0] == '\\' || (uri.size() > 1 && uri[1] == ':'))
        return "absolute paths are not allowed";
    if (uri[0] == '~') return "'~' expansion is not allowed";
    if (uri.find_first_of("$`") != std::string::npos) return "shell expansion characters ($ `) are not allowed";
    // Reject ".." as a path component, in either separator style and percent-encoded.
    std::string decoded;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
            decoded += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    if (decoded.find_first_of("$`") != std::string::npos) return "shell expansion characters ($ `) are not allowed";
    if (decoded[0] == '/' || decoded[0] == '\\') return "absolute paths are not allowed";
    size_t start = 0;
    while (start <= decoded.size()) {
        const size_t end = decoded.find_first_of("/\\", start);
        const std::string part = decoded.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (part == "..") return "'..' leaves the scene's folder";
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return {};
}

void checkExternalUris(const std::filesystem::path& file) {
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(jsonText(file));
    } catch (const nlohmann::json::exception& e) {
        throw InputError(fmt::format("{}: malformed JSON: {}", file.string(), e.what()));
    }
    if (!json.is_object()) throw InputError(fmt::format("{}: the top level is not a JSON object", file.string()));
    for (const char* kind : {"buffers", "images"}) {
        const auto it = json.find(kind);
        if (it == json.end() || !it->is_array()) continue;
        for (size_t i = 0; i < it->size(); ++i) {
            const auto& entry = (*it)[i];
            if (!entry.is_object() || !entry.contains("uri")) continue;
            if (!entry["uri"].is_string())
                throw InputError(fmt::format("{}: {}[{}].uri: not a string", file.string(), kind, i));
            const std::string uri = entry["uri"].get<std::string>();
            const std::string reason = uriRefusalReason(uri);
            if (!reason.empty())
                throw InputError(fmt::format("{}: {}[{}].uri \"{}\": refused: {}", file.string(), kind, i,
                                             uri.size() > 80 ? uri.substr(0, 80) + "..." : uri, reason));
        }
    }
}

}  // namespace vkp
