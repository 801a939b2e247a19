#include "support/chi_square.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace vkp::test {
namespace {

// Regularised upper incomplete gamma Q(a, x) (series for x < a + 1, continued fraction beyond).
double gammaQ(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double lnGammaA = std::lgamma(a);
    if (x < a + 1.0) {
        double sum = 1.0 / a, term = sum;
        for (int n = 1; n < 1000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * 1e-15) break;
        }
        return 1.0 - sum * std::exp(-x + a * std::log(x) - lnGammaA);
    }
    double b = x + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::abs(c) < 1e-300) c = 1e-300;
        d = 1.0 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - lnGammaA) * h;
}

}  // namespace

double chiSquarePValue(double statistic, int dof) {
    return gammaQ(0.5 * dof, 0.5 * statistic);
}

ChiSquareResult chiSquareSphere(const std::function<bool(int, glm::vec3&)>& sample,
                                const std::function<double(const glm::vec3&)>& pdf, int sampleCount,
                                int thetaBins, int phiBins, int subdivisions) {
    const int bins = thetaBins * phiBins;
    std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);  // last: no sample
    for (int i = 0; i < sampleCount; ++i) {
        glm::vec3 w;
        if (!sample(i, w)) { observed[bins] += 1.0; continue; }
        const double z = std::clamp<double>(w.z, -1.0, 1.0);
        int t = std::min(thetaBins - 1, static_cast<int>((1.0 - z) * 0.5 * thetaBins));
        double phi = std::atan2(w.y, w.x);
        if (phi < 0) phi += 2.0 * M_PI;
        int p = std::min(phiBins - 1, static_cast<int>(phi / (2.0 * M_PI) * phiBins));
        observed[t * phiBins + p] += 1.0;
    }
    // Integrate the pdf over each bin in (z, phi), where dOmega = dz dphi.
    const int kSub = subdivisions;
    double total = 0.0;
    for (int t = 0; t < thetaBins; ++t)
        for (int p = 0; p < phiBins; ++p) {
            double sum = 0.0;
            for (int a = 0; a < kSub; ++a)
                for (int b = 0; b < kSub; ++b) {
                    const double z = 1.0 - 2.0 * (t + (a + 0.5) / kSub) / thetaBins;
                    const double phi = 2.0 * M_PI * (p + (b + 0.5) / kSub) / phiBins;
                    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                    sum += pdf(glm::vec3(r * std::cos(phi), r * std::sin(phi), z));
                }
            const double area = (2.0 / thetaBins) * (2.0 * M_PI / phiBins);
            expected[t * phiBins + p] = sum / (kSub * kSub) * area * sampleCount;
            total += expected[t * phiBins + p];
        }
    expected[bins] = std::max(0.0, sampleCount - total);

    // Pool bins with expected counts below 5 (in order of expected count) into one.
    std::vector<int> order(bins + 1);
    for (int i = 0; i <= bins; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
    ChiSquareResult result;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    int cells = 0;
    for (int idx : order) {
        if (expected[idx] < 5.0 || (pooledExpected > 0.0 && pooledExpected < 5.0)) {
            pooledObserved += observed[idx];
            pooledExpected += expected[idx];
            continue;
        }
        const double d = observed[idx] - expected[idx];
        result.statistic += d * d / expected[idx];
        ++cells;
    }
    if (pooledExpected > 0.0) {
        const double d = pooledObserved - pooledExpected;
        result.statistic += d * d / pooledExpected;
        ++cells;
    } else if (pooledObserved > 0.0) {
        result.statistic = 1e30;  // samples where the pdf claims none
    }
    result.degreesOfFreedom = std::max(1, cells - 1);
    result.pValue = chiSquarePValue(result.statistic, result.degreesOfFreedom);
    result.details = fmt::format("chi2 = {:.1f}, dof = {}, p = {:.3g}, pooled expected {:.1f} observed {:.0f}",
                                 result.statistic, result.degreesOfFreedom, result.pValue, pooledExpected,
                                 pooledObserved);
    return result;
}

}  // namespace vkp::test
