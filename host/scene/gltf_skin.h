// Skins (glTF 2.0 section 3.7.3) posed by their joints' world transforms: a skinned vertex is
// sum_j weight_j * (jointWorld_j * inverseBindMatrix_j) * v, in world space (the skinned mesh's own
// node transform is ignored, as the specification says).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkp {

// The joint matrices of skins[skin]: worldOf(joints[j]) * inverseBindMatrices[j] (identity without
// inverseBindMatrices), one per joint. worldOf gives a node's world transform in the pose drawn.
// Errors (InputError) name `skins[skin]`: no joints, a joint that is no node, inverseBindMatrices
// not MAT4 float, fewer than the joints, or not finite.
std::vector<glm::dmat4> jointMatrices(const tinygltf::Model& model, int skin, const std::function<glm::dmat4(int)>& worldOf);

struct SkinnedVertices {
    std::vector<uint8_t> mirrored;  // per vertex: its skinning matrix has a negative determinant
    size_t unweighted = 0;          // vertices whose weights are all 0: left where they are (bind space)
};

// Moves the primitive's vertices (after its morph targets) by the skin: positions by the blended
// matrix M = sum_j w_j * joints[J_j] / sum_j w_j (weights that do not sum to 1 are renormalised),
// normals by its inverse transpose (renormalised when the triangles are made), tangents' xyz by M
// (w flipped where M mirrors). Influences come from JOINTS_n / WEIGHTS_n, n = 0, 1, ... while both
// are present: joints unsigned byte or short, weights float or normalized unsigned byte or short.
// Errors are InputErrors naming `element`: no JOINTS_0/WEIGHTS_0, a set with only one of the two,
// wrong types or counts, a joint index beyond the skin's joints, negative or non-finite weights.
SkinnedVertices applySkin(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          const std::vector<glm::dmat4>& joints, std::vector<glm::vec3>& positions,
                          std::vector<glm::vec3>& normals, std::vector<glm::vec4>& tangents, const std::string& element);

}  // namespace vkp
