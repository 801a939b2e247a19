#include "scene/gltf_instancing.h"

#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/quaternion.hpp>

#include "scene/gltf_accessors.h"
#include "scene/gltf_morph.h"
#include "scene/gltf_primitive_modes.h"
#include "scene/gltf_variants.h"
#include "util/errors.h"

namespace vkp {
namespace {

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

const tinygltf::Value* instancingAttributes(const tinygltf::Node& node) {
    const auto it = node.extensions.find(kMeshGpuInstancing);
    if (it == node.extensions.end() || !it->second.Has("attributes")) return nullptr;
    return &it->second.Get("attributes");
}

// The accessor index of attribute `name`, -1 when absent.
int attributeAccessor(const tinygltf::Model& model, const tinygltf::Value& attributes, const char* name,
                      const std::string& element) {
    if (!attributes.Has(name)) return -1;
    const tinygltf::Value& v = attributes.Get(name);
    if (!v.IsInt() || v.Get<int>() < 0 || static_cast<size_t>(v.Get<int>()) >= model.accessors.size())
        fail(element + ".attributes." + name, "is not the index of an accessor");
    return v.Get<int>();
}

bool finite(const glm::dvec4& v) { return std::isfinite(v.x + v.y + v.z + v.w); }

}  // namespace

std::vector<glm::dmat4> readMeshInstances(const tinygltf::Model& model, const tinygltf::Node& node,
                                          const std::string& nodeElement) {
    const std::string element = nodeElement + ".extensions." + kMeshGpuInstancing;
    const auto it = node.extensions.find(kMeshGpuInstancing);
    if (it == node.extensions.end()) return {};
    if (!it->second.IsObject() || !it->second.Has("attributes") || !it->second.Get("attributes").IsObject())
        fail(element, "has no attributes object");
    const tinygltf::Value& attributes = it->second.Get("attributes");
    const int translation = attributeAccessor(model, attributes, "TRANSLATION", element);
    const int rotation = attributeAccessor(model, attributes, "ROTATION", element);
    const int scale = attributeAccessor(model, attributes, "SCALE", element);
    if (translation < 0 && rotation < 0 && scale < 0) fail(element, "names none of TRANSLATION, ROTATION, SCALE");
    // The extension's types: TRANSLATION and SCALE VEC3 float, ROTATION VEC4 float or normalized
    // (signed) byte/short; the accessor reader checks bounds and converts normalized integers.
    const auto checkType = [&](int accessor, const char* name, int type, bool quaternion) {
        if (accessor < 0) return;
        const tinygltf::Accessor& a = model.accessors[accessor];
        const bool normalizedInt = a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                                    a.componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
        if (a.type != type || !(a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || (quaternion && normalizedInt)))
            fail(fmt::format("{}.attributes.{}", element, name),
                 fmt::format("accessors[{}] must be {} float{}", accessor, quaternion ? "VEC4" : "VEC3",
                             quaternion ? " or normalized byte/short" : ""));
    };
    checkType(translation, "TRANSLATION", TINYGLTF_TYPE_VEC3, false);
    checkType(rotation, "ROTATION", TINYGLTF_TYPE_VEC4, true);
    checkType(scale, "SCALE", TINYGLTF_TYPE_VEC3, false);
    std::vector<glm::vec3> t, s;
    std::vector<glm::vec4> r;
    if (translation >= 0) t = readVec3Accessor(model, translation);
    if (rotation >= 0) r = readVec4Accessor(model, rotation);
    if (scale >= 0) s = readVec3Accessor(model, scale);
    const size_t count = translation >= 0 ? t.size() : rotation >= 0 ? r.size() : s.size();
    if ((translation >= 0 && t.size() != count) || (rotation >= 0 && r.size() != count) ||
        (scale >= 0 && s.size() != count))
        fail(element, "TRANSLATION, ROTATION and SCALE have different counts");
    std::vector<glm::dmat4> out(count, glm::dmat4(1.0));
    for (size_t i = 0; i < count; ++i) {
        glm::dmat4 tm(1.0), rm(1.0), sm(1.0);
        if (!t.empty()) {
            if (!finite(glm::dvec4(glm::dvec3(t[i]), 0.0))) fail(element, fmt::format("TRANSLATION {} is not finite", i));
            tm[3] = glm::dvec4(glm::dvec3(t[i]), 1.0);
        }
        if (!r.empty()) {
            const glm::dquat q(r[i].w, r[i].x, r[i].y, r[i].z);  // glTF stores (x, y, z, w)
            const double length = glm::length(q);
            if (!finite(glm::dvec4(r[i])) || !(std::abs(length - 1.0) < 1.0e-2))
                fail(element, fmt::format("ROTATION {} is not a unit quaternion", i));
            rm = glm::mat4_cast(q / length);
        }
        if (!s.empty()) {
            if (!finite(glm::dvec4(glm::dvec3(s[i]), 0.0))) fail(element, fmt::format("SCALE {} is not finite", i));
            for (int k = 0; k < 3; ++k) sm[k][k] = s[i][k];
        }
        out[i] = tm * rm * sm;
    }
    return out;
}

uint64_t declaredInstanceCount(const tinygltf::Model& model, const tinygltf::Node& node) {
    const tinygltf::Value* attributes = instancingAttributes(node);
    if (!attributes || !attributes->IsObject()) return 1;
    for (const char* name : {"TRANSLATION", "ROTATION", "SCALE"}) {
        if (!attributes->Has(name) || !attributes->Get(name).IsInt()) continue;
        const int accessor = attributes->Get(name).Get<int>();
        if (accessor >= 0 && static_cast<size_t>(accessor) < model.accessors.size())
            return model.accessors[accessor].count;
    }
    return 1;  // readMeshInstances names the problem
}

std::vector<bool> planInstancedMeshes(const tinygltf::Model& model, const std::vector<int>& roots,
                                      const std::vector<Material>& materials, uint64_t minTriangles,
                                      bool everyMesh) {
    const size_t meshCount = model.meshes.size();
    std::vector<bool> animatedNode(model.nodes.size(), false);
    for (const tinygltf::Animation& animation : model.animations)
        for (const tinygltf::AnimationChannel& channel : animation.channels)
            if (channel.target_node >= 0 && static_cast<size_t>(channel.target_node) < model.nodes.size() &&
                channel.target_path != "weights")
                animatedNode[channel.target_node] = true;

    std::vector<uint64_t> draws(meshCount, 0);
    std::vector<bool> animated(meshCount, false);
    // Geometry that depends on the drawing node: a skin (world-space vertices) or morph weights
    // that differ between the nodes drawing the mesh.
    std::vector<bool> perNode(meshCount, false);
    std::vector<const std::vector<double>*> weights(meshCount, nullptr);
    struct Pending {
        int node;
        bool animated;  // an ancestor (or the node) moves
    };
    std::vector<Pending> stack;
    for (int root : roots) stack.push_back({root, false});
    std::vector<bool> seen(model.nodes.size(), false);
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        if (p.node < 0 || static_cast<size_t>(p.node) >= model.nodes.size() || seen[p.node]) continue;  // walk() names it
        seen[p.node] = true;
        const tinygltf::Node& node = model.nodes[p.node];
        const bool moves = p.animated || animatedNode[p.node];
        if (node.mesh >= 0 && static_cast<size_t>(node.mesh) < meshCount) {
            draws[node.mesh] += declaredInstanceCount(model, node);
            animated[node.mesh] = animated[node.mesh] || moves;
            const std::vector<double>& w = morphWeights(node, model.meshes[node.mesh]);
            if (node.skin >= 0 || (weights[node.mesh] && *weights[node.mesh] != w)) perNode[node.mesh] = true;
            weights[node.mesh] = &w;
        }
        for (int child : node.children) stack.push_back({child, moves});
    }

