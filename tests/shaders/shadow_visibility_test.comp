// Ray-traced reference of the raster shadow mask: for each pixel centre's visible point and each
// raster light (at most 32), the shadow ray of the path tracer's next-event estimate
// (lightVisible, scene_access.glsl). out[3 * pixel] = bit per light: visible; out[3 * pixel + 1] =
// bit per light: the pixel sees a surface whose camera side faces the light (only there does the
// mask matter: elsewhere the BSDF term is zero); out[3 * pixel + 2] = the visible triangle
// (0xffffffff: none), so the host can tell creases (geometric edges) from flat surfaces.
#version 460
#extension GL_GOOGLE_include_directive : require

#define VKP_BSDF_TABLES_BINDING kSceneTablesBinding  // as scene_access.glsl: the scene's tables
#include "test_kernels.glsl"
#include "render/scene_access.glsl"
#include "shared/halton.glsl"
#include "render/camera_and_lights.glsl"
#include "raster/raster_light_access.glsl"

layout(local_size_x = kTestGroupSize) in;

layout(std430, set = 0, binding = kShadowTestLightBinding) readonly buffer RasterLights { GpuLight rasterLights[]; };
layout(std430, set = 0, binding = kShadowTestOutputBinding) writeonly buffer Out { uint result[]; };
layout(push_constant) uniform Push { RasterDirectParams params; };

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    uint px = pixel % params.width;
    uint py = pixel / params.width;
    vec3 dir = cameraRayDirection(params.camera, params.width, params.height, vec2(float(px) + 0.5f, float(py) + 0.5f));
    float tHit;
    uint tri;
    float b1;
    float b2;
    uint visible = 0u;
    uint relevant = 0u;
    uint visibleTriangle = 0xffffffffu;
    if (traceClosest(params.camera.position, dir, kInfinity, false, tHit, tri, b1, b2)) {
        SurfaceHit hit = surfaceAt(tri, b1, b2, dir, 0.0f);
        visibleTriangle = tri;
        vec3 sideNormal = hit.frontFace ? hit.geometricNormal : -hit.geometricNormal;
        for (uint k = 0u; k < params.lightCount; ++k) {
            LightSample ls = rasterLightSample(rasterLights[params.firstLight + k], hit.position);
            if (dot(ls.wi, sideNormal) <= 0.0f || max(ls.radiance.r, max(ls.radiance.g, ls.radiance.b)) <= 0.0f) continue;
            relevant |= 1u << k;
            if (lightVisible(hit.position, hit.geometricNormal, ls)) visible |= 1u << k;
        }
    }
    result[3u * pixel] = visible;
    result[3u * pixel + 1u] = relevant;
    result[3u * pixel + 2u] = visibleTriangle;
}
