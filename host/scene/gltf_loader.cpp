#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_accessors.h"
#include "scene/gltf_uri_policy.h"
#include "util/errors.h"

extern "C" int stbi_info_from_memory(const unsigned char* buffer, int len, int* x, int* y, int* comp);

namespace vkp {
namespace {

namespace fs = std::filesystem;

// KHR_lights_punctual photometric units -> radiometric, at the luminous efficacy Blender's glTF
// importer assumes by default (683 lm/W): candela -> W/sr, lux -> W/m^2.
constexpr float kLumensPerWatt = 683.0f;

struct FsContext {
    fs::path folder;
    const GltfLimits* limits;
    std::string error;
};

// tinygltf file-system callbacks: no path expansion, reads only inside the scene's folder and
// only files within the size limit. URIs were already screened by checkExternalUris().
bool fileExists(const std::string& path, void* user) {
    auto* ctx = static_cast<FsContext*>(user);
    std::error_code ec;
    const fs::path canonical = fs::weakly_canonical(path, ec);
    if (ec) return false;
    const fs::path folder = fs::weakly_canonical(ctx->folder, ec);
    const auto rel = canonical.lexically_relative(folder);
    if (rel.empty() || rel.native().rfind("..", 0) == 0) return false;
    return fs::is_regular_file(canonical, ec);
}

std::string expandFilePath(const std::string& path, void*) { return path; }

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    auto* ctx = static_cast<FsContext*>(user);
    if (!fileExists(path, user)) {
        if (err) *err += fmt::format("file '{}' is missing or outside the scene's folder\n", path);
        return false;
    }
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec || size > ctx->limits->maxFileBytes) {
        if (err) *err += fmt::format("file '{}' exceeds the size limit of {} bytes\n", path, ctx->limits->maxFileBytes);
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(size);
    if (size && !in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
        if (err) *err += fmt::format("cannot read '{}'\n", path);
        return false;
    }
    return true;
}

bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err = "writing is not allowed";
    return false;
}

// Checks the image header against the limits before tinygltf's decoder allocates anything.
bool loadImageChecked(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int reqWidth,
                      int reqHeight, const unsigned char* bytes, int size, void* user) {
    const auto* limits = static_cast<const GltfLimits*>(user);
    int w = 0, h = 0, comp = 0;
    if (!stbi_info_from_memory(bytes, size, &w, &h, &comp)) {
        if (err) *err += fmt::format("images[{}]: not a decodable PNG/JPEG image\n", index);
        return false;
    }
    if (w <= 0 || h <= 0 || static_cast<uint32_t>(w) > limits->maxImageDimension ||
        static_cast<uint32_t>(h) > limits->maxImageDimension || uint64_t(w) * uint64_t(h) > limits->maxImagePixels) {
        if (err)
            *err += fmt::format("images[{}]: {}x{} exceeds the image size limit ({} per side, {} pixels)\n", index, w, h,
                                limits->maxImageDimension, limits->maxImagePixels);
        return false;
    }
    return tinygltf::LoadImageData(image, index, err, warn, reqWidth, reqHeight, bytes, size, nullptr);
}

glm::mat4 localTransform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::mat4 m;
        for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(node.matrix[i]);  // column-major
        return m;
    }
    glm::mat4 m(1.0f);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        m *= glm::mat4_cast(glm::quat(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                                      static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2])));
    if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

double numberOr(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) return fallback;
    const tinygltf::Value& v = object.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

class Loader {
public:
    Loader(const fs::path& path, const GltfLimits& limits) : m_path(path), m_limits(limits) {}

