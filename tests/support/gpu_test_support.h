// GPU test support: one lavapipe Vulkan context with validation for the whole test binary, the
// test shaders registered, and a check that no validation message arrived during a test.
#pragma once

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

// Base fixture for tests that use the GPU: checks validation after each test.
class GpuTest : public ::testing::Test {
protected:
    void TearDown() override { expectNoValidationMessages(); }
};

}  // namespace vkp::test
