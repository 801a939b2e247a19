// The compact photon record (32 bytes) and its packing. Shared by the photon tracing pass, the
// hash grid and the gathers; the host reads it for export and tests.
#ifndef VKP_PHOTON_GLSL
#define VKP_PHOTON_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

const uint kPhotonValid = 1u;    // the slot holds a stored photon (slots of absorbed paths stay 0)
const uint kPhotonCaustic = 2u;  // path light -> specular+ -> here (L S+ D): the caustic map
const uint kPhotonPrimary = 4u;  // first hit after the light (direct): skipped by indirect estimates

// Largest finite value a half float (a photon's relative power) holds.
const float kMaxHalfFloat = 65504.0f;

// Power is stored relative to the nominal photon power of the map (total emitted power / photons
// emitted, kept by the host), as half floats: values near 1, 11-bit precision.
struct GpuPhoton {
    vec3 position;        // world space
    uint powerRG;         // packHalf2x16(relative power r, g)
    uint powerBFlags;     // low 16 bits: half relative power b; high 16 bits: kPhoton* flags
    uint direction;       // octahedral unit vector (16+16 bits): towards where the photon came from
    uint normal;          // octahedral unit vector (16+16 bits): surface normal on the arrival side
    uint lightIndex;      // index of the emitting light (GpuLight buffer)
};
STATIC_ASSERT_SIZE(GpuPhoton, 32)

// Octahedral encoding of unit vectors (Cigolle et al., "A Survey of Efficient Representations for
// Independent Unit Vectors", JCGT 2014), 16 bits per coordinate.
INLINE vec2 signNotZero(vec2 v) {
    return vec2(v.x >= 0.0f ? 1.0f : -1.0f, v.y >= 0.0f ? 1.0f : -1.0f);
}

INLINE uint encodeOctahedral(vec3 n) {
    float l1 = abs(n.x) + abs(n.y) + abs(n.z);
    vec2 p = vec2(n.x, n.y) / l1;
    if (n.z < 0.0f) {
        vec2 s = signNotZero(p);
        p = vec2((1.0f - abs(p.y)) * s.x, (1.0f - abs(p.x)) * s.y);
    }
    return packSnorm2x16(p);
}

INLINE vec3 decodeOctahedral(uint packed) {
    vec2 p = unpackSnorm2x16(packed);
    vec3 n = vec3(p.x, p.y, 1.0f - abs(p.x) - abs(p.y));
    if (n.z < 0.0f) {
        vec2 s = signNotZero(vec2(n.x, n.y));
        n = vec3((1.0f - abs(n.y)) * s.x, (1.0f - abs(n.x)) * s.y, n.z);
    }
    return normalize(n);
}

INLINE GpuPhoton makePhoton(vec3 position, vec3 relativePower, vec3 direction, vec3 normal, uint flags,
                            uint lightIndex) {
    GpuPhoton p;
    p.position = position;
    p.powerRG = packHalf2x16(vec2(relativePower.x, relativePower.y));
    p.powerBFlags = (packHalf2x16(vec2(relativePower.z, 0.0f)) & 0xffffu) | (flags << 16u);
    p.direction = encodeOctahedral(direction);
    p.normal = encodeOctahedral(normal);
    p.lightIndex = lightIndex;
    return p;
}

// The photon with another relative power (position, directions and flags bit for bit the same).
INLINE GpuPhoton withRelativePower(GpuPhoton p, vec3 relativePower) {
    p.powerRG = packHalf2x16(vec2(relativePower.x, relativePower.y));
    p.powerBFlags = (packHalf2x16(vec2(relativePower.z, 0.0f)) & 0xffffu) | (p.powerBFlags & 0xffff0000u);
    return p;
}

INLINE vec3 photonRelativePower(GpuPhoton p) {
    vec2 rg = unpackHalf2x16(p.powerRG);
    float b = unpackHalf2x16(p.powerBFlags & 0xffffu).x;
    return vec3(rg.x, rg.y, b);
}

INLINE uint photonFlags(GpuPhoton p) {
    return p.powerBFlags >> 16u;
}

// Push constants of photon_trace.comp.
struct PhotonTraceParams {
    vec3 sceneCenter;     // bounding sphere of the scene (directional lights emit from its disk)
    float sceneRadius;
    uint firstPath;       // Halton index of the first photon path of this dispatch
    uint pathCount;
    uint maxDeposits;     // photon slots per path: slot = (path - firstPath) * maxDeposits + k
    uint seed;
    uint lightCount;
    float totalPower;     // watts, luminance-weighted sum over the lights (SceneArrays)
    uint pathStride;      // 0 or 1: paths firstPath, firstPath+1, ...; N: firstPath + local * N (one
                          // selective-update group, docs/photon-mapping.md); slots stay local * maxDeposits + k
    uint pathList;        // 1: path `local` is firstPath + pathList[local] (the path-list binding: a
                          // selective update's marked groups in one dispatch), pathStride ignored; 0: off
    uint requiredFlags;   // kPhotonPrimary / kPhotonCaustic: the only kind the map keeps. Other deposits
                          // take no slot, and a path ends once it can make no more of that kind (the
                          // caustic map's paths pass photon-storing surfaces they leave by a delta lobe)
    uint trackPaths;      // 1: write each path's track (shared/path_track.glsl) at the track binding, path
                          // `local` at index local (a selective update's exact change detection); 0: off
    uint pad1;
    uint pad2;
};
STATIC_ASSERT_SIZE(PhotonTraceParams, 64)

SHARED_END
#endif
