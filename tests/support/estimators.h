// Statistics of independent estimates (renders of different seeds, say): their mean and its
// standard error, and checks that an estimator agrees with a value or with another estimator
// within k standard errors (plus a stated relative tolerance for a known bias).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace vkp::test {

struct Estimate {
    double mean = 0.0;
    double standardError = 0.0;  // of the mean
};

// The mean of `samples` (independent estimates) and the standard error of that mean.
inline Estimate estimate(const std::vector<double>& samples) {
    Estimate e;
    const double n = double(samples.size());
    if (samples.empty()) return e;
    double sum = 0.0, sumSq = 0.0;
    for (double v : samples) {
        sum += v;
        sumSq += v * v;
    }
    e.mean = sum / n;
    if (samples.size() > 1) e.standardError = std::sqrt(std::max(0.0, (sumSq - n * e.mean * e.mean) / (n - 1)) / n);
    return e;
}

// EXPECT that `e` reads `value` within k standard errors plus `relTolerance` x |value|.
inline void expectAgrees(const Estimate& e, double value, double k, double relTolerance, const std::string& what) {
    const double bound = k * e.standardError + relTolerance * std::abs(value);
    EXPECT_NEAR(e.mean, value, bound) << what << ": " << e.mean << " against " << value << " (standard error "
                                      << e.standardError << ", ratio " << e.mean / value << ")";
}

// EXPECT that two independent estimators agree within k combined standard errors plus
// `relTolerance` x |b|.
inline void expectAgree(const Estimate& a, const Estimate& b, double k, double relTolerance, const std::string& what) {
    const double se = std::sqrt(a.standardError * a.standardError + b.standardError * b.standardError);
    const double bound = k * se + relTolerance * std::abs(b.mean);
    EXPECT_NEAR(a.mean, b.mean, bound) << what << ": " << a.mean << " against " << b.mean << " (combined standard error "
                                       << se << ", ratio " << a.mean / b.mean << ")";
}

}  // namespace vkp::test
