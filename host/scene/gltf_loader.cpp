// glTF 2.0 -> vkp::Scene. The steps: preflight (gltf_preflight.cpp: container, JSON, references,
// URIs, file sizes), tinygltf parsing through confined file callbacks (gltf_files.cpp), materials
// and textures (gltf_materials.cpp), then a walk of the default scene's node tree that flattens
// every triangle primitive to world space (accessors read by gltf_accessors.cpp) and collects
// punctual lights and perspective cameras. docs/scene-format.md is the user-facing description.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_set>

#include <fmt/format.h>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_accessors.h"
#include "scene/gltf_files.h"
#include "scene/gltf_instancing.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_primitive_modes.h"
#include "scene/gltf_preflight.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_morph.h"
#include "scene/gltf_skin.h"
#include "scene/gltf_tangents.h"
#include "scene/gltf_variants.h"
#include "util/errors.h"
#include "util/printable.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

// KHR_lights_punctual photometric units -> radiometric, at the luminous efficacy Blender's glTF
// importer assumes (683 lm/W, the peak of the photopic curve): candela -> W/sr, lux -> W/m^2.
constexpr float kLumensPerWatt = 683.0f;
constexpr double kHalfPi = 1.57079632679489662;
constexpr double kPi = 3.14159265358979324;

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(element.empty() ? what : fmt::format("{}: {}", element, what));
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// glTF: either a column-major matrix or T * R * S; the spec forbids both, the matrix wins here.
glm::dmat4 localTransform(const tinygltf::Node& node, const std::string& element) {
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) fail(element + ".matrix", "needs 16 numbers");
        glm::dmat4 m;
        std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m));
        return m;
    }
    const auto wrongSize = [&](const std::vector<double>& v, size_t n) { return !v.empty() && v.size() != n; };
    if (wrongSize(node.translation, 3)) fail(element + ".translation", "needs 3 numbers");
    if (wrongSize(node.rotation, 4)) fail(element + ".rotation", "needs 4 numbers");
    if (wrongSize(node.scale, 3)) fail(element + ".scale", "needs 3 numbers");
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (!node.translation.empty()) t[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    if (!node.rotation.empty()) {
        // glTF stores (x, y, z, w); glm's constructor takes w first.
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (!(length > 0.0) || !std::isfinite(length)) fail(element + ".rotation", "is not a unit quaternion");
        r = glm::mat4_cast(q / length);
    }
    for (size_t k = 0; k < node.scale.size(); ++k) s[k][k] = node.scale[k];
    return t * r * s;
}

// tinygltf appends to its error text as it goes (a tolerated GLB misalignment, then the fatal
// problem): the last line is the one that stopped it.
std::string lastLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    text = text.substr(text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1);
    return text.size() > 300 ? text.substr(0, 297) + "..." : text;
}

// A primitive's vertex attributes as read (object space); empty vectors: absent.
struct Vertices {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs[2];      // TEXCOORD_0 and the scene's second set (remapTexCoordSets)
    std::vector<glm::vec4> colors;      // COLOR_0 as RGBA
    std::vector<glm::vec4> tangents;    // TANGENT, or generated (gltf_tangents.cpp) for normal maps
    std::vector<uint8_t> mirrored;      // skinned: per vertex, whether its skinning matrix mirrors
};

class Loader {
public:
    Loader(const fs::path& path, const GltfLimits& limits)
        : m_path(path), m_limits(limits),
          m_folder(path.has_parent_path() ? path.parent_path() : fs::path(".")), m_files(m_folder, limits) {}

    Scene load() {
        prepare();
        return flatten(nullptr, false);
    }

    // Parsing, materials and textures: everything but the node walk (done once per file).
    void prepare() {
        parse();
        m_scene.source = m_path;
        m_materials.emplace(m_model, m_scene, [this](const std::string& message) { warn(message); });
        m_materials->convertAll();
        remapTexCoordSets();
        describeFile();
        m_sceneIndex = m_limits.sceneIndex >= 0 ? m_limits.sceneIndex
                       : m_model.defaultScene >= 0 ? m_model.defaultScene
                                                   : 0;
        const std::string sceneName = fmt::format("scenes[{}]", m_sceneIndex);
        if (m_model.scenes.empty()) fail("scenes", "the file has no scene, so no triangle geometry to render");
        if (static_cast<size_t>(m_sceneIndex) >= m_model.scenes.size())
            fail(m_limits.sceneIndex >= 0 ? fmt::format("--scene {}", m_sceneIndex) : sceneName,
                 fmt::format("does not exist (the file has {} scene(s))", m_model.scenes.size()));
        m_instancedMesh = planInstancedMeshes(m_model, m_model.scenes[m_sceneIndex].nodes, m_scene.materials,
                                              m_limits.instanceMinTriangles, m_limits.instanceEveryMesh);
        checkSize(m_model.scenes[m_sceneIndex].nodes, sceneName);
        findParents();
    }

    // The scene's triangles, instances, lights and cameras in world space, with the local
    // transforms of `overrides` (indexed by node; nullopt or absent: the node's own) in place of
    // the file's. keepBase false: the last flatten of this loader (no copy of the textures).
    Scene flatten(const std::vector<std::optional<glm::dmat4>>* overrides, bool keepBase = true,
                  const std::vector<glm::dvec3>* worldOffsets = nullptr) {
        const std::string sceneName = fmt::format("scenes[{}]", m_sceneIndex);
        Scene base = keepBase ? m_scene : Scene{};  // materials, textures and file facts; no geometry yet
        m_overrides = overrides;
        m_worldOffsets = worldOffsets;
        m_skippedPrimitives = 0;
        m_triangleKeys.clear();
        m_meshSlot.assign(m_model.meshes.size(), -1);
        m_nodeWorld.assign(m_model.nodes.size(), std::nullopt);
        walk(m_model.scenes[m_sceneIndex].nodes);
        m_overrides = nullptr;
        m_worldOffsets = nullptr;
        if (m_scene.triangles.empty() && m_scene.instances.empty())
            fail(sceneName, m_skippedPrimitives ? "no triangle geometry to render (primitives of other modes are skipped)"
                                                : "no triangle geometry to render");
        checkScale(sceneName);
        std::swap(base, m_scene);
        return base;
    }

