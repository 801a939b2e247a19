// Pearson chi-square goodness-of-fit for sampling routines (the Mitsuba/Nori approach): bin the
// samples over (cos theta, phi), integrate the claimed pdf over each bin numerically, pool bins
// with small expected counts, and compare with the chi-square distribution.
#pragma once

#include <functional>
#include <string>

#include <glm/glm.hpp>

namespace vkp::test {

struct ChiSquareResult {
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 0.0;
    std::string details;
};

// Upper tail of the chi-square distribution: P(X > statistic).
double chiSquarePValue(double statistic, int degreesOfFreedom);

// `sample(i, w)` draws the i-th sample into w (unit vector over the full sphere) and returns
// false when the routine produced no sample (it then counts as mass outside the pdf's support).
// `pdf(w)` is the claimed solid-angle density, integrated over each bin on a
// subdivisions x subdivisions grid (raise it for pdfs with sharp edges).
ChiSquareResult chiSquareSphere(const std::function<bool(int, glm::vec3&)>& sample,
                                const std::function<double(const glm::vec3&)>& pdf, int sampleCount,
                                int thetaBins = 16, int phiBins = 32, int subdivisions = 12);

}  // namespace vkp::test
