// Silent terminations: work that a bound ended without its own condition being met, counted on
// the GPU so the host can warn (host/render/terminations.h; docs/testing.md). Every kernel that
// traverses the BVH or loops over data-dependent ranges notes what happened to it
// (shared/termination_record.glsl: noteTermination) and adds one per affected item at the end of the
// item (shaders/common/termination_counters.glsl: countTerminations). The counter buffer is the same
// for every kernel: set kTerminationSet, binding kTerminationBinding, bound by vk::ComputeKernel
// to the context's buffer, so no kernel's own bindings change.
#ifndef VKP_KERNELS_TERMINATIONS_GLSL
#define VKP_KERNELS_TERMINATIONS_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kTerminationSet = 1u;      // descriptor set of the counter buffer
const uint kTerminationBinding = 0u;  // its binding: uint[kTerminationCounterCount]

// What ended the work (bit `kind` of the per-invocation flags).
const uint kTerminationStackOverflow = 0u;  // the BVH traversal stack was full: a subtree was skipped
const uint kTerminationLoopLimit = 1u;      // a loop ended before its condition (lavapipe's 65535-iteration budget)
const uint kTerminationLoopBound = 2u;      // a loop reached its own iteration bound (e.g. a photon's bounce cap)
const uint kTerminationKindCount = 3u;

// Which items the counts count.
const uint kTerminationSamples = 0u;        // camera samples (path tracers, visible points, raster direct)
const uint kTerminationGathers = 1u;        // photon-map lookups (estimates, final-gather rays, SPPM, radiance photons)
const uint kTerminationPhotonPaths = 2u;    // photon paths
const uint kTerminationImportonPaths = 3u;  // importon paths
const uint kTerminationGridCells = 4u;      // photon-grid cells whose bucket sort was cut
const uint kTerminationSubjectCount = 5u;

const uint kTerminationCounterCount = kTerminationKindCount * kTerminationSubjectCount;

// Slot of the counter of items of `subject` that `kind` cut short.
INLINE uint terminationSlot(uint kind, uint subject) {
    return kind * kTerminationSubjectCount + subject;
}

SHARED_END
#endif
