#include "scene/gltf_preflight.h"

#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "scene/gltf_extensions.h"
#include "scene/gltf_schema.h"
#include "scene/gltf_uri_policy.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

// Real glTF files nest about 8 levels; tinygltf converts extensions and extras recursively, so a
// file nested thousands deep would overflow its stack.
constexpr int kMaxJsonDepth = 64;

constexpr uint32_t kGlbVersion = 2;
constexpr uint32_t kChunkJson = 0x4E4F534Au;  // "JSON", little-endian
constexpr uint32_t kChunkBin = 0x004E4942u;   // "BIN\0"

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(element.empty() ? what : element + ": " + what);
}

std::string member(const std::string& element, std::string_view key) {
    return element.empty() ? std::string(key) : fmt::format("{}.{}", element, key);
}

std::string shown(const std::string& uri) {
    return fmt::format("\"{}\"", uri.size() > 80 ? uri.substr(0, 77) + "..." : uri);
}

const Json* find(const Json& object, std::string_view key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

std::optional<uint64_t> toIndex(const Json& value) {
    if (value.is_number_unsigned()) return value.get<uint64_t>();
    if (value.is_number_integer() && value.get<int64_t>() >= 0) return static_cast<uint64_t>(value.get<int64_t>());
    return std::nullopt;
}

std::optional<uint64_t> uintField(const Json& object, std::string_view key, const std::string& element, bool required) {
    const Json* value = find(object, key);
    if (!value) {
        if (required) fail(element, fmt::format("\"{}\" is missing", key));
        return std::nullopt;
    }
    const auto index = toIndex(*value);
    if (!index) fail(member(element, key), "not a non-negative integer");
    return index;
}

// `object.key`, when present (or required), must index one of `count` elements of `target`.
void checkRef(const Json& object, std::string_view key, const std::string& element, std::string_view target,
              size_t count, bool required = false) {
    const auto index = uintField(object, key, element, required);
    if (index && *index >= count)
        fail(member(element, key), fmt::format("{}[{}] does not exist (the file has {})", target, *index, count));
}

const Json& arrayField(const Json& object, std::string_view key, const std::string& element) {
    static const Json kEmpty = Json::array();
    const Json* value = find(object, key);
    if (!value) return kEmpty;
    if (!value->is_array()) fail(member(element, key), "not an array");
    return *value;
}

void checkRefArray(const Json& object, std::string_view key, const std::string& element, std::string_view target,
                   size_t count) {
    const Json& refs = arrayField(object, key, element);
    for (size_t i = 0; i < refs.size(); ++i) {
        const std::string name = fmt::format("{}[{}]", member(element, key), i);
        const auto index = toIndex(refs[i]);
        if (!index) fail(name, "not a non-negative integer");
        if (*index >= count) fail(name, fmt::format("{}[{}] does not exist (the file has {})", target, *index, count));
    }
}

template <typename F>
void forEachObject(const Json& root, std::string_view key, F&& visit) {
    const Json& items = arrayField(root, key, "");
    for (size_t i = 0; i < items.size(); ++i) {
        const std::string element = fmt::format("{}[{}]", key, i);
        if (!items[i].is_object()) fail(element, "not a JSON object");
        visit(items[i], element, i);
    }
}

std::vector<unsigned char> readFile(const fs::path& path, const GltfLimits& limits) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) fail("", "no such file");
    if (!fs::is_regular_file(status)) fail("", "not a regular file");
    const uint64_t size = fs::file_size(path, ec);
    if (ec) fail("", fmt::format("cannot read the file size: {}", ec.message()));
    if (size > limits.maxFileBytes)
        fail("", fmt::format("{} bytes is more than the {}-byte limit", size, limits.maxFileBytes));
    if (size == 0) fail("", "the file is empty");
    std::vector<unsigned char> bytes(size);
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
        fail("", "cannot read the file");
    return bytes;
}

uint32_t readU32(const std::vector<unsigned char>& bytes, size_t at) {
    uint32_t value;
    std::memcpy(&value, bytes.data() + at, 4);  // GLB is little-endian, as are the hosts we build for
    return value;
}

