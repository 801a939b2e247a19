// Vertex stage of the depth pre-pass and of the shadow volumes: homogeneous world positions
// (w = 1 for scene vertices, w = 0 for vertices extruded to infinity) to clip space. Both passes
// use this one shader so the front caps land on exactly the depths the pre-pass wrote (the same
// code on the same inputs, `precise`; `invariant` on gl_Position trips the validation layer's
// SPIR-V checks).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/shadow_volume.glsl"

layout(location = 0) in vec4 position;
layout(push_constant) uniform Push { RasterParams params; };

void main() {
    // precise: no fused multiply-adds, so shadow_volume.geom computes bit-identical depths.
    precise vec4 clip = params.viewProj * position;
    gl_Position = clip;
}
