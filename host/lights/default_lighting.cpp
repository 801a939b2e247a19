#include "lights/default_lighting.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "bvh/scene_bvh.h"
#include "scene/scene.h"
#include "scene/textured_emission.h"
#include "shared/sampling.glsl"
#include "util/errors.h"

namespace vkp {

double emitterLanding(const Scene& scene, uint32_t rays) {
    // The emissive triangles and their power, as emitterShare weighs them.
    const TexturedEmission emission(scene);
    std::vector<uint32_t> emitters;
    std::vector<double> power;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        if (t.material >= scene.materials.size()) continue;
        const Material& m = scene.materials[t.material];
        if (!glm::any(glm::greaterThan(m.emissive, glm::vec3(0.0f)))) continue;
        const double area = 0.5 * glm::length(glm::cross(glm::dvec3(t.p[1] - t.p[0]), glm::dvec3(t.p[2] - t.p[0])));
        const double p = gpu::luminance(glm::vec3(emission.meanEmission(t))) * area * (m.doubleSided ? 2.0 : 1.0);
        if (!(p > 0.0)) continue;
        emitters.push_back(i);
        power.push_back(p);
    }
    if (emitters.empty() || rays == 0) return 0.0;
    const SceneBvh bvh = buildSceneBvh(scene);
    const gpu::BvhArrays arrays = bvh.arrays();
    const float reach = rayOffsetScale(scene.bounds);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::discrete_distribution<size_t> pick(power.begin(), power.end());
    uint32_t landed = 0;
    for (uint32_t r = 0; r < rays; ++r) {
        const size_t k = pick(rng);
        const Triangle& t = scene.triangles[emitters[k]];
        const glm::vec2 b = gpu::sampleTriangleBarycentrics(glm::vec2(u(rng), u(rng)));
        const glm::vec3 p = t.p[0] * (1.0f - b.x - b.y) + t.p[1] * b.x + t.p[2] * b.y;
        // The front is the side the vertex normals face (the winding's side when they agree or
        // are missing); a double-sided emitter sends half its light out of each side.
        glm::vec3 n = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
        if (!(glm::length(n) > 0.0f)) continue;  // a degenerate triangle: its ray counts as lost
        n = glm::normalize(n);
        if (glm::dot(n, t.n[0] + t.n[1] + t.n[2]) < 0.0f) n = -n;
        if (scene.materials[t.material].doubleSided && u(rng) < 0.5f) n = -n;
        glm::vec3 tangent, bitangent;
        gpu::orthonormalBasis(n, tangent, bitangent);
        const glm::vec3 dir = gpu::toWorld(gpu::sampleCosineHemisphere(glm::vec2(u(rng), u(rng))), tangent, bitangent, n);
        // The shaders' offset (scene_access.glsl rayEpsilon).
        const float eps = 1.0e-4f * std::max({reach, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        landed += closestHit(arrays, p + n * eps, dir, std::numeric_limits<float>::infinity()).hit;
    }
    return double(landed) / double(rays);
}

EmitterShare landedEmitterShare(const Scene& scene) {
    EmitterShare share = emitterShare(scene);
    if (share.emitterPower > 0.0) share.landing = emitterLanding(scene);
    return share;
}

void applyEnvironment(Scene& scene, const EnvironmentSettings& settings, std::string& note,
                      const EnvironmentLimits& limits) {
    settings.check();
    Environment env;
    glm::vec3 constant(0.0f);
    if (settings.value.empty()) {
        if (!scene.lights.empty()) {  // punctual lights light the scene; --exposure auto shows it
            scene.environment = Environment{};
            return;
        }
        if (sceneHasLights(scene)) {
            EmitterShare share = emitterShare(scene);
            // Landing can only lower the share: it is traced only where the emitted power is enough.
            if (share.share() >= kMinEmitterShare) share.landing = emitterLanding(scene);
            if (share.share() >= kMinEmitterShare) {
                scene.environment = Environment{};
                return;
            }
            note = fmt::format("note: the light the emissive surfaces put on the scene is {:.2g} % of what a white sky "
                               "would bring (under {:g} %; {:.0f} % of their light lands on a surface): the scene is lit "
                               "by a uniform white environment of radiance 1 as well (--env to choose another, --env 0 "
                               "for the emitters alone)",
                               100.0 * share.share(), 100.0 * kMinEmitterShare, 100.0 * share.landing);
        } else {
            note = "note: the scene has no lights: it is lit by a uniform white environment of radiance 1 (--env to "
                   "choose another, --env 0 to refuse such scenes)";
        }
        constant = glm::vec3(1.0f);
    } else if (parseEnvironmentConstant(settings.value, constant)) {
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(constant[k]) || constant[k] < 0.0f || constant[k] > 1.0e20f)
                throw InputError(fmt::format("--env {}: a radiance must be finite, >= 0 and at most 1e20", settings.value));
    } else {
        env = loadEnvironmentMap(settings.value, limits);
    }
    if (!env.present) {
        env.radiance = constant;
        env.present = constant.x > 0.0f || constant.y > 0.0f || constant.z > 0.0f;
        env.source = "constant";
    }
    env.radiance *= settings.strength;
    for (float& v : env.rgb) v *= settings.strength;
    env.rotation = glm::radians(settings.rotationDegrees);
    env.importanceSampling = settings.importanceSampling;
    if (settings.strength <= 0.0f) env.present = false;
    if (!env.present && !sceneHasLights(scene))
        throw InputError(fmt::format("{}: no lights: add a KHR_lights_punctual light, give a material an emissiveFactor, "
                                     "or light the scene with --env",
                                     scene.source.string()));
    if (!env.present) env = Environment{};
    scene.environment = std::move(env);
}

}  // namespace vkp
