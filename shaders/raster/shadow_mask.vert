// Full-screen triangle of the mask writer: after a light's volumes were counted into the stencil
// buffer, every pixel with a zero count (outside all volumes: lit) gets 1 in the light's channel.
#version 460

void main() {
    vec2 p = vec2(float((gl_VertexIndex << 1) & 2), float(gl_VertexIndex & 2));
    gl_Position = vec4(p * 2.0f - 1.0f, 0.0f, 1.0f);
}
