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

inline bool sameBits(const glm::vec3& a, const glm::vec3& b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }
inline bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof(a)) == 0; }

}  // namespace vkp::test
