// How next-event estimation chooses a light and samples it: --light-sampler, --triangle-sampling
// and the photon light cells' flags (lights/light_cells.h), with their defaults, checks and help.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CLI { class App; }

namespace vkp {

enum class LightSampler { Power, Bvh, Photon };
// How an emissive triangle is sampled once chosen: by the solid angle it subtends (area where that
// is tiny or nearly a hemisphere), or by area only (the behaviour before solid-angle sampling).
enum class TriangleSampling { SolidAngle, Area };

struct LightSampling {
    LightSampler sampler = LightSampler::Power;
    TriangleSampling triangles = TriangleSampling::SolidAngle;
    uint32_t cellPhotons = 200000;  // --light-photons: photon paths whose primary hits fill the cells
    uint32_t cellK = 8;             // --light-cell-k: candidates per cell at most
    float cellFloor = 0.25f;        // --light-cell-floor: probability of the light BVH's choice
    float cellSize = 0.0f;          // --light-cell-size (m); 0: the scene's largest extent / 40

    // Registers the options in `command`, writing into this object.
    void addOptions(CLI::App& command);
    // Throws InputError naming the flag of a value out of range, or a light-cell option given
    // (`command` parsed) without --light-sampler photon, which alone reads them.
    void check() const;
    void checkGiven(const CLI::App& command) const;
};

// The --light-sampler names: power, bvh, photon.
const std::vector<std::pair<std::string, LightSampler>>& lightSamplerChoices();
std::string_view lightSamplerName(LightSampler sampler);
// Throws InputError naming --light-sampler for an unknown name.
LightSampler parseLightSampler(std::string_view name);

}  // namespace vkp
