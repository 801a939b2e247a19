// The toy integrator of tests/integrator_seam_test.cpp: adds `sampleCount` samples of a constant
// radiance to every pixel of the film (vec4 per pixel: RGB sum and sample count).
#version 460

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) buffer Film { vec4 film[]; };

layout(push_constant) uniform Push {
    vec4 radiance;
    uint pixels;
    uint sampleCount;
};

void main() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= pixels) return;
    film[pixel] += vec4(radiance.rgb * float(sampleCount), float(sampleCount));
}
