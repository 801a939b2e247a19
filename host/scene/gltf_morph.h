// Morph targets (glTF 2.0 section 3.7.2.2) applied with their static weights: a primitive's
// POSITION, NORMAL and TANGENT displacements added to its base attributes.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <tiny_gltf.h>

namespace vkp {

// The weights a node draws its mesh with: the node's `weights` when present, else the mesh's,
// else none (every weight 0). Not checked here (applyMorphTargets checks them per primitive).
const std::vector<double>& morphWeights(const tinygltf::Node& node, const tinygltf::Mesh& mesh);

// The primitive's vertices after its morph targets: position += sum_i weights[i] * targets[i].POSITION,
// and likewise for normals and tangents (xyz; w stays). `normals` and `tangents` are left alone when
// empty (a target's NORMAL or TANGENT then has nothing to move); they are renormalised later, when the
// triangles are made. Every target accessor is read and checked whatever its weight (bounds through
// gltf_accessors.h, sparse accessors included; count equal to the base's; finite values), so a bad
// target is refused even at weight 0. `weights` empty: all 0; otherwise its size must equal the
// number of targets (`weightsElement` names where the weights come from). Returns the names of target
// attributes that are not applied (TEXCOORD_n, COLOR_n, ...), for a warning.
// Errors are InputErrors naming `element` (the primitive) and the target.
std::vector<std::string> applyMorphTargets(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                           const std::vector<double>& weights, const std::string& weightsElement,
                                           std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                                           std::vector<glm::vec4>& tangents, const std::string& element);

}  // namespace vkp
