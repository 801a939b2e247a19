// Shader unit harness kernel: evaluates one shared function (chosen by `function`) for `count`
// inputs. tests/shared_functions_test.cpp runs the same code compiled as C++ and compares.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/harness_functions.glsl"

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 0) readonly buffer Inputs { HarnessInput inputs[]; };
layout(std430, set = 0, binding = 1) writeonly buffer Outputs { uvec4 outputs[]; };
layout(push_constant) uniform Push { uint count; uint function; } push;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    outputs[i] = evaluateHarnessFunction(push.function, inputs[i]);
}
