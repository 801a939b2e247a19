// Auxiliary images for denoisers and compositing (--aov, docs/output.md): per pixel, camera rays
// followed through delta bounces (mirrors, smooth glass) to the first surface with a non-delta
// lobe, as Open Image Denoise expects its albedo and normal: the surface's base colour (textured)
// and its world-space shading normal facing the ray, averaged over kAovSamples jittered rays;
// the depth is the distance along the camera's forward axis to the first surface the centre ray
// hits (kAovBackgroundDepth where it escapes). Rays that escape add the environment's radiance
// as albedo (a visible sky is its own albedo, as OIDN suggests) and a zero normal.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/aov.glsl"
#include "render/scene_access.glsl"
#include "render/path_vertex.glsl"
#include "shared/halton.glsl"

layout(local_size_x = kAovGroupSize) in;

layout(std430, set = 0, binding = kAovAlbedoBinding) writeonly buffer Albedo { vec4 albedo[]; };
layout(std430, set = 0, binding = kAovNormalBinding) writeonly buffer Normal { vec4 normalDepth[]; };

layout(push_constant) uniform Push { AovParams params; };

const uint kAovStream = 0x414f5653u;  // "AOVS"

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    vec3 albedoSum = vec3(0.0f);
    vec3 normalSum = vec3(0.0f);
    float depth = kAovBackgroundDepth;
    for (uint s = 0u; s < kAovSamples; ++s) {
        Sampler rng = makePixelSampler(s, kAovSamples, hashCombine(hashCombine(params.seed, kAovStream), pixel));
        vec2 jitter = s == 0u ? vec2(0.5f) : nextSample2(rng);
        Ray ray = cameraRay(params.camera, params.width, params.height,
                            vec2(float(pixel % params.width) + jitter.x, float(pixel / params.width) + jitter.y));
        for (uint bounce = 0u; bounce <= params.maxSpecularDepth; ++bounce) {
            PathVertex v;
            if (!traceVertex(ray, v)) {
                int env = environmentLightIndex(uint(lights.length()));
                if (env >= 0) albedoSum += min(environmentRadiance(lights[env], ray.dir), vec3(1.0f));
                break;
            }
            if (s == 0u && bounce == 0u) depth = dot(v.hit.position - params.camera.position, params.camera.forward);
            bool onlyDelta = (specularLobeIsDelta(v.bsdf) && v.bsdf.metallic >= 1.0f) || (specularIsDelta(v.bsdf) && v.bsdf.transmission >= 1.0f);
            if (!onlyDelta || bounce == params.maxSpecularDepth) {
                albedoSum += v.bsdf.baseColor;
                normalSum += v.n;
                break;
            }
            vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
            BsdfSample bs = sampleVertexBsdf(v, true, u);
            if (bs.lobe == kLobeNone) break;
            spawnRay(v, bs, ray);
        }
    }
    float n = length(normalSum);
    albedo[pixel] = vec4(albedoSum / float(kAovSamples), 0.0f);
    normalDepth[pixel] = vec4(n > 0.0f ? normalSum / n : vec3(0.0f), depth);
}
