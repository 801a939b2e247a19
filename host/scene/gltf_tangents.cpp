#include "scene/gltf_tangents.h"

#include <algorithm>
#include <cmath>

namespace vkp {
namespace {

// v without its component along unit n, normalised; zero when nothing is left.
glm::dvec3 projectOnPlane(const glm::dvec3& v, const glm::dvec3& n) {
    const glm::dvec3 p = v - n * glm::dot(n, v);
    const double length = glm::length(p);
    return length > 1e-20 && std::isfinite(length) ? p / length : glm::dvec3(0.0);
}

double cornerAngle(const glm::dvec3& a, const glm::dvec3& b) {
    const double la = glm::length(a), lb = glm::length(b);
    if (!(la > 0.0 && lb > 0.0)) return 0.0;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0));
}

}  // namespace

std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs, const std::vector<uint32_t>& indices) {
    std::vector<glm::dvec3> tangentSum(positions.size(), glm::dvec3(0.0)), bitangentSum(positions.size(), glm::dvec3(0.0));
    std::vector<glm::dvec3> normalOf(positions.size(), glm::dvec3(0.0));
    if (uvs.size() != positions.size()) return std::vector<glm::vec4>(positions.size(), glm::vec4(0.0f));
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        const uint32_t v[3] = {indices[i], indices[i + 1], indices[i + 2]};
        const glm::dvec3 p[3] = {glm::dvec3(positions[v[0]]), glm::dvec3(positions[v[1]]), glm::dvec3(positions[v[2]])};
        const glm::dvec2 t[3] = {glm::dvec2(uvs[v[0]]), glm::dvec2(uvs[v[1]]), glm::dvec2(uvs[v[2]])};
        const glm::dvec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
        const glm::dvec2 d1 = t[1] - t[0], d2 = t[2] - t[0];
        const double det = d1.x * d2.y - d2.x * d1.y;
        const glm::dvec3 face = glm::cross(e1, e2);
        if (det == 0.0 || !std::isfinite(det) || glm::length(face) == 0.0) continue;  // no UV frame
        // dP/du and dP/dv; glTF's v runs down the image, so the bitangent (+Y of the map) is -dP/dv.
        const glm::dvec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::dvec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 n = normals.empty() ? glm::normalize(face) : glm::normalize(glm::dvec3(normals[v[k]]));
            if (!std::isfinite(n.x + n.y + n.z)) continue;
            const double angle = cornerAngle(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
            tangentSum[v[k]] += angle * projectOnPlane(dPdu, n);
            bitangentSum[v[k]] += angle * projectOnPlane(-dPdv, n);
            normalOf[v[k]] = n;
        }
    }
    std::vector<glm::vec4> out(positions.size(), glm::vec4(0.0f));
    for (size_t i = 0; i < out.size(); ++i) {
        const glm::dvec3 tangent = projectOnPlane(tangentSum[i], normalOf[i]);
        if (tangent == glm::dvec3(0.0)) continue;
        const double w = glm::dot(glm::cross(normalOf[i], tangent), bitangentSum[i]) < 0.0 ? -1.0 : 1.0;
        out[i] = glm::vec4(glm::vec3(tangent), float(w));
    }
    return out;
}

}  // namespace vkp
