// Scenes built in code for tests with analytic answers.
#pragma once

#include <random>
#include <string>

#include "scene/scene.h"

namespace vkp::test {

// A closed cube [-1,1]^3 whose every face is Lambertian with albedo `albedo` (ior 1, so no
// specular) and emits `emission` from both sides, seen by a camera at its centre. The radiance
// everywhere is emission / (1 - albedo).
Scene furnaceScene(float albedo, float emission);
// The same material inside a sphere of radius 1 (`rings` x `segments` facets with smooth normals,
// seen from the inside: the material is double-sided): a curved furnace without edges, radiance
// emission / (1 - albedo) for a true sphere (the facets' smooth normals keep a little less).
Scene sphereFurnaceScene(float albedo, float emission, int rings = 16, int segments = 24);

// A scene shipped in scenes/, by name without the extension ("cornell-box").
Scene shippedScene(const std::string& name);

}  // namespace vkp::test

namespace vkp::test {

// Builders for small shadow scenes (tests/render/shadow_volume_test.cpp). Materials: index 0 is a grey
// Lambertian added by shadowTestScene().
Scene shadowTestScene();
// Axis-aligned box [lo, hi] as 12 triangles with shared corners, outward normals (a closed,
// consistently oriented 2-manifold). With `openTop` the +y face is left out (an open mesh).
void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, bool openTop = false);
// A quad (two triangles) with corners a, b, c, d counter-clockwise seen from its front.
void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);
void addPointLight(Scene& scene, glm::vec3 position, glm::vec3 intensity);
// A directional light from above (0.4, -1, -0.3) and a spot light at (-1, 3, 1) aimed down
// (cones 0.3 / 0.6 rad): the non-point lights of the raster tests.
void addSunAndSpot(Scene& scene, glm::vec3 sunIntensity, glm::vec3 spotIntensity);
Camera lookAt(glm::vec3 eye, glm::vec3 target, float yfov = 0.9f);

}  // namespace vkp::test

namespace vkp::test {

// Instancing (tests/scene/instancing_render_test.cpp, bvh_gpu_test.cpp): a UV sphere of radius r with smooth
// normals and a unit box, as object-space meshes of `material`.
Mesh sphereMesh(float r, uint32_t material, int rings = 8, int segments = 12);
Mesh boxMesh(uint32_t material);
// A random transform within `bounds`: rotation, non-uniform scale around `size`, a quarter mirrored.
glm::mat4 randomTransform(std::mt19937& rng, const Bounds& bounds, float size);
// The Cornell box with `count` instances (alternately the sphere and the box, grey, non-emissive)
// at random transforms in the middle of the room.
Scene instancedCornell(uint32_t count, uint32_t seed);
// A glass sphere (radius `radius`, ior 1.5, an instance of a mesh: it moves in place) centred at
// `centre` over a grey floor [-2, 2] x [-2, 2] (y = 0) under a point light at (0, 1.5, 0), which
// focuses a caustic on the floor under it; the bounds are the floor's and the light's, whatever
// the sphere's place (as an animation's frames keep the still bounds).
Scene glassSphereOverFloor(glm::vec3 centre, float radius = 0.25f);

}  // namespace vkp::test
