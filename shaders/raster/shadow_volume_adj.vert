// Vertex stage of the geometry-shader shadow volumes: the clip position exactly as
// raster_position.vert computes it for the pre-pass, and the world position (w = 1 for scene
// vertices, w = 0 for the "no neighbour" marker of open triangles) for shadow_volume.geom.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/shadow_volume.glsl"

layout(location = 0) in vec4 position;
layout(location = 0) out vec4 worldPosition;
layout(push_constant) uniform Push { RasterVolumeParams params; };

void main() {
    precise vec4 clip = params.viewProj * position;
    gl_Position = clip;
    worldPosition = position;
}
