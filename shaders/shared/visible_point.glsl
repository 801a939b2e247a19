// Visible points of the photon integrator: where a camera path, after following delta
// (mirror/glass) bounces, first meets a surface that scatters diffusely or glossily. Photon
// estimates and final gathers read them; they are written by visible_points.comp.
#ifndef VKP_VISIBLE_POINT_GLSL
#define VKP_VISIBLE_POINT_GLSL
#include "compat.glsl"
#include "gpu_types.glsl"
SHARED_BEGIN

const uint kVisiblePointValid = 1u;
const uint kVisiblePointFrontFace = 2u;

struct GpuVisiblePoint {
    vec3 position;          // world space
    uint material;
    vec3 throughput;        // camera path weight up to this point (delta bounces, absorption)
    uint shadingNormal;     // octahedral (photon.glsl), on the side the camera path arrived from
    vec2 barycentrics;      // (b1, b2) on `triangle`: the material's textures and COLOR_0 there
    uint wo;                // octahedral unit vector towards the previous path vertex
    uint geometricNormal;   // octahedral, on the arrival side (for offsetting gather rays)
    uint flags;
    uint pixel;
    uint triangle;          // hit id (docs/bvh.md)
    float coneWidth;        // the camera ray's cone there (textures' mipmap levels, PathVertex.coneWidth)
};
STATIC_ASSERT_SIZE(GpuVisiblePoint, 64)

// Push constants of visible_points.comp.
struct VisiblePointParams {
    GpuCamera camera;
    uint width;
    uint height;
    uint sampleIndex;       // Halton index of this pass's camera sample in every pixel
    uint seed;
    uint maxSpecularDepth;  // delta bounces followed before giving up on a path
    uint lightCount;
    uint flags;             // kPathFlagRaster* (the raster pass covers the first vertex's direct
                            // light of those lights), kPathFlagPixelCentres
    uint pad0;
};
STATIC_ASSERT_SIZE(VisiblePointParams, 96)

SHARED_END
#endif
