// Ray offsets scale with the scene (scene_access.glsl rayEpsilon, docs/scene-format.md "Scale"):
// the Cornell box in millimetres, metres and kilometres (a root node scale) renders the same
// image, and a scene 0.002 units across is no longer refused.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_runner.h"
#include "image/exr.h"
#include "image/image.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// scenes/cornell-box.gltf under one more root node that scales everything (its camera too) by `scale`.
fs::path scaledBox(const fs::path& dir, double scale) {
    json doc = json::parse(std::ifstream(fs::path(VKPHOTON_SCENES) / "cornell-box.gltf"));
    json& scene = doc["scenes"][doc.value("scene", 0)];
    const json roots = scene["nodes"];
    doc["nodes"].push_back({{"name", "unit"}, {"scale", {scale, scale, scale}}, {"children", roots}});
    scene["nodes"] = json::array({doc["nodes"].size() - 1});
    const fs::path path = dir / ("box-" + std::to_string(scale) + ".gltf");
    std::ofstream(path) << doc.dump();
    return path;
}

ImageRgb render(const fs::path& scene, const fs::path& dir, const std::string& integrator) {
    const fs::path exr = dir / (scene.stem().string() + "-" + integrator + ".exr");
    const test::RunResult r = test::runVkphoton("render " + scene.string() + " --quiet --integrator " + integrator +
                                                " --spp 16 --width 24 --height 24 --seed 3 --exposure 0 -o " +
                                                exr.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r.exitCode == 0 ? readExr(exr) : ImageRgb{};
}

TEST(ScaleInvariance, TheCornellBoxInMillimetresMetresAndKilometresRendersTheSame) {
    const fs::path dir = test::freshTempDir("scale", "box");
    // The box is 2 units across: at 1e-3 it spans 0.002, which the loader used to refuse (its
    // ray offsets were at least 1e-4 units: 5 % of the box).
    const ImageRgb metres = render(scaledBox(dir, 1.0), dir, "path");
    ASSERT_TRUE(isWellFormed(metres));
    const double mean = meanValue(metres);
    ASSERT_GT(mean, 0.05);
    for (const double scale : {1.0e-3, 1.0e3}) {
        const ImageRgb scaled = render(scaledBox(dir, scale), dir, "path");
        ASSERT_TRUE(isWellFormed(scaled)) << scale;
        // The same seed draws the same samples: the images differ only where rounding sends a
        // path another way. Means within 0.1 %, pixels within 1 % of the mean on average (with
        // the offsets of before, 1e-4 units at least, the millimetre box was 1.2 % off).
        EXPECT_NEAR(meanValue(scaled), mean, 0.001 * mean) << scale;
        double difference = 0.0;
        for (size_t i = 0; i < metres.pixels.size(); ++i) difference += std::abs(scaled.pixels[i] - metres.pixels[i]);
        EXPECT_LT(difference / double(metres.pixels.size()), 0.01 * mean) << scale;
    }
}

}  // namespace
}  // namespace vkp
