// --deposit and its flags (docs/importance-deposition.md): which traced photons a photon map
// keeps. Shared by the photon integrators and `vkphoton photons`.
#pragma once

#include <cstdint>
#include <string>

namespace CLI { class App; }

namespace vkp {

enum class DepositMode {
    All,         // every photon (Jensen)
    Importance,  // kept with a probability from the camera's importance (Keller & Wald 2000)
    Density,     // kept until a required density is met (Suykens & Willems 2000)
};

const char* depositModeName(DepositMode mode);

struct DepositOptions {
    DepositMode mode = DepositMode::Importance;  // --deposit (docs/benchmarks.md: importance wins)
    uint32_t importonPaths = 1u << 16;  // --importons: camera paths of the importon pass
    float epsilon = 0.01f;              // --deposit-epsilon: floor of the acceptance probability
    bool cutoff = false;                // --deposit-cutoff: drop photons below epsilon (biased)
    float densityAccuracy = 2.0e4f;     // --density-accuracy: required density per unit path importance
    uint32_t densityRounds = 8;         // --density-rounds
    bool densityRoulette = false;       // --density-roulette: weight kept photons instead of redistributing

    // Throws InputError naming the flag of a value out of range.
    void check() const;
    // Registers --deposit, --importons, --deposit-epsilon, --deposit-cutoff, --density-accuracy,
    // --density-rounds and --density-roulette in `group`, writing into this object.
    void addOptions(CLI::App& group);
};

}  // namespace vkp
