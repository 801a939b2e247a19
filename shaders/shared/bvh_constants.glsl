// BVH limits shared by the host build and the GPU traversal.
#ifndef VKP_BVH_CONSTANTS_GLSL
#define VKP_BVH_CONSTANTS_GLSL
#include "compat.glsl"
SHARED_BEGIN

// Traversal stack size; the build turns nodes at this depth into leaves.
const uint kBvhMaxDepth = 48u;
// Leaves hold at most this many triangles unless the depth limit forces more.
const uint kBvhMaxLeafSize = 8u;
// Nodes one traversal visits at most (a bound for every loop; lavapipe cuts at 65535 loop
// iterations per invocation before this is reached). A walk that reaches it is counted.
const uint kBvhMaxSteps = 1u << 22u;

SHARED_END
#endif
