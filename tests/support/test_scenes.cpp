#include "support/test_scenes.h"

#include <array>
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/gltf_loader.h"

namespace vkp::test {

Scene furnaceScene(float albedo, float emission) {
    Scene scene;
    Material m;
    m.name = "furnace";
    m.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.ior = 1.0f;
    m.specular = 0.0f;  // KHR_materials_specular 0: exactly Lambert
    m.emissive = glm::vec3(emission);
    m.doubleSided = true;
    scene.materials.push_back(m);

    // Each face as two triangles; normals point inwards.
    const glm::vec3 c[8] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    const int faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7}, {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
    for (const auto& f : faces) {
        const glm::vec3 n = -glm::normalize(glm::cross(c[f[1]] - c[f[0]], c[f[2]] - c[f[0]]));
        for (int k = 0; k < 2; ++k) {
            Triangle t;
            const int idx[3] = {f[0], f[1 + k], f[2 + k]};
            for (int v = 0; v < 3; ++v) {
                t.p[v] = c[idx[v]];
                t.n[v] = n;
                t.uv[v] = glm::vec2(0.0f);
            }
            t.material = 0;
            scene.triangles.push_back(t);
            for (const auto& p : t.p) scene.bounds.grow(p);
        }
    }
    Camera camera;
    camera.position = glm::vec3(0.0f);
    camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera.yfov = 1.2f;
    scene.cameras.push_back(camera);
    return scene;
}

}  // namespace vkp::test

namespace vkp::test {
namespace {

void addTriangle(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    Triangle t;
    t.p[0] = a;
    t.p[1] = b;
    t.p[2] = c;
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (int v = 0; v < 3; ++v) {
        t.n[v] = n;
        t.uv[v] = glm::vec2(0.0f);
        scene.bounds.grow(t.p[v]);
    }
    t.material = 0;
    scene.triangles.push_back(t);
}

}  // namespace

Scene shadowTestScene() {
    Scene scene;
    Material m;
    m.name = "grey";
    m.baseColor = glm::vec4(0.7f, 0.7f, 0.7f, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.ior = 1.0f;
    m.specular = 0.0f;  // KHR_materials_specular 0: exactly Lambert
    // Both faces seen by the camera (open boxes are looked into): single-sided materials' back
    // faces are culled for camera rays (docs/scene-format.md "Back faces").
    m.doubleSided = true;
    scene.materials.push_back(m);
    return scene;
}

void addQuad(Scene& scene, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    addTriangle(scene, a, b, c);
    addTriangle(scene, a, c, d);
}

void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, bool openTop) {
    const glm::vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                            {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    // Counter-clockwise seen from outside.
    addQuad(scene, c[0], c[3], c[2], c[1]);  // -z
    addQuad(scene, c[4], c[5], c[6], c[7]);  // +z
    addQuad(scene, c[0], c[4], c[7], c[3]);  // -x
    addQuad(scene, c[1], c[2], c[6], c[5]);  // +x
    addQuad(scene, c[0], c[1], c[5], c[4]);  // -y
    if (!openTop) addQuad(scene, c[3], c[7], c[6], c[2]);  // +y
}

void addPointLight(Scene& scene, glm::vec3 position, glm::vec3 intensity) {
    PunctualLight l;
    l.name = "point";
    l.type = LightType::Point;
    l.position = position;
    l.intensity = intensity;
    scene.lights.push_back(l);
}

void addSunAndSpot(Scene& scene, glm::vec3 sunIntensity, glm::vec3 spotIntensity) {
    PunctualLight sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    sun.intensity = sunIntensity;
    scene.lights.push_back(sun);
    PunctualLight spot;
    spot.type = LightType::Spot;
    spot.position = {-1.0f, 3.0f, 1.0f};
    spot.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.4f));
    spot.innerConeAngle = 0.3f;
    spot.outerConeAngle = 0.6f;
    spot.intensity = spotIntensity;
    scene.lights.push_back(spot);
}

Scene shippedScene(const std::string& name) {
    return loadGltf(std::string(VKPHOTON_SCENES) + "/" + name + ".gltf");
}

Camera lookAt(glm::vec3 eye, glm::vec3 target, float yfov) {
    Camera c;
    c.position = eye;
    c.forward = glm::normalize(target - eye);
    const glm::vec3 right = glm::normalize(glm::cross(c.forward, glm::vec3(0.0f, 1.0f, 0.0f)));
    c.up = glm::cross(right, c.forward);
    c.yfov = yfov;
    return c;
}

}  // namespace vkp::test

