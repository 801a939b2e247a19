// The BSDF's albedo tables (shared/bsdf_tables.glsl) against fresh integration, and their
// generator: with VKPHOTON_WRITE_BSDF_TABLES=FILE the test rewrites the values in FILE.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "shared/bsdf_microfacet.glsl"
#include "shared/bsdf_sheen.glsl"
#include "shared/bsdf_tables.glsl"
#include "shared/bsdf.glsl"

namespace vkp {
namespace {

using namespace vkp::gpu;

constexpr int kSize = 32;

double tableCos(int i) { return (i + 0.5) / kSize; }
double tableRoughness(int j) { return j / double(kSize - 1); }

glm::vec3 fromCos(double mu) { return glm::vec3(static_cast<float>(std::sqrt(std::max(0.0, 1.0 - mu * mu))), 0.0f, static_cast<float>(mu)); }

// E(mu, r): albedo of D G2 / (4 cos cos) (F = 1) by stratified visible-normal sampling, whose
// weight is G2 / G1(wo).
double ggxAlbedo(double mu, double roughness, int strata = 256) {
    const float alpha = std::max(static_cast<float>(roughness * roughness), kMinAlpha);
    const glm::vec3 wo = fromCos(mu);
    double sum = 0.0;
    for (int a = 0; a < strata; ++a)
        for (int b = 0; b < strata; ++b) {
            const glm::vec2 u((a + 0.5f) / strata, (b + 0.5f) / strata);
            const glm::vec3 h = sampleGgxVisibleNormal(wo, alpha, u);
            const glm::vec3 wi = glm::reflect(-wo, h);
            if (wi.z <= 0.0f) continue;
            sum += ggxG2(wo, wi, alpha) / ggxG1(wo, alpha);
        }
    return sum / (double(strata) * strata);
}

// Albedo of the white Charlie lobe by quadrature over the hemisphere (cos theta = t^2 nodes).
double sheenAlbedoAt(double mu, double roughness, int steps = 256) {
    const float alpha = sheenAlpha(static_cast<float>(roughness));
    const glm::vec3 wo = fromCos(mu);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        const double t = (i + 0.5) / steps;
        const double c = t * t;
        const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
        for (int j = 0; j < steps; ++j) {
            const double phi = kPi * (j + 0.5) / steps;  // symmetric in phi: integrate half, double
            const glm::vec3 wi(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)), static_cast<float>(c));
            sum += charlieSheen(wo, wi, alpha) * c * 2.0 * t;
        }
    }
    return sum * (1.0 / steps) * (kPi / steps) * 2.0;
}

std::vector<double> computeTables() {
    std::vector<double> values(2 * kSize * kSize + kSize);
    for (int j = 0; j < kSize; ++j) {
        double average = 0.0;
        for (int i = 0; i < kSize; ++i) {
            const double e = ggxAlbedo(tableCos(i), tableRoughness(j));
            values[j * kSize + i] = e;
            average += 2.0 * e * tableCos(i) / kSize;
            values[kSize * kSize + j * kSize + i] = sheenAlbedoAt(tableCos(i), tableRoughness(j));
        }
        values[2 * kSize * kSize + j] = average;
    }
    return values;
}

TEST(BsdfTables, MatchFreshIntegration) {
    if (const char* path = std::getenv("VKPHOTON_WRITE_BSDF_TABLES")) {
        const std::vector<double> values = computeTables();
        std::ifstream in(path);
        ASSERT_TRUE(in) << path;
        std::stringstream text;
        text << in.rdbuf();
        std::string s = text.str();
        const std::string begin = "// BEGIN VALUES\n", end = "// END VALUES\n";
        const size_t a = s.find(begin), b = s.find(end);
        ASSERT_NE(a, std::string::npos);
        ASSERT_NE(b, std::string::npos);
        std::string body;
        for (size_t k = 0; k < values.size(); ++k)
            body += fmt::format("{:.6f}f{}", values[k], k + 1 == values.size() ? "\n" : (k % 8 == 7 ? ",\n" : ", "));
        s = s.substr(0, a + begin.size()) + body + s.substr(b);
        std::ofstream(path) << s;
        GTEST_SKIP() << "wrote " << path;
    }
    // A sample of entries (all of them take a few seconds more), including the edges.
    for (int j : {0, 1, 5, 16, 31})
        for (int i : {0, 3, 15, 31}) {
            EXPECT_NEAR(bsdfTableValue(kTableGgxAlbedo, i, j), ggxAlbedo(tableCos(i), tableRoughness(j), 128), 2e-3)
                << "GGX albedo mu " << tableCos(i) << " roughness " << tableRoughness(j);
            EXPECT_NEAR(bsdfTableValue(kTableSheenAlbedo, i, j), sheenAlbedoAt(tableCos(i), tableRoughness(j), 192), 3e-3)
                << "sheen albedo mu " << tableCos(i) << " roughness " << tableRoughness(j);
        }
}

// Closed forms: E = 1 for a perfectly smooth mirror (F = 1); E(1, alpha 1) = 1 - ln 2 (the
// lookup at cos 1 reads the last cell centre, cos 0.984, where E is 0.3099).
TEST(BsdfTables, ClosedForms) {
    EXPECT_NEAR(bsdfTableValue(kTableGgxAlbedo, kSize - 1, 0), 1.0, 2e-3);
    EXPECT_NEAR(bsdfTableLookup(kTableGgxAlbedo, 1.0f, 1.0f), 1.0 - std::log(2.0), 4e-3);
    EXPECT_NEAR(ggxAverageAlbedo(0.0f), 1.0, 3e-3);
}

}  // namespace
}  // namespace vkp
