// The viewer's image on the device (interface: shared/kernels/display.glsl; host/view/display_pass.h).
// One invocation per pixel: the film's mean plus SPPM's estimate (the host's image, resolved here),
// kept as linear radiance for screenshots, then exposure, the display transform by tetrahedral
// lookup in the host-filled lattice, 8-bit rounding as the PNG's (round to nearest), and the
// selected node's outline (orange where a masked pixel has an unmasked 4-neighbour).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/display.glsl"
#include "shared/photon_render.glsl"

#include "common/item_index.glsl"

layout(local_size_x = kDisplayGroupSize) in;

layout(std430, set = 0, binding = kDisplayFilmBinding) readonly buffer Film { vec4 sums[]; };
layout(std430, set = 0, binding = kDisplayProgressiveBinding) readonly buffer Progressive { SppmPixel sppm[]; };
layout(std430, set = 0, binding = kDisplayLatticeBinding) readonly buffer Lattice { vec4 lattice[]; };
layout(std430, set = 0, binding = kDisplayMaskBinding) readonly buffer Mask { uint mask[]; };
layout(std430, set = 0, binding = kDisplayLinearBinding) writeonly buffer Linear { vec4 linearImage[]; };
layout(std430, set = 0, binding = kDisplayPixelBinding) writeonly buffer Pixels { uint pixels[]; };

layout(push_constant) uniform Push { DisplayParams params; };

vec3 latticeAt(uvec3 i) {
    return lattice[(i.z * kDisplayLatticeSize + i.y) * kDisplayLatticeSize + i.x].rgb;
}

// Tetrahedral interpolation of the lattice at radiance rgb (after exposure), as OpenColorIO
// offers for 3-D LUTs: the cell is split into six tetrahedra by the order of the three fractions,
// which within a cell on the diagonal is the order of the channels, so the kinks where a hue-based
// transform (AgX) changes with the channels' order lie on tetrahedron faces and are reproduced;
// trilinear interpolation smeared them (up to 7 codes off, against 1 code now).
vec3 displayTransform(vec3 rgb) {
    vec3 c = vec3(displayLatticeCoordinate(rgb.r), displayLatticeCoordinate(rgb.g), displayLatticeCoordinate(rgb.b));
    uvec3 i = min(uvec3(floor(c)), uvec3(kDisplayLatticeSize - 2u));
    vec3 f = c - vec3(i);
    vec3 c000 = latticeAt(i), c111 = latticeAt(i + uvec3(1, 1, 1));
    if (f.x >= f.y) {
        if (f.y >= f.z)
            return (1.0f - f.x) * c000 + (f.x - f.y) * latticeAt(i + uvec3(1, 0, 0)) +
                   (f.y - f.z) * latticeAt(i + uvec3(1, 1, 0)) + f.z * c111;
        if (f.x >= f.z)
            return (1.0f - f.x) * c000 + (f.x - f.z) * latticeAt(i + uvec3(1, 0, 0)) +
                   (f.z - f.y) * latticeAt(i + uvec3(1, 0, 1)) + f.y * c111;
        return (1.0f - f.z) * c000 + (f.z - f.x) * latticeAt(i + uvec3(0, 0, 1)) +
               (f.x - f.y) * latticeAt(i + uvec3(1, 0, 1)) + f.y * c111;
    }
    if (f.z >= f.y)
        return (1.0f - f.z) * c000 + (f.z - f.y) * latticeAt(i + uvec3(0, 0, 1)) +
               (f.y - f.x) * latticeAt(i + uvec3(0, 1, 1)) + f.x * c111;
    if (f.z >= f.x)
        return (1.0f - f.y) * c000 + (f.y - f.z) * latticeAt(i + uvec3(0, 1, 0)) +
               (f.z - f.x) * latticeAt(i + uvec3(0, 1, 1)) + f.x * c111;
    return (1.0f - f.y) * c000 + (f.y - f.x) * latticeAt(i + uvec3(0, 1, 0)) +
           (f.x - f.z) * latticeAt(i + uvec3(1, 1, 0)) + f.z * c111;
}

bool masked(int x, int y) {
    return x >= 0 && y >= 0 && x < int(params.width) && y < int(params.height) &&
           mask[uint(y) * params.width + uint(x)] != 0u;
}

void main() {
    uint pixel = itemIndex();
    if (pixel >= params.width * params.height) return;
    vec4 s = sums[pixel];
    float inv = s.w > 0.0f ? 1.0f / s.w : 0.0f;
    vec3 radiance = vec3(s.x * inv, s.y * inv, s.z * inv);
    if (params.hasProgressive != 0u) radiance += sppmRadiance(sppm[pixel], params.passes);
    linearImage[pixel] = vec4(radiance, 1.0f);

    uvec3 bytes = uvec3(clamp(displayTransform(radiance * params.exposureScale), 0.0f, 1.0f) * 255.0f + 0.5f);
    if (params.hasMask != 0u) {
        int x = int(pixel % params.width), y = int(pixel / params.width);
        if (masked(x, y) && !(masked(x - 1, y) && masked(x + 1, y) && masked(x, y - 1) && masked(x, y + 1)))
            bytes = uvec3(255u, 160u, 0u);  // orange
    }
    if (params.bgra != 0u) bytes = bytes.bgr;
    pixels[pixel] = bytes.r | (bytes.g << 8u) | (bytes.b << 16u) | (255u << 24u);
}