    Scene load() {
        readModel();
        m_scene.source = m_path;
        for (size_t i = 0; i < m_model.materials.size(); ++i) m_scene.materials.push_back(material(static_cast<int>(i)));
        const int sceneIndex = m_model.defaultScene >= 0 ? m_model.defaultScene : 0;
        if (m_model.scenes.empty()) fail("scenes", "the file has no scene");
        if (static_cast<size_t>(sceneIndex) >= m_model.scenes.size())
            fail("scene", fmt::format("default scene {} does not exist", sceneIndex));
        std::vector<int> visiting;
        for (int root : m_model.scenes[sceneIndex].nodes) visit(root, glm::mat4(1.0f), visiting);
        if (m_scene.triangles.empty())
            fail(fmt::format("scenes[{}]", sceneIndex), "no triangle geometry to render");
        bool emissive = !m_scene.lights.empty();
        for (const Triangle& t : m_scene.triangles)
            emissive = emissive || glm::any(glm::greaterThan(m_scene.materials[t.material].emissive, glm::vec3(0.0f)));
        if (!emissive)
            fail(fmt::format("scenes[{}]", sceneIndex),
                 "no lights: add a KHR_lights_punctual light or an emissive material");
        return std::move(m_scene);
    }

private:
    [[noreturn]] void fail(const std::string& element, const std::string& what) const {
        throw InputError(fmt::format("{}: {}: {}", m_path.string(), element, what));
    }

