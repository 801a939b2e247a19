// Error kinds and the exit codes they map to (0 ok, 1 runtime failure, 2 bad usage or bad input;
// 3 from `vkphoton compare`: the images differ).
#pragma once
#include <stdexcept>
#include <string>

namespace vkp {

// Bad input: a scene file, a flag value, a path. Exit code 2.
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A failure at run time that is not the user's input: Vulkan errors, I/O failures. Exit code 1.
struct RuntimeError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

constexpr int kExitOk = 0;
constexpr int kExitRuntimeFailure = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitImagesDiffer = 3;

}  // namespace vkp
