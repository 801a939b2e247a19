#include "support/sky_box_scenes.h"

#include <utility>

#include "support/test_scenes.h"

namespace vkp::test {

Scene skyBoxScene(const SkyBoxOptions& options) {
    Scene scene;
    Material cube;  // Lambert (KHR_materials_specular 0)
    cube.baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    cube.metallic = 0.0f;
    cube.specular = 0.0f;
    Material box = cube;
    box.baseColor = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
    box.doubleSided = options.doubleSided;
    if (options.emissive) box.emissive = glm::vec3(0.1f);
    scene.materials = {cube, box};
    if (options.withBox) {
        addBox(scene, glm::vec3(-10.0f), glm::vec3(10.0f), options.openTop);
        for (Triangle& t : scene.triangles) {
            t.material = 1;
            if (options.outward) continue;
            std::swap(t.p[1], t.p[2]);  // facing inward
            for (glm::vec3& n : t.n) n = -n;
        }
        if (options.instanced) {
            Mesh mesh;
            mesh.name = "sky box";
            mesh.triangles = std::move(scene.triangles);
            scene.triangles.clear();
            for (const Triangle& t : mesh.triangles)
                for (const glm::vec3& p : t.p) mesh.bounds.grow(p);
            scene.meshes.push_back(std::move(mesh));
            scene.instances.push_back({0, glm::mat4(1.0f), 0});
        } else {
            scene.drawings.push_back({0, 0, 0, static_cast<uint32_t>(scene.triangles.size())});
        }
    }
    const auto first = static_cast<uint32_t>(scene.triangles.size());
    const glm::vec3 at(options.cubeOutside ? 20.0f : 0.0f, 0.0f, 0.0f);
    addBox(scene, at - 1.0f, at + 1.0f);
    for (uint32_t i = first; i < scene.triangles.size(); ++i) scene.triangles[i].material = 0;
    scene.drawings.push_back({1, 1, first, static_cast<uint32_t>(scene.triangles.size()) - first});
    return scene;
}

}  // namespace vkp::test
