// First pass of the photon integrator, one camera sample per pixel: follows the camera path
// through mirror-like bounces (smooth glass, mirrors, polished metal) to the first surface that
// stores photons (shared/bsdf.glsl storesPhotons), adds what needs no photons to the film —
// emission seen directly or through those bounces, and direct light by next-event estimation at
// the visible point and at polished-metal vertices — and stores the visible point for the photon
// estimates (caustics, indirect light) that follow.
//
// A surface that is partly delta and partly not (a smooth clear coat over a diffuse base) becomes
// the visible point: its delta part is not followed further (one visible point per sample). A
// partly transmissive one is the visible point or the glass, chosen by its transmission.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_estimates.glsl"
#include "render/scene_access.glsl"
#include "render/path_vertex.glsl"
#include "shared/halton.glsl"
#include "shared/photon.glsl"
#include "shared/visible_point.glsl"
#include "render/camera_and_lights.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

layout(std430, set = 0, binding = kVisiblePointsFilmBinding) buffer Film { vec4 film[]; };  // rgb sum, sample count
layout(std430, set = 0, binding = kVisiblePointsPointBinding) writeonly buffer VisiblePoints { GpuVisiblePoint visiblePoints[]; };
layout(std430, set = 0, binding = kVisiblePointsRasterDirectBinding) readonly buffer RasterDirect { vec4 rasterDirect[]; };  // --direct raster

layout(push_constant) uniform Push { VisiblePointParams params; };

// The camera samples of the photon integrator use their own Halton stream per pixel.
const uint kVisiblePointStream = 0x56495350u;  // "VISP"

void findVisiblePoint() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    Sampler rng = makePixelSampler(params.sampleIndex, params.camera.pixelSamples, hashCombine(hashCombine(params.seed, kVisiblePointStream), pixel));
    vec2 jitter = nextSample2(rng);
    if ((params.flags & kPathFlagPixelCentres) != 0u) jitter = vec2(0.5f);
    vec2 filmPixel = vec2(float(pixel % params.width) + jitter.x, float(pixel / params.width) + jitter.y);
    Ray ray = cameraRay(params.camera, params.width, params.height, filmPixel);
    vec3 throughput = vec3(1.0f);
    vec3 radiance = vec3(0.0f);
    bool lastDelta = true;  // the camera ray, then: was the last bounce a delta lobe
    float lastPdf = 0.0f;   // solid-angle pdf of the last bounce (polished metal)
    vec3 lastPosition = vec3(0.0f);  // that bounce's vertex and shading normal (MIS light pdf)
    vec3 lastNormal = vec3(0.0f);
    GpuVisiblePoint vp;  // all fields written, so invalid points are zero bytes but for pixel
    vp.position = vec3(0.0f);
    vp.material = 0u;
    vp.throughput = vec3(0.0f);
    vp.shadingNormal = 0u;
    vp.barycentrics = vec2(0.0f);
    vp.wo = 0u;
    vp.geometricNormal = 0u;
    vp.flags = 0u;
    vp.pixel = pixel;
    vp.triangle = 0u;
    vp.coneWidth = 0.0f;

    for (uint depth = 0u; depth <= params.maxSpecularDepth; ++depth) {
        PathVertex v;
        if (!traceVertex(ray, v)) {
            // The environment, weighted like emission against a polished-metal vertex's estimate.
            radiance += throughput * escapedRadiance(params.lightCount, ray.dir, !lastDelta, lastPdf, lastPosition, lastNormal);
            break;
        }
        throughput *= v.transmittance;
        // Emission behind delta bounces counts in full; behind a polished-metal bounce it is
        // weighted against that vertex's next-event estimate.
        if (emitsTowards(v.material, v.hit.frontFace)) {
            float weight = lastDelta ? 1.0f : emissionMisWeight(v, lastPdf, params.lightCount, lastPosition, lastNormal);
            if (rasterCoversEmission(params.flags, depth, lastDelta)) weight = 0.0f;
            radiance += throughput * v.emitted * weight;
        }

        // --direct raster: the first vertex's covered lights come from the raster pass.
        uint skip = rasterCoveredLightTypes(params.flags, depth);
        // A surface that stores photons: direct light by its opaque layer, then the visible point.
        // A partly transmissive one (0 < transmission < 1) is the visible point only with
        // probability 1 - transmission (its throughput divided by that: the estimates evaluate the
        // material's BSDF, the opaque share in it); otherwise the path goes on through its
        // dielectric layer alone (transmission set to 1 there), like through glass.
        float transmissionShare = storesPhotons(v.bsdf) ? v.bsdf.transmission : 0.0f;
        if (storesPhotons(v.bsdf)) {
            PathVertex opaque = v;
            opaque.bsdf.transmission = 0.0f;  // the opaque layer's f, scaled by its share below
            radiance += throughput * (1.0f - transmissionShare) * directLight(opaque, params.lightCount, false, skip, rng);
        }
        bool throughLayer = transmissionShare > 0.0f && nextSample(rng) < transmissionShare;
        if (storesPhotons(v.bsdf) && !throughLayer) {
            vp.position = v.hit.position;
            vp.material = v.hit.material;
            vp.throughput = throughput / (1.0f - transmissionShare);
            vp.shadingNormal = encodeOctahedral(v.n);
            vp.barycentrics = v.barycentrics;
            vp.triangle = v.triangle;
            vp.coneWidth = v.coneWidth;
            vp.wo = encodeOctahedral(-ray.dir);
            vp.geometricNormal = encodeOctahedral(v.hit.frontFace ? v.hit.geometricNormal : -v.hit.geometricNormal);
            vp.flags = kVisiblePointValid | (v.hit.frontFace ? kVisiblePointFrontFace : 0u);
            break;
        }
        if (throughLayer) v.bsdf.transmission = 1.0f;
        if (depth == params.maxSpecularDepth) break;
        // A polished metal or rough glass: direct light by next-event estimation (MIS), then on by
        // its lobe.
        if (!specularLobeIsDelta(v.bsdf))
            radiance += throughput * directLight(v, params.lightCount, true, skip, rng);
        vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        BsdfSample bs = sampleVertexBsdf(v, true, u);
        if (bs.lobe == kLobeNone) break;
        throughput *= bs.weight;
        lastDelta = isDeltaForMis(bs);
        lastPdf = lastDelta ? bs.pdf : misPdfOfSample(v, bs);
        lastPosition = v.hit.position;
        lastNormal = v.n;
        spawnRay(v, bs, ray);
    }
    if (rasterDirectLightOn(params.flags)) radiance += rasterDirect[pixel].rgb;
    if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(0.0f);
    film[pixel] += vec4(radiance, 1.0f);
    visiblePoints[pixel] = vp;
}

void main() {
    findVisiblePoint();
    countTerminations(kTerminationSamples);  // rays and gathers this invocation's bounds cut short
}
