#include "app/cli_options.h"

#include <exception>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "util/cli_choice.h"
#include "util/errors.h"

namespace vkp {

void addFrameOptions(CLI::App& cmd, FrameSettings& frame, bool& bsdfOnly) {
    cmd.add_option("--spp", frame.samplesPerPixel, "Samples per pixel")->capture_default_str();
    cmd.add_option("--width", frame.width, "Image width in pixels")->capture_default_str();
    cmd.add_option("--height", frame.height, "Image height in pixels")->capture_default_str();
    cmd.add_option("--seed", frame.seed, "Random seed: the same seed gives the same image on the same device")
        ->capture_default_str();
    cmd.add_option("--max-depth", frame.maxDepth, "Maximum path length (bounces)")->capture_default_str();
    cmd.add_option("--time-limit", frame.timeLimitSeconds,
                   "Stop after this many seconds (0: no limit); the image is marked partial");
    cmd.add_option("--camera", frame.cameraIndex,
                   "Index of the scene camera to render from [default: first, or a framing of the scene]")
        ->check(CLI::NonNegativeNumber);
    cmd.add_flag("--no-nee", bsdfOnly, "Disable next-event estimation (BSDF sampling only; a reference)");
    const std::vector<std::pair<std::string, DirectLight>> direct{{"traced", DirectLight::Traced},
                                                                  {"raster", DirectLight::Raster}};
    cmd.add_option("--direct", frame.direct,
                   "Direct light at the first vertex: traced (next-event estimation, the reference) or raster "
                   "(stencil shadow volumes)")
        ->transform(oneOf(direct))
        ->option_text(choiceText(direct, frame.direct));
    cmd.add_option("--area-light-samples", frame.areaLightSamples,
                   "--direct raster: point samples per emissive triangle (0: emissive triangles stay traced)")
        ->capture_default_str();
}

// Finite or not: ViewOverride::check names the flag.
std::optional<glm::vec3> parsePoint(const std::string& text) {
    glm::vec3 p;
    size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const size_t end = k < 2 ? text.find(',', start) : text.size();
        if (end == std::string::npos) return std::nullopt;
        const std::string part = text.substr(start, end - start);
        size_t used = 0;
        try {
            p[k] = std::stof(part, &used);
        } catch (const std::exception&) {
            return std::nullopt;
        }
        if (used != part.size()) return std::nullopt;
        start = end + 1;
    }
    return p;
}

// --look-from, --look-at, --fov, for every command that resolves a camera.
void addViewOptions(CLI::App& cmd, ViewOverride& view) {
    const CLI::Validator point(
        [](std::string& input) -> std::string {
            return parsePoint(input) ? "" : "'" + input + "' is not three numbers X,Y,Z";
        },
        "");
    cmd.add_option_function<std::string>(
           "--look-from", [&view](const std::string& text) { view.lookFrom = parsePoint(text); },
           "Camera position X,Y,Z (world units): overrides the camera's; it looks at --look-at, else at the scene's centre")
        ->check(point)
        ->type_name("X,Y,Z");
    cmd.add_option_function<std::string>(
           "--look-at", [&view](const std::string& text) { view.lookAt = parsePoint(text); },
           "Point X,Y,Z the camera looks at (world units), from --look-from or where the camera stands")
        ->check(point)
        ->type_name("X,Y,Z");
    cmd.add_option_function<float>("--fov", [&view](float degrees) { view.fovDegrees = degrees; },
                                   "Vertical field of view in degrees, 0 < DEG < 180 [default: the camera's; 40 for the "
                                   "default framing]")
        ->type_name("DEG");
}

// --env, --env-strength, --env-rotation (scene/environment.h, docs/environment.md).
void addEnvironmentOptions(CLI::App& cmd, EnvironmentSettings& env) {
    cmd.add_option("--env", env.value,
                   "Environment light: an equirectangular .hdr or .exr map, or a radiance V or R,G,B (0: none) "
                   "[default: none, or radiance 1 for a scene without lights]")
        ->type_name("FILE|VALUE");
    cmd.add_option("--env-strength", env.strength, "Multiplies the environment's radiance")->capture_default_str();
    cmd.add_option("--env-rotation", env.rotationDegrees,
                   "Turns the environment map about +Y by DEG (right-handed: at 90 what faced +X faces -Z)")
        ->type_name("DEG")
        ->capture_default_str();
    const std::vector<std::pair<std::string, bool>> sampling{{"map", true}, {"uniform", false}};
    cmd.add_option("--env-sampling", env.importanceSampling,
                   "Next-event directions towards a map: map (its luminance x sin(theta) distribution) or uniform "
                   "(over the sphere; a baseline)")
        ->transform(oneOf(sampling))
        ->option_text(choiceText(sampling, env.importanceSampling));
}

void addDeviceOptions(CLI::App& cmd, std::string& device, bool& validate, double& maxMemoryGiB,
                      TextureOptions& textures) {
    cmd.add_option("--device", device, "Vulkan device: index or name substring (see `vkphoton devices`)");
    cmd.add_flag("--validate", validate, "Enable the Khronos validation layer; any message is an error");
    cmd.add_option("--max-memory", maxMemoryGiB,
                   "Memory the scene may take, in GiB, estimated from its triangle count before loading "
                   "(0: the memory available)")
        ->capture_default_str();
    cmd.add_option("--max-texture-size", textures.maxSize,
                   "Largest texture width/height in texels: larger textures are halved (box filter) until they "
                   "fit, with a warning (0: no limit; textures the device cannot hold are always downscaled)")
        ->check(CLI::Range(0u, 1u << 16))
        ->capture_default_str();
    cmd.add_flag("--mipmaps,!--no-mipmaps", textures.mipmaps,
                 "Filter minified textures over what each camera sample covers (mipmaps chosen by ray cones, "
                 "as the samplers' minFilter says; the default), or read full-resolution texels only "
                 "(--no-mipmaps: noisier at few samples, the supersampled reference at many)");
}

// --scene N: which of the file's glTF scenes to load.
void addSceneIndexOption(CLI::App& cmd, int& sceneIndex) {
    cmd.add_option("--scene", sceneIndex, "Index of the glTF scene to load [default: the file's `scene`, else 0]")
        ->check(CLI::NonNegativeNumber);
}

// An option given an empty value (`--q ''`) is a mistake: CLI11 would leave the default.
void refuseEmptyValues(CLI::App& app) {
    for (const CLI::Option* option : app.get_options())
        for (const std::string& value : option->results())
            if (value.empty() && option->get_expected_min() > 0)
                throw InputError(fmt::format("{} '': the value is empty", option->get_name()));
    for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) refuseEmptyValues(*sub);
}

// A path option that was given must not be empty: `-o ''` is a mistake, not "the default".
void requireNonEmpty(const CLI::App& cmd, const char* name, const std::filesystem::path& value) {
    if (cmd.get_option(name)->count() > 0 && value.empty())
        throw InputError(fmt::format("{} '': the path is empty", name));
}

void refuseWithout(const CLI::App& cmd, std::initializer_list<const char*> options, const char* needed) {
    for (const char* name : options)
        if (cmd.get_option(name)->count() > 0)
            throw InputError(fmt::format("{} is read only with {}, which was not given", name, needed));
}

}  // namespace vkp
