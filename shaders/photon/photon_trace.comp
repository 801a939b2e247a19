// Photon tracing (Jensen's first pass, as in shared/papers/004): photon path i is generated
// entirely from Halton point i — light choice by power, position on the light, direction, then
// per bounce BSDF sampling and Russian roulette with unmodified power — so any path can be
// regenerated (and later retraced in place) from its index alone.
//
// Photons are stored at every hit on a surface that stores photons (diffuse or broadly glossy;
// shared/bsdf.glsl storesPhotons), in the fixed slot (path - firstPath) * maxDeposits + k of the k-th stored photon of the path,
// so the result does not depend on scheduling. Flags: primary (first hit after the light),
// caustic (light -> one or more mirror-like bounces -> here: L S+ D); all others are global photons.
// Power is stored relative to the nominal photon power totalPower / pathCount.
// A path that makes more deposits n than it has slots M goes on: its slots keep a uniform random
// M of its n deposits (reservoir sampling, Vitter's algorithm R, from a hash of the path and the
// deposit's number, so the path's own trajectory is unchanged), each then weighted n / M: the
// map's expected flux is every deposit's, as if the path had n slots (ending the path at M lost
// the light it still carried: 17 % of a furnace of albedo 0.8 at 8 slots).
// With params.trackPaths each path also writes its track (shared/path_track.glsl): its ray origins,
// last hit or escape direction and light, which a selective update tests against what moved.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_trace.glsl"
#include "render/scene_access.glsl"
#include "render/path_vertex.glsl"
#include "shared/halton.glsl"
#include "shared/photon.glsl"
#include "shared/path_track.glsl"

layout(local_size_x = kPhotonTraceGroupSize) in;

layout(std430, set = 0, binding = kPhotonTracePhotonBinding) buffer Photons { GpuPhoton photons[]; };
layout(std430, set = 0, binding = kPhotonTraceCounterBinding) buffer Counters { uint counters[]; };
layout(std430, set = 0, binding = kPhotonTracePathListBinding) readonly buffer PathList { uint pathList[]; };
layout(std430, set = 0, binding = kPhotonTraceTrackBinding) writeonly buffer Tracks { GpuPathTrack tracks[]; };

layout(push_constant) uniform Push { PhotonTraceParams params; };

// Photon paths share one scrambling of the Halton sequence per run: the sample index alone
// tells paths apart (the periodicity selective photon tracing relies on).
const uint kPhotonStream = 0x50484f54u;  // "PHOT"
const uint kReservoirStream = 0x52535652u;  // "RSVR": which slot a deposit past the path's slots replaces

// The counter of stored photons of a photon's kind.
uint storedCounter(uint flags) {
    if ((flags & kPhotonPrimary) != 0u) return kPhotonCounterStoredPrimary;
    if ((flags & kPhotonCaustic) != 0u) return kPhotonCounterStoredCaustic;
    return kPhotonCounterStoredGlobal;
}

// Deposit number `deposits` (1-based) of a path whose `maxDeposits` slots are full: the slot it
// replaces with probability maxDeposits / deposits (Vitter's algorithm R), or maxDeposits for none.
uint reservoirSlot(uint path, uint deposits) {
    uint h = hashCombine(hashCombine(hashCombine(params.seed, kReservoirStream), path), deposits);
    return min(uint(uintToUnitFloat(h) * float(deposits)), deposits - 1u);
}

struct EmittedPhoton {
    vec3 origin;
    vec3 dir;
    vec3 flux;     // watts carried by this photon (before dividing by the number of paths)
    vec3 normal;   // surface normal at the emission point (zero for punctual lights)
};

