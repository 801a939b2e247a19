// Photon-guided path tracer reading the guiding cache (guide_cache_build.comp): the grid of the
// vertex's cache cell and normal bin instead of a k-nearest gather at every vertex.
#version 460
#extension GL_GOOGLE_include_directive : require

#define GUIDED
#define GUIDE_CACHE
#include "render/path_tracer.glsl"
