#include "lights/surface_rays.h"

#include <algorithm>
#include <cmath>

#include "scene/scene.h"
#include "shared/sampling.glsl"

namespace vkp {

SurfaceRay frontRay(const Triangle& t, bool twoSided, float reach, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    SurfaceRay ray;
    const glm::vec2 b = gpu::sampleTriangleBarycentrics(glm::vec2(u(rng), u(rng)));
    const glm::vec3 p = t.p[0] * (1.0f - b.x - b.y) + t.p[1] * b.x + t.p[2] * b.y;
    glm::vec3 n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
    if (!(glm::length(n) > 0.0f)) return ray;
    n = glm::normalize(n);
    if (glm::dot(n, t.n[0] + t.n[1] + t.n[2]) < 0.0f) n = -n;
    if (twoSided && u(rng) < 0.5f) n = -n;
    glm::vec3 tangent, bitangent;
    gpu::orthonormalBasis(n, tangent, bitangent);
    ray.direction = gpu::toWorld(gpu::sampleCosineHemisphere(glm::vec2(u(rng), u(rng))), tangent, bitangent, n);
    const float eps = 1.0e-4f * std::max({reach, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    ray.origin = p + n * eps;
    ray.valid = true;
    return ray;
}

}  // namespace vkp
