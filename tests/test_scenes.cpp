#include "test_scenes.h"

namespace vkp::test {

Scene furnaceScene(float albedo, float emission) {
    Scene scene;
    Material m;
    m.name = "furnace";
    m.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.ior = 1.0f;
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
