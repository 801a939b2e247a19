// Benchmark counterpart of shaders/raster/raster_direct.comp with the mask replaced by a shadow ray
// (lightVisible, as the path tracer's next-event estimate traces it): the exact direct light of
// one raster light per dispatch (lavapipe's loop budget: one shadow ray per invocation and
// dispatch), added to the direct buffer. Bindings: bench_kernels.glsl.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "bench_kernels.glsl"
#include "render/scene_access.glsl"
#include "shared/halton.glsl"
#include "render/camera_and_lights.glsl"
#include "raster/raster_light_access.glsl"

layout(local_size_x = kBenchGroupSize) in;

layout(std430, set = 0, binding = kTracedDirectLightBinding) readonly buffer RasterLights { GpuLight rasterLights[]; };
layout(std430, set = 0, binding = kTracedDirectOutputBinding) buffer Direct { vec4 direct[]; };
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
    if (!traceClosest(params.camera.position, dir, kInfinity, true, tHit, tri, b1, b2)) return;
    SurfaceHit hit = surfaceAt(tri, b1, b2, dir, 0.0f);
    BsdfParams bsdf = bsdfParamsAtHit(materials[hit.material], hit);
    vec3 n = hit.frontFace ? hit.shadingNormal : -hit.shadingNormal;
    vec3 t;
    vec3 b;
    orthonormalBasis(n, t, b);
    vec3 wo = toLocal(-dir, t, b, n);
    if (wo.z <= 0.0f) wo.z = 1.0e-4f;
    vec3 sideNormal = hit.frontFace ? hit.geometricNormal : -hit.geometricNormal;
    LightSample ls = rasterLightSample(rasterLights[params.firstLight], hit.position);
    vec3 wi = toLocal(ls.wi, t, b, n);
    if (wi.z <= 0.0f || dot(ls.wi, sideNormal) <= 0.0f) return;
    if (!lightVisible(hit.position, hit.geometricNormal, ls)) return;
    direct[pixel] += vec4(evalBsdf(bsdf, wo, wi) * wi.z * ls.radiance, 0.0f);
}
