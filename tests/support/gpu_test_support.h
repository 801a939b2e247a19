// GPU test support: one lavapipe Vulkan context with validation for the whole test binary, the
// test shaders registered, and a check that no validation message arrived during a test.
#pragma once

#include <cstdint>
#include <memory>

#include <gtest/gtest.h>

#include "vk/context.h"

namespace vkp::test {

// The shared context (created on first use, validation always on); registers the test shaders.
vk::Context& gpu();

// Makes the test shaders (tests/shaders/) visible to vk::shaderCode() without creating a device.
void registerTestShaders();

// Fills and frees `bytes` of device memory with a pattern that reads as valid photons, so that a
// pass reading memory it never wrote gives different results in the next run.
void poisonDeviceMemory(uint64_t bytes);

// Fails the current test if the validation layer reported anything since the last call.
void expectNoValidationMessages();

// Whether the shared context runs on Mesa's lavapipe (llvmpipe), where the suite normally runs.
// Two of its properties some tests rely on and other drivers do not have: float division and
// square root correctly rounded (the Vulkan spec allows 2.5 and 3 ulp), and the 65535-iteration
// loop budget per shader invocation (docs/photon-mapping.md).
bool onLavapipe();

// How many representable floats lie between a and b (0 when equal; huge across signs or NaN).
uint32_t ulpDistance(float a, float b);

// Base fixture for tests that use the GPU: checks validation after each test.
class GpuTest : public ::testing::Test {
protected:
    void TearDown() override { expectNoValidationMessages(); }
};

}  // namespace vkp::test