    // The default material, made now when a primitive needs it: flatten() starts each walk from
    // the materials as they are here (loadGltf makes it lazily, at the same index).
    void prepareDefaultMaterial() {
        for (const tinygltf::Mesh& mesh : m_model.meshes)
            for (const tinygltf::Primitive& primitive : mesh.primitives)
                if (primitive.material < 0) {
                    m_materials->defaultMaterial();
                    return;
                }
    }

    const tinygltf::Model& model() const { return m_model; }
    void warnAbout(const std::string& message) const { warn(message); }

private:
    // Triangles the scene will have, from the accessors' counts alone (every node that references
    // a mesh counts it again), against the limits before any vertex is decoded: a small file can
    // list a large primitive many times.
    void checkSize(const std::vector<int>& roots, const std::string& sceneName) const {
        uint64_t triangles = 0;
        std::vector<int> stack(roots.rbegin(), roots.rend());
        std::vector<bool> seen(m_model.nodes.size(), false);
        std::vector<bool> meshCounted(m_model.meshes.size(), false);
        while (!stack.empty()) {
            const int index = stack.back();
            stack.pop_back();
            if (index < 0 || size_t(index) >= m_model.nodes.size() || seen[index]) continue;  // walk() names it
            seen[index] = true;
            const tinygltf::Node& node = m_model.nodes[index];
            // An instanced mesh's triangles are stored once; a flattened one's per drawing.
            const bool instanced = node.mesh >= 0 && size_t(node.mesh) < m_model.meshes.size() && m_instancedMesh[node.mesh];
            const uint64_t copies = instanced ? (meshCounted[node.mesh] ? 0 : 1) : declaredInstanceCount(m_model, node);
            if (instanced) meshCounted[node.mesh] = true;
            if (node.mesh >= 0 && size_t(node.mesh) < m_model.meshes.size())
                for (const tinygltf::Primitive& primitive : m_model.meshes[node.mesh].primitives) {
                    if (!isTriangleMode(primitive.mode)) continue;
                    const auto position = primitive.attributes.find("POSITION");
                    const int accessor = primitive.indices >= 0 ? primitive.indices
                                         : position != primitive.attributes.end() ? position->second : -1;
                    if (accessor >= 0 && size_t(accessor) < m_model.accessors.size())
                        triangles += triangleCountOfMode(primitive.mode, m_model.accessors[accessor].count) * copies;
                }
            stack.insert(stack.end(), node.children.rbegin(), node.children.rend());
        }
        if (triangles > m_limits.maxTriangles)
            fail(sceneName, fmt::format("{} triangles (counting every mesh reference) exceed the limit of {}", triangles,
                                        m_limits.maxTriangles));
        if (triangles > m_limits.deviceMaxTriangles)
            throw RuntimeError(fmt::format("{}: {} triangles (counting every mesh reference) exceed what the device holds "
                                           "({} triangles: its storage-buffer range)",
                                           sceneName, triangles, m_limits.deviceMaxTriangles));
        const uint64_t bytes = triangles * kHostBytesPerTriangle;
        if (bytes > m_limits.maxMemoryBytes)
            throw RuntimeError(fmt::format("{}: {} triangles need about {:.1f} GiB of memory; {:.1f} GiB are allowed "
                                           "(--max-memory, default: the memory available)",
                                           sceneName, triangles, bytes / double(1ull << 30),
                                           m_limits.maxMemoryBytes / double(1ull << 30)));
    }

