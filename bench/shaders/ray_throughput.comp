// Ray throughput kernel for bench/path_tracer_bench.cpp. mode 0: one camera ray per pixel
// (coherent); mode 1: from each camera hit, one cosine-distributed diffuse bounce ray
// (incoherent). Only the bounce ray is timed in mode 1 by subtracting mode 0 on the host.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "bench_kernels.glsl"
#include "render/scene_access.glsl"
#include "shared/halton.glsl"

layout(local_size_x = kBenchGroupSize) in;
layout(std430, set = 0, binding = kRayBenchResultBinding) buffer Result { uint hitCount[]; };

layout(push_constant) uniform Push { RayBenchParams push; };

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= push.width * push.height) return;
    Sampler rng = makeSampler(push.seed, hashCombine(7u, pixel));
    vec2 jitter = nextSample2(rng);
    vec2 ndc = vec2(2.0f * (float(pixel % push.width) + jitter.x) / float(push.width) - 1.0f,
                    1.0f - 2.0f * (float(pixel / push.width) + jitter.y) / float(push.height));
    vec3 dir = normalize(push.camera.forward + ndc.x * push.camera.aspect * push.camera.tanHalfFovY * push.camera.right +
                         ndc.y * push.camera.tanHalfFovY * push.camera.up);
    float t;
    uint tri;
    float b1;
    float b2;
    uint hits = 0u;
    if (traceClosest(push.camera.position, dir, kInfinity, true, t, tri, b1, b2)) {
        hits = 1u;
        if (push.mode == 1u) {
            SurfaceHit hit = surfaceAt(tri, b1, b2, dir, 0.0f);
            vec3 n = hit.frontFace ? hit.geometricNormal : -hit.geometricNormal;
            vec3 tangent;
            vec3 bitangent;
            orthonormalBasis(n, tangent, bitangent);
            vec3 bounce = toWorld(sampleCosineHemisphere(nextSample2(rng)), tangent, bitangent, n);
            vec3 origin = offsetRayOrigin(hit.position, n, bounce);
            if (traceClosest(origin, bounce, kInfinity, false, t, tri, b1, b2)) hits = 2u;
        }
    }
    hitCount[pixel] = hits;
}