namespace vkp::test {

// A UV sphere of radius r at the origin with smooth (vertex) normals: interpolated shading
// normals go through the instance transform too.
Scene sphereFurnaceScene(float albedo, float emission, int rings, int segments) {
    Scene scene = furnaceScene(albedo, emission);
    const Mesh sphere = sphereMesh(1.0f, 0, rings, segments);
    scene.triangles = sphere.triangles;
    scene.bounds = sphere.bounds;
    return scene;
}

Mesh sphereMesh(float r, uint32_t material, int rings, int segments) {
    Mesh mesh;
    mesh.name = "sphere";
    const auto point = [&](int i, int j) {
        const float theta = float(i) / rings * 3.14159265f, phi = float(j) / segments * 6.28318531f;
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const glm::vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1), d = point(i, j + 1);
            for (const auto& tri : {std::array<glm::vec3, 3>{a, c, b}, std::array<glm::vec3, 3>{a, d, c}}) {
                Triangle t;
                for (int k = 0; k < 3; ++k) {
                    t.p[k] = r * tri[k];
                    t.n[k] = tri[k];
                    t.uv[k] = glm::vec2(0.0f);  // Triangle leaves them uninitialised
                }
                if (glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0])) < 1e-8f) continue;  // at the poles
                t.material = material;
                mesh.triangles.push_back(t);
                for (const glm::vec3& p : t.p) mesh.bounds.grow(p);
            }
        }
    return mesh;
}

Mesh boxMesh(uint32_t material) {
    Scene tmp;
    addBox(tmp, glm::vec3(-0.5f), glm::vec3(0.5f));
    Mesh mesh;
    mesh.name = "box";
    for (Triangle t : tmp.triangles) {
        t.material = material;
        mesh.triangles.push_back(t);
        for (const glm::vec3& p : t.p) mesh.bounds.grow(p);
    }
    return mesh;
}

// Random rigid-ish transforms (rotation, non-uniform scale, some mirrored) inside `bounds`.
glm::mat4 randomTransform(std::mt19937& rng, const Bounds& bounds, float size) {
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const glm::vec3 at = bounds.min + glm::vec3(u(rng), u(rng), u(rng)) * bounds.extent();
    glm::mat4 m = glm::translate(glm::mat4(1.0f), at);
    m = glm::rotate(m, 6.2831853f * u(rng), glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f)));
    glm::vec3 scale = size * glm::vec3(0.5f + u(rng), 0.5f + u(rng), 0.5f + u(rng));
    if (u(rng) < 0.25f) scale.x = -scale.x;  // mirrored
    return glm::scale(m, scale);
}

// The Cornell box with a sphere and a box mesh placed `count` times (plus their static part).
Scene glassSphereOverFloor(glm::vec3 centre, float radius) {
    Scene scene = shadowTestScene();
    addQuad(scene, {-2, 0, -2}, {-2, 0, 2}, {2, 0, 2}, {2, 0, -2});  // floor, facing up
    addPointLight(scene, {0.0f, 1.5f, 0.0f}, glm::vec3(20.0f));
    scene.bounds.grow(glm::vec3(0.0f, 1.5f, 0.0f));
    Material glass;
    glass.name = "glass";
    glass.metallic = 0.0f;
    glass.roughness = 0.0f;
    glass.transmission = 1.0f;
    glass.ior = 1.5f;
    glass.thickness = 2.0f * radius;
    scene.materials.push_back(glass);
    scene.meshes.push_back(sphereMesh(radius, static_cast<uint32_t>(scene.materials.size() - 1), 16, 24));
    scene.instances.push_back({0, glm::translate(glm::mat4(1.0f), centre), -1});
    return scene;
}

Scene instancedCornell(uint32_t count, uint32_t seed) {
    Scene scene = shippedScene("cornell-box");
    Material grey;
    grey.name = "instanced grey";
    grey.baseColor = glm::vec4(0.7f, 0.6f, 0.5f, 1.0f);
    grey.metallic = 0.0f;
    grey.roughness = 0.6f;
    scene.materials.push_back(grey);
    const auto material = static_cast<uint32_t>(scene.materials.size() - 1);
    scene.meshes.push_back(sphereMesh(1.0f, material));
    scene.meshes.push_back(boxMesh(material));
    Bounds inner;  // the middle of the room
    inner.min = scene.bounds.center() - 0.3f * scene.bounds.extent();
    inner.max = scene.bounds.center() + 0.3f * scene.bounds.extent();
    std::mt19937 rng(seed);
    const float size = 0.06f * glm::length(scene.bounds.extent());
    for (uint32_t i = 0; i < count; ++i)
        scene.instances.push_back({i % 2, randomTransform(rng, inner, size), -1});
    return scene;
}

}  // namespace vkp::test
