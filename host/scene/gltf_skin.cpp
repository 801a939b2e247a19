#include "scene/gltf_skin.h"

#include <cmath>

#include <fmt/format.h>

#include "scene/gltf_accessors.h"
#include "util/errors.h"

namespace vkp {
namespace {

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        if (!std::isfinite(m[c].x + m[c].y + m[c].z + m[c].w)) return false;
    return true;
}

int attribute(const tinygltf::Primitive& primitive, const std::string& name) {
    const auto it = primitive.attributes.find(name);
    return it == primitive.attributes.end() ? -1 : it->second;
}

// One JOINTS_n / WEIGHTS_n pair, read and type-checked.
struct InfluenceSet {
    std::vector<glm::vec4> joints, weights;
};

InfluenceSet readInfluences(const tinygltf::Model& model, int jointsAccessor, int weightsAccessor, int set,
                            size_t vertices, const std::string& element) {
    const std::string jointsName = fmt::format("{}.attributes.JOINTS_{}", element, set);
    const std::string weightsName = fmt::format("{}.attributes.WEIGHTS_{}", element, set);
    // Indices exist (the preflight checks every attribute's reference).
    const tinygltf::Accessor& j = model.accessors.at(jointsAccessor);
    const tinygltf::Accessor& w = model.accessors.at(weightsAccessor);
    if (j.normalized || (j.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                         j.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
        fail(jointsName, fmt::format("accessors[{}] must be unsigned byte or short, not normalized", jointsAccessor));
    const bool normalizedUnsigned = w.normalized && (w.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                     w.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    if (w.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !normalizedUnsigned)
        fail(weightsName, fmt::format("accessors[{}] must be float or normalized unsigned byte or short", weightsAccessor));
    InfluenceSet out;
    try {
        out.joints = readVec4Accessor(model, jointsAccessor);
    } catch (const InputError& e) {
        fail(jointsName, e.what());
    }
    try {
        out.weights = readVec4Accessor(model, weightsAccessor);
    } catch (const InputError& e) {
        fail(weightsName, e.what());
    }
    if (out.joints.size() != vertices)
        fail(jointsName, fmt::format("{} elements, but POSITION has {}", out.joints.size(), vertices));
    if (out.weights.size() != vertices)
        fail(weightsName, fmt::format("{} elements, but POSITION has {}", out.weights.size(), vertices));
    return out;
}

}  // namespace

std::vector<glm::dmat4> jointMatrices(const tinygltf::Model& model, int skinIndex, const std::function<glm::dmat4(int)>& worldOf) {
    const std::string element = fmt::format("skins[{}]", skinIndex);
    if (skinIndex < 0 || static_cast<size_t>(skinIndex) >= model.skins.size()) fail(element, "does not exist");
    const tinygltf::Skin& skin = model.skins[skinIndex];
    if (skin.joints.empty()) fail(element + ".joints", "is empty");
    std::vector<glm::dmat4> inverseBind;
    if (skin.inverseBindMatrices >= 0) {
        try {
            inverseBind = readMat4Accessor(model, skin.inverseBindMatrices);
        } catch (const InputError& e) {
            fail(element + ".inverseBindMatrices", e.what());
        }
        if (inverseBind.size() < skin.joints.size())
            fail(element + ".inverseBindMatrices", fmt::format("accessors[{}] has {} matrices for {} joints",
                                                               skin.inverseBindMatrices, inverseBind.size(), skin.joints.size()));
    }
    std::vector<glm::dmat4> out(skin.joints.size());
    for (size_t j = 0; j < skin.joints.size(); ++j) {
        const int node = skin.joints[j];
        if (node < 0 || static_cast<size_t>(node) >= model.nodes.size())
            fail(fmt::format("{}.joints[{}]", element, j), fmt::format("nodes[{}] does not exist", node));
        const glm::dmat4 ibm = inverseBind.empty() ? glm::dmat4(1.0) : inverseBind[j];
        if (!isFinite(ibm)) fail(element + ".inverseBindMatrices", fmt::format("matrix {} is not finite", j));
        out[j] = worldOf(node) * ibm;
    }
    return out;
}

SkinnedVertices applySkin(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          const std::vector<glm::dmat4>& joints, std::vector<glm::vec3>& positions,
                          std::vector<glm::vec3>& normals, std::vector<glm::vec4>& tangents, const std::string& element) {
    std::vector<InfluenceSet> sets;
    // Sets 0, 1, ... while present; glTF numbers sets without gaps.
    for (int set = 0;; ++set) {
        const int j = attribute(primitive, fmt::format("JOINTS_{}", set));
        const int w = attribute(primitive, fmt::format("WEIGHTS_{}", set));
        if (j < 0 && w < 0) break;
        if (j < 0 || w < 0)
            fail(element, fmt::format("has {}_{} without {}_{}", j < 0 ? "WEIGHTS" : "JOINTS", set,
                                      j < 0 ? "JOINTS" : "WEIGHTS", set));
        sets.push_back(readInfluences(model, j, w, set, positions.size(), element));
    }
    if (sets.empty()) fail(element, "is drawn by a skinned node but has no JOINTS_0 and WEIGHTS_0");

    SkinnedVertices out;
    out.mirrored.assign(positions.size(), 0);
    for (size_t v = 0; v < positions.size(); ++v) {
        glm::dmat4 m(0.0);
        double total = 0.0;
        for (size_t s = 0; s < sets.size(); ++s)
            for (int k = 0; k < 4; ++k) {
                const double weight = sets[s].weights[v][k];
                const double joint = sets[s].joints[v][k];
                if (!(weight >= 0.0) || !std::isfinite(weight))
                    fail(element, fmt::format("WEIGHTS_{} element {} is negative or not finite", s, v));
                if (joint >= static_cast<double>(joints.size()))
                    fail(element, fmt::format("JOINTS_{} element {} names joint {}, but the skin has {} joints", s, v, joint,
                                              joints.size()));
                if (weight == 0.0) continue;
                m += weight * joints[static_cast<size_t>(joint)];
                total += weight;
            }
        if (total == 0.0) {
            ++out.unweighted;
            continue;
        }
        m /= total;
        const glm::dmat3 linear(m);
        positions[v] = glm::vec3(m * glm::dvec4(glm::dvec3(positions[v]), 1.0));
        if (!normals.empty()) normals[v] = glm::vec3(glm::transpose(glm::inverse(linear)) * glm::dvec3(normals[v]));
        const bool mirrored = glm::determinant(linear) < 0.0;
        out.mirrored[v] = mirrored ? 1 : 0;
        if (!tangents.empty()) {
            const glm::vec4 t = tangents[v];
            tangents[v] = glm::vec4(glm::vec3(linear * glm::dvec3(t)), mirrored ? -t.w : t.w);
        }
    }
    return out;
}

}  // namespace vkp
