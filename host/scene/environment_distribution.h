// The environment map's data as the GPU reads it (layout in shaders/shared/environment.glsl): RGB
// radiance, then the 2-D piecewise-constant distribution of luminance x sin(theta) that
// importance-samples it (conditional CDF per row, marginal CDF over rows).
#pragma once

#include <vector>

#include "scene/environment.h"

namespace vkp {

// The floats of a map (empty for a constant or no environment).
std::vector<float> environmentGpuData(const Environment& env);

// Radiance averaged over the sphere, as luminance: the constant's, or the map's pixels weighted
// by their solid angle.
double environmentMeanLuminance(const Environment& env);

// Power the environment sends through the scene's bounding sphere (of radius r): 4 pi x mean
// luminance x pi r^2, the selection weight against other lights and the photon power it emits.
double environmentPower(const Environment& env, double sceneRadius);

}  // namespace vkp
