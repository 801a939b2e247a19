// Shadow volumes in a geometry shader with triangle adjacency, the alternative to
// shadow_volume_build.comp (docs/benchmarks.md compares them; the same volumes, the same
// orientation). Input: a triangle (vertices 0, 2, 4) and the far vertex of the neighbour across
// each edge (1: edge 0-2, 3: edge 2-4, 5: edge 4-0); a neighbour with w = 0 marks a triangle of an
// open or non-manifold component, which gets a closed volume of its own.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/shadow_volume.glsl"

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 24) out;
layout(push_constant) uniform Push { RasterVolumeParams params; };

float facing(vec3 a, vec3 b, vec3 c, vec4 l) {
    return dot(cross(b - a, c - a), l.xyz - a * l.w);
}

// precise, like raster_position.vert: the front caps must land on exactly the pre-pass depths.
void put(vec4 p) {
    precise vec4 clip = params.viewProj * p;
    gl_Position = clip;
    EmitVertex();
}

// precise: every use of a vertex's extrusion (back cap, both adjacent sides) must be bit-identical,
// or shared edges crack and the top-left rule no longer counts each pixel once.
vec4 extrude(vec3 p, vec4 l) {
    precise vec3 d = p * l.w - l.xyz;
    return vec4(d, 0.0f);
}

bool lessThanPoint(vec3 p, vec3 q) {
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return p.z < q.z;
}

void main() {
    vec4 l = params.light;
    vec3 v[3] = vec3[3](gl_in[0].gl_Position.xyz, gl_in[2].gl_Position.xyz, gl_in[4].gl_Position.xyz);
    vec4 adj[3] = vec4[3](gl_in[1].gl_Position, gl_in[3].gl_Position, gl_in[5].gl_Position);
    bool open = adj[0].w == 0.0f;
    float f = facing(v[0], v[1], v[2], l);
    if (open && f < 0.0f) {
        vec3 tmp = v[1];
        v[1] = v[2];
        v[2] = tmp;
        f = -f;
    }
    if (!(f > 0.0f)) return;
    put(vec4(v[0], 1.0f));
    put(vec4(v[1], 1.0f));
    put(vec4(v[2], 1.0f));
    EndPrimitive();
    put(extrude(v[0], l));
    put(extrude(v[2], l));
    put(extrude(v[1], l));
    EndPrimitive();
    for (int e = 0; e < 3; ++e) {
        vec3 a = v[e];
        vec3 b = v[(e + 1) % 3];
        // The neighbour walks the edge the other way: (b, a, far vertex) is its winding.
        if (open || !(facing(b, a, adj[e].xyz, l) > 0.0f)) {
            // The same split and vertex order as shadow_volume_build.comp's emitSide, so the
            // opposite sides of neighbouring per-triangle volumes cancel pixel for pixel.
            bool forward = lessThanPoint(a, b);
            vec3 lo = forward ? a : b;
            vec3 hi = forward ? b : a;
            if (forward) {
                put(vec4(lo, 1.0f)); put(extrude(lo, l)); put(extrude(hi, l)); EndPrimitive();
                put(vec4(lo, 1.0f)); put(extrude(hi, l)); put(vec4(hi, 1.0f)); EndPrimitive();
            } else {
                put(vec4(lo, 1.0f)); put(extrude(hi, l)); put(extrude(lo, l)); EndPrimitive();
                put(vec4(lo, 1.0f)); put(vec4(hi, 1.0f)); put(extrude(hi, l)); EndPrimitive();
            }
        }
    }
}
