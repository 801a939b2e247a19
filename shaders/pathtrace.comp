// Reference path tracer: next-event estimation on all lights combined with BSDF sampling by
// multiple importance sampling (power heuristic), Russian roulette, Beer-Lambert absorption inside
// KHR_materials_volume solids. One invocation per pixel adds `sampleCount` samples to the film;
// a pixel is written by exactly one invocation, so accumulation is deterministic.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "scene_access.glsl"
#include "shared/halton.glsl"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 8) buffer Film { vec4 film[]; };  // rgb sum, sample count
layout(std430, set = 0, binding = 9) buffer Counters { uint counters[]; };
// counters[0]: samples that produced a non-finite value (dropped)

layout(push_constant) uniform Push { PathTraceParams params; };

vec3 cameraRayDirection(vec2 pixel) {
    GpuCamera cam = params.camera;
    vec2 ndc = vec2(2.0f * pixel.x / float(params.width) - 1.0f,
                    1.0f - 2.0f * pixel.y / float(params.height));
    return normalize(cam.forward + ndc.x * cam.aspect * cam.tanHalfFovY * cam.right +
                     ndc.y * cam.tanHalfFovY * cam.up);
}

// Next-event estimation at a non-delta surface point (MIS-weighted for area lights).
vec3 directLight(SurfaceHit hit, BsdfParams bsdf, vec3 wo, vec3 t, vec3 b, vec3 n,
                 inout Sampler rng) {
    float uPick = nextSample(rng);
    vec2 uLight = nextSample2(rng);
    if (params.lightCount == 0u) return vec3(0.0f);
    LightSample ls = sampleLight(pickLight(uPick, params.lightCount), hit.position, uLight);
    if (ls.pdf <= 0.0f) return vec3(0.0f);
    vec3 wi = toLocal(ls.wi, t, b, n);
    vec3 sideNormal = hit.frontFace ? hit.geometricNormal : -hit.geometricNormal;
    if (wi.z <= 0.0f || dot(ls.wi, sideNormal) <= 0.0f) return vec3(0.0f);  // light behind the surface
    vec3 f = evalBsdf(bsdf, wo, wi);
    if (f.r + f.g + f.b <= 0.0f) return vec3(0.0f);
    vec3 origin = offsetRayOrigin(hit.position, hit.geometricNormal, ls.wi);
    float tMax = ls.delta && ls.distance >= kInfinity ? kInfinity : ls.distance * 0.9999f;
    if (traceAny(origin, ls.wi, tMax)) return vec3(0.0f);
    float weight = ls.delta ? 1.0f : powerHeuristic(ls.pdf, pdfBsdf(bsdf, wo, wi));
    return f * wi.z * ls.radiance * (weight / ls.pdf);
}

vec3 tracePath(vec3 origin, vec3 dir, inout Sampler rng) {
    vec3 radiance = vec3(0.0f);
    vec3 throughput = vec3(1.0f);
    bool lastDelta = true;       // camera rays count as delta: emission is added unweighted
    float lastPdf = 0.0f;
    vec3 mediumSigma = vec3(0.0f);  // absorption of the solid the ray is inside (Beer-Lambert)
    bool useNee = (params.flags & kPathFlagNoDirectLightSampling) == 0u;

    for (uint depth = 0u; depth <= params.maxDepth; ++depth) {
        float tHit;
        uint tri;
        float b1;
        float b2;
        if (!traceClosest(origin, dir, kInfinity, tHit, tri, b1, b2)) break;
        throughput *= exp(-mediumSigma * tHit);
        SurfaceHit hit = surfaceAt(tri, b1, b2, dir);
        GpuMaterial material = materials[hit.material];

        if (emitsTowards(material, hit.frontFace)) {
            vec3 le = emittedRadiance(material, hit.uv);
            if (le.r + le.g + le.b > 0.0f) {
                float weight = 1.0f;
                if (useNee && !lastDelta) {
                    float cosLight = abs(dot(dir, hit.geometricNormal));
                    float lightPdf = hit.emitterPdfArea * tHit * tHit / max(cosLight, 1.0e-8f);
                    weight = powerHeuristic(lastPdf, lightPdf);
                }
                radiance += throughput * le * weight;
            }
        }
        if (depth == params.maxDepth) break;

        BsdfParams bsdf = bsdfParamsAt(material, hit.uv);
        // Shading frame on the side the ray came from.
        vec3 n = hit.frontFace ? hit.shadingNormal : -hit.shadingNormal;
        vec3 t;
        vec3 b;
        orthonormalBasis(n, t, b);
        vec3 wo = toLocal(-dir, t, b, n);
        if (wo.z <= 0.0f) wo.z = 1.0e-4f;  // shading normal facing away: treat as grazing

        if (useNee) radiance += throughput * directLight(hit, bsdf, wo, t, b, n, rng);
        else { nextSample(rng); nextSample(rng); nextSample(rng); }

        vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        BsdfSample bs = sampleBsdf(bsdf, wo, hit.frontFace, true, u);
        float uRoulette = nextSample(rng);
        if (bs.lobe == kLobeNone) break;
        throughput *= bs.weight;
        lastDelta = (bs.lobe & kLobeDelta) != 0u;
        lastPdf = bs.pdf;
        dir = normalize(toWorld(bs.wi, t, b, n));
        origin = offsetRayOrigin(hit.position, hit.geometricNormal, dir);

        // Entering or leaving a solid with KHR_materials_volume absorption.
        if ((bs.lobe & kLobeTransmission) != 0u && (material.flags & kMaterialThinWalled) == 0u)
            mediumSigma = hit.frontFace ? material.attenuationCoeff : vec3(0.0f);

        // Russian roulette after a few bounces, survival by the throughput's largest component.
        if (depth >= 3u) {
            float survive = min(max(throughput.r, max(throughput.g, throughput.b)), 0.95f);
            if (uRoulette >= survive) break;
            throughput /= survive;
        }
    }
    return radiance;
}

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    uint px = pixel % params.width;
    uint py = pixel / params.width;
    uint streamSeed = hashCombine(params.seed, pixel);
    vec4 acc = film[pixel];
    for (uint i = 0u; i < params.sampleCount; ++i) {
        Sampler rng = makeSampler(params.firstSample + i, streamSeed);
        vec2 jitter = nextSample2(rng);
        vec3 dir = cameraRayDirection(vec2(float(px) + jitter.x, float(py) + jitter.y));
        vec3 l = tracePath(params.camera.position, dir, rng);
        if (any(isnan(l)) || any(isinf(l))) {
            atomicAdd(counters[0], 1u);
            l = vec3(0.0f);
        }
        acc += vec4(l, 1.0f);
    }
    film[pixel] = acc;
}
