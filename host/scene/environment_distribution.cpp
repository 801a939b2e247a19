#include "scene/environment_distribution.h"

#include <cmath>

#include "shared/sampling.glsl"

namespace vkp {
namespace {

constexpr double kPiD = 3.14159265358979323846;

double rowSinTheta(uint32_t j, uint32_t height) { return std::sin(kPiD * (j + 0.5) / height); }

// Inclusive prefix sums of `weights` normalized to end at 1 (uniform when they sum to 0), into out.
void appendCdf(const std::vector<double>& weights, std::vector<float>& out) {
    double total = 0.0;
    for (double w : weights) total += w;
    double running = 0.0;
    for (size_t k = 0; k < weights.size(); ++k) {
        running += total > 0.0 ? weights[k] : 1.0;
        const double denominator = total > 0.0 ? total : double(weights.size());
        out.push_back(k + 1 == weights.size() ? 1.0f : static_cast<float>(running / denominator));
    }
}

}  // namespace

std::vector<float> environmentGpuData(const Environment& env) {
    std::vector<float> data;
    if (!env.present || env.width == 0) return data;
    const uint32_t w = env.width, h = env.height;
    data.reserve(size_t(w) * h * 4 + h);
    data.insert(data.end(), env.rgb.begin(), env.rgb.end());
    std::vector<double> rowWeights(h, 0.0);
    std::vector<double> row(w);
    for (uint32_t j = 0; j < h; ++j) {
        const double s = rowSinTheta(j, h);
        for (uint32_t i = 0; i < w; ++i) {
            const float* p = &env.rgb[3 * (size_t(j) * w + i)];
            row[i] = double(gpu::luminance(glm::vec3(p[0], p[1], p[2]))) * s;
            rowWeights[j] += row[i];
        }
        appendCdf(row, data);
    }
    appendCdf(rowWeights, data);
    return data;
}

double environmentMeanLuminance(const Environment& env) {
    if (!env.present) return 0.0;
    if (env.width == 0) return gpu::luminance(env.radiance);
    const uint32_t w = env.width, h = env.height;
    double sum = 0.0;
    for (uint32_t j = 0; j < h; ++j) {
        double rowSum = 0.0;
        for (uint32_t i = 0; i < w; ++i) {
            const float* p = &env.rgb[3 * (size_t(j) * w + i)];
            rowSum += gpu::luminance(glm::vec3(p[0], p[1], p[2]));
        }
        // Solid angle of a pixel of row j: (2 pi / w) (pi / h) sin(theta_j).
        sum += rowSum * rowSinTheta(j, h) * (2.0 * kPiD / w) * (kPiD / h);
    }
    return sum / (4.0 * kPiD);
}

double environmentPower(const Environment& env, double sceneRadius) {
    return 4.0 * kPiD * environmentMeanLuminance(env) * kPiD * sceneRadius * sceneRadius;
}

}  // namespace vkp
