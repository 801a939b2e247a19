// Writes "lit" into the mask; the pipeline's colour write mask picks the light's RGBA channel.
#version 460

layout(location = 0) out vec4 mask;

void main() {
    mask = vec4(1.0f);
}