// Samples the emission of light `index` from 4 sample dimensions. flux is the light's emitted
// power as seen through this sample: (emitted radiance or intensity) / (pdf of the sample),
// divided by the light's selection probability.
EmittedPhoton emitPhoton(uint index, vec2 uPosition, vec2 uDirection, float uSide) {
    GpuLight light = lights[index];
    EmittedPhoton e;
    e.normal = vec3(0.0f);
    if (light.type == kLightTriangle) {
        GpuTriangle t = triangles[light.triangle];
        GpuTriangleShading s = shading[light.triangle];
        vec2 b = sampleTriangleBarycentrics(uPosition);
        vec3 c = cross(t.v1.xyz - t.v0.xyz, t.v2.xyz - t.v0.xyz);
        float area = 0.5f * length(c);
        vec3 n = c / (2.0f * area);
        GpuMaterial m = materials[s.material];
        float sides = 1.0f;
        if ((m.flags & kMaterialDoubleSided) != 0u) {
            sides = 2.0f;
            if (uSide < 0.5f) n = -n;
        }
        vec3 tangent;
        vec3 bitangent;
        orthonormalBasis(n, tangent, bitangent);
        e.origin = (1.0f - b.x - b.y) * t.v0.xyz + b.x * t.v1.xyz + b.y * t.v2.xyz;
        e.origin = offsetRayOrigin(e.origin, n, n);
        e.dir = toWorld(sampleCosineHemisphere(uDirection), tangent, bitangent, n);
        e.normal = n;
        // Le cos / (1/A * cos/pi * 1/sides): cosine sampling cancels the cosine.
        e.flux = emittedRadiance(m, interpolatedUv(s, b.x, b.y)) * (kPi * area * sides) / light.selectPdf;
        return e;
    }
    if (light.type == kLightEnvironment) {
        // A direction towards the environment from its distribution (sampleEnvironment), then a
        // point on a disk of the scene's bounding radius perpendicular to it, outside the scene:
        // Le cos / (pdf(w) * 1 / (pi r^2)) with the disk facing the photon (cos = 1).
        vec3 radiance;
        float pdf;
        vec3 w = sampleEnvironment(light, uDirection, radiance, pdf);
        vec3 tangent;
        vec3 bitangent;
        orthonormalBasis(-w, tangent, bitangent);
        float r = params.sceneRadius * sqrt(uPosition.x);
        float phi = kTwoPi * uPosition.y;
        e.origin = params.sceneCenter + w * (2.0f * params.sceneRadius) + r * (cos(phi) * tangent + sin(phi) * bitangent);
        e.dir = -w;
        e.flux = pdf > 0.0f ? radiance * (kPi * params.sceneRadius * params.sceneRadius) / (pdf * light.selectPdf) : vec3(0.0f);
        return e;
    }
    if (light.type == kLightDirectional) {
        // A disk of the scene's bounding radius perpendicular to the light, outside the scene.
        vec3 tangent;
        vec3 bitangent;
        orthonormalBasis(light.direction, tangent, bitangent);
        float r = params.sceneRadius * sqrt(uPosition.x);
        float phi = kTwoPi * uPosition.y;
        e.origin = params.sceneCenter - light.direction * (2.0f * params.sceneRadius) +
                   r * (cos(phi) * tangent + sin(phi) * bitangent);
        e.dir = light.direction;
        e.flux = light.intensity * (kPi * params.sceneRadius * params.sceneRadius) / light.selectPdf;
        return e;
    }
    e.origin = light.position;
    if (light.type == kLightSpot) {
        // Uniform in the outer cone, weighted by the smooth falloff.
        float cosOuter = -light.spotOffset / light.spotScale;
        vec3 tangent;
        vec3 bitangent;
        orthonormalBasis(light.direction, tangent, bitangent);
        vec3 local = sampleUniformCone(uDirection, cosOuter);
        e.dir = toWorld(local, tangent, bitangent, light.direction);
        float f = clamp(local.z * light.spotScale + light.spotOffset, 0.0f, 1.0f);
        e.flux = light.intensity * (f * f * kTwoPi * (1.0f - cosOuter)) / light.selectPdf;
        return e;
    }
    e.dir = sampleUniformSphere(uDirection);
    e.flux = light.intensity * (4.0f * kPi) / light.selectPdf;
    return e;
}

// The path's track as it is traced: vertex k of the path (a ray origin or its last hit) kept
// exactly while k < kPathTrackVertices, and from the last kept one on bounded by a box.
uint trackCount = 0u;
vec3 trackLo = vec3(kInfinity);
vec3 trackHi = vec3(-kInfinity);

void trackVertex(uint local, vec3 p) {
    if (params.trackPaths == 0u) return;
    if (trackCount < kPathTrackVertices) tracks[local].vertex[trackCount] = vec4(p, 0.0f);
    if (trackCount + 1u >= kPathTrackVertices) {
        trackLo = min(trackLo, p);
        trackHi = max(trackHi, p);
    }
    trackCount += 1u;
}

