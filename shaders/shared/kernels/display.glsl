// Interface of display.comp (host/view/display_pass.h): the viewer's image on the device. One
// invocation per pixel resolves the film (sums / samples, plus SPPM's estimate where the
// integrator keeps one), writes that linear radiance for screenshots, and the 8-bit display
// pixel the swapchain copy takes: exposure, then the display transform read from a lattice
// the host fills with the PNG's own transform (image/view_transform.h), then the selection's
// outline. The lattice's axes are per-channel log2 radiance (the shaper below), as OpenColorIO
// bakes view transforms into 3-D LUTs (Blender's AgX is such a 37^3 cube).
#ifndef VKP_KERNELS_DISPLAY_GLSL
#define VKP_KERNELS_DISPLAY_GLSL
#include "shared/compat.glsl"
SHARED_BEGIN

const uint kDisplayGroupSize = 64u;

const uint kDisplayFilmBinding = 0u;       // vec4 per pixel: radiance sums, sample count
const uint kDisplayProgressiveBinding = 1u;  // SppmPixel per pixel (read when hasProgressive)
const uint kDisplayLatticeBinding = 2u;    // vec4 per lattice point: display-encoded RGB (0..1), x fastest
const uint kDisplayMaskBinding = 3u;       // uint per pixel: 1 inside the selected node
const uint kDisplayLinearBinding = 4u;     // vec4 per pixel (written): the resolved radiance
const uint kDisplayPixelBinding = 5u;      // uint per pixel (written): R | G << 8 | B << 16 | A << 24
const uint kDisplayBindingCount = 6u;

// Lattice points per axis and the radiance range they span: 2^-15 .. 2^9, 24 stops at 0.375 stop
// per cell, with a point at exactly 1 (point 40), where Clamp and ACES' fit have their kinks.
// Below the range the display value is that of its bottom (under 0.2 of an 8-bit code for every
// transform); above it, that of its top.
const uint kDisplayLatticeSize = 65u;
const float kDisplayLog2Min = -15.0f;
const float kDisplayLog2Max = 9.0f;

struct DisplayParams {
    uint width;
    uint height;
    float passes;           // the integrator's samples so far (sppmRadiance's passes)
    float exposureScale;    // 2^EV
    uint hasProgressive;    // 1: add sppmRadiance of kDisplayProgressiveBinding
    uint hasMask;           // 1: outline the mask
    uint bgra;              // 1: the surface wants B, G, R, A bytes
    uint pad0;
};
STATIC_ASSERT_SIZE(DisplayParams, 32)

// Where radiance x (after exposure) lies on a lattice axis, in lattice cells (0 .. size - 1).
INLINE float displayLatticeCoordinate(float x) {
    float l = log2(max(x, 1e-30f));
    float t = clamp((l - kDisplayLog2Min) / (kDisplayLog2Max - kDisplayLog2Min), 0.0f, 1.0f);
    return t * float(kDisplayLatticeSize - 1u);
}

// The radiance at lattice point i of an axis (the inverse of displayLatticeCoordinate).
INLINE float displayLatticeRadiance(uint i) {
    float t = float(i) / float(kDisplayLatticeSize - 1u);
    return exp2(kDisplayLog2Min + t * (kDisplayLog2Max - kDisplayLog2Min));
}

SHARED_END

#ifdef __cplusplus
namespace vkp::gpu {

struct DisplayKernel {
    static constexpr const char* kShader = "display.comp";
    static constexpr bool kRowsOfGroups = true;  // items by itemIndex(): windows past 4 M pixels
    static constexpr uint32_t kBindingCount = kDisplayBindingCount;
    static constexpr uint32_t kGroupSize = kDisplayGroupSize;
    using Push = DisplayParams;
};

}  // namespace vkp::gpu
#endif
#endif