    std::vector<bool> instanced(meshCount, false);
    for (size_t m = 0; m < meshCount; ++m) {
        uint64_t triangles = 0;
        bool emissive = false;
        for (const tinygltf::Primitive& primitive : model.meshes[m].primitives) {
            if (!isTriangleMode(primitive.mode)) continue;
            const auto position = primitive.attributes.find("POSITION");
            const int accessor = primitive.indices >= 0 ? primitive.indices
                                 : position != primitive.attributes.end() ? position->second : -1;
            if (accessor >= 0 && static_cast<size_t>(accessor) < model.accessors.size())
                triangles += triangleCountOfMode(primitive.mode, model.accessors[accessor].count);
            // Its own material and every KHR_materials_variants material: any emissive one keeps
            // the mesh flattened, whichever variant is rendered.
            std::vector<int> candidates = variantMaterials(primitive);
            candidates.push_back(primitive.material);
            for (const int material : candidates)
                if (material >= 0 && static_cast<size_t>(material) < materials.size()) {
                    const glm::vec3 e = materials[material].emissive;
                    emissive = emissive || e.x > 0.0f || e.y > 0.0f || e.z > 0.0f;
                }
        }
        instanced[m] = !emissive && !perNode[m] && triangles > 0 &&
                       ((draws[m] >= 2 && triangles >= minTriangles) || ((animated[m] || everyMesh) && draws[m] >= 1));
    }
    return instanced;
}

}  // namespace vkp
