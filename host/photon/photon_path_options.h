// --photons and --max-deposits: how many photon paths a map traces and how many photons each path
// may store. Defaults, checks and help live here once, for every command that traces maps
// (render's photon and sppm integrators, `vkphoton photons`).
#pragma once

#include <cstdint>
#include <string>

namespace CLI { class App; }

namespace vkp {

inline constexpr uint32_t kDefaultPhotonPaths = 200000;
inline constexpr uint32_t kDefaultMaxDeposits = 8;
inline constexpr uint32_t kMaxDepositsLimit = 64;   // slots per path at most (--max-deposits)
inline constexpr uint32_t kMaxPhotonPaths = 1u << 30;  // maps of any size: docs/photon-mapping.md

// Registers --photons (help `pathsHelp`) and --max-deposits, writing into `paths` and `maxDeposits`.
void addPhotonPathOptions(CLI::App& group, uint32_t& paths, uint32_t& maxDeposits, const std::string& pathsHelp);
// Throws InputError naming --photons or --max-deposits when out of range.
void checkPhotonPaths(uint32_t paths, uint32_t maxDeposits);

}  // namespace vkp