    // What single-precision rendering can handle (docs/scene-format.md, "Scale"): a scene so small
    // that floats underflow, too far from the origin for its size, or lights too strong for floats.
    void checkScale(const std::string& sceneName) const {
        const glm::dvec3 lo(m_scene.bounds.min), hi(m_scene.bounds.max);
        const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
        const double reach = std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y),
                                       std::abs(hi.z)});
        // Down to kMinSceneExtent any size renders alike: the ray offsets scale with the scene
        // (scene_access.glsl rayEpsilon). Below it, products of distances underflow floats.
        if (!(extent >= kMinSceneExtent))
            fail(sceneName, fmt::format("the geometry spans only {:.3g} units; below {:g} single precision underflows "
                                        "(products of distances): scale the scene up with a node scale",
                                        extent, kMinSceneExtent));
        if (reach > kMaxOffsetPerExtent * extent)
            fail(sceneName, fmt::format("the geometry spans {:.3g} units but lies {:.3g} units from the origin: more than "
                                        "{:g} times its size loses single precision; move it towards the origin",
                                        extent, reach, kMaxOffsetPerExtent));
        double power = 0.0;
        for (const Triangle& t : m_scene.triangles) {
            const Material& m = m_scene.materials[t.material];
            const double luminance = 0.2126 * m.emissive.x + 0.7152 * m.emissive.y + 0.0722 * m.emissive.z;
            if (luminance > 0.0)
                power += kPi * luminance * 0.5 * glm::length(glm::cross(glm::dvec3(t.p[1] - t.p[0]), glm::dvec3(t.p[2] - t.p[0])));
        }
        // Punctual lights: 4 pi I for point and spot lights, E times the scene's cross-section for
        // directional ones (what the photon tracer emits over).
        for (const PunctualLight& light : m_scene.lights)
            power += double(glm::length(light.intensity)) *
                     (light.type == LightType::Directional ? kPi * extent * extent : 4.0 * kPi);
        if (!(power <= kMaxTotalPower))
            fail(sceneName, fmt::format("the lights emit about {:.3g} W, beyond the {:g} W single-precision photon powers "
                                        "can carry",
                                        power, kMaxTotalPower));
    }

    void warn(const std::string& message) const {
        fmt::print(stderr, "warning: {}\n", printable(m_path.string() + ": " + message));
    }

    void parse() {
        GltfDocument document = preflightGltf(m_path, m_limits, m_files);
        const MeshoptFallbacks fallbacks = prepareMeshoptFallbacks(document);
        tinygltf::TinyGLTF gltf;
        gltf.SetFsCallbacks(m_files.callbacks());
        gltf.SetImageLoader(GltfFileAccess::imageLoader(), &m_files);
        std::string err, warnings;
        if (document.bytes.size() > UINT32_MAX) fail("", "files over 4 GiB are not supported");  // tinygltf's sizes
        const auto size = static_cast<unsigned int>(document.bytes.size());
        const bool ok = document.binary
            ? gltf.LoadBinaryFromMemory(&m_model, &err, &warnings, document.bytes.data(), size, m_folder.string())
            : gltf.LoadASCIIFromString(&m_model, &err, &warnings, reinterpret_cast<const char*>(document.bytes.data()),
                                       size, m_folder.string());
        if (!m_files.imageError().empty()) fail("", m_files.imageError());
        if (!ok) fail("", err.empty() ? "tinygltf could not read the file" : "tinygltf: " + lastLine(err));
        for (size_t start = 0; start < warnings.size();) {
            const size_t end = std::min(warnings.find('\n', start), warnings.size());
            if (end > start) warn("tinygltf: " + warnings.substr(start, end - start));
            start = end + 1;
        }
        decodeMeshoptViews(m_model, fallbacks);  // before Draco: its streams may lie in compressed views
        decodeDracoPrimitives(m_model);
    }

    // What `vkphoton info` reports beside the scene: extensions, nodes, skins, animations, and the
    // extensions each material (or one of its texture references) names.
    void describeFile() {
        SceneFileInfo& info = m_scene.file;
        info.extensionsUsed = m_model.extensionsUsed;
        info.extensionsRequired = m_model.extensionsRequired;
        info.nodes = m_model.nodes.size();
        info.skins = m_model.skins.size();
        for (const tinygltf::Animation& a : m_model.animations)
            info.animations.push_back({a.name, a.channels.size(), a.samplers.size()});
        info.materialVariants = materialVariantNames(m_model);
        m_variant = materialVariantIndex(info.materialVariants, m_limits.materialVariant);
        for (size_t i = 0; i < m_model.materials.size(); ++i) {
            const tinygltf::Material& source = m_model.materials[i];
            const auto& pbr = source.pbrMetallicRoughness;
            std::vector<std::string>& names = m_scene.materials[i].extensions;
            for (const tinygltf::ExtensionMap* map :
                 {&source.extensions, &pbr.baseColorTexture.extensions, &pbr.metallicRoughnessTexture.extensions,
                  &source.normalTexture.extensions, &source.occlusionTexture.extensions, &source.emissiveTexture.extensions})
                for (const auto& entry : *map)
                    if (std::find(names.begin(), names.end(), entry.first) == names.end()) names.push_back(entry.first);
        }
    }


    // Depth-first, pre-order (so cameras and lights keep the file's node order), iterative so a
    // deep hierarchy cannot exhaust the stack. Each node may be reached once: glTF node trees are
    // strict trees, and refusing a second parent also refuses cycles and exponential DAGs.
    void walk(const std::vector<int>& roots) {
        struct Pending {
            int node;
            glm::dmat4 parent;
        };
        std::vector<Pending> stack;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0)});
        std::vector<bool> seen(m_model.nodes.size(), false);
        while (!stack.empty()) {
            const Pending pending = stack.back();
            stack.pop_back();
            const std::string element = fmt::format("nodes[{}]", pending.node);
            if (pending.node < 0 || static_cast<size_t>(pending.node) >= m_model.nodes.size()) fail(element, "does not exist");
            if (seen[pending.node]) fail(element, "is reached twice from the scene (a node has one parent; no cycles)");
            seen[pending.node] = true;
            const tinygltf::Node& node = m_model.nodes[pending.node];
            glm::dmat4 world = pending.parent * local(pending.node);
            if (m_worldOffsets && size_t(pending.node) < m_worldOffsets->size())
                world[3] += glm::dvec4((*m_worldOffsets)[pending.node], 0.0);  // translate(offset) * world
            if (!isFinite(world)) fail(element, "the world transform is not finite");
            visit(node, world, element);
            for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) stack.push_back({*it, world});
        }
    }

    // A node's local transform in the pose being flattened: the animated one of m_overrides, else
    // the file's.
    glm::dmat4 local(int index) const {
        const bool overridden = m_overrides && size_t(index) < m_overrides->size() && (*m_overrides)[index].has_value();
        return overridden ? *(*m_overrides)[index] : localTransform(m_model.nodes[index], fmt::format("nodes[{}]", index));
    }

    // Every node's parent (-1 for none, -2 for several), for world transforms of nodes outside
    // the walk's order (skin joints).
    void findParents() {
        m_parent.assign(m_model.nodes.size(), -1);
        for (size_t p = 0; p < m_model.nodes.size(); ++p)
            for (const int child : m_model.nodes[p].children)
                if (child >= 0 && size_t(child) < m_parent.size()) m_parent[child] = m_parent[child] == -1 ? int(p) : -2;
    }

    // A node's world transform in the pose being flattened (the walk's product parent * local,
    // from its root down), memoised per flatten. Used for skin joints, which may lie anywhere in
    // the node tree, also outside the scene walked.
    glm::dmat4 nodeWorld(int index) {
        std::vector<int> chain;  // index, its parent, ..., its root
        for (int n = index; n >= 0 && !m_nodeWorld[n]; n = m_parent[n]) {
            const std::string element = fmt::format("nodes[{}]", n);
            if (chain.size() > m_model.nodes.size()) fail(element, "is its own ancestor (a cycle of children)");
            if (m_parent[n] == -2) fail(element, "is the child of several nodes (a node has one parent)");
            chain.push_back(n);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const int parent = m_parent[*it];
            const glm::dmat4 world = (parent >= 0 ? *m_nodeWorld[parent] : glm::dmat4(1.0)) * local(*it);
            if (!isFinite(world)) fail(fmt::format("nodes[{}]", *it), "the world transform is not finite");
            m_nodeWorld[*it] = world;
        }
        return *m_nodeWorld[index];
    }

    void visit(const tinygltf::Node& node, const glm::dmat4& world, const std::string& element) {
        if (node.mesh >= 0) addMeshDrawings(node, world, element);
        if (node.camera >= 0) addCamera(node.camera, world, element);
        if (const auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end()) {
            const tinygltf::Value& light = it->second.Get("light");
            if (!light.IsInt()) fail(element + ".extensions.KHR_lights_punctual.light", "not an integer");
            addLight(light.Get<int>(), world, element);
        }
    }

    // A light's or camera's position: within the coordinates single precision handles.
    glm::vec3 position(const glm::dmat4& world, const std::string& nodeElement, const char* what) const {
        const glm::dvec3 p(world[3]);
        const double reach = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        if (!(reach <= kMaxCoordinate))
            fail(nodeElement, fmt::format("the {} lies at ({:.3g}, {:.3g}, {:.3g}), beyond the +-{:g} units vkphoton handles",
                                          what, p.x, p.y, p.z, kMaxCoordinate));
        return glm::vec3(p);
    }

    // The node's mesh, once or at each EXT_mesh_gpu_instancing transform (in the node's space):
    // flattened to world space, or as instances of a Scene::meshes entry (gltf_instancing.h).
    void addMeshDrawings(const tinygltf::Node& node, const glm::dmat4& world, const std::string& element) {
        if (static_cast<size_t>(node.mesh) >= m_model.meshes.size()) fail(fmt::format("meshes[{}]", node.mesh), "does not exist");
        std::vector<glm::dmat4> transforms;
        try {
            transforms = readMeshInstances(m_model, node, element);
        } catch (const InputError& e) {  // accessor errors name only the accessor
            if (std::string_view(e.what()).rfind(element, 0) == 0) throw;
            fail(fmt::format("{}.extensions.{}", element, kMeshGpuInstancing), e.what());
        }
        if (transforms.empty()) transforms.push_back(glm::dmat4(1.0));
        const int nodeIndex = static_cast<int>(&node - m_model.nodes.data());
        // A skinned mesh is placed by its joints alone: glTF ignores the skinned node's transform.
        std::vector<glm::dmat4> joints;
        if (node.skin >= 0) joints = jointMatrices(m_model, node.skin, [this](int n) { return nodeWorld(n); });
        m_drawingNode = &node;
        m_skinJoints = node.skin >= 0 ? &joints : nullptr;
        for (const glm::dmat4& local : transforms) {
            const glm::dmat4 placed = (node.skin >= 0 ? glm::dmat4(1.0) : world) * local;
            if (!isFinite(placed)) fail(element, "an instance's world transform is not finite");
            if (m_instancedMesh[node.mesh]) {
                addInstance(node.mesh, placed, nodeIndex, element);
                continue;
            }
            const auto first = static_cast<uint32_t>(m_scene.triangles.size());
            addMesh(node.mesh, placed, element);
            const auto count = static_cast<uint32_t>(m_scene.triangles.size()) - first;
            if (count > 0) m_scene.drawings.push_back({nodeIndex, node.mesh, first, count});
        }
        m_drawingNode = nullptr;
        m_skinJoints = nullptr;
    }

    // An instance of an instanced mesh, whose object-space triangles are read at its first use. A
    // singular transform (a zero scale) draws nothing: skipped with a warning.
    void addInstance(int meshIndex, const glm::dmat4& world, int nodeIndex, const std::string& nodeElement) {
        if (m_meshSlot[meshIndex] < 0) {
            Mesh mesh;
            mesh.name = m_model.meshes[meshIndex].name.empty() ? fmt::format("meshes[{}]", meshIndex)
                                                               : m_model.meshes[meshIndex].name;
            std::unordered_set<std::string> keys;
            m_target = &mesh;
            m_targetKeys = &keys;
            try {
                addMesh(meshIndex, glm::dmat4(1.0), nodeElement);
            } catch (...) {
                m_target = nullptr;
                m_targetKeys = nullptr;
                throw;
            }
            m_target = nullptr;
            m_targetKeys = nullptr;
            m_meshSlot[meshIndex] = static_cast<int>(m_scene.meshes.size());
            m_scene.meshes.push_back(std::move(mesh));
        }
        const Mesh& mesh = m_scene.meshes[m_meshSlot[meshIndex]];
        if (mesh.triangles.empty()) return;  // nothing survived (degenerate or skipped primitives)
        const double det = glm::determinant(glm::dmat3(world));
        if (!(std::abs(det) > 1.0e-30)) {
            if (!m_warnedSingularInstance) warn(fmt::format("{}: an instance of meshes[{}] has a zero scale (singular "
                                                            "transform) and draws nothing; skipped", nodeElement, meshIndex));
            m_warnedSingularInstance = true;
            return;
        }
        for (int corner = 0; corner < 8; ++corner) {
            const glm::dvec3 p((corner & 1) ? mesh.bounds.max.x : mesh.bounds.min.x,
                               (corner & 2) ? mesh.bounds.max.y : mesh.bounds.min.y,
                               (corner & 4) ? mesh.bounds.max.z : mesh.bounds.min.z);
            const glm::dvec3 w(world * glm::dvec4(p, 1.0));
            if (!(std::max({std::abs(w.x), std::abs(w.y), std::abs(w.z)}) <= kMaxCoordinate))
                fail(nodeElement, fmt::format("an instance of meshes[{}] reaches ({:.3g}, {:.3g}, {:.3g}) in world space, "
                                              "beyond the +-{:g} units vkphoton handles",
                                              meshIndex, w.x, w.y, w.z, kMaxCoordinate));
            m_scene.bounds.grow(glm::vec3(w));
        }
        m_scene.instances.push_back({static_cast<uint32_t>(m_meshSlot[meshIndex]), glm::mat4(world), nodeIndex});
    }

    void addMesh(int meshIndex, const glm::dmat4& world, const std::string& nodeElement) {
        if (static_cast<size_t>(meshIndex) >= m_model.meshes.size())
            fail(fmt::format("meshes[{}]", meshIndex), "does not exist");
        const tinygltf::Mesh& mesh = m_model.meshes[meshIndex];
        m_meshIndex = meshIndex;
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string element = fmt::format("meshes[{}].primitives[{}]", meshIndex, p);
            try {
                m_nodeElement = nodeElement;
                addPrimitive(mesh.primitives[p], world, element);
            } catch (const InputError& e) {
                // Accessor errors name only the accessor; say which primitive read it.
                if (std::string_view(e.what()).rfind(element, 0) == 0) throw;
                fail(element, e.what());
            }
        }
    }

    uint32_t primitiveMaterial(const tinygltf::Primitive& primitive, const std::string& element) {
        // KHR_materials_variants: the chosen variant's material where the primitive maps one.
        const int material = variantMaterial(primitive, m_variant, m_scene.file.materialVariants.size(), element);
        if (material < 0) return m_materials->defaultMaterial();
        if (static_cast<size_t>(material) >= m_model.materials.size())
            fail(element, fmt::format("materials[{}] does not exist", material));
        return static_cast<uint32_t>(material);
    }

    // The three positions, in a rotation-independent order (a triangle listed again from another
    // vertex is the same triangle), as 36 bytes.
    static std::string triangleKey(const Triangle& t) {
        int first = 0;
        for (int k = 1; k < 3; ++k)
            if (std::memcmp(&t.p[k], &t.p[first], sizeof(glm::vec3)) < 0) first = k;
        std::string key(36, '\0');
        for (int k = 0; k < 3; ++k) std::memcpy(key.data() + 12 * k, &t.p[(first + k) % 3], 12);
        return key;
    }

    void addPrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& world, const std::string& element) {
        m_primitiveElement = element;
        if (!isTriangleMode(primitive.mode)) {
            ++m_skippedPrimitives;
            warn(fmt::format("{}: mode {} (points or lines) has no triangles; skipped", element, primitive.mode));
            return;
        }
        const auto attribute = [&](const char* name) {
            const auto it = primitive.attributes.find(name);
            return it == primitive.attributes.end() ? -1 : it->second;
        };
        if (attribute("POSITION") < 0) fail(element, "has no POSITION attribute");
        Vertices v;
        v.positions = readVec3Accessor(m_model, attribute("POSITION"));
        for (size_t i = 0; i < v.positions.size(); ++i)
            if (!std::isfinite(v.positions[i].x) || !std::isfinite(v.positions[i].y) || !std::isfinite(v.positions[i].z))
                fail(element, fmt::format("POSITION {} is NaN or infinite (accessors[{}])", i, attribute("POSITION")));
        if (attribute("NORMAL") >= 0) v.normals = readVec3Accessor(m_model, attribute("NORMAL"));
        if (attribute("TEXCOORD_0") >= 0) v.uvs[0] = readVec2Accessor(m_model, attribute("TEXCOORD_0"));
        const std::string secondSet = fmt::format("TEXCOORD_{}", m_secondTexCoordSet);
        if (attribute(secondSet.c_str()) >= 0) v.uvs[1] = readVec2Accessor(m_model, attribute(secondSet.c_str()));
        if (attribute("COLOR_0") >= 0) v.colors = readColorAccessor(m_model, attribute("COLOR_0"));
        if (!v.normals.empty() && v.normals.size() != v.positions.size()) fail(element, "NORMAL and POSITION counts differ");
        for (int set = 0; set < 2; ++set)
            if (!v.uvs[set].empty() && v.uvs[set].size() != v.positions.size())
                fail(element, fmt::format("TEXCOORD_{} and POSITION counts differ", set == 0 ? 0 : m_secondTexCoordSet));
        if (!v.colors.empty() && v.colors.size() != v.positions.size()) fail(element, "COLOR_0 and POSITION counts differ");
        for (size_t i = 0; i < v.colors.size(); ++i)
            if (!std::isfinite(v.colors[i].x + v.colors[i].y + v.colors[i].z + v.colors[i].w))
                fail(element, fmt::format("COLOR_0 {} is NaN or infinite (accessors[{}])", i, attribute("COLOR_0")));
        std::vector<uint32_t> indices;
        if (primitive.indices >= 0) {
            indices = readIndexAccessor(m_model, primitive.indices);
        } else {
            indices.resize(v.positions.size());
            for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<uint32_t>(i);
        }
        // A strip or fan of n >= 3 vertices draws n - 2 triangles (fewer draw none); a list needs 3 per triangle.
        if (primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP && primitive.mode != TINYGLTF_MODE_TRIANGLE_FAN &&
            indices.size() % 3 != 0)
            fail(element, fmt::format("{} vertices is not a multiple of 3", indices.size()));
        for (size_t i = 0; i < indices.size(); ++i)
            if (indices[i] >= v.positions.size())
                fail(element, fmt::format("index {} (element {} of accessors[{}]) is out of range ({} vertices)",
                                          indices[i], i, primitive.indices, v.positions.size()));
        // Strips and fans (modes 5 and 6) as triangle lists, with the specification's winding.
        indices = triangleListIndices(primitive.mode, indices);
        const uint32_t material = primitiveMaterial(primitive, element);
        checkTexCoordSets(m_scene.materials[material], v, element);
        const Material& m = m_scene.materials[material];
        // Tangents for the normal maps: the base's and the coat's (KHR_materials_clearcoat), which
        // share the TANGENT attribute or the tangents generated from the base map's TEXCOORD set
        // (else the coat map's); and for KHR_materials_anisotropy, whose direction is given in
        // tangent space (generated from its texture's set, else TEXCOORD_0).
        const int tangentTexture = m.normalTexture >= 0 ? m.normalTexture
                                   : m.clearcoat > 0.0f && m.clearcoatNormalTexture >= 0 ? m.clearcoatNormalTexture
                                                                                         : m.anisotropyTexture;
        const bool wantsTangents = tangentTexture >= 0 || m.anisotropy > 0.0f;
        const int tangentSet = tangentTexture >= 0 ? m_scene.textureViews[tangentTexture].texCoord : 0;
        if (wantsTangents && attribute("TANGENT") >= 0) {
            v.tangents = readVec4Accessor(m_model, attribute("TANGENT"));
            if (v.tangents.size() != v.positions.size()) fail(element, "TANGENT and POSITION counts differ");
            for (size_t i = 0; i < v.tangents.size(); ++i)
                if (!std::isfinite(v.tangents[i].x + v.tangents[i].y + v.tangents[i].z + v.tangents[i].w))
                    fail(element, fmt::format("TANGENT {} is NaN or infinite (accessors[{}])", i, attribute("TANGENT")));
        }
        morph(primitive, v, element);
        if (wantsTangents && attribute("TANGENT") < 0)  // from the morphed shape; the skin moves them
            v.tangents = generateTangents(v.positions, v.normals, v.uvs[tangentSet], indices);
        skin(primitive, v, element);
        if ((m_target ? m_target->triangles : m_scene.triangles).size() + indices.size() / 3 > m_limits.maxTriangles)
            fail(element, fmt::format("the scene exceeds the limit of {} triangles", m_limits.maxTriangles));
        emitTriangles(v, indices, world, material);
    }

    // Morph targets with the drawing node's (else the mesh's) weights (gltf_morph.h), once the
    // counts are checked.
    void morph(const tinygltf::Primitive& primitive, Vertices& v, const std::string& element) {
        if (!primitive.targets.empty()) {
            const tinygltf::Mesh& mesh = m_model.meshes[m_meshIndex];
            const std::vector<double>& weights = morphWeights(*m_drawingNode, mesh);
            const std::string weightsElement =
                &weights == &mesh.weights ? fmt::format("meshes[{}].weights", m_meshIndex) : m_nodeElement + ".weights";
            for (const std::string& semantic : applyMorphTargets(m_model, primitive, weights, weightsElement, v.positions,
                                                                 v.normals, v.tangents, element))
                warnOnce(fmt::format("morph target attribute {} is not applied (only POSITION, NORMAL and TANGENT are)",
                                     semantic));
        }
    }

    // The drawing node's skin (gltf_skin.h): vertices to world space, after morph targets.
    void skin(const tinygltf::Primitive& primitive, Vertices& v, const std::string& element) {
        if (m_skinJoints) {
            const SkinnedVertices skinned = applySkin(m_model, primitive, *m_skinJoints, v.positions, v.normals, v.tangents, element);
            v.mirrored = skinned.mirrored;
            if (skinned.unweighted > 0)
                warnOnce(fmt::format("{}: {} vertices have no joint weight (all WEIGHTS 0); they are not skinned", element,
                                     skinned.unweighted));
        }
    }

    void warnOnce(const std::string& message) {
        if (m_warned.insert(message).second) warn(message);
    }

    // Every texture of the material reads a TEXCOORD set the primitive has (set 0 may be absent:
    // its coordinates are then zero, as before sets were checked).
    void checkTexCoordSets(const Material& m, const Vertices& v, const std::string& element) const {
        for (const int view : {m.baseColorTexture, m.metallicRoughnessTexture, m.emissiveTexture, m.normalTexture,
                               m.specularTexture, m.specularColorTexture, m.sheenColorTexture, m.sheenRoughnessTexture,
                               m.clearcoatTexture, m.clearcoatRoughnessTexture, m.transmissionTexture,
                               m.clearcoatNormalTexture, m.anisotropyTexture, m.iridescenceTexture,
                               m.iridescenceThicknessTexture}) {
            if (view < 0) continue;
            const int slot = m_scene.textureViews[view].texCoord, set = m_texCoordSetOfView[view];
            if (set > 0 && v.uvs[slot].empty())
                fail(element, fmt::format("material \"{}\" reads TEXCOORD_{}, which the primitive does not have", m.name, set));
        }
    }

    // A triangle holds two TEXCOORD sets (Triangle::uv, uv1; GpuTriangleShading): TEXCOORD_0 and
    // the smallest other set any texture reads (TEXCOORD_1 when none does). Each texture view's
    // texCoord becomes the slot (0 or 1) the device reads; the file's set stays in
    // m_texCoordSetOfView. Textures reading a third set read TEXCOORD_0 instead, with a warning.
    void remapTexCoordSets() {
        m_texCoordSetOfView.clear();
        for (const TextureView& view : m_scene.textureViews) m_texCoordSetOfView.push_back(view.texCoord);
        int second = -1;
        for (const int set : m_texCoordSetOfView)
            if (set > 0 && (second < 0 || set < second)) second = set;
        m_secondTexCoordSet = second < 0 ? 1 : second;
        std::set<int> warned;
        for (size_t i = 0; i < m_scene.textureViews.size(); ++i) {
            const int set = m_texCoordSetOfView[i];
            int& slot = m_scene.textureViews[i].texCoord;
            slot = set == 0 ? 0 : set == m_secondTexCoordSet ? 1 : 0;
            if (set != 0 && set != m_secondTexCoordSet && warned.insert(set).second)
                warn(fmt::format("textures read TEXCOORD_{}, but a triangle holds two sets (TEXCOORD_0 and TEXCOORD_{} in "
                                 "this file): they read TEXCOORD_0 instead",
                                 set, m_secondTexCoordSet));
        }
    }

    // World-space triangles. Normals use the inverse transpose, tangents the transform itself; a
    // mirroring transform (negative determinant) swaps two vertices so the winding, and with it
    // the geometric normal, stays consistent with the transformed normals, and flips the
    // tangents' handedness. Missing normals are flat (per face), as the glTF spec requires.
    // Triangles with zero area or a non-finite normal are dropped and counted.
    void emitTriangles(const Vertices& vertices, const std::vector<uint32_t>& indices, const glm::dmat4& world,
                       uint32_t material) {
        const std::vector<glm::vec3>& positions = vertices.positions;
        const std::vector<glm::vec3>& normals = vertices.normals;
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
        // Skinned vertices are in world space already (world is the identity); a triangle whose
        // skinning matrices mirror (at two of its corners or more) is turned like a mirrored node's.
        const auto mirroredBySkin = [&](const uint32_t* corner) {
            return !vertices.mirrored.empty() &&
                   vertices.mirrored[corner[0]] + vertices.mirrored[corner[1]] + vertices.mirrored[corner[2]] >= 2;
        };
        // Unit length or nothing: double precision so that neither huge nor tiny (but finite)
        // vectors overflow on the way, and an explicit zero test (normalising 0 gives NaN).
        const auto unit = [](const glm::dvec3& v, glm::vec3& out) {
            const double length = glm::length(v);
            out = glm::vec3(v / length);
            return length > 0.0 && std::isfinite(length) && std::isfinite(out.x + out.y + out.z);
        };
        for (size_t i = 0; i < indices.size(); i += 3) {
            uint32_t v[3] = {indices[i], indices[i + 1], indices[i + 2]};
            if (mirrored != mirroredBySkin(v)) std::swap(v[1], v[2]);
            Triangle t;
            for (int k = 0; k < 3; ++k) {
                // In double, then checked: a float matrix would turn 1e20 x 1e20 into infinity.
                const glm::dvec3 p(world * glm::dvec4(glm::dvec3(positions[v[k]]), 1.0));
                const double reach = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
                if (!(reach <= kMaxCoordinate))
                    fail(m_primitiveElement, fmt::format("vertex {} of {} lies at ({:.3g}, {:.3g}, {:.3g}) in world space, "
                                                         "beyond the +-{:g} units vkphoton handles",
                                                         v[k], m_nodeElement, p.x, p.y, p.z, kMaxCoordinate));
                t.p[k] = glm::vec3(p);
                t.uv[k] = vertices.uvs[0].empty() ? glm::vec2(0.0f) : vertices.uvs[0][v[k]];
                t.uv1[k] = vertices.uvs[1].empty() ? glm::vec2(0.0f) : vertices.uvs[1][v[k]];
                if (!vertices.colors.empty()) t.color[k] = glm::clamp(vertices.colors[v[k]], 0.0f, 1.0f);
            }
            glm::vec3 face;
            const glm::dvec3 p0(t.p[0]);
            bool valid = unit(glm::cross(glm::dvec3(t.p[1]) - p0, glm::dvec3(t.p[2]) - p0), face);
            for (int k = 0; k < 3 && valid; ++k) {
                if (normals.empty()) t.n[k] = face;
                else valid = unit(normalMatrix * glm::dvec3(normals[v[k]]), t.n[k]);
            }
            if (!valid) {
                ++m_scene.droppedDegenerateTriangles;
                continue;
            }
            // Tangents: w = 0 (no normal mapping on this triangle) unless all three are usable.
            bool tangents = !vertices.tangents.empty();
            for (int k = 0; k < 3 && tangents; ++k) {
                const glm::vec4 tangent = vertices.tangents[v[k]];
                glm::vec3 direction;
                tangents = tangent.w != 0.0f && unit(glm::dmat3(world) * glm::dvec3(tangent), direction);
                t.tangent[k] = glm::vec4(direction, (tangent.w < 0.0f) != mirrored ? -1.0f : 1.0f);
            }
            if (!tangents)
                for (glm::vec4& tangent : t.tangent) tangent = glm::vec4(0.0f);
            // An exact copy of an earlier triangle adds nothing to the image, but a million of them
            // overlap in every BVH leaf and make rays too long for the device's loop limit.
            if (!(m_targetKeys ? *m_targetKeys : m_triangleKeys).insert(triangleKey(t)).second) {
                ++m_scene.droppedDuplicateTriangles;
                continue;
            }
            t.material = material;
            if (m_target) {  // an instanced mesh, in object space (addInstance)
                for (const glm::vec3& p : t.p) m_target->bounds.grow(p);
                m_target->triangles.push_back(t);
                continue;
            }
            for (const glm::vec3& p : t.p) m_scene.bounds.grow(p);
            m_scene.triangles.push_back(t);
        }
    }

    void addCamera(int index, const glm::dmat4& world, const std::string& nodeElement) {
        const std::string element = fmt::format("cameras[{}]", index);
        if (static_cast<size_t>(index) >= m_model.cameras.size()) fail(element, "does not exist");
        const tinygltf::Camera& source = m_model.cameras[index];
        const bool orthographic = source.type == "orthographic";
        if (!orthographic && source.type != "perspective")
            fail(element + ".type", fmt::format("unknown camera type \"{}\"", source.type));
        const double yfov = orthographic ? 0.6911 : source.perspective.yfov;
        const double aspect = orthographic ? 0.0 : source.perspective.aspectRatio;
        const double ymag = orthographic ? source.orthographic.ymag : 0.0;
        if (!(yfov > 0.0 && yfov < kPi)) fail(element + ".perspective.yfov", fmt::format("{} is not in (0, pi)", yfov));
        if (!(aspect >= 0.0 && std::isfinite(aspect)))
            fail(element + ".perspective.aspectRatio", fmt::format("{} is not a positive number (or absent)", aspect));
        // glTF allows a negative ymag (a mirrored view); the magnitude is the view's half height.
        if (orthographic && !(std::abs(ymag) > 0.0 && std::abs(ymag) <= kMaxCoordinate))
            fail(element + ".orthographic.ymag", fmt::format("{} is not a non-zero number within +-{:g}", ymag, kMaxCoordinate));
        // The camera looks down its local -Z with +Y up; orthonormalise in case of scale or shear.
        const glm::dvec3 forward = glm::normalize(-glm::dvec3(world[2]));
        const glm::dvec3 up = glm::normalize(glm::dvec3(world[1]) - glm::dot(glm::dvec3(world[1]), forward) * forward);
        if (!std::isfinite(glm::dot(forward, up)) || !std::isfinite(glm::length(up)))
            fail(element, "the node's transform is degenerate (no view direction)");
        Camera camera;
        camera.name = source.name.empty() ? element : source.name;
        camera.position = position(world, nodeElement, "camera");
        camera.forward = glm::vec3(forward);
        camera.up = glm::vec3(up);
        camera.yfov = static_cast<float>(yfov);
        camera.aspectRatio = static_cast<float>(aspect);
        camera.orthoHalfHeight = static_cast<float>(std::abs(ymag));
        m_scene.cameras.push_back(camera);
    }

    void addLight(int index, const glm::dmat4& world, const std::string& nodeElement) {
        const std::string element = fmt::format("extensions.KHR_lights_punctual.lights[{}]", index);
        if (index < 0 || static_cast<size_t>(index) >= m_model.lights.size()) fail(element, "does not exist");
        const tinygltf::Light& source = m_model.lights[index];
        PunctualLight light;
        light.name = source.name.empty() ? element : source.name;
        if (source.type == "point") light.type = LightType::Point;
        else if (source.type == "spot") light.type = LightType::Spot;
        else if (source.type == "directional") light.type = LightType::Directional;
        else fail(element + ".type", fmt::format("unknown light type \"{}\"", source.type));
        if (!source.color.empty() && source.color.size() != 3) fail(element + ".color", "needs 3 numbers");
        const glm::dvec3 color = source.color.empty() ? glm::dvec3(1.0) : glm::dvec3(source.color[0], source.color[1], source.color[2]);
        // In the float the renderer uses, and bounded so that photon powers and film sums stay finite.
        const glm::vec3 intensity = glm::vec3(color * source.intensity / double(kLumensPerWatt));
        if (!std::isfinite(intensity.x + intensity.y + intensity.z) || glm::any(glm::lessThan(intensity, glm::vec3(0.0f))))
            fail(element, "intensity and color must be finite and non-negative");
        if (glm::any(glm::greaterThan(glm::dvec3(intensity), glm::dvec3(kMaxRadiometric))))
            fail(element + ".intensity", fmt::format("{:g} makes {:.3g} W/sr or W/m^2, beyond the {:g} vkphoton handles",
                                                     source.intensity, std::max({intensity.x, intensity.y, intensity.z}),
                                                     kMaxRadiometric));
        light.intensity = intensity;
        if (light.type == LightType::Spot) {
            const double inner = source.spot.innerConeAngle, outer = source.spot.outerConeAngle;
            if (!(inner >= 0.0 && inner <= outer && outer > 0.0 && outer <= kHalfPi))
                fail(element + ".spot", fmt::format("cone angles {} and {} need 0 <= inner <= outer <= pi/2", inner, outer));
            light.innerConeAngle = static_cast<float>(inner);
            light.outerConeAngle = static_cast<float>(outer);
        }
        // Lights shine along their node's local -Z; scale does not change a punctual light.
        const glm::dvec3 direction = glm::normalize(-glm::dvec3(world[2]));
        if (!std::isfinite(direction.x + direction.y + direction.z))
            fail(element, "its node's transform is degenerate (no direction)");
        light.position = position(world, nodeElement, "light");
        light.direction = glm::vec3(direction);
        m_scene.lights.push_back(light);
    }

    fs::path m_path;
    GltfLimits m_limits;
    fs::path m_folder;
    GltfFileAccess m_files;
    tinygltf::Model m_model;
    Scene m_scene;
    std::optional<GltfMaterials> m_materials;  // made once the model is parsed
    std::vector<int> m_texCoordSetOfView;     // the file's TEXCOORD set of each Scene::textureViews entry
    int m_secondTexCoordSet = 1;              // the set Triangle::uv1 holds (remapTexCoordSets)
    size_t m_skippedPrimitives = 0;
    std::unordered_set<std::string> m_triangleKeys;
    // Instanced meshes (gltf_instancing.h): which glTF meshes, their Scene::meshes index once
    // read (-1 before), and where emitTriangles puts a mesh's triangles while it is read.
    std::vector<bool> m_instancedMesh;
    std::vector<int> m_meshSlot;
    Mesh* m_target = nullptr;
    std::unordered_set<std::string>* m_targetKeys = nullptr;
    bool m_warnedSingularInstance = false;
    std::string m_nodeElement, m_primitiveElement;  // what emitTriangles names
    const tinygltf::Node* m_drawingNode = nullptr;  // the node whose mesh is read (its morph weights, skin)
    int m_meshIndex = -1;
    const std::vector<glm::dmat4>* m_skinJoints = nullptr;  // the drawing node's joint matrices when it has a skin
    std::vector<int> m_parent;                              // findParents()
    std::vector<std::optional<glm::dmat4>> m_nodeWorld;     // nodeWorld()'s memo, per flatten
    std::set<std::string> m_warned;                         // warnOnce()
    int m_sceneIndex = 0;
    int m_variant = -1;  // KHR_materials_variants: the chosen variant (GltfLimits::materialVariant), -1: none
    const std::vector<std::optional<glm::dmat4>>* m_overrides = nullptr;  // flatten()'s animated local transforms
    const std::vector<glm::dvec3>* m_worldOffsets = nullptr;              // flatten()'s node translations (view)
};

