// GLSL side of the silent-termination counters (shared/kernels/terminations.glsl): the counter
// buffer every kernel that can cut work short declares, and the per-item flush. A kernel calls
// countTerminations(subject) when an item (a sample, a photon path, a gather) ends: each kind
// noted since the last call adds one to its counter and the record is cleared.
#ifndef VKP_TERMINATION_COUNTERS_GLSL
#define VKP_TERMINATION_COUNTERS_GLSL
#include "shared/termination_record.glsl"

layout(std430, set = kTerminationSet, binding = kTerminationBinding) buffer TerminationCounters {
    uint terminationCounters[];
};

// No loop: lavapipe's loop budget may be spent by the time this runs.
void countTerminations(uint subject) {
    if (gTerminations == 0u) return;
    if ((gTerminations & (1u << kTerminationStackOverflow)) != 0u)
        atomicAdd(terminationCounters[terminationSlot(kTerminationStackOverflow, subject)], 1u);
    if ((gTerminations & (1u << kTerminationLoopLimit)) != 0u)
        atomicAdd(terminationCounters[terminationSlot(kTerminationLoopLimit, subject)], 1u);
    if ((gTerminations & (1u << kTerminationLoopBound)) != 0u)
        atomicAdd(terminationCounters[terminationSlot(kTerminationLoopBound, subject)], 1u);
    gTerminations = 0u;
}

// Counts `missing` items of `subject` that a cut loop never finished (0: nothing): the one in
// flight with what it noted, and the rest as cut by the loop budget.
void countCutItems(uint subject, uint missing) {
    if (missing == 0u) return;
    noteTermination(kTerminationLoopLimit);
    countTerminations(subject);
    if (missing > 1u) atomicAdd(terminationCounters[terminationSlot(kTerminationLoopLimit, subject)], missing - 1u);
}

#endif
