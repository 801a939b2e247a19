// Importon tracing (Keller & Wald 2000, §2.2, after Peter & Pietrek): camera paths, indexed by
// Halton point like photon paths, followed through delta bounces and stored at every surface that
// stores photons, a few bounces deep, carrying visual importance. Path i fills the slots
// i * maxDeposits + k, so the result does not depend on scheduling. The record, GpuImporton, is
// described in shared/importance.glsl.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/importons.glsl"
#include "render/scene_access.glsl"
#include "render/path_vertex.glsl"
#include "shared/halton.glsl"
#include "shared/importance.glsl"
#include "shared/photon.glsl"

layout(local_size_x = kImportonGroupSize) in;

layout(std430, set = 0, binding = kImportonTraceImportonBinding) writeonly buffer Importons { GpuImporton importons[]; };

layout(push_constant) uniform Push { ImportonTraceParams params; };

const uint kImportonStream = 0x494d5054u;  // "IMPT"

void traceImporton() {
    uint local = gl_GlobalInvocationID.x;
    if (local >= params.pathCount) return;
    Sampler rng = makeSampler(params.firstPath + local, hashCombine(params.seed, kImportonStream));
    vec2 film = nextSample2(rng);
    vec2 filmPixel = film * vec2(float(params.width), float(params.height));
    Ray ray = cameraRay(params.camera, params.width, params.height, filmPixel);
    vec3 throughput = vec3(1.0f);
    // The last stored vertex y and f_r(y) cos(y) towards the next one, for the path importance.
    bool haveY = false;
    vec3 yPosition = vec3(0.0f);
    float yScatter = 0.0f;
    float yAlbedo = 1.0f;  // luminance of the throughput up to y: the albedo of earlier bounces

    uint slot = local * params.maxDeposits;
    uint stored = 0u;
    uint bounces = 0u;  // bounces taken and whether a break ended the path (else its bounds did,
    bool ended = false; // or lavapipe's loop budget cut it: fewer bounces than the bounds allow)
    for (uint depth = 0u; depth < params.maxDepth && stored < params.maxDeposits; ++depth) {
        bounces += 1u;
        PathVertex v;
        if (!traceVertex(ray, v)) {
            ended = true;
            break;
        }
        throughput *= v.transmittance;
        vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        BsdfSample bs = sampleVertexBsdf(v, true, u);

        if (storesPhotons(v.bsdf)) {
            float pathImportance = 0.0f;
            if (haveY) {
                vec3 d = v.hit.position - yPosition;
                // Clamped to the range makeImporton rounds to half precision in (corners make
                // 1 / |x - y|^2 unbounded).
                pathImportance = min(yAlbedo * yScatter * v.wo.z / max(dot(d, d), 1.0e-8f), kMaxHalfFloat);
            }
            uint flags = kImportonValid | (stored == 0u && !haveY ? kImportonPrimary : 0u);
            importons[slot + stored] = makeImporton(v.hit.position, luminance(throughput), pathImportance, v.n, flags);
            stored += 1u;
            haveY = true;
            yPosition = v.hit.position;
            yAlbedo = luminance(throughput);
            yScatter = bs.lobe == kLobeNone ? 0.0f : luminance(evalVertexBsdf(v, bs.wi)) * abs(bs.wi.z);
        }
        if (bs.lobe == kLobeNone || !(luminance(throughput * bs.weight) > 0.0f)) {
            ended = true;
            break;
        }
        throughput *= bs.weight;
        spawnRay(v, bs, ray);
    }
    if (!ended && stored < params.maxDeposits) noteLoopCut(bounces, params.maxDepth);
}

void main() {
    traceImporton();
    countTerminations(kTerminationImportonPaths);  // rays and gathers this invocation's bounds cut short
}
