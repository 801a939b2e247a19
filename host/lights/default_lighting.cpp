#include "lights/default_lighting.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bvh/scene_bvh.h"
#include "lights/backdrop.h"
#include "lights/surface_rays.h"
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
    std::discrete_distribution<size_t> pick(power.begin(), power.end());
    uint32_t landed = 0;
    for (uint32_t r = 0; r < rays; ++r) {
        const size_t k = pick(rng);
        const Triangle& t = scene.triangles[emitters[k]];
        const SurfaceRay ray = frontRay(t, scene.materials[t.material].doubleSided, reach, rng);
        if (!ray.valid) continue;  // a degenerate triangle: its ray counts as lost
        landed += closestHit(arrays, ray.origin, ray.direction, std::numeric_limits<float>::infinity()).hit;
    }
    return double(landed) / double(rays);
}

namespace {

// emitterShare, with the landing fraction traced only where the emitted power alone reaches
// kMinEmitterShare (landing can only lower the share).
EmitterShare weighedEmitterShare(const Scene& scene) {
    EmitterShare share = emitterShare(scene);
    if (share.share() >= kMinEmitterShare) share.landing = emitterLanding(scene);
    return share;
}

// Whether the environment is what lights the scene: no punctual light, and emitters (if any)
// that are details by the rule above.
bool litByEnvironmentAlone(const Scene& scene) {
    if (!scene.lights.empty()) return false;
    return !sceneHasLights(scene) || weighedEmitterShare(scene).share() < kMinEmitterShare;
}

// Sky boxes around an environment-lit scene become backdrops (backdrop.h); the note names them.
// `litByEnvironment`: already known that the environment is the light (the default rule chose it).
void findSkyBoxes(Scene& scene, std::string& note, bool litByEnvironment) {
    scene.backdropNodes.clear();
    if (!scene.environment.present || !(litByEnvironment || litByEnvironmentAlone(scene))) return;
    scene.backdropNodes = findBackdrops(scene);
    if (scene.backdropNodes.empty()) return;
    if (!note.empty()) note += "\n";
    note += fmt::format("note: nodes[{}] encloses the scene, facing inward, and hides the environment from it: a sky "
                        "box, seen by camera rays only, so the environment lights the scene through it",
                        fmt::join(scene.backdropNodes, "], nodes["));
}

}  // namespace

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
    const bool defaultSky = settings.value.empty();  // reached only where the rule adds the sky
    if (defaultSky) {
        if (!scene.lights.empty()) {  // punctual lights light the scene; --exposure auto shows it
            scene.environment = Environment{};
            return;
        }
        if (sceneHasLights(scene)) {
            const EmitterShare share = weighedEmitterShare(scene);
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
    findSkyBoxes(scene, note, defaultSky);
}

}  // namespace vkp
