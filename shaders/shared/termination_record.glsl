// The per-invocation record of silent terminations (shared/kernels/terminations.glsl): shared
// code that hits a bound (BVH traversal, gathers) sets a bit here; the kernel adds the bits to the
// counters once per item (shaders/common/termination_counters.glsl). In C++ (the host's traversal,
// host/bvh) the record is a thread-local variable tests can read and clear.
#ifndef VKP_TERMINATIONS_GLSL
#define VKP_TERMINATIONS_GLSL
#include "compat.glsl"
#include "kernels/terminations.glsl"
SHARED_BEGIN

#ifdef __cplusplus
inline thread_local uint gTerminations = 0u;
#else
uint gTerminations = 0u;
#endif

INLINE void noteTermination(uint kind) {
    gTerminations |= 1u << kind;
}

// Notes a loop that ended before its own condition: `iterations` (counted in the loop body)
// short of `expected`. Counting, rather than re-testing the loop's condition after it, keeps the
// compiler from proving the test false (it does not know lavapipe's budget exits the loop).
INLINE void noteLoopCut(uint iterations, uint expected) {
    if (iterations < expected) noteTermination(kTerminationLoopLimit);
}

SHARED_END
#endif
