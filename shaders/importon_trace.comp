// Importon tracing (Keller & Wald 2000, §2.2, after Peter & Pietrek): camera paths, indexed by
// Halton point like photon paths, followed through delta bounces and stored at every surface that
// stores photons, a few bounces deep, carrying visual importance. Path i fills the slots
// i * maxDeposits + k, so the result does not depend on scheduling. The record layout is
// described in shared/importance.glsl.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/importons.glsl"
#include "scene_access.glsl"
#include "shared/halton.glsl"
#include "shared/importance.glsl"
#include "shared/photon.glsl"

layout(local_size_x = kImportonGroupSize) in;

layout(std430, set = 0, binding = kImportonTraceImportonBinding) writeonly buffer Importons { GpuPhoton importons[]; };

layout(push_constant) uniform Push { ImportonTraceParams params; };

const uint kImportonStream = 0x494d5054u;  // "IMPT"

void main() {
    uint local = gl_GlobalInvocationID.x;
    if (local >= params.pathCount) return;
    Sampler rng = makeSampler(params.firstPath + local, hashCombine(params.seed, kImportonStream));
    vec2 film = nextSample2(rng);
    vec3 origin = params.camera.position;
    vec3 dir = cameraRayDirection(params.camera, params.width, params.height,
                                  film * vec2(float(params.width), float(params.height)));
    vec3 throughput = vec3(1.0f);
    // The last stored vertex y and f_r(y) cos(y) towards the next one, for the path importance.
    bool haveY = false;
    vec3 yPosition = vec3(0.0f);
    float yScatter = 0.0f;
    float yAlbedo = 1.0f;  // luminance of the throughput up to y: the albedo of earlier bounces
    vec3 mediumSigma = vec3(0.0f);

    uint slot = local * params.maxDeposits;
    uint stored = 0u;
    for (uint depth = 0u; depth < params.maxDepth && stored < params.maxDeposits; ++depth) {
        float tHit;
        uint tri;
        float b1;
        float b2;
        if (!traceClosest(origin, dir, kInfinity, tHit, tri, b1, b2)) break;
        throughput *= exp(-mediumSigma * tHit);
        SurfaceHit hit = surfaceAt(tri, b1, b2, dir);
        GpuMaterial material = materials[hit.material];
        BsdfParams bsdf = bsdfParamsAt(material, hit.uv);
        vec3 n = hit.frontFace ? hit.shadingNormal : -hit.shadingNormal;
        vec3 t;
        vec3 b;
        orthonormalBasis(n, t, b);
        vec3 wo = toLocal(-dir, t, b, n);
        if (wo.z <= 0.0f) wo.z = 1.0e-4f;
        vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        BsdfSample bs = sampleBsdf(bsdf, wo, hit.frontFace, true, u);

        if (storesPhotons(bsdf)) {
            float pathImportance = 0.0f;
            if (haveY) {
                vec3 d = hit.position - yPosition;
                // Clamped to the half float's range (corners make 1 / |x - y|^2 unbounded).
                pathImportance = min(yAlbedo * yScatter * wo.z / max(dot(d, d), 1.0e-8f), kMaxHalfFloat);
            }
            uint flags = kPhotonValid | (stored == 0u && !haveY ? kPhotonPrimary : 0u);
            importons[slot + stored] = makePhoton(hit.position, vec3(luminance(throughput), pathImportance, 0.0f),
                                                  -dir, n, flags, 0u);
            stored += 1u;
            haveY = true;
            yPosition = hit.position;
            yAlbedo = luminance(throughput);
            yScatter = bs.lobe == kLobeNone ? 0.0f : luminance(evalBsdf(bsdf, wo, bs.wi)) * abs(bs.wi.z);
        }
        if (bs.lobe == kLobeNone) break;
        throughput *= bs.weight;
        if (!(luminance(throughput) > 0.0f)) break;
        dir = normalize(toWorld(bs.wi, t, b, n));
        origin = offsetRayOrigin(hit.position, hit.geometricNormal, dir);
        if ((bs.lobe & kLobeTransmission) != 0u && (material.flags & kMaterialThinWalled) == 0u)
            mediumSigma = hit.frontFace ? material.attenuationCoeff : vec3(0.0f);
    }
}
