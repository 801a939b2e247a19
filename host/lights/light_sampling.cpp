#include "lights/light_sampling.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "shared/light_selection.glsl"
#include "util/check_range.h"
#include "util/cli_choice.h"
#include "util/errors.h"

namespace vkp {
namespace {

const std::vector<std::pair<std::string, TriangleSampling>>& triangleSamplingChoices() {
    static const std::vector<std::pair<std::string, TriangleSampling>> choices{
        {"solid-angle", TriangleSampling::SolidAngle}, {"area", TriangleSampling::Area}};
    return choices;
}

// The options only --light-sampler photon reads.
constexpr const char* kCellOptions[] = {"--light-photons", "--light-cell-k", "--light-cell-floor", "--light-cell-size"};

}  // namespace

const std::vector<std::pair<std::string, LightSampler>>& lightSamplerChoices() {
    static const std::vector<std::pair<std::string, LightSampler>> choices{
        {"power", LightSampler::Power}, {"bvh", LightSampler::Bvh}, {"photon", LightSampler::Photon}};
    return choices;
}

std::string_view lightSamplerName(LightSampler sampler) {
    for (const auto& [name, value] : lightSamplerChoices())
        if (value == sampler) return name;
    return "?";
}

LightSampler parseLightSampler(std::string_view name) {
    for (const auto& [choice, value] : lightSamplerChoices())
        if (choice == name) return value;
    throw InputError(fmt::format("--light-sampler {}: expected power, bvh or photon", name));
}

void LightSampling::addOptions(CLI::App& command) {
    command.add_option("--light-sampler", sampler,
                       "How next-event estimation chooses a light: power (in proportion to emitted power) or bvh (a "
                       "light BVH by importance at the shading point, Conty Estevez & Kulla 2018) or photon (per "
                       "cell, the lights whose primary photons arrive there, Keller & Wald 2000, mixed with bvh); "
                       "default: bvh for scenes with more than 16 lights (emissive triangles count one each), else "
                       "power")
        ->transform(oneOf(lightSamplerChoices()))
        ->option_text("power|bvh|photon [auto]");
    command.add_option("--triangle-sampling", triangles,
                       "How next-event estimation samples an emissive triangle: solid-angle (uniform over the solid "
                       "angle it subtends, Arvo 1995; by area where that is tiny) or area (by area only)")
        ->transform(oneOf(triangleSamplingChoices()))
        ->option_text(choiceText(triangleSamplingChoices(), triangles));
    command.add_option("--light-photons", cellPhotons,
                       "--light-sampler photon: photon paths whose primary hits fill the light cells")
        ->capture_default_str();
    command.add_option("--light-cell-k", cellK, "--light-sampler photon: candidate lights per cell at most")
        ->capture_default_str();
    command.add_option("--light-cell-floor", cellFloor,
                       "--light-sampler photon: probability of choosing by the light BVH instead of the cell (> 0 "
                       "keeps the estimate unbiased)")
        ->capture_default_str();
    command.add_option("--light-cell-size", cellSize,
                       "--light-sampler photon: cell size in metres (0: the scene's largest extent / 40)")
        ->capture_default_str();
}

void LightSampling::check() const {
    checkRange("--light-photons", cellPhotons, 1u, 100000000u);
    checkRange("--light-cell-k", cellK, 1u, gpu::kLightCellMaxK);
    checkRange("--light-cell-floor", cellFloor, 0.001f, 1.0f);
    checkRange("--light-cell-size", cellSize, 0.0f, 1.0e6f);
}

void LightSampling::checkGiven(const CLI::App& command) const {
    if (sampler == LightSampler::Photon) return;
    for (const char* name : kCellOptions)
        if (command.get_option(name)->count() > 0)
            throw InputError(fmt::format("{} is an option of --light-sampler photon: --light-sampler {} does not read it",
                                         name, lightSamplerName(sampler)));
}

}  // namespace vkp
