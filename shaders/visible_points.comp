// First pass of the photon integrator, one camera sample per pixel: follows the camera path
// through mirror-like bounces (smooth glass, mirrors, polished metal) to the first surface that
// stores photons (shared/bsdf.glsl storesPhotons), adds what needs no photons to the film —
// emission seen directly or through those bounces, and direct light by next-event estimation at
// the visible point and at polished-metal vertices — and stores the visible point for the photon
// estimates (caustics, indirect light) that follow.
//
// A surface that is partly delta and partly not (a smooth clear coat over a diffuse base) becomes
// the visible point: its delta part is not followed further (one visible point per sample).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_estimates.glsl"
#include "scene_access.glsl"
#include "shared/halton.glsl"
#include "shared/photon.glsl"
#include "shared/visible_point.glsl"
#include "camera_and_lights.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

layout(std430, set = 0, binding = kVisiblePointsFilmBinding) buffer Film { vec4 film[]; };  // rgb sum, sample count
layout(std430, set = 0, binding = kVisiblePointsPointBinding) writeonly buffer VisiblePoints { GpuVisiblePoint visiblePoints[]; };
layout(std430, set = 0, binding = kVisiblePointsRasterDirectBinding) readonly buffer RasterDirect { vec4 rasterDirect[]; };  // --direct raster

layout(push_constant) uniform Push { VisiblePointParams params; };

// The camera samples of the photon integrator use their own Halton stream per pixel.
const uint kVisiblePointStream = 0x56495350u;  // "VISP"

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    Sampler rng = makeSampler(params.sampleIndex, hashCombine(hashCombine(params.seed, kVisiblePointStream), pixel));
    vec2 jitter = nextSample2(rng);
    if ((params.flags & kPathFlagPixelCentres) != 0u) jitter = vec2(0.5f);
    vec3 origin = params.camera.position;
    vec3 dir = cameraRayDirection(params.camera, params.width, params.height,
                                  vec2(float(pixel % params.width) + jitter.x, float(pixel / params.width) + jitter.y));
    vec3 throughput = vec3(1.0f);
    vec3 radiance = vec3(0.0f);
    vec3 mediumSigma = vec3(0.0f);
    bool lastDelta = true;  // the camera ray, then: was the last bounce a delta lobe
    float lastPdf = 0.0f;   // solid-angle pdf of the last bounce (polished metal)
    GpuVisiblePoint vp;  // all fields written, so invalid points are zero bytes but for pixel
    vp.position = vec3(0.0f);
    vp.material = 0u;
    vp.throughput = vec3(0.0f);
    vp.shadingNormal = 0u;
    vp.uv = vec2(0.0f);
    vp.wo = 0u;
    vp.geometricNormal = 0u;
    vp.flags = 0u;
    vp.pixel = pixel;
    vp.pad0 = 0u;
    vp.pad1 = 0u;

    for (uint depth = 0u; depth <= params.maxSpecularDepth; ++depth) {
        float tHit;
        uint tri;
        float b1;
        float b2;
        if (!traceClosest(origin, dir, kInfinity, tHit, tri, b1, b2)) break;
        throughput *= exp(-mediumSigma * tHit);
        SurfaceHit hit = surfaceAt(tri, b1, b2, dir);
        GpuMaterial material = materials[hit.material];
        // Emission behind delta bounces counts in full; behind a polished-metal bounce it is
        // weighted against that vertex's next-event estimate.
        if (emitsTowards(material, hit.frontFace)) {
            float weight = lastDelta ? 1.0f : emissionMisWeight(hit, dir, tHit, lastPdf);
            // The raster term holds all of a covered area light's light at the first vertex.
            if (depth == 1u && !lastDelta && (params.flags & kPathFlagRasterAreaLights) != 0u) weight = 0.0f;
            radiance += throughput * emittedRadiance(material, hit.uv) * weight;
        }

        BsdfParams bsdf = bsdfParamsAt(material, hit.uv);
        vec3 n = hit.frontFace ? hit.shadingNormal : -hit.shadingNormal;
        vec3 t;
        vec3 b;
        orthonormalBasis(n, t, b);
        vec3 wo = toLocal(-dir, t, b, n);
        if (wo.z <= 0.0f) wo.z = 1.0e-4f;

        // --direct raster: the first vertex's covered lights come from the raster pass.
        uint skip = 0u;
        if (depth == 0u && (params.flags & kPathFlagRasterDeltaLights) != 0u)
            skip |= (1u << kLightPoint) | (1u << kLightSpot) | (1u << kLightDirectional);
        if (depth == 0u && (params.flags & kPathFlagRasterAreaLights) != 0u) skip |= 1u << kLightTriangle;
        if (storesPhotons(bsdf)) {
            radiance += throughput * directLightSkipping(hit, bsdf, wo, t, b, n, params.lightCount, false, skip, rng);
            vp.position = hit.position;
            vp.material = hit.material;
            vp.throughput = throughput;
            vp.shadingNormal = encodeOctahedral(n);
            vp.uv = hit.uv;
            vp.wo = encodeOctahedral(-dir);
            vp.geometricNormal = encodeOctahedral(hit.frontFace ? hit.geometricNormal : -hit.geometricNormal);
            vp.flags = kVisiblePointValid | (hit.frontFace ? kVisiblePointFrontFace : 0u);
            break;
        }
        if (depth == params.maxSpecularDepth) break;
        // A polished metal: direct light by next-event estimation (MIS), then on by its lobe.
        if (!specularIsDelta(bsdf))
            radiance += throughput * directLightSkipping(hit, bsdf, wo, t, b, n, params.lightCount, true, skip, rng);
        vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        BsdfSample bs = sampleBsdf(bsdf, wo, hit.frontFace, true, u);
        if (bs.lobe == kLobeNone) break;
        throughput *= bs.weight;
        lastDelta = (bs.lobe & kLobeDelta) != 0u;
        lastPdf = bs.pdf;
        dir = normalize(toWorld(bs.wi, t, b, n));
        origin = offsetRayOrigin(hit.position, hit.geometricNormal, dir);
        if ((bs.lobe & kLobeTransmission) != 0u && (material.flags & kMaterialThinWalled) == 0u)
            mediumSigma = hit.frontFace ? material.attenuationCoeff : vec3(0.0f);
    }
    if ((params.flags & (kPathFlagRasterDeltaLights | kPathFlagRasterAreaLights)) != 0u) radiance += rasterDirect[pixel].rgb;
    if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(0.0f);
    film[pixel] += vec4(radiance, 1.0f);
    visiblePoints[pixel] = vp;
}
