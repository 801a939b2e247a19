// Lighting pass of the raster direct light (host/passes/raster_direct_pass.h): for the visible
// point of each pixel centre, the BSDF-weighted contribution of each light of one mask pass times
// its mask channel, in float, added to the direct buffer (summed over passes). This is exactly the
// expectation of the path tracer's next-event estimate at the first vertex for those lights, with
// the shadow ray replaced by the stencil result (Dmitriev et al. 2002, section 6.1).
// Reads: scene, raster lights, masks. Writes: direct (vec4 per pixel); shared/kernels/raster_direct.glsl.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/raster_direct.glsl"
#include "render/scene_access.glsl"
#include "shared/halton.glsl"
#include "render/camera_and_lights.glsl"
#include "raster/raster_light_access.glsl"

layout(local_size_x = kRasterDirectGroupSize) in;

layout(std430, set = 0, binding = kRasterDirectLightBinding) readonly buffer RasterLights { GpuLight rasterLights[]; };
layout(std430, set = 0, binding = kRasterDirectMaskBinding) readonly buffer Masks { uint masks[]; };
layout(std430, set = 0, binding = kRasterDirectOutputBinding) buffer Direct { vec4 direct[]; };
layout(push_constant) uniform Push { RasterDirectParams params; };

void rasterDirectLight() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    uint px = pixel % params.width;
    uint py = pixel / params.width;
    vec2 filmPixel = vec2(float(px) + 0.5f, float(py) + 0.5f);
    // The same vertex as the path tracer's first one (traceVertex: shading frame and all), its
    // textures filtered over the whole pixel: this one sample stands for all of the pixel's.
    GpuCamera camera = params.camera;
    camera.pixelSamples = 1u;
    PathVertex v;
    if (!traceVertex(cameraRay(camera, params.width, params.height, filmPixel), v)) return;
    vec3 sideNormal = v.hit.frontFace ? v.hit.geometricNormal : -v.hit.geometricNormal;

    uint mask = masks[params.maskOffset + pixel];
    // Alpha-tested triangles (MASK/BLEND) write no depth and cast no volumes (host/passes/
    // shadow_volume_pass.cpp): the mask is exact for opaque occluders at opaque visible points.
    // Where the visible point is itself alpha-tested the mask saw what lies behind it, and where
    // the mask says lit an alpha-tested occluder may still block: a shadow ray decides there.
    bool alphaSurface = params.alphaTested != 0u && triangles[v.hit.triangle].v0.w != 0.0f;
    vec3 sum = vec3(0.0f);
    for (uint k = 0u; k < params.lightCount; ++k) {
        LightSample ls = rasterLightSample(rasterLights[params.firstLight + k], v.hit.position);
        bool through = dot(ls.wi, sideNormal) <= 0.0f;  // behind the surface: lit only through rough glass
        bool lit = ((mask >> (8u * k)) & 0xffu) != 0u;
        if (!through && !lit && !alphaSurface) continue;  // in this light's shadow volume
        vec3 wi = toLocal(ls.wi, v.t, v.b, v.n);
        vec3 f = evalVertexDirect(v, ls, wi);  // as the traced estimate's f
        if (f.r + f.g + f.b <= 0.0f) continue;
        // The masks see light on the arrival side only: light through the surface takes a shadow ray.
        if ((through || params.alphaTested != 0u) && !lightVisible(v.hit.position, v.hit.geometricNormal, ls)) continue;
        sum += f * abs(wi.z) * ls.radiance;
    }
    direct[pixel] += vec4(sum * v.transmittance, 0.0f);  // a dispersive surface's spectral weight (camera rays cross no medium)
}

void main() {
    rasterDirectLight();
    countTerminations(kTerminationSamples);  // rays and gathers this invocation's bounds cut short
}
