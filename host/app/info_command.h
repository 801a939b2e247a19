// `vkphoton info SCENE`: what the glTF file holds and what vkphoton makes of it (geometry,
// materials, lights, cameras, animations, extensions read or ignored, texture memory, bounds),
// as text or JSON. Loads the scene on the CPU only: no Vulkan device is needed.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace vkp {

struct InfoCommandOptions {
    std::filesystem::path scene;
    int sceneIndex = -1;  // --scene
    bool json = false;
};

// The report as JSON; the text form prints the same fields.
nlohmann::json sceneReport(const Scene& scene);
int runInfo(const InfoCommandOptions& options);

}  // namespace vkp