// Loader errors start with the file; the parts above name only the element.
template <typename F> auto withFileName(const std::filesystem::path& path, F&& f) -> decltype(f()) {
    try {
        return f();
    } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", path.string(), e.what()));
    } catch (const RuntimeError& e) {
        throw RuntimeError(fmt::format("{}: {}", path.string(), e.what()));
    } catch (const std::bad_alloc&) {
        throw InputError(fmt::format("{}: out of memory while loading (is the file hostile?)", path.string()));
    } catch (const std::exception& e) {
        throw InputError(fmt::format("{}: unreadable glTF: {}", path.string(), e.what()));
    }
}

}  // namespace

class GltfSceneSource::State : public Loader {
public:
    using Loader::Loader;
};

GltfSceneSource::GltfSceneSource(const std::filesystem::path& path, const GltfLimits& limits) : m_path(path) {
    withFileName(path, [&] {
        m_state = std::make_unique<State>(path, limits);
        m_state->prepare();
        m_state->prepareDefaultMaterial();
        m_animation.emplace(m_state->model(), [this](const std::string& message) { m_state->warnAbout(message); });
        return 0;
    });
}

GltfSceneSource::~GltfSceneSource() = default;

Scene GltfSceneSource::sceneAt(double seconds, const NodeOffsets* offsets) {
    return withFileName(m_path, [&] {
        const std::vector<std::optional<glm::dmat4>> local = m_animation->localTransforms(seconds);
        return m_state->flatten(&local, true, offsets);
    });
}

Scene GltfSceneSource::stillScene(const NodeOffsets* offsets) {
    return withFileName(m_path, [&] { return m_state->flatten(nullptr, true, offsets); });
}

int GltfSceneSource::findNode(const std::string& name) const {
    const auto& nodes = m_state->model().nodes;
    for (size_t i = 0; i < nodes.size(); ++i)
        if (nodes[i].name == name) return static_cast<int>(i);
    return -1;
}

std::string GltfSceneSource::nodeName(int index) const {
    const auto& nodes = m_state->model().nodes;
    if (index < 0 || size_t(index) >= nodes.size()) return {};
    return nodes[index].name.empty() ? fmt::format("nodes[{}]", index) : nodes[index].name;
}

Scene loadGltf(const std::filesystem::path& path, const GltfLimits& limits) {
    // tinygltf reports by return value, but a malformed file must never escape as anything but
    // bad input: withFileName maps every exception to an error naming the file.
    return withFileName(path, [&] { return Loader(path, limits).load(); });
}

}  // namespace vkp
