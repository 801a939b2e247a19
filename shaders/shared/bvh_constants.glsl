// BVH limits shared by the host build and the GPU traversal.
#ifndef VKP_BVH_CONSTANTS_GLSL
#define VKP_BVH_CONSTANTS_GLSL
#include "compat.glsl"
SHARED_BEGIN

// Traversal stack size; the build turns nodes at this depth into leaves.
const uint kBvhMaxDepth = 48u;
// Leaves hold at most this many triangles unless the depth limit forces more.
const uint kBvhMaxLeafSize = 8u;

SHARED_END
#endif
