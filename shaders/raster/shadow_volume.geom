// Shadow volumes in a geometry shader with triangle adjacency, the alternative to
// shadow_volume_build.comp (docs/benchmarks.md compares them; the same volumes, the same
// orientation, the same side-quad split). Input: a triangle (vertices 0, 2, 4) and the far vertex
// of the neighbour across each edge (1: edge 0-2, 3: edge 2-4, 5: edge 4-0); a neighbour with
// w = 0 marks a triangle of an open or non-manifold component, which gets a volume of its own.
// Scene vertices keep the clip positions raster_position.vert computed (the pre-pass's own), so
// front caps land on exactly the pre-pass depths; only extruded vertices are projected here.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/shadow_volume.glsl"

layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 24) out;
layout(location = 0) in vec4 worldPosition[];
layout(push_constant) uniform Push { RasterVolumeParams params; };

float facing(vec3 a, vec3 b, vec3 c, vec4 l) {
    return dot(cross(b - a, c - a), l.xyz - a * l.w);
}

bool lessThanPoint(vec3 p, vec3 q) {
    if (p.x != q.x) return p.x < q.x;
    if (p.y != q.y) return p.y < q.y;
    return p.z < q.z;
}

void putClip(vec4 clip) {
    gl_Position = clip;
    EmitVertex();
}

// A vertex pushed away from the light to infinity, projected.
void putExtruded(vec3 p, vec4 l) {
    precise vec3 d = p * l.w - l.xyz;
    precise vec4 clip = params.viewProj * vec4(d, 0.0f);
    putClip(clip);
}

// Side of edge a -> b unless the neighbour (far vertex `far`, walking b -> a) also faces the light.
// ca, cb: the clip positions of a and b.
void emitSide(vec3 a, vec3 b, vec4 ca, vec4 cb, vec4 far, vec4 l, bool open) {
    if (!open && facing(b, a, far.xyz, l) > 0.0f) return;
    bool forward = lessThanPoint(a, b);
    vec3 lo = forward ? a : b;
    vec3 hi = forward ? b : a;
    vec4 clo = forward ? ca : cb;
    vec4 chi = forward ? cb : ca;
    if (forward) {
        putClip(clo); putExtruded(lo, l); putExtruded(hi, l); EndPrimitive();
        putClip(clo); putExtruded(hi, l); putClip(chi); EndPrimitive();
    } else {
        putClip(clo); putExtruded(hi, l); putExtruded(lo, l); EndPrimitive();
        putClip(clo); putClip(chi); putExtruded(hi, l); EndPrimitive();
    }
}

void main() {
    vec4 l = params.light;
    vec3 v0 = worldPosition[0].xyz;
    vec3 v1 = worldPosition[2].xyz;
    vec3 v2 = worldPosition[4].xyz;
    vec4 c0 = gl_in[0].gl_Position;
    vec4 c1 = gl_in[2].gl_Position;
    vec4 c2 = gl_in[4].gl_Position;
    vec4 n01 = worldPosition[1];
    vec4 n12 = worldPosition[3];
    vec4 n20 = worldPosition[5];
    bool open = n01.w == 0.0f;
    float f = facing(v0, v1, v2, l);
    if (open && f < 0.0f) {  // open: turn the triangle towards the light (v1 <-> v2)
        vec3 tv = v1; v1 = v2; v2 = tv;
        vec4 tc = c1; c1 = c2; c2 = tc;
        f = -f;
    }
    if (!(f > 0.0f)) return;
    putClip(c0); putClip(c1); putClip(c2); EndPrimitive();                          // front cap
    putExtruded(v0, l); putExtruded(v2, l); putExtruded(v1, l); EndPrimitive();     // back cap
    emitSide(v0, v1, c0, c1, n01, l, open);
    emitSide(v1, v2, c1, c2, n12, l, open);
    emitSide(v2, v0, c2, c0, n20, l, open);
}
