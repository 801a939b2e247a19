// Auxiliary images (--aov albedo,normal,depth): albedo and world-space normal of the first
// surface without a delta lobe, as Open Image Denoise expects them, and depth in metres along the
// camera's forward axis (shaders/render/aov.comp). Written as extra EXR channels named as pbrt-v4 and
// Blender name them (docs/output.md).
#pragma once

#include <string>
#include <vector>

#include "image/exr.h"
#include "image/image.h"
#include "render/frame.h"

namespace vkp {

class GpuScene;

struct AovSettings {
    bool albedo = false;
    bool normal = false;
    bool depth = false;
    bool any() const { return albedo || normal || depth; }
};

// "albedo,normal,depth" (any subset, any order); InputError naming --aov for anything else.
AovSettings parseAovList(const std::string& list);

struct AovImages {
    ImageRgb albedo;             // linear RGB
    ImageRgb normal;             // unit world-space normal per pixel (0 where no surface)
    std::vector<float> depth;    // metres; kAovBackgroundDepth where no surface
};

// Renders the auxiliary images of `frame` (one dispatch; camera and size from the frame).
AovImages renderAovs(const GpuScene& scene, const Frame& frame);

// The EXR channels of the requested images: Albedo.R/G/B, N.X/N.Y/N.Z, Z.
std::vector<ExrChannel> aovChannels(const AovImages& images, const AovSettings& settings);

}  // namespace vkp
