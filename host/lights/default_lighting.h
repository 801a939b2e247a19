// The default lighting rule (docs/environment.md): what lights a scene rendered without --env.
// Most glTF files carry no lights because viewers light them with an environment; many that have
// emissive materials use them for details (a helmet's lamps, a radio's buttons, a test cube that
// glows) that light nothing else. Such scenes get the default white sky too; scenes whose
// emitters light them (a lamp in a room) or that have punctual lights keep their own light.
#pragma once

#include <cstdint>
#include <string>

#include "scene/environment.h"

namespace vkp {

// Below this share of the light (EmitterShare::share: what the emitters put on the scene's
// surfaces against what the sky would bring) the emissive surfaces are details: without --env
// the scene gets the default sky too.
constexpr double kMinEmitterShare = 0.01;

// The fraction of the emissive triangles' power that lands on a surface of the scene, by `rays`
// rays cast on the host (the shaders' traversal, bvh/scene_bvh.h): each from a point of an
// emissive triangle chosen by power, uniform over its area, cosine-distributed about its front
// (either side if double-sided). 0 for a closed emitter seen from outside that faces out (all of
// its light leaves the scene), 1 for a lamp inside a closed room. Deterministic.
double emitterLanding(const Scene& scene, uint32_t rays = 4096);
// emitterShare with the landing fraction estimated.
EmitterShare landedEmitterShare(const Scene& scene);

// Sets scene.environment from the settings. Without --env: a scene with punctual lights gets
// none; one whose emissive triangles give at least kMinEmitterShare of the light (landed) gets
// none; any other scene a uniform environment of radiance 1 (times --env-strength), and `note`
// says so. `--env 0` (or any zero constant) means no environment: a scene without lights is then
// refused (InputError) as before environments existed. Where the environment is the scene's
// only light (no punctual light, emitters that are details), its sky boxes become backdrops
// (Scene::backdropNodes, lights/backdrop.h), and `note` names them.
void applyEnvironment(Scene& scene, const EnvironmentSettings& settings, std::string& note,
                      const EnvironmentLimits& limits = {});

}  // namespace vkp
