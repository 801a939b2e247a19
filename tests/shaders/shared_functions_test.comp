// Shader unit harness kernel: evaluates one shared function (chosen by `function`) for `count`
// inputs. tests/shared/shared_functions_test.cpp runs the same code compiled as C++ and compares.
#version 460
#extension GL_GOOGLE_include_directive : require

#define VKP_BSDF_TABLES_BINDING 2u  // kHarnessTablesBinding (test_kernels.glsl)
#include "shared/harness_functions.glsl"
#include "test_kernels.glsl"

layout(local_size_x = kTestGroupSize) in;
layout(std430, set = 0, binding = kHarnessInputBinding) readonly buffer Inputs { HarnessInput inputs[]; };
layout(std430, set = 0, binding = kHarnessOutputBinding) writeonly buffer Outputs { uvec4 outputs[]; };
layout(push_constant) uniform Push { HarnessParams push; };

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= push.count) return;
    outputs[i] = evaluateHarnessFunction(push.function, inputs[i]);
}
