// Rays leaving the surfaces of a scene, cast on the host by the default lighting rule
// (default_lighting.h: where an emitter's light lands; backdrop.h: what the scene's surfaces see).
#pragma once

#include <random>

#include <glm/glm.hpp>

namespace vkp {

struct Triangle;

struct SurfaceRay {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f};
    bool valid = false;  // false for a degenerate triangle
};

// A point uniform over t's area and a cosine-distributed direction about its front: the side its
// vertex normals face (the winding's side when they agree or are missing), or either side at
// random when twoSided. The origin is offset along that side as the shaders offset rays
// (scene_access.glsl rayEpsilon), with `reach` the scene's rayOffsetScale (bvh/scene_bvh.h).
SurfaceRay frontRay(const Triangle& t, bool twoSided, float reach, std::mt19937& rng);

}  // namespace vkp
