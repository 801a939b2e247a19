// Silent terminations (shaders/shared/kernels/terminations.glsl): work a bound cut short —
// lavapipe's 65535-iteration loop budget, a full BVH traversal stack, a loop's own iteration
// bound — counted on the GPU per kind and per kind of item, in the context's counter buffer that
// every kernel shares. The driver clears them before a render and reports them after it: named
// stats values (terminations.<kind>.<items>, 0 included) and one warning per kind that happened.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "shared/kernels/terminations.glsl"

namespace vkp {

namespace vk {
class Context;
}
class Stats;

struct TerminationCounts {
    std::array<uint32_t, gpu::kTerminationCounterCount> counts{};

    uint32_t at(uint32_t kind, uint32_t subject) const { return counts[gpu::terminationSlot(kind, subject)]; }
    uint64_t total() const;
};

// Names as they appear in the stats ("stackOverflow", "samples").
std::string terminationKindName(uint32_t kind);
std::string terminationSubjectName(uint32_t subject);

// Zeroes the context's counters (submits and waits).
void clearTerminations(vk::Context& context);
// Read-back of the context's counters (after the last submission).
TerminationCounts readTerminations(const vk::Context& context);
// Sets terminations.<kind>.<subject> for every kind and subject, and a warning per kind that cut
// anything short, naming how many items of which kinds.
void reportTerminations(const TerminationCounts& counts, Stats& stats);

}  // namespace vkp
