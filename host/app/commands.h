// The vkphoton subcommands. Each returns a process exit code (util/errors.h).
#pragma once

#include <filesystem>
#include <vector>
#include <string>

#include "lights/light_tree.h"
#include "image/view_transform.h"
#include "photon/deposit_options.h"
#include "photon/photon_path_options.h"
#include "render/frame.h"
#include "animation/frame_sequence.h"
#include "render/integrator_registry.h"
#include "render/aov.h"
#include "guiding/path_guide.h"
#include "scene/environment.h"

namespace vkp {

// Without --light-sampler: the light BVH for scenes with more lights than this, else power.
constexpr size_t kAutoBvhLights = 16;
// The light sampler a render without --light-sampler uses for `scene`.
LightSampler autoLightSampler(const Scene& scene);

// How the scene's textures are held and filtered (every command that loads a scene).
struct TextureOptions {
    uint32_t maxSize = 0;               // --max-texture-size: 0 = no limit
    bool mipmaps = true;                // --no-mipmaps: level 0 only, whatever the samplers' minFilter
};

struct RenderCommandOptions {
    std::filesystem::path scene;
    std::filesystem::path output;       // .exr; empty: out/<scene name>.exr
    std::filesystem::path statsJson;    // empty: none
    FrameSettings frame;
    // The PNG's exposure and view transform: metered (--exposure auto) unless --exposure EV.
    DisplaySettings display{ViewTransform::AgX, 0.0f, true};
    AovSettings aov;                    // --aov: extra EXR channels
    EnvironmentSettings environment;   // --env, --env-strength, --env-rotation
    // --light-sampler, --triangle-sampling, the photon cells' flags. Without --light-sampler the
    // choice is automatic (lightSamplerAuto): bvh for scenes with more than kAutoBvhLights lights,
    // power for fewer (docs/benchmarks.md: bvh 6.5x lower relMSE at equal time on rooms-10x10,
    // the same per sample but slower on the Cornell box's single quad).
    LightSampling lightSampling;
    bool lightSamplerAuto = false;
    double maxMemoryGiB = 0.0;          // --max-memory: 0 = the memory available
    TextureOptions textures;            // --max-texture-size, --no-mipmaps
    int sceneIndex = -1;                // --scene: the glTF scene; -1: the file's default
    std::string variant;                // --variant: a KHR_materials_variants variant by name; "": none
    std::string device;
    bool validate = false;
    bool quiet = false;
    bool noEnergyCompensation = false;  // the glTF spec's plain single-scattering GGX
    std::optional<FrameRange> frames;   // --frames FIRST:LAST: an animation's frames (app/frames_command.h)
    double fps = 24.0;                  // --fps: frame f is at f / fps seconds
    int animation = -1;                 // --animation N: only that glTF animation; -1: all together
    bool photonUpdateFull = false;      // --photon-update full: retrace every photon path per frame
    uint32_t photonBudget = 0;          // --photon-budget: selective paths per map and frame; 0: paths / 8 + pilots
    uint32_t photonGroups = 2310;       // --photon-groups: selective update's Halton-periodic groups
    bool photonDetectPilots = false;    // --photon-detect pilots: the paper's pilots only (no path tracks)
    bool verifyUpdate = false;          // --verify-update: each selective map against a full retrace
    bool sceneRebuildEachFrame = false; // --scene-update rebuild: a new scene and kernels every frame
};

struct PhotonsCommandOptions {
    std::filesystem::path scene;
    std::filesystem::path output;       // .ply; empty: out/<scene name>-photons.ply
    uint32_t photons = kDefaultPhotonPaths;  // --photons: photon paths to emit
    uint32_t maxDeposits = kDefaultMaxDeposits;
    uint32_t seed = 0;
    // --deposit and its flags; every photon unless told otherwise.
    DepositOptions deposit = [] {
        DepositOptions d;
        d.mode = DepositMode::All;
        return d;
    }();
    uint32_t width = 512, height = 512; // the image the importons' camera looks at
    int cameraIndex = -1;
    ViewOverride view;
    EnvironmentSettings environment;   // --env, --env-strength, --env-rotation
    double maxMemoryGiB = 0.0;
    TextureOptions textures;            // --max-texture-size, --no-mipmaps
    int sceneIndex = -1;
    std::string device;
    bool validate = false;
    bool quiet = false;

    void check() const;
};

struct GuideGridCommandOptions {
    std::filesystem::path scene;
    std::filesystem::path output;       // .png; empty: out/<scene name>-guide-X-Y.png
    uint32_t x = 0, y = 0;              // the pixel
    uint32_t width = 512, height = 512;
    int cameraIndex = -1;
    ViewOverride view;
    uint32_t seed = 0;
    GuideSettings guide;
    EnvironmentSettings environment;   // --env, --env-strength, --env-rotation
    double maxMemoryGiB = 0.0;
    TextureOptions textures;            // --max-texture-size, --no-mipmaps
    int sceneIndex = -1;
    std::string device;
    bool validate = false;
    bool quiet = false;

    void check() const;
};

// Limits of the loader for a scene rendered on `context`'s device: its triangle capacity and the
// memory allowed (`maxMemoryGiB`, 0: what /proc/meminfo says is available).
struct GltfLimits;
namespace vk { class Context; }
GltfLimits deviceSceneLimits(const vk::Context& context, double maxMemoryGiB);

// Checks, before any work, what a render of `options` will write: every EXR path in `exrs` (and
// the PNG beside it) and the stats JSON writable, the EXRs named .exr, flags that cannot combine.
// Throws InputError: a bad path or flag must not cost a render.
void checkRenderOutputs(const RenderCommandOptions& options, const std::vector<std::filesystem::path>& exrs);
// Renders with the integrator `config` builds (its settings checked already).
int runRender(const RenderCommandOptions& options, const IntegratorConfig& config);
int runGuideGrid(const GuideGridCommandOptions& options);
int runPhotons(const PhotonsCommandOptions& options);
int runDevices();

}  // namespace vkp
