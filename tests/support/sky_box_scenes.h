// Scenes for the sky-box tests (lights/backdrop.h): a Lambert cube [-1, 1]^3 (glTF node 1) inside
// a box [-10, 10]^3 (node 0), as the loader records them (Scene::drawings), lit by nothing.
#pragma once

#include "scene/scene.h"

namespace vkp::test {

struct SkyBoxOptions {
    bool doubleSided = false;   // the box's material
    bool outward = false;       // its faces turned out (as a closed object's)
    bool openTop = false;       // without its +y face
    bool emissive = false;      // its material glows
    bool cubeOutside = false;   // the cube at x = 20, outside the box
    bool withBox = true;        // false: the cube alone
    bool instanced = false;     // the box drawn as an instance of a mesh (as `view` draws every node)
};

Scene skyBoxScene(const SkyBoxOptions& options = {});

}  // namespace vkp::test
