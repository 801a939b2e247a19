// Shadow volume geometry for up to four lights (one mask pass): one invocation per (triangle,
// light) writes kVolumeVerticesPerTriangle homogeneous vertices, unused ones as degenerate
// triangles. Volumes are closed and outward-facing, with caps, extruded to infinity (w = 0), as
// z-fail counting needs (Dmitriev et al. 2002, section 6.1; Everitt & Kilgard 2002):
//   closed 2-manifold components: front cap = light-facing triangles, back cap = their extrusion,
//     sides = silhouette edges (facing triangle whose neighbour across the edge does not face);
//   everything else: each triangle, turned to face the light, gets its own closed volume, so open
//     and non-manifold meshes shadow correctly at the cost of more fill.
// Reads: shadow triangles, raster lights. Writes: volume vertices (shared/kernels/raster_direct.glsl).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/raster_direct.glsl"
#include "shared/gpu_types.glsl"
#include "shared/shadow_volume.glsl"

layout(local_size_x = kShadowVolumeGroupSize) in;

layout(std430, set = 0, binding = kShadowVolumeTriangleBinding) readonly buffer Tris { GpuShadowTriangle tris[]; };
layout(std430, set = 0, binding = kShadowVolumeLightBinding) readonly buffer Lights { GpuLight lights[]; };
layout(std430, set = 0, binding = kShadowVolumeVertexBinding) writeonly buffer Volumes { vec4 volumeVertices[]; };
layout(push_constant) uniform Push { ShadowVolumeParams params; };

// The light as a homogeneous point: (position, 1), or (-direction, 0) for directional lights.
vec4 lightPoint(GpuLight light) {
    if (light.type == kLightDirectional) return vec4(-light.direction, 0.0f);
    return vec4(light.position, 1.0f);
}

// Signed facing of triangle (a, b, c) towards the light: > 0 when the light is on its front side.
float facing(vec3 a, vec3 b, vec3 c, vec4 l) {
    return dot(cross(b - a, c - a), l.xyz - a * l.w);
}

bool faces(uint t, vec4 l) {
    GpuShadowTriangle s = tris[t];
    return facing(s.v0.xyz, s.v1.xyz, s.v2.xyz, l) > 0.0f;
}

// A vertex pushed away from the light to infinity.
// precise: every use of a vertex's extrusion (back cap, both adjacent sides) must be bit-identical,
// or shared edges crack and the top-left rule no longer counts each pixel once.
vec4 extrude(vec3 p, vec4 l) {
    precise vec3 d = p * l.w - l.xyz;
    return vec4(d, 0.0f);
}

uint g_out;

void emit(vec4 a, vec4 b, vec4 c) {
    volumeVertices[g_out] = a;
    volumeVertices[g_out + 1u] = b;
    volumeVertices[g_out + 2u] = c;
    g_out += 3u;
}

// Lexicographic order of points, to split shared side quads the same way from both triangles.
bool lessThanPoint(vec3 p, vec3 q) {
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return p.z < q.z;
}

// Side quad of edge a -> b (counter-clockwise seen from the light), facing out of the volume.
// Neighbouring per-triangle volumes emit the same quad with opposite orientation, and the two must
// cancel pixel for pixel: both split it along the same diagonal (from the lexicographically
// smaller endpoint lo to the other's extrusion) and list each triangle from lo, only the winding
// differs. Otherwise rounding in the two triangulations makes their depths differ where the quad
// meets the surface, leaving a seam of false shadow along the shared edge.
void emitSide(vec3 a, vec3 b, vec4 l) {
    bool forward = lessThanPoint(a, b);
    vec3 lo = forward ? a : b;
    vec3 hi = forward ? b : a;
    vec4 plo = vec4(lo, 1.0f);
    vec4 phi = vec4(hi, 1.0f);
    vec4 elo = extrude(lo, l);
    vec4 ehi = extrude(hi, l);
    if (forward) {
        emit(plo, elo, ehi);
        emit(plo, ehi, phi);
    } else {
        emit(plo, ehi, elo);
        emit(plo, phi, ehi);
    }
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= params.triangleCount * params.lightCount) return;
    uint t = i % params.triangleCount;
    uint slot = i / params.triangleCount;
    vec4 l = lightPoint(lights[params.firstLight + slot]);
    uint base = i * kVolumeVerticesPerTriangle;
    g_out = base;

    GpuShadowTriangle s = tris[t];
    vec3 v[3] = vec3[3](s.v0.xyz, s.v1.xyz, s.v2.xyz);
    float f = facing(v[0], v[1], v[2], l);
    bool emitAll = s.closed == 0u;
    if (emitAll && f < 0.0f) {  // open: turn the triangle towards the light
        vec3 tmp = v[1];
        v[1] = v[2];
        v[2] = tmp;
        f = -f;
    }
    if (f > 0.0f) {
        emit(vec4(v[0], 1.0f), vec4(v[1], 1.0f), vec4(v[2], 1.0f));    // front cap
        emit(extrude(v[0], l), extrude(v[2], l), extrude(v[1], l));    // back cap, reversed
        uint nb[3] = uint[3](s.neighbor0, s.neighbor1, s.neighbor2);
        for (uint e = 0u; e < 3u; ++e) {
            // Silhouette: the neighbour across the edge does not face the light. For closed
            // triangles the edge order is the stored one (f > 0 was not flipped).
            if (emitAll || !faces(nb[e], l)) emitSide(v[e], v[(e + 1u) % 3u], l);
        }
    }
    for (uint k = g_out; k < base + kVolumeVerticesPerTriangle; ++k) volumeVertices[k] = vec4(0.0f);
}
