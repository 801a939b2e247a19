// Photon-guided path tracer (shaders/render/path_tracer.glsl with GUIDED, --integrator guided): at
// surfaces without delta lobes, directions come from a mixture of a photon-flux grid (Jensen
// 1995, shared/guiding.glsl) and the BSDF, weighted by the mixture density (unbiased).
#version 460
#extension GL_GOOGLE_include_directive : require

#define GUIDED
#include "render/path_tracer.glsl"
