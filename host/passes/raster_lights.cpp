#include "passes/raster_lights.h"

#include <algorithm>
#include <cmath>

#include "shared/sampling.glsl"

namespace vkp {
namespace {

float radicalInverse2(uint32_t i) {
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x00ff00ffu) << 8u) | ((i & 0xff00ff00u) >> 8u);
    i = ((i & 0x0f0f0f0fu) << 4u) | ((i & 0xf0f0f0f0u) >> 4u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xccccccccu) >> 2u);
    i = ((i & 0x55555555u) << 1u) | ((i & 0xaaaaaaaau) >> 1u);
    return static_cast<float>(i) * 2.3283064365386963e-10f;
}

}  // namespace

std::vector<gpu::GpuLight> buildRasterLights(const SceneArrays& a, uint32_t areaSamples, const std::vector<bool>* keep) {
    std::vector<gpu::GpuLight> out;
    for (size_t index = 0; index < a.lights.size(); ++index) {
        const gpu::GpuLight& light = a.lights[index];
        if (keep && index < keep->size() && !(*keep)[index]) continue;
        if (light.type == gpu::kLightEnvironment) continue;  // left to the compute integrators
        if (light.type != gpu::kLightTriangle) {
            out.push_back(light);
            continue;
        }
        if (areaSamples == 0) continue;
        const gpu::GpuTriangle& t = a.triangles[light.triangle];
        const gpu::GpuMaterial& m = a.materials[a.shading[light.triangle].material];
        const glm::vec3 p0(t.v0), p1(t.v1), p2(t.v2);
        const glm::vec3 c = glm::cross(p1 - p0, p2 - p0);
        const float area = 0.5f * glm::length(c);
        if (!(area > 0.0f)) continue;
        const glm::vec3 n = c / (2.0f * area);
        for (uint32_t i = 0; i < areaSamples; ++i) {
            const glm::vec2 u((i + 0.5f) / static_cast<float>(areaSamples), radicalInverse2(i));
            const glm::vec2 b = gpu::sampleTriangleBarycentrics(u);
            const glm::vec3 p = (1.0f - b.x - b.y) * p0 + b.x * p1 + b.y * p2;
            gpu::GpuLight s{};
            s.type = gpu::kLightAreaSample;
            // Lifted off the emitter by the shaders' ray epsilon (scene_access.glsl rayEpsilon), as
            // a traced shadow ray to this point would stop short of it: the emitter and the surface
            // it sits in must not shadow their own sample.
            const float eps = 1.0e-4f * std::max(a.topLevel.header.rayOffsetScale,
                                                 std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
            s.position = p + n * eps;
            s.direction = n;
            // Radiance times the area each sample stands for: intensity in W/sr along the normal.
            // Emissive textures are not applied (the factor only).
            s.intensity = m.emissive * (area / static_cast<float>(areaSamples));
            s.spotScale = (m.flags & gpu::kMaterialDoubleSided) ? 1.0f : 0.0f;
            s.triangle = light.triangle;
            s.selectPdf = 0.0f;
            out.push_back(s);
        }
    }
    return out;
}

}  // namespace vkp
