#include "photon/deposit_options.h"

#include <CLI/CLI.hpp>

#include "util/check_range.h"
#include "util/cli_choice.h"

namespace vkp {

const char* depositModeName(DepositMode mode) {
    switch (mode) {
        case DepositMode::Importance: return "importance";
        case DepositMode::Density: return "density";
        default: return "all";
    }
}

void DepositOptions::check() const {
    // One dispatch (the importon pass is not chunked): 4 M paths take seconds on lavapipe.
    checkRange("--importons", importonPaths, 1u, 1u << 22);
    checkRange("--deposit-epsilon", epsilon, 1.0e-6f, 1.0f);
    checkPositive("--density-accuracy", densityAccuracy);
    checkRange("--density-rounds", densityRounds, 1u, 256u);
}

void DepositOptions::addOptions(CLI::App& group) {
    const std::vector<std::pair<std::string, DepositMode>> modes{
        {"all", DepositMode::All}, {"importance", DepositMode::Importance}, {"density", DepositMode::Density}};
    group.add_option("--deposit", mode,
                     "Which photons the maps keep: all; importance (kept with a probability from the camera's "
                     "importance, Keller & Wald); density (kept until a required density is met, Suykens & Willems)")
        ->transform(oneOf(modes))
        ->option_text(choiceText(modes, mode));
    group.add_option("--importons", importonPaths, "Camera paths of the importon pass (--deposit importance|density)")
        ->capture_default_str();
    group.add_option("--deposit-epsilon", epsilon,
                     "Least acceptance probability of a photon (its power grows at most 1/epsilon times)")
        ->capture_default_str();
    group.add_flag("--deposit-cutoff", cutoff,
                   "Drop photons whose acceptance is below --deposit-epsilon instead of clamping it (biased, fewer photons)");
    group.add_option("--density-accuracy", densityAccuracy,
                     "--deposit density: required photons per square unit per unit of path importance")
        ->capture_default_str();
    group.add_option("--density-rounds", densityRounds,
                     "--deposit density: rounds of tracing, deciding and rebuilding the grid")
        ->capture_default_str();
    group.add_flag("--density-roulette", densityRoulette,
                   "--deposit density: keep photons with Russian-roulette weights instead of handing rejected power "
                   "to the stored neighbours");
}

}  // namespace vkp
