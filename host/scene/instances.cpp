// Instances back to world-space triangles (scene.h): the single-level scene they stand for.
#include <utility>

#include "scene/scene.h"

namespace vkp {

void appendInstanceTriangles(const Mesh& mesh, const glm::mat4& transform, std::vector<Triangle>& out) {
    const glm::mat3 linear(transform);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
    const bool mirrored = glm::determinant(linear) < 0.0f;
    const auto unit = [](glm::vec3 v) {
        const float length = glm::length(v);
        return length > 0.0f ? v / length : v;
    };
    for (const Triangle& source : mesh.triangles) {
        Triangle t = source;
        for (int k = 0; k < 3; ++k) {
            t.p[k] = glm::vec3(transform * glm::vec4(source.p[k], 1.0f));
            t.n[k] = unit(normalMatrix * source.n[k]);
            if (source.tangent[k].w != 0.0f)
                t.tangent[k] = glm::vec4(unit(linear * glm::vec3(source.tangent[k])),
                                         mirrored ? -source.tangent[k].w : source.tangent[k].w);
        }
        if (mirrored) {  // keep the winding consistent with the normals (gltf_loader.cpp emitTriangles)
            std::swap(t.p[1], t.p[2]);
            std::swap(t.n[1], t.n[2]);
            std::swap(t.uv[1], t.uv[2]);
            std::swap(t.uv1[1], t.uv1[2]);
            std::swap(t.color[1], t.color[2]);
            std::swap(t.tangent[1], t.tangent[2]);
        }
        out.push_back(t);
    }
}

std::vector<Triangle> flattenedTriangles(const Scene& scene) {
    std::vector<Triangle> out = scene.triangles;
    for (const Instance& instance : scene.instances)
        appendInstanceTriangles(scene.meshes.at(instance.mesh), instance.transform, out);
    return out;
}

}  // namespace vkp
