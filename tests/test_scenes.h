// Scenes built in code for tests with analytic answers.
#pragma once

#include "scene/scene.h"

namespace vkp::test {

// A closed cube [-1,1]^3 whose every face is Lambertian with albedo `albedo` (ior 1, so no
// specular) and emits `emission` from both sides, seen by a camera at its centre. The radiance
// everywhere is emission / (1 - albedo).
Scene furnaceScene(float albedo, float emission);

}  // namespace vkp::test