struct JsonSpan {
    size_t offset = 0;
    size_t length = 0;
    std::optional<uint64_t> binLength;  // the GLB's BIN chunk, when there is one
};

// GLB layout: 12-byte header (magic, version, length), a JSON chunk, optionally a BIN chunk;
// each chunk is (length, type, data). tinygltf reads 8 bytes past a BIN chunk whose declared
// length ends within 8 bytes of the file's end, so the bounds are checked here.
JsonSpan glbJson(const std::vector<unsigned char>& bytes) {
    if (bytes.size() < 20) fail("GLB header", "truncated (a .glb needs at least 20 bytes)");
    if (const uint32_t version = readU32(bytes, 4); version != kGlbVersion)
        fail("GLB header", fmt::format("version {} is not 2", version));
    const uint64_t length = readU32(bytes, 8);
    if (length != bytes.size())
        fail("GLB header", fmt::format("declares {} bytes but the file has {}", length, bytes.size()));
    JsonSpan span{20, readU32(bytes, 12), std::nullopt};
    if (readU32(bytes, 16) != kChunkJson) fail("GLB chunk 0", "not a JSON chunk");
    if (span.length == 0 || 20 + uint64_t(span.length) > length)
        fail("GLB chunk 0", fmt::format("{} bytes do not fit in the file", span.length));
    const uint64_t bin = 20 + uint64_t(span.length);
    if (bin == length) return span;
    if (bin + 8 > length) fail("GLB chunk 1", "truncated chunk header");
    const uint64_t binLength = readU32(bytes, bin);
    if (readU32(bytes, bin + 4) != kChunkBin) fail("GLB chunk 1", "not a BIN chunk");
    if (bin + 8 + binLength > length) fail("GLB chunk 1", fmt::format("{} bytes do not fit in the file", binLength));
    if (binLength == 0 || binLength % 4 != 0) fail("GLB chunk 1", "the length must be a positive multiple of 4");
    span.binLength = binLength;
    return span;
}

