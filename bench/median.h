// The median of repeated timings, the figure every benchmark reports.
#pragma once

#include <algorithm>
#include <vector>

namespace vkp::bench {

inline double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

}  // namespace vkp::bench