    void readModel() {
        std::error_code ec;
        if (!fs::exists(m_path, ec)) throw InputError(fmt::format("{}: no such file", m_path.string()));
        if (!fs::is_regular_file(m_path, ec)) throw InputError(fmt::format("{}: not a regular file", m_path.string()));
        const auto size = fs::file_size(m_path, ec);
        if (ec || size > m_limits.maxFileBytes)
            throw InputError(fmt::format("{}: larger than the {}-byte limit", m_path.string(), m_limits.maxFileBytes));
        checkExternalUris(m_path);

        FsContext fsContext{m_path.has_parent_path() ? m_path.parent_path() : fs::path("."), &m_limits, {}};
        tinygltf::TinyGLTF gltf;
        gltf.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &writeWholeFile, &fsContext});
        gltf.SetImageLoader(&loadImageChecked, const_cast<GltfLimits*>(&m_limits));
        std::string err, warn;
        std::ifstream in(m_path, std::ios::binary);
        char magic[4] = {};
        in.read(magic, 4);
        const bool binary = in.gcount() == 4 && std::string(magic, 4) == "glTF";
        const bool ok = binary ? gltf.LoadBinaryFromFile(&m_model, &err, &warn, m_path.string())
                               : gltf.LoadASCIIFromFile(&m_model, &err, &warn, m_path.string());
        if (!ok) {
            while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
            const auto newline = err.find('\n');
            throw InputError(fmt::format("{}: {}", m_path.string(),
                                         err.empty() ? "not a valid glTF 2.0 file" : err.substr(0, newline)));
        }
    }

    int texture(int textureIndex, bool srgb, const std::string& element) {
        if (textureIndex < 0) return -1;
        if (static_cast<size_t>(textureIndex) >= m_model.textures.size())
            fail(element, fmt::format("texture {} does not exist", textureIndex));
        const int source = m_model.textures[textureIndex].source;
        if (source < 0 || static_cast<size_t>(source) >= m_model.images.size())
            fail(fmt::format("textures[{}]", textureIndex), fmt::format("image {} does not exist", source));
        const auto key = std::make_pair(source, srgb);
        if (auto it = m_textureIndex.find(key); it != m_textureIndex.end()) return it->second;
        const tinygltf::Image& img = m_model.images[source];
        const std::string name = fmt::format("images[{}]", source);
        if (img.width <= 0 || img.height <= 0 || img.component < 1 || img.component > 4 ||
            (img.bits != 8 && img.bits != 16))
            fail(name, "unsupported image format (need 8- or 16-bit, 1-4 channels)");
        const size_t pixels = size_t(img.width) * img.height;
        const size_t bytesPerChannel = img.bits / 8;
        if (img.image.size() < pixels * img.component * bytesPerChannel) fail(name, "decoded image data is truncated");
        Texture t;
        t.name = img.name.empty() ? name : img.name;
        t.width = static_cast<uint32_t>(img.width);
        t.height = static_cast<uint32_t>(img.height);
        t.srgb = srgb;
        t.rgba8.resize(pixels);
        for (size_t p = 0; p < pixels; ++p) {
            uint8_t c[4] = {0, 0, 0, 255};
            for (int k = 0; k < img.component; ++k) {
                // 16-bit channels are big-endian in PNG but tinygltf stores them native: take the high byte.
                const size_t at = (p * img.component + k) * bytesPerChannel;
                c[k] = bytesPerChannel == 2 ? static_cast<uint8_t>((img.image[at] | (img.image[at + 1] << 8)) >> 8)
                                            : img.image[at];
            }
            if (img.component == 1 || img.component == 2) {  // grey (+ alpha)
                c[3] = img.component == 2 ? c[1] : 255;
                c[1] = c[2] = c[0];
            }
            t.rgba8[p] = uint32_t(c[0]) | (uint32_t(c[1]) << 8) | (uint32_t(c[2]) << 16) | (uint32_t(c[3]) << 24);
        }
        const int index = static_cast<int>(m_scene.textures.size());
        m_scene.textures.push_back(std::move(t));
        m_textureIndex[key] = index;
        return index;
    }

    Material material(int index) {
        const tinygltf::Material& src = m_model.materials[index];
        const std::string element = fmt::format("materials[{}]", index);
        Material m;
        m.name = src.name.empty() ? element : src.name;
        const auto& pbr = src.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            m.baseColor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
        m.metallic = static_cast<float>(pbr.metallicFactor);
        m.roughness = static_cast<float>(pbr.roughnessFactor);
        if (src.emissiveFactor.size() == 3)
            m.emissive = glm::vec3(src.emissiveFactor[0], src.emissiveFactor[1], src.emissiveFactor[2]);
        m.doubleSided = src.doubleSided;
        m.baseColorTexture = texture(pbr.baseColorTexture.index, true, element);
        m.metallicRoughnessTexture = texture(pbr.metallicRoughnessTexture.index, false, element);
        m.emissiveTexture = texture(src.emissiveTexture.index, true, element);
        const auto ext = [&](const char* name) -> const tinygltf::Value* {
            auto it = src.extensions.find(name);
            return it == src.extensions.end() ? nullptr : &it->second;
        };
        if (const auto* e = ext("KHR_materials_emissive_strength"))
            m.emissive *= static_cast<float>(numberOr(*e, "emissiveStrength", 1.0));
        if (const auto* e = ext("KHR_materials_transmission"))
            m.transmission = static_cast<float>(numberOr(*e, "transmissionFactor", 0.0));
        if (const auto* e = ext("KHR_materials_ior")) m.ior = static_cast<float>(numberOr(*e, "ior", 1.5));
        if (const auto* e = ext("KHR_materials_volume")) {
            m.thickness = static_cast<float>(numberOr(*e, "thicknessFactor", 0.0));
            m.attenuationDistance = static_cast<float>(numberOr(*e, "attenuationDistance", INFINITY));
            if (e->Has("attenuationColor") && e->Get("attenuationColor").IsArray() &&
                e->Get("attenuationColor").ArrayLen() == 3)
                for (int k = 0; k < 3; ++k)
                    m.attenuationColor[k] = static_cast<float>(e->Get("attenuationColor").Get(k).GetNumberAsDouble());
        }
        const float values[] = {m.baseColor.x, m.baseColor.y, m.baseColor.z, m.baseColor.w, m.metallic, m.roughness,
                                m.emissive.x, m.emissive.y, m.emissive.z, m.transmission, m.ior, m.thickness};
        for (float v : values)
            if (!std::isfinite(v) || v < 0.0f) fail(element, "material factors must be finite and non-negative");
        if (m.ior < 1.0f && m.ior != 0.0f) fail(element, fmt::format("ior {} is below 1", m.ior));
        if (m.ior == 0.0f) m.ior = 1.0f;  // KHR_materials_ior: 0 means no specular reflection
        return m;
    }

    uint32_t defaultMaterial() {
        if (m_defaultMaterial < 0) {
            m_defaultMaterial = static_cast<int>(m_scene.materials.size());
            Material m;
            m.name = "default";
            m_scene.materials.push_back(m);
        }
        return static_cast<uint32_t>(m_defaultMaterial);
    }

    void visit(int nodeIndex, const glm::mat4& parent, std::vector<int>& visiting) {
        const std::string element = fmt::format("nodes[{}]", nodeIndex);
        if (nodeIndex < 0 || static_cast<size_t>(nodeIndex) >= m_model.nodes.size())
            fail(element, "no such node");
        if (std::find(visiting.begin(), visiting.end(), nodeIndex) != visiting.end())
            fail(element, "the node hierarchy has a cycle");
        if (visiting.size() > 256) fail(element, "the node hierarchy is deeper than 256");
        const tinygltf::Node& node = m_model.nodes[nodeIndex];
        const glm::mat4 world = parent * localTransform(node);
        for (int k = 0; k < 16; ++k)
            if (!std::isfinite(glm::value_ptr(world)[k])) fail(element, "the transform is not finite");
        if (node.mesh >= 0) addMesh(node.mesh, world);
        else if (node.mesh < -1) fail(element, "invalid mesh index");
        if (node.camera >= 0) addCamera(node.camera, world, element);
        if (auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end())
            addLight(static_cast<int>(numberOr(it->second, "light", -1)), world, element);
        visiting.push_back(nodeIndex);
        for (int child : node.children) visit(child, world, visiting);
        visiting.pop_back();
    }

    void addMesh(int meshIndex, const glm::mat4& world) {
        if (static_cast<size_t>(meshIndex) >= m_model.meshes.size())
            fail(fmt::format("meshes[{}]", meshIndex), "no such mesh");
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
        const bool flipWinding = glm::determinant(glm::mat3(world)) < 0.0f;
        const tinygltf::Mesh& mesh = m_model.meshes[meshIndex];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string element = fmt::format("meshes[{}].primitives[{}]", meshIndex, p);
            try {
                addPrimitive(mesh.primitives[p], world, normalMatrix, flipWinding, element);
            } catch (const InputError& e) {
                if (std::string(e.what()).rfind(m_path.string() + ":", 0) == 0) throw;
                fail(element, e.what());
            }
        }
    }

    void addPrimitive(const tinygltf::Primitive& prim, const glm::mat4& world, const glm::mat3& normalMatrix,
                      bool flipWinding, const std::string& element) {
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
            ++m_skippedPrimitives;
            fmt::print(stderr, "warning: {}: {}: mode {} is not triangles; skipped\n", m_path.string(), element, prim.mode);
            return;
        }
        const auto position = prim.attributes.find("POSITION");
        if (position == prim.attributes.end()) fail(element, "no POSITION attribute");
        const auto positions = readVec3Accessor(m_model, position->second);
        for (size_t i = 0; i < positions.size(); ++i)
            if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) || !std::isfinite(positions[i].z))
                fail(element, fmt::format("POSITION {} is NaN or infinite", i));
        std::vector<glm::vec3> normals;
        if (auto it = prim.attributes.find("NORMAL"); it != prim.attributes.end()) {
            normals = readVec3Accessor(m_model, it->second);
            if (normals.size() != positions.size()) fail(element, "NORMAL and POSITION counts differ");
        }
        std::vector<glm::vec2> uvs;
        if (auto it = prim.attributes.find("TEXCOORD_0"); it != prim.attributes.end()) {
            uvs = readVec2Accessor(m_model, it->second);
            if (uvs.size() != positions.size()) fail(element, "TEXCOORD_0 and POSITION counts differ");
        }
        std::vector<uint32_t> indices;
        if (prim.indices >= 0) {
            indices = readIndexAccessor(m_model, prim.indices);
        } else {
            indices.resize(positions.size());
            for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
        }
        if (indices.size() % 3 != 0) fail(element, fmt::format("{} indices is not a multiple of 3", indices.size()));
        for (size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= positions.size())
                fail(element, fmt::format("index {} at position {} is out of range ({} vertices)", indices[i], i, positions.size()));
        uint32_t material;
        if (prim.material < 0) material = defaultMaterial();
        else if (static_cast<size_t>(prim.material) >= m_model.materials.size())
            fail(element, fmt::format("material {} does not exist", prim.material));
        else material = static_cast<uint32_t>(prim.material);
        if (m_scene.triangles.size() + indices.size() / 3 > m_limits.maxTriangles)
            fail(element, fmt::format("more than {} triangles", m_limits.maxTriangles));

        for (size_t i = 0; i < indices.size(); i += 3) {
            uint32_t idx[3] = {indices[i], indices[i + 1], indices[i + 2]};
            if (flipWinding) std::swap(idx[1], idx[2]);  // keep the front face counter-clockwise
            Triangle t;
            for (int k = 0; k < 3; ++k) {
                t.p[k] = glm::vec3(world * glm::vec4(positions[idx[k]], 1.0f));
                t.uv[k] = uvs.empty() ? glm::vec2(0.0f) : uvs[idx[k]];
            }
            const glm::vec3 cross = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
            const float len = glm::length(cross);
            if (!(len > 0.0f) || !std::isfinite(len)) {
                ++m_scene.droppedDegenerateTriangles;
                continue;
            }
            const glm::vec3 faceNormal = cross / len;
            for (int k = 0; k < 3; ++k) {
                glm::vec3 n = normals.empty() ? faceNormal : normalMatrix * normals[idx[k]];
                const float nl = glm::length(n);
                t.n[k] = nl > 0.0f && std::isfinite(nl) ? n / nl : faceNormal;
            }
            t.material = material;
            for (const auto& p : t.p) m_scene.bounds.grow(p);
            m_scene.triangles.push_back(t);
        }
    }

    void addCamera(int index, const glm::mat4& world, const std::string& element) {
        if (static_cast<size_t>(index) >= m_model.cameras.size()) fail(element, fmt::format("camera {} does not exist", index));
        const tinygltf::Camera& src = m_model.cameras[index];
        if (src.type != "perspective") {
            fmt::print(stderr, "warning: {}: cameras[{}]: only perspective cameras are supported; skipped\n", m_path.string(), index);
            return;
        }
        Camera c;
        c.name = src.name.empty() ? fmt::format("cameras[{}]", index) : src.name;
        c.position = glm::vec3(world[3]);
        c.forward = glm::normalize(-glm::vec3(world[2]));
        glm::vec3 up = glm::vec3(world[1]);
        up = up - glm::dot(up, c.forward) * c.forward;
        c.up = glm::normalize(up);
        c.yfov = static_cast<float>(src.perspective.yfov);
        c.aspectRatio = static_cast<float>(src.perspective.aspectRatio);
        if (!(c.yfov > 0.0f && c.yfov < 3.14f) || !std::isfinite(glm::dot(c.forward, c.up)))
            fail(fmt::format("cameras[{}]", index), "invalid perspective camera (yfov or transform)");
        m_scene.cameras.push_back(c);
    }

    void addLight(int index, const glm::mat4& world, const std::string& element) {
        if (index < 0 || static_cast<size_t>(index) >= m_model.lights.size())
            fail(element, fmt::format("KHR_lights_punctual light {} does not exist", index));
        const tinygltf::Light& src = m_model.lights[index];
        const std::string name = fmt::format("KHR_lights_punctual.lights[{}]", index);
        PunctualLight l;
        l.name = src.name.empty() ? name : src.name;
        glm::vec3 color(1.0f);
        if (src.color.size() == 3) color = glm::vec3(src.color[0], src.color[1], src.color[2]);
        l.intensity = color * static_cast<float>(src.intensity) / kLumensPerWatt;
        l.position = glm::vec3(world[3]);
        l.direction = glm::normalize(-glm::vec3(world[2]));
        if (src.type == "point") l.type = LightType::Point;
        else if (src.type == "spot") {
            l.type = LightType::Spot;
            l.innerConeAngle = static_cast<float>(src.spot.innerConeAngle);
            l.outerConeAngle = static_cast<float>(src.spot.outerConeAngle);
        } else if (src.type == "directional") l.type = LightType::Directional;
        else fail(name, fmt::format("unknown light type '{}'", src.type));
        if (!std::isfinite(l.intensity.x + l.intensity.y + l.intensity.z) || glm::any(glm::lessThan(l.intensity, glm::vec3(0.0f))))
            fail(name, "intensity and color must be finite and non-negative");
        m_scene.lights.push_back(l);
    }

    fs::path m_path;
    const GltfLimits& m_limits;
    tinygltf::Model m_model;
    Scene m_scene;
    std::map<std::pair<int, bool>, int> m_textureIndex;
    int m_defaultMaterial = -1;
    size_t m_skippedPrimitives = 0;
};

}  // namespace

Scene loadGltf(const std::filesystem::path& path, const GltfLimits& limits) { return Loader(path, limits).load(); }

}  // namespace vkp
