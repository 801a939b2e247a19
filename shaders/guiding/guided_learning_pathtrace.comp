// Photon-guided path tracer reading the guiding cache and refining it from its own samples
// (shared/kernels/guide_learn.glsl, guiding/guide_learning.glsl): the cached path tracer that
// also adds each guided vertex's sampled incident radiance to its grid.
#version 460
#extension GL_GOOGLE_include_directive : require

#define GUIDED
#define GUIDE_CACHE
#define GUIDE_LEARN
#include "render/path_tracer.glsl"
