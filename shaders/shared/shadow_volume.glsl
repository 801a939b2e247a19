// Shared layouts of the raster direct-light pass (host/passes/shadow_volume_pass.h): stencil
// shadow volumes (Dmitriev et al. 2002, section 6.1, after Everitt & Kilgard's robust z-fail
// volumes) and the RGBA shadow mask that holds four lights per pass.
#ifndef VKP_SHADOW_VOLUME_GLSL
#define VKP_SHADOW_VOLUME_GLSL
#include "compat.glsl"
#include "gpu_types.glsl"
SHARED_BEGIN

// The paper's RGBA mask: one colour channel per light, so one mask per four lights.
const uint kLightsPerMaskPass = 4u;
// Worst case per triangle and light: front cap (3), back cap (3), three side quads (3 x 6).
// Unused slots are written as degenerate triangles, so every triangle owns fixed slots.
const uint kVolumeVerticesPerTriangle = 24u;
const uint kShadowNoNeighbor = 0xffffffffu;

// Area-light sample used by the raster pass: a point on an emissive triangle radiating
// intensity * max(0, cos) towards direction's side (both sides when the emitter is double-sided).
const uint kLightAreaSample = 4u;

// A scene triangle prepared for extrusion, in BVH order. Triangles of a closed, consistently
// oriented 2-manifold component know their three edge neighbours and extrude only silhouette
// edges; all others (open or non-manifold meshes) get a closed volume of their own.
struct GpuShadowTriangle {
    vec4 v0;                // world position, w = 1
    vec4 v1;
    vec4 v2;
    uint neighbor0;         // triangle across edge v0v1 (kShadowNoNeighbor when open)
    uint neighbor1;         // across v1v2
    uint neighbor2;         // across v2v0
    uint closed;            // 1: part of a closed 2-manifold component
};
STATIC_ASSERT_SIZE(GpuShadowTriangle, 64)

// Push constants of shadow_volume_build.comp.
struct ShadowVolumeParams {
    uint triangleCount;
    uint firstLight;        // index in the raster light list of the pass's first light
    uint lightCount;        // lights in this pass (1..4)
    uint pad0;
};
STATIC_ASSERT_SIZE(ShadowVolumeParams, 16)

// Push constants of the raster pipelines (raster_position.vert, shadow_mask.*).
struct RasterParams {
    mat4 viewProj;          // world (homogeneous) -> clip, reversed infinite depth
};
STATIC_ASSERT_SIZE(RasterParams, 64)

// Push constants of the geometry-shader volumes (shadow_volume.geom).
struct RasterVolumeParams {
    mat4 viewProj;
    vec4 light;             // homogeneous light point: (position, 1), or (-direction, 0)
};
STATIC_ASSERT_SIZE(RasterVolumeParams, 80)

// Push constants of raster_direct.comp.
struct RasterDirectParams {
    GpuCamera camera;
    uint width;
    uint height;
    uint firstLight;        // raster light index of mask channel 0 of this pass
    uint lightCount;        // lights in this pass
    uint maskOffset;        // first uint of this pass's mask in the mask buffer
    uint alphaTested;       // 1: the scene has alpha-tested triangles, which cast no volumes: shadow rays decide
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(RasterDirectParams, 96)

SHARED_END
#endif
