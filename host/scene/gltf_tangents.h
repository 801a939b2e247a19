// Per-vertex tangents for normal-mapped primitives that have no TANGENT attribute.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace vkp {

// glTF asks for MikkTSpace tangents. This computes what MikkTSpace gives in the common case
// (docs/scene-format.md, "Normal maps"): for every corner of every triangle, the face's tangent
// (dP/du) and bitangent (-dP/dv: glTF's v runs down the image, the normal map's +Y points up) are
// projected onto the plane of the vertex normal and added, weighted by the corner's angle; the
// tangent is the normalised sum, and w = +-1 says whether cross(normal, tangent) points along the
// summed bitangent. Differences from MikkTSpace: vertices are not split where faces of opposite
// UV handedness or different smoothing meet (their tangents are averaged), and degenerate UV
// triangles are skipped instead of borrowing a neighbour's frame. A vertex with no usable
// tangent gets w = 0 (its triangles are not normal-mapped).
// `normals` may be empty (flat shading: face normals); `uvs` empty gives only w = 0 tangents.
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& indices);

}  // namespace vkp
