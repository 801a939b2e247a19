// Range checks of settings, one rule for the library and the command line: the message names
// the flag and the value, and NaN never passes (every comparison with it is false).
#pragma once

#include <limits>
#include <string_view>

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {

template <typename T> void checkRange(std::string_view flag, T value, T lowest, T highest) {
    if (!(value >= lowest && value <= highest))
        throw InputError(fmt::format("{} {}: must be between {} and {}", flag, value, lowest, highest));
}

template <typename T> void checkPositive(std::string_view flag, T value) {
    if (!(value > T(0)) || !(value < std::numeric_limits<T>::infinity()))
        throw InputError(fmt::format("{} {}: must be a positive number", flag, value));
}

}  // namespace vkp
