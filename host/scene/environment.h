// The environment light (--env): a constant radiance or an equirectangular .hdr/.exr map, and the
// default white sky of scenes without lights. docs/environment.md describes the mapping and the
// flags; shaders/shared/environment.glsl evaluates and samples it on the GPU.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace vkp {

struct Scene;

// What the command line asked for.
struct EnvironmentSettings {
    std::string value;            // --env: "" (default), "V" or "R,G,B" (a constant), or a file
    float strength = 1.0f;        // --env-strength: multiplies the radiance
    float rotationDegrees = 0.0f; // --env-rotation: about +Y, right-handed
    bool importanceSampling = true; // --env-sampling: map (true) or uniform (the benchmark's baseline)
    void check() const;           // InputError for a negative or non-finite strength or rotation
};

// Limits on a map, checked from its header before its pixels are decoded.
struct EnvironmentLimits {
    uint32_t maxDimension = 16384;            // width and height
    uint64_t maxPixels = uint64_t(1) << 25;   // 8192 x 4096
    uint64_t maxMemoryBytes = UINT64_MAX;     // host memory the map may take while loading
};

// Host bytes per map pixel at the peak of loading: the decoded RGB (12), our RGB copy (12) and
// the sampling distribution (4), with a margin; the GPU copy is 16 per pixel.
constexpr uint64_t kEnvironmentBytesPerPixel = 48;

// The environment as the renderer uses it: present or not, a constant or a map, radiance with
// the strength applied.
struct Environment {
    bool present = false;
    glm::vec3 radiance{0.0f};     // the constant (width 0)
    uint32_t width = 0;           // map size; 0 for a constant
    uint32_t height = 0;
    std::vector<float> rgb;       // width * height * 3, row-major, top row (the zenith) first
    float rotation = 0.0f;        // radians about +Y
    bool importanceSampling = true; // false: sample a map uniformly over the sphere
    std::string source;           // "constant" or the file, for messages and the EXR header
};

// "V" or "R,G,B" as a radiance; false when `text` is not numbers (then it is a file name).
bool parseEnvironmentConstant(const std::string& text, glm::vec3& radiance);

// Reads an equirectangular .hdr (Radiance RGBE) or .exr map. InputError (exit 2) for a missing,
// unreadable, corrupt, too small (under 2x2), too large, or non-finite/negative map.
Environment loadEnvironmentMap(const std::filesystem::path& path, const EnvironmentLimits& limits = {});

// True when the scene has a punctual light or an emissive triangle.
bool sceneHasLights(const Scene& scene);

// The default lighting rule's measure (lights/default_lighting.h): the power the scene's emissive
// triangles emit (pi x luminance of the mean emitted radiance x area, twice if double-sided, as
// the light sampler weighs them; emissive textures averaged over the texels each triangle reads),
// the fraction of it that lands on a surface of the scene (`landing`; 1 here, estimated by
// lights/default_lighting.h's landedEmitterShare), against the power the default white sky of
// radiance 1 would send into the scene's bounding sphere (4 pi^2 r^2: its weight as a light).
// share = landed / (landed + sky).
struct EmitterShare {
    double emitterPower = 0.0;
    double landing = 1.0;
    double skyPower = 0.0;
    double landedPower() const { return emitterPower * landing; }
    double share() const { return landedPower() > 0.0 ? landedPower() / (landedPower() + skyPower) : 0.0; }
};
// The emitted power and the sky's (landing 1).
EmitterShare emitterShare(const Scene& scene);

}  // namespace vkp