// Also refuses NUL bytes: tinygltf stops reading at one, so text after it would be ignored.
void checkNesting(const unsigned char* text, size_t length) {
    int depth = 0;
    bool inString = false, escaped = false;
    for (size_t i = 0; i < length; ++i) {
        const char c = static_cast<char>(text[i]);
        if (c == '\0') fail("", fmt::format("the JSON text holds a NUL byte at byte {}", i));
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth) fail("", fmt::format("JSON nested deeper than {} levels", kMaxJsonDepth));
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

Json parseJson(const unsigned char* text, size_t length) {
    checkNesting(text, length);
    try {
        Json json = Json::parse(text, text + length);
        if (!json.is_object()) fail("", "the top level is not a JSON object");
        return json;
    } catch (const Json::exception& e) {
        // nlohmann quotes what it last read, which can be a whole data: URI.
        const std::string what = e.what();
        fail("", fmt::format("malformed JSON: {}", what.size() > 240 ? what.substr(0, 237) + "..." : what));
    }
}

void checkAsset(const Json& root) {
    const Json* asset = find(root, "asset");
    if (!asset || !asset->is_object()) fail("asset", "missing (is this a glTF 2.0 file?)");
    const Json* version = find(*asset, "version");
    if (!version || !version->is_string() || version->get<std::string>().rfind("2.", 0) != 0)
        fail("asset.version", "must be \"2.x\": only glTF 2.0 is supported");
    for (const Json& name : arrayField(root, "extensionsRequired", "")) {
        if (!name.is_string()) fail("extensionsRequired", "holds a non-string");
        // Only extensions the loader reads may be required (others make the file unreadable).
        if (!gltfExtensionIsRead(name.get<std::string>()))
            fail("extensionsRequired", fmt::format("{} is required by the file but not supported", name.get<std::string>()));
    }
}

// Where the base64 payload of a data: URI starts, when the media type is one of `types`.
std::optional<size_t> dataPayload(const std::string& uri, std::initializer_list<std::string_view> types) {
    for (const std::string_view type : types) {
        const std::string prefix = fmt::format("data:{};base64,", type);
        if (uri.rfind(prefix, 0) == 0) return prefix.size();
    }
    return std::nullopt;
}

// The bytes tinygltf's base64 decoder yields: it stops at the first character outside the
// alphabet (normally the '=' padding).
uint64_t base64Length(const std::string& uri, size_t payload) {
    size_t digits = 0;
    for (size_t i = payload; i < uri.size(); ++i, ++digits) {
        const unsigned char c = static_cast<unsigned char>(uri[i]);
        if (!std::isalnum(c) && c != '+' && c != '/') break;
    }
    const size_t tail = digits % 4;
    return digits / 4 * 3 + (tail == 2 ? 1 : tail == 3 ? 2 : 0);
}

class Preflight {
public:
    Preflight(const fs::path& folder, const GltfLimits& limits, GltfFileAccess& files)
        : m_folder(folder), m_limits(limits), m_files(files) {}

    void check(const Json& root, const JsonSpan& span, bool binary) {
        checkAsset(root);
        validateGltfSchema(root);
        countElements(root);
        checkBuffers(root, span, binary);
        checkBufferViews(root);
        checkImages(root);
        checkReferences(root);
    }

private:
    void countElements(const Json& root) {
        for (const char* key : {"scenes", "nodes", "meshes", "accessors", "bufferViews", "buffers", "images",
                                "textures", "materials", "cameras", "samplers", "skins", "animations"})
            m_count[key] = arrayField(root, key, "").size();
        const Json* lights = find(root, "extensions");
        lights = lights ? find(*lights, "KHR_lights_punctual") : nullptr;
        const Json& lightArray = lights ? arrayField(*lights, "lights", "extensions.KHR_lights_punctual") : Json::array();
        for (size_t i = 0; i < lightArray.size(); ++i)
            if (!lightArray[i].is_object())
                fail(fmt::format("extensions.KHR_lights_punctual.lights[{}]", i), "not a JSON object");
        m_count["lights"] = lightArray.size();
    }

    // An external file named by `element.uri`: refused by policy, missing, or too large.
    fs::path externalFile(const std::string& uri, const std::string& element) {
        const std::string where = member(element, "uri");
        if (const std::string reason = uriRefusalReason(uri); !reason.empty())
            fail(where, fmt::format("{} is refused: {}", shown(uri), reason));
        const auto file = resolveInFolder(m_folder, m_folder / uriToRelativePath(uri));
        if (!file) fail(where, fmt::format("file {} not found inside the scene's folder", shown(uri)));
        std::error_code ec;
        const uint64_t size = fs::file_size(*file, ec);
        if (ec || size > m_limits.maxFileBytes)
            fail(where, fmt::format("file {} is larger than the {}-byte limit", shown(uri), m_limits.maxFileBytes));
        m_files.registerUri(uri);
        return *file;
    }

    // A buffer without data of its own: EXT/KHR_meshopt_compression's decoding target.
    static bool isMeshoptFallback(const Json& buffer) {
        const Json* extensions = find(buffer, "extensions");
        return extensions && extensions->is_object() &&
               (extensions->contains("EXT_meshopt_compression") || extensions->contains("KHR_meshopt_compression"));
    }

    void checkBuffers(const Json& root, const JsonSpan& span, bool binary) {
        forEachObject(root, "buffers", [&](const Json& buffer, const std::string& element, size_t i) {
            const uint64_t length = *uintField(buffer, "byteLength", element, true);
            if (length == 0) fail(member(element, "byteLength"), "must be at least 1");
            m_bufferLengths.push_back(length);
            const Json* uri = find(buffer, "uri");
            if (!uri) {
                if (isMeshoptFallback(buffer)) {  // decoded from compressed views (gltf_meshopt.h)
                    if (length > m_limits.maxFileBytes)
                        fail(element, fmt::format("the meshopt fallback's byteLength {} exceeds the {}-byte limit",
                                                  length, m_limits.maxFileBytes));
                    return;
                }
                if (!binary || i != 0) fail(element, "no uri (only the first buffer of a .glb may omit it)");
                if (!span.binLength) fail(element, "the .glb has no BIN chunk to hold it");
                if (length > *span.binLength)
                    fail(element, fmt::format("byteLength {} exceeds the GLB's BIN chunk ({} bytes)", length, *span.binLength));
                return;
            }
            if (!uri->is_string()) fail(member(element, "uri"), "not a string");
            const std::string& text = uri->get_ref<const std::string&>();
            if (isDataUri(text)) {
                const auto payload = dataPayload(text, {"application/octet-stream", "application/gltf-buffer"});
                if (!payload)
                    fail(member(element, "uri"), "a data: URI must be base64 application/octet-stream or gltf-buffer");
                if (const uint64_t decoded = base64Length(text, *payload); decoded != length)
                    fail(element, fmt::format("the data: URI holds {} bytes but byteLength is {}", decoded, length));
                return;
            }
            const fs::path file = externalFile(text, element);
            std::error_code ec;
            if (const uint64_t size = fs::file_size(file, ec); size < length)
                fail(element, fmt::format("file {} has {} bytes but byteLength is {} (short buffer)", shown(text), size, length));
            m_files.expectBufferLength(file, length);
        });
    }

    void checkBufferViews(const Json& root) {
        forEachObject(root, "bufferViews", [&](const Json& view, const std::string& element, size_t) {
            checkRef(view, "buffer", element, "buffers", m_bufferLengths.size(), true);
            const uint64_t buffer = *uintField(view, "buffer", element, true);
            const uint64_t offset = uintField(view, "byteOffset", element, false).value_or(0);
            const uint64_t length = *uintField(view, "byteLength", element, true);
            const uint64_t available = m_bufferLengths[buffer];
            if (length == 0) fail(member(element, "byteLength"), "must be at least 1");
            if (offset > available || length > available - offset)
                fail(element, fmt::format("bytes [{}, {}) exceed buffers[{}] ({} bytes)", offset, offset + length,
                                          buffer, available));
            const auto stride = uintField(view, "byteStride", element, false);
            if (stride && (*stride < 4 || *stride > 252 || *stride % 4 != 0))
                fail(member(element, "byteStride"), fmt::format("{} is not a multiple of 4 in [4, 252]", *stride));
        });
    }

    void checkImages(const Json& root) {
        forEachObject(root, "images", [&](const Json& image, const std::string& element, size_t) {
            const Json* uri = find(image, "uri");
            const bool hasView = find(image, "bufferView") != nullptr;
            if (uri && hasView) fail(element, "has both a uri and a bufferView");
            if (!uri && !hasView) fail(element, "has neither a uri nor a bufferView");
            if (hasView) return checkRef(image, "bufferView", element, "bufferViews", m_count["bufferViews"]);
            if (!uri->is_string()) fail(member(element, "uri"), "not a string");
            const std::string& text = uri->get_ref<const std::string&>();
            if (!isDataUri(text)) {
                externalFile(text, element);
            } else if (const auto payload = dataPayload(text, {"image/png", "image/jpeg", "application/octet-stream"});
                       !payload) {
                // tinygltf decodes no other data: URIs; a WebP (EXT_texture_webp) comes as a file or bufferView.
                fail(member(element, "uri"),
                     "a data: URI must be base64 image/png or image/jpeg (a WebP must be a file or a bufferView)");
            } else if (base64Length(text, *payload) == 0) {
                fail(member(element, "uri"), "the data: URI holds no data");
            }
        });
    }

    void checkReferences(const Json& root) {
        checkRef(root, "scene", "", "scenes", m_count["scenes"]);
        forEachObject(root, "scenes", [&](const Json& scene, const std::string& element, size_t) {
            checkRefArray(scene, "nodes", element, "nodes", m_count["nodes"]);
        });
        forEachObject(root, "nodes", [&](const Json& node, const std::string& element, size_t) { checkNode(node, element); });
        forEachObject(root, "meshes", [&](const Json& mesh, const std::string& element, size_t) { checkMesh(mesh, element); });
        forEachObject(root, "accessors", [&](const Json& accessor, const std::string& element, size_t) {
            checkRef(accessor, "bufferView", element, "bufferViews", m_count["bufferViews"]);
            checkAccessor(accessor, element);
            const Json* sparse = find(accessor, "sparse");
            if (!sparse) return;
            for (const char* part : {"indices", "values"}) {
                const std::string name = fmt::format("{}.sparse.{}", element, part);
                const Json* p = find(*sparse, part);
                if (!p || !p->is_object()) fail(name, "missing or not an object");
                checkRef(*p, "bufferView", name, "bufferViews", m_count["bufferViews"], true);
            }
        });
        forEachObject(root, "textures", [&](const Json& texture, const std::string& element, size_t) {
            checkRef(texture, "source", element, "images", m_count["images"]);
            checkRef(texture, "sampler", element, "samplers", m_count["samplers"]);
        });
        forEachObject(root, "skins", [&](const Json& skin, const std::string& element, size_t) {
            checkRef(skin, "inverseBindMatrices", element, "accessors", m_count["accessors"]);
            checkRef(skin, "skeleton", element, "nodes", m_count["nodes"]);
            checkRefArray(skin, "joints", element, "nodes", m_count["nodes"]);
        });
        forEachObject(root, "animations", [&](const Json& animation, const std::string& element, size_t) {
            checkAnimation(animation, element);
        });
        forEachObject(root, "cameras", [&](const Json& camera, const std::string& element, size_t) {
            checkCamera(camera, element);
        });
        forEachObject(root, "materials", [&](const Json& material, const std::string& element, size_t) {
            checkMaterial(material, element);
        });
    }

    // What the schema cannot say: a byte offset aligned to the component size, no normalized
    // floats (the specification's MUSTs).
    void checkAccessor(const Json& accessor, const std::string& element) {
        const int componentType = accessor.at("componentType").get<int>();
        const int size = componentType == 5120 || componentType == 5121 ? 1 : componentType == 5122 || componentType == 5123 ? 2 : 4;
        if (const Json* offset = find(accessor, "byteOffset"); offset && offset->get<uint64_t>() % size != 0)
            fail(member(element, "byteOffset"),
                 fmt::format("{} is not a multiple of the component size ({} bytes)", offset->get<uint64_t>(), size));
        if (const Json* normalized = find(accessor, "normalized");
            normalized && normalized->get<bool>() && (componentType == 5126 || componentType == 5125))
            fail(member(element, "normalized"), "must not be true for FLOAT or UNSIGNED_INT components");
    }

    void checkCamera(const Json& camera, const std::string& element) {
        for (const char* kind : {"perspective", "orthographic"}) {
            const Json* projection = find(camera, kind);
            if (!projection) continue;
            const std::string name = member(element, kind);
            const Json* znear = find(*projection, "znear");
            const Json* zfar = find(*projection, "zfar");
            // In float, as used: 1 and 1.00000001 are one plane.
            if (znear && zfar && !(zfar->get<float>() > znear->get<float>()))
                fail(member(name, "zfar"), fmt::format("{} is not greater than znear {}", zfar->get<double>(), znear->get<double>()));
            for (const char* key : {"xmag", "ymag"})
                if (const Json* mag = find(*projection, key); mag && mag->get<float>() == 0.0f) fail(member(name, key), "must not be zero");
        }
        const std::string type = camera.at("type").get<std::string>();
        if (!find(camera, type.c_str())) fail(element, fmt::format("type \"{}\" but no \"{}\" object", type, type));
    }

    void checkAnimation(const Json& animation, const std::string& element) {
        const size_t samplers = arrayField(animation, "samplers", element).size();
        const Json& channels = arrayField(animation, "channels", element);
        for (size_t c = 0; c < channels.size(); ++c) {
            const std::string name = fmt::format("{}.channels[{}]", element, c);
            checkRef(channels[c], "sampler", name, member(element, "samplers"), samplers);
            if (const Json* target = find(channels[c], "target"))
                checkRef(*target, "node", member(name, "target"), "nodes", m_count["nodes"]);
        }
        const Json& samplerArray = arrayField(animation, "samplers", element);
        for (size_t i = 0; i < samplerArray.size(); ++i) {
            const std::string name = fmt::format("{}.samplers[{}]", element, i);
            checkRef(samplerArray[i], "input", name, "accessors", m_count["accessors"]);
            checkRef(samplerArray[i], "output", name, "accessors", m_count["accessors"]);
        }
    }

    void checkNode(const Json& node, const std::string& element) {
        checkRef(node, "mesh", element, "meshes", m_count["meshes"]);
        checkRef(node, "skin", element, "skins", m_count["skins"]);
        checkRef(node, "camera", element, "cameras", m_count["cameras"]);
        checkRefArray(node, "children", element, "nodes", m_count["nodes"]);
        const Json* extensions = find(node, "extensions");
        if (const Json* light = extensions ? find(*extensions, "KHR_lights_punctual") : nullptr)
            checkRef(*light, "light", member(element, "extensions.KHR_lights_punctual"),
                     "extensions.KHR_lights_punctual.lights", m_count["lights"], true);
    }

    void checkMesh(const Json& mesh, const std::string& element) {
        const Json& primitives = arrayField(mesh, "primitives", element);
        if (primitives.empty()) fail(element, "has no primitives");
        for (size_t p = 0; p < primitives.size(); ++p) {
            const Json& primitive = primitives[p];
            const std::string name = fmt::format("{}.primitives[{}]", element, p);
            if (!primitive.is_object()) fail(name, "not a JSON object");
            checkRef(primitive, "indices", name, "accessors", m_count["accessors"]);
            checkRef(primitive, "material", name, "materials", m_count["materials"]);
            const Json* attributes = find(primitive, "attributes");
            if (!attributes || !attributes->is_object()) fail(name, "\"attributes\" is missing or not an object");
            for (const auto& [semantic, value] : attributes->items())
                checkRef(*attributes, semantic, member(name, "attributes"), "accessors", m_count["accessors"]);
            const Json& targets = arrayField(primitive, "targets", name);
            for (size_t t = 0; t < targets.size(); ++t)
                for (const auto& [semantic, value] : targets[t].items())
                    checkRef(targets[t], semantic, fmt::format("{}.targets[{}]", name, t), "accessors", m_count["accessors"]);
        }
    }

    void checkMaterial(const Json& material, const std::string& element) {
        const auto checkInfo = [&](const Json& owner, const char* key, const std::string& ownerName) {
            const Json* info = find(owner, key);
            if (!info) return;
            if (!info->is_object()) fail(member(ownerName, key), "not an object");
            checkRef(*info, "index", member(ownerName, key), "textures", m_count["textures"], true);
        };
        if (const Json* pbr = find(material, "pbrMetallicRoughness")) {
            const std::string name = member(element, "pbrMetallicRoughness");
            checkInfo(*pbr, "baseColorTexture", name);
            checkInfo(*pbr, "metallicRoughnessTexture", name);
        }
        for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) checkInfo(material, key, element);
        // Texture references inside the material extensions vkphoton knows.
        if (const Json* extensions = find(material, "extensions"))
            for (const auto& [name, extension] : extensions->items())
                for (const char* key : {"transmissionTexture", "thicknessTexture"})
                    checkInfo(extension, key, fmt::format("{}.extensions.{}", element, name));
    }

    fs::path m_folder;
    const GltfLimits& m_limits;
    GltfFileAccess& m_files;
    std::map<std::string, size_t> m_count;
    std::vector<uint64_t> m_bufferLengths;
};

}  // namespace

GltfDocument preflightGltf(const fs::path& path, const GltfLimits& limits, GltfFileAccess& files) {
    GltfDocument document;
    document.bytes = readFile(path, limits);
    document.binary = document.bytes.size() >= 4 && std::memcmp(document.bytes.data(), "glTF", 4) == 0;
    const JsonSpan span = document.binary ? glbJson(document.bytes) : JsonSpan{0, document.bytes.size(), std::nullopt};
    // The JSON chunk is padded to 4 bytes, with spaces by the specification; some exporters pad
    // with NUL bytes, which are not JSON text.
    size_t jsonLength = span.length;
    while (document.binary && jsonLength > 0 && document.bytes[span.offset + jsonLength - 1] == 0 &&
           span.length - jsonLength < 3)
        --jsonLength;
    const Json root = parseJson(document.bytes.data() + span.offset, jsonLength);
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    Preflight(folder, limits, files).check(root, span, document.binary);
    return document;
}

}  // namespace vkp
