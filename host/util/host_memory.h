// The host's free memory, for limits checked before large allocations (scene loading, and photon
// maps on CPU devices such as lavapipe, whose device memory is the host's).
#pragma once

#include <cstdint>

namespace vkp {

// MemAvailable of /proc/meminfo in bytes (0 when it cannot be read).
uint64_t hostMemoryAvailable();

}  // namespace vkp
