#include "photon/photon_path_options.h"

#include <CLI/CLI.hpp>

#include "util/check_range.h"

namespace vkp {

void addPhotonPathOptions(CLI::App& group, uint32_t& paths, uint32_t& maxDeposits, const std::string& pathsHelp) {
    group.add_option("--photons", paths, pathsHelp)->capture_default_str();
    group.add_option("--max-deposits", maxDeposits,
                     "Photon slots per path: a path with more deposits keeps a uniform random sample of them, each "
                     "weighted up (unbiased; fewer slots make those paths' photons noisier)")
        ->capture_default_str();
}

void checkPhotonPaths(uint32_t paths, uint32_t maxDeposits) {
    checkRange("--photons", paths, 1u, kMaxPhotonPaths);
    checkRange("--max-deposits", maxDeposits, 1u, kMaxDepositsLimit);
}

}  // namespace vkp
