// The display transform of the PNG: exposure, a view transform (tone mapping) from linear
// Rec.709 radiance to display-linear Rec.709 in [0, 1], and the sRGB encoding. The EXR is never
// touched by any of it: it stays linear.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace vkp {

// --tonemap. docs/output.md compares them.
enum class ViewTransform {
    Clamp,    // clip to [0, 1] per channel: Blender's "Standard"
    AcesFit,  // Narkowicz's fit of the ACES RRT + ODT, per channel (earlier versions' only curve)
    AgX,      // Blender 4's AgX view, base contrast (see agxDisplayLinear)
};

// The names --tonemap accepts and the EXR header records, in that enum's order.
std::vector<std::pair<std::string, ViewTransform>> viewTransformChoices();
std::string viewTransformName(ViewTransform view);

struct DisplaySettings {
    // AgX by default: Blender's default view since 4.0, it keeps mid grey where the linear image
    // has it (0.18 -> display 0.18, as Clamp does), and bright saturated light desaturates
    // towards white instead of skewing to the nearest primary or secondary.
    ViewTransform view = ViewTransform::AgX;
    float exposureEv = 0.0f;  // the radiance is scaled by 2^exposureEv first
    // --exposure auto: exposureEv is to be metered from the image (image/exposure.h) before the
    // PNG is written; the PNG writer itself always applies exposureEv.
    bool autoExposure = false;

    // Throws InputError naming --exposure unless it is finite and within [-64, 64].
    void check() const;
    // 2^exposureEv, built so that one more EV is exactly twice the scale.
    float exposureScale() const;
};

// ACES filmic curve fitted by Narkowicz (2015), (x(2.51x + 0.03)) / (x(2.43x + 0.59) + 0.14),
// clamped to [0, 1]; applied per channel. Monotonic; NaN and x <= 0 give 0, +inf gives 1.
float tonemapAces(float x);

// Blender 4's AgX view transform ("AgX Base sRGB" in its OpenColorIO config, look "None")
// evaluated analytically: linear Rec.709 scene radiance -> display-linear Rec.709, non-negative,
// up to about 1.4 at the top of its range (the sRGB encoding clips). Mid grey 0.18 maps to 0.18;
// black to 0. NaN counts as 0. The steps and their sources are in view_transform.cpp.
glm::vec3 agxDisplayLinear(glm::vec3 rec709);
// The function Blender's 37^3 AgX_Base_sRGB.cube samples: E-Gamut log2 input (0..1 for -10..+15
// stops around 0.18) -> Rec.709 encoded with a 1/2.4 power. For comparing with that LUT.
glm::dvec3 agxBaseSrgbLut(glm::dvec3 eGamutLog2);

// `view` of linear Rec.709 radiance (after exposure): display-linear Rec.709 in [0, 1].
glm::vec3 applyViewTransform(glm::vec3 linear, ViewTransform view);

// The exact piecewise sRGB OETF (IEC 61966-2-1): 12.92x up to 0.0031308, else
// 1.055x^(1/2.4) - 0.055. Input clamped to [0, 1]; NaN gives 0.
float linearToSrgb(float x);
// linearToSrgb scaled to 0..255 and rounded to nearest: 0 -> 0, 1 -> 255.
uint8_t linearToSrgb8(float x);

// One pixel of linear radiance to 8-bit sRGB: exposure, view transform, OETF, rounding.
std::array<uint8_t, 3> toDisplayBytes(glm::vec3 linear, const DisplaySettings& display = {});

}  // namespace vkp
