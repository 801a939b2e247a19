// Helpers of the shared-BSDF tests: local directions by angle, and bitwise equality of results.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

namespace vkp::test {

// The unit vector at polar cosine cosTheta and azimuth phi around +z.
inline glm::vec3 localDirection(float cosTheta, float phi) {
    const float s = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return glm::vec3(s * std::cos(phi), s * std::sin(phi), cosTheta);
}

// The integral over the sphere of f(wi, mu) dω, mu = |wi.z|, by a midpoint rule in (t, phi) with
// mu = t^3 on each hemisphere (nodes crowd at the horizon, where grazing lobes live): `steps`
// bands per hemisphere and steps / 2 sectors. f returns a double or a glm::dvec3.
template <class F>
auto sphereQuadrature(int steps, F f) {
    constexpr double kTwoPi = 6.283185307179586;
    decltype(f(glm::vec3(0.0f), 0.0)) sum(0.0);
    for (int side = -1; side <= 1; side += 2)
        for (int i = 0; i < steps; ++i) {
            const double t = (i + 0.5) / steps;
            const double mu = t * t * t;
            for (int j = 0; j < steps / 2; ++j) {
                const double phi = kTwoPi * (j + 0.5) / (steps / 2);
                glm::vec3 wi = localDirection(static_cast<float>(mu), static_cast<float>(phi));
                wi.z *= static_cast<float>(side);
                sum += f(wi, mu) * (3.0 * t * t);
            }
        }
    return sum * ((1.0 / steps) * (kTwoPi / (steps / 2)));
}

inline bool sameBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }
inline bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

}  // namespace vkp::test
