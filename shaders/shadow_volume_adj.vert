// Vertex stage of the geometry-shader shadow volumes: world positions pass through unchanged
// (w = 1 for scene vertices, w = 0 for the "no neighbour" marker vertex of open triangles);
// shadow_volume.geom extrudes and projects them.
#version 460

layout(location = 0) in vec4 position;

void main() {
    gl_Position = position;
}