void main() {
    uint local = gl_GlobalInvocationID.x;
    if (local >= params.pathCount || params.lightCount == 0u) return;
    uint offset = params.pathList != 0u ? pathList[local] : local * max(params.pathStride, 1u);
    Sampler rng = makeSampler(params.firstPath + offset, hashCombine(params.seed, kPhotonStream));
    float uLight = nextSample(rng);
    vec2 uPosition = nextSample2(rng);
    vec2 uDirection = nextSample2(rng);
    float uSide = nextSample(rng);
    uint lightIndex = pickLight(uLight, params.lightCount);
    EmittedPhoton e = emitPhoton(lightIndex, uPosition, uDirection, uSide);
    // Relative to the nominal photon power totalPower / pathCount.
    vec3 power = e.flux / params.totalPower;

    uint slot = local * params.maxDeposits;
    uint deposits = 0u;  // of the map's kind, stored or not
    bool onlySpecularSoFar = true;  // every bounce since the light was a delta lobe
    Ray ray = rayFrom(e.origin, e.dir);
    uint outcome = kPhotonCounterCount;  // set by each break below; left as is, the loop's bound or
    uint bounces = 0u;                   // lavapipe's budget ended the path (fewer bounces)
    vec3 lastHit = vec3(0.0f);
    bool endsAtHit = false;  // the path's last ray hit a surface (else it left the scene or was cut before tracing)
    for (uint depth = 0u; depth < kPhotonMaxBounces; ++depth) {
        bounces += 1u;
        PathVertex v;
        trackVertex(local, ray.origin);
        endsAtHit = false;
        if (!traceVertex(ray, v)) {
            outcome = kPhotonCounterLost;
            break;
        }
        endsAtHit = true;
        lastHit = v.hit.position;
        power *= v.transmittance;

        if (storesPhotons(v.bsdf)) {
            uint flags = kPhotonValid;
            if (depth == 0u) {
                flags |= kPhotonPrimary;
            } else if (onlySpecularSoFar) {
                flags |= kPhotonCaustic;
            }
            if ((flags & params.requiredFlags) == params.requiredFlags) {
                deposits += 1u;
                uint k = deposits <= params.maxDeposits ? deposits - 1u : reservoirSlot(params.firstPath + offset, deposits);
                if (k < params.maxDeposits) {
                    // The kinds' counters bound the map's compaction: a replaced photon leaves its own.
                    if (deposits > params.maxDeposits) atomicAdd(counters[storedCounter(photonFlags(photons[slot + k]))], ~0u);
                    photons[slot + k] = makePhoton(v.hit.position, power, -ray.dir, v.n, flags, lightIndex);
                    atomicAdd(counters[storedCounter(flags)], 1u);
                }
            }
        }

        vec3 u = vec3(nextSample(rng), nextSample(rng), nextSample(rng));
        float uRoulette = nextSample(rng);
        BsdfSample bs = sampleVertexBsdf(v, false, u);
        if (bs.lobe == kLobeNone) {
            outcome = kPhotonCounterAbsorbed;
            break;
        }
        // Russian roulette with (nearly) unmodified power: survive with the probability of the
        // scattering weight's largest channel; the power only changes by the weight's colour.
        float survive = min(max(bs.weight.r, max(bs.weight.g, bs.weight.b)), 1.0f);
        if (uRoulette >= survive) {
            outcome = kPhotonCounterAbsorbed;
            break;
        }
        power *= bs.weight / survive;
        onlySpecularSoFar = onlySpecularSoFar && ((bs.lobe & kLobeDelta) != 0u || !storesPhotons(v.bsdf));
        // A map of primary or caustic photons only: the path can make no more of them.
        if ((params.requiredFlags & kPhotonPrimary) != 0u ||
            ((params.requiredFlags & kPhotonCaustic) != 0u && !onlySpecularSoFar)) {
            outcome = kPhotonCounterTruncated;
            break;
        }
        spawnRay(v, bs, ray);
    }
    if (outcome == kPhotonCounterCount) {
        noteTermination(bounces < kPhotonMaxBounces ? kTerminationLoopLimit : kTerminationLoopBound);
        outcome = kPhotonCounterTruncated;
    }
    atomicAdd(counters[outcome], 1u);
    if (params.trackPaths != 0u) {
        if (endsAtHit) trackVertex(local, lastHit);
        uint header = min(trackCount, kPathTrackVertices);
        if (trackCount > kPathTrackVertices) header |= kPathTrackOverflow;
        if (outcome == kPhotonCounterLost) header |= kPathTrackEscaped;
        tracks[local].vertex[0].w = uintBitsToFloat(header);
        tracks[local].vertex[1].w = uintBitsToFloat(lightIndex);
        tracks[local].vertex[2].w = ray.dir.x;
        tracks[local].vertex[3].w = ray.dir.y;
        tracks[local].vertex[4].w = ray.dir.z;
        tracks[local].boxLo = vec4(trackLo, 0.0f);
        tracks[local].boxHi = vec4(trackHi, 0.0f);
    }
    if (deposits > params.maxDeposits) {  // each kept deposit stands for deposits / maxDeposits of them
        float weight = float(deposits) / float(params.maxDeposits);
        for (uint k = 0u; k < params.maxDeposits; ++k) {
            GpuPhoton p = photons[slot + k];
            photons[slot + k] = withRelativePower(p, min(photonRelativePower(p) * weight, vec3(kMaxHalfFloat)));
        }
        atomicAdd(counters[kPhotonCounterSampled], 1u);
    }
    countTerminations(kTerminationPhotonPaths);
}
