// Constants shared by host and shaders: math, sampler layout.
#ifndef VKP_CONSTANTS_GLSL
#define VKP_CONSTANTS_GLSL
#include "compat.glsl"
SHARED_BEGIN

const float kPi = 3.14159265358979f;
const float kInvPi = 0.318309886183791f;
const float kTwoPi = 6.28318530717959f;
const float kOneMinusEpsilon = 0.99999994f;  // largest float below 1
const float kInfinity = 3.0e38f;

// Halton dimensions used before the sampler falls back to hashed random numbers.
const uint kHaltonDimensions = 32u;

SHARED_END
#endif
