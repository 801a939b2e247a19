#include "scene/gltf_morph.h"

#include <cmath>

#include <fmt/format.h>

#include "scene/gltf_accessors.h"
#include "util/errors.h"

namespace vkp {
namespace {

[[noreturn]] void fail(const std::string& element, const std::string& what) {
    throw InputError(fmt::format("{}: {}", element, what));
}

// base[i] += weight * displacement[i] for the xyz of every element, in double and back.
template <typename V>
void addDisplacement(std::vector<V>& base, const std::vector<glm::vec3>& displacement, double weight) {
    for (size_t i = 0; i < base.size(); ++i)
        for (int c = 0; c < 3; ++c) base[i][c] = static_cast<float>(double(base[i][c]) + weight * double(displacement[i][c]));
}

}  // namespace

const std::vector<double>& morphWeights(const tinygltf::Node& node, const tinygltf::Mesh& mesh) {
    return node.weights.empty() ? mesh.weights : node.weights;
}

std::vector<std::string> applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                           const std::vector<double>& weights, const std::string& weightsElement,
                                           std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                                           std::vector<glm::vec4>& tangents, const std::string& element) {
    std::vector<std::string> ignored;
    const size_t targets = primitive.targets.size();
    if (targets == 0) return ignored;
    if (!weights.empty() && weights.size() != targets)
        fail(element, fmt::format("has {} morph target(s) but {} has {} weight(s)", targets, weightsElement, weights.size()));
    for (size_t w = 0; w < weights.size(); ++w)
        if (!std::isfinite(weights[w])) fail(fmt::format("{}[{}]", weightsElement, w), "is not a finite number");
    for (size_t t = 0; t < targets; ++t) {
        const double weight = weights.empty() ? 0.0 : weights[t];
        for (const auto& [semantic, accessor] : primitive.targets[t]) {
            const std::string name = fmt::format("{}.targets[{}].{}", element, t, semantic);
            std::vector<glm::vec3>* vec3Base = semantic == "POSITION" ? &positions : semantic == "NORMAL" ? &normals : nullptr;
            if (!vec3Base && semantic != "TANGENT") {
                ignored.push_back(semantic);
                continue;
            }
            std::vector<glm::vec3> displacement;
            try {
                displacement = readVec3Accessor(model, accessor);
            } catch (const InputError& e) {
                fail(name, e.what());
            }
            if (displacement.size() != positions.size())
                fail(name, fmt::format("accessors[{}] has {} elements but POSITION has {}", accessor, displacement.size(),
                                       positions.size()));
            for (size_t i = 0; i < displacement.size(); ++i)
                if (!std::isfinite(displacement[i].x + displacement[i].y + displacement[i].z))
                    fail(name, fmt::format("element {} is NaN or infinite (accessors[{}])", i, accessor));
            if (weight == 0.0) continue;
            if (vec3Base) {
                if (!vec3Base->empty()) addDisplacement(*vec3Base, displacement, weight);
            } else if (!tangents.empty()) {
                addDisplacement(tangents, displacement, weight);
            }
        }
    }
    return ignored;
}

}  // namespace vkp
