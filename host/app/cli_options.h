// Command-line pieces every vkphoton command that loads a scene shares: one function per concept
// (the frame, the view, the environment, the device and textures, the glTF scene), each owning
// its options' names, help and defaults, and checks of what was given.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "app/commands.h"

namespace CLI { class App; }

namespace vkp {

// --spp, --width, --height, --seed, --max-depth, --time-limit, --camera, --no-nee, --direct,
// --area-light-samples: the frame a render samples.
void addFrameOptions(CLI::App& cmd, FrameSettings& frame, bool& bsdfOnly);
// "X,Y,Z": three comma-separated numbers.
std::optional<glm::vec3> parsePoint(const std::string& text);
// --look-from, --look-at, --fov, for every command that resolves a camera.
void addViewOptions(CLI::App& cmd, ViewOverride& view);
// --env, --env-strength, --env-rotation, --env-sampling (scene/environment.h, docs/environment.md).
void addEnvironmentOptions(CLI::App& cmd, EnvironmentSettings& env);
// --device, --validate, --max-memory, --max-texture-size, --mipmaps/--no-mipmaps.
void addDeviceOptions(CLI::App& cmd, std::string& device, bool& validate, double& maxMemoryGiB,
                      TextureOptions& textures);
// --scene N: which of the file's glTF scenes to load.
void addSceneIndexOption(CLI::App& cmd, int& sceneIndex);
// An option given an empty value (`--q ''`) is a mistake: CLI11 would leave the default.
void refuseEmptyValues(CLI::App& app);
// A path option that was given must not be empty: `-o ''` is a mistake, not "the default".
void requireNonEmpty(const CLI::App& cmd, const char* name, const std::filesystem::path& value);
// Throws InputError naming the first of `options` given on `cmd`: they are read only with
// `needed` (e.g. "--frames"), which was not given.
void refuseWithout(const CLI::App& cmd, std::initializer_list<const char*> options, const char* needed);

}  // namespace vkp
