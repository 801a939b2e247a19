// `vkphoton compare`: two EXRs are the same image when every channel's values have the same bits,
// whatever their headers say. The timings in a render's header change its length, so file bytes
// (and the bytes after the header, which start with the scan-line offset table) are no test of
// "same seed, same image": that once made a cold shader cache look like a different image.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cli_runner.h"
#include "image/atomic_file.h"
#include "image/exr.h"
#include "image/image.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

using test::RunResult;

// A 8x8 image with a different value in every channel of every pixel.
ImageRgb pattern() {
    ImageRgb image = makeImage(8, 8);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = 0.01f * float(i) + 0.5f;
    return image;
}

ExrAttributes timings(const std::string& seconds) {
    return {{"vkphoton/seed", "3"}, {"vkphoton/renderSeconds", seconds}, {"vkphoton/totalSeconds", seconds}};
}

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

RunResult compare(const fs::path& a, const fs::path& b) {
    return test::runVkphoton("compare " + a.string() + " " + b.string());
}

TEST(CompareCommand, SamePixelsWithTimingsOfAnotherLengthAreIdentical) {
    const fs::path dir = test::freshTempDir("compare", "timings");
    // A warm run under 10 s and a cold-cache run over it: the header is two bytes longer.
    writeExr(dir / "warm.exr", pattern(), timings("9.734"));
    writeExr(dir / "cold.exr", pattern(), timings("54.702"));
    const std::string warm = fileBytes(dir / "warm.exr"), cold = fileBytes(dir / "cold.exr");
    // The premise: the files differ (the header's length, so the offset table's values), while
    // the compressed pixel blocks at their ends are the same.
    ASSERT_NE(warm.size(), cold.size());
    ASSERT_EQ(warm.substr(warm.size() - 64), cold.substr(cold.size() - 64));

    const RunResult r = compare(dir / "warm.exr", dir / "cold.exr");
    EXPECT_EQ(r.exitCode, kExitOk) << r.output;
    EXPECT_NE(r.output.find("pixels identical, bit for bit (8x8, 3 channels: B, G, R)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("header attributes that differ: vkphoton/renderSeconds, vkphoton/totalSeconds"),
              std::string::npos)
        << r.output;
}

TEST(CompareCommand, OneUlpInOneChannelIsADifference) {
    const fs::path dir = test::freshTempDir("compare", "ulp");
    ImageRgb changed = pattern();
    float& g = changed.at(5, 2)[1];
    g = std::nextafter(g, 2.0f);
    writeExr(dir / "a.exr", pattern(), timings("1.000"));
    writeExr(dir / "b.exr", changed, timings("1.000"));
    const RunResult r = compare(dir / "a.exr", dir / "b.exr");
    EXPECT_EQ(r.exitCode, kExitImagesDiffer) << r.output;
    EXPECT_NE(r.output.find("pixels differ: 1 of 192 values in 1 of 64 pixels; first at (5, 2) G:"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("header attributes that differ"), std::string::npos) << r.output;
}

TEST(CompareCommand, SignedZerosDiffer) {
    const fs::path dir = test::freshTempDir("compare", "zero");
    ImageRgb positive = pattern(), negative = pattern();
    positive.pixels[0] = 0.0f;
    negative.pixels[0] = -0.0f;
    writeExr(dir / "a.exr", positive);
    writeExr(dir / "b.exr", negative);
    EXPECT_EQ(compare(dir / "a.exr", dir / "b.exr").exitCode, kExitImagesDiffer);
}

TEST(CompareCommand, AovChannelsAreCompared) {
    const fs::path dir = test::freshTempDir("compare", "aov");
    std::vector<float> depth(64, 2.0f);
    writeBytesAtomically(dir / "z.exr", exrBytes(dir / "z.exr", pattern(), {}, {{"Z", depth}}));
    depth[63] = 3.0f;
    writeBytesAtomically(dir / "z2.exr", exrBytes(dir / "z2.exr", pattern(), {}, {{"Z", depth}}));
    writeExr(dir / "rgb.exr", pattern());

    const RunResult same = compare(dir / "z.exr", dir / "z.exr");
    EXPECT_EQ(same.exitCode, kExitOk) << same.output;
    EXPECT_NE(same.output.find("4 channels: B, G, R, Z"), std::string::npos) << same.output;
    const RunResult value = compare(dir / "z.exr", dir / "z2.exr");
    EXPECT_EQ(value.exitCode, kExitImagesDiffer) << value.output;
    EXPECT_NE(value.output.find("1 of 256 values in 1 of 64 pixels; first at (7, 7) Z: 2 vs 3"), std::string::npos)
        << value.output;
    const RunResult missing = compare(dir / "z.exr", dir / "rgb.exr");
    EXPECT_EQ(missing.exitCode, kExitImagesDiffer) << missing.output;
    EXPECT_NE(missing.output.find("channels in one file only (A: Z)"), std::string::npos) << missing.output;
}

TEST(CompareCommand, OtherSizesDifferAndUnreadableFilesAreBadInput) {
    const fs::path dir = test::freshTempDir("compare", "input");
    writeExr(dir / "a.exr", pattern());
    writeExr(dir / "small.exr", makeImage(4, 4));
    const RunResult sizes = compare(dir / "a.exr", dir / "small.exr");
    EXPECT_EQ(sizes.exitCode, kExitImagesDiffer) << sizes.output;
    EXPECT_NE(sizes.output.find("different sizes"), std::string::npos) << sizes.output;
    const RunResult absent = compare(dir / "a.exr", dir / "absent.exr");
    EXPECT_EQ(absent.exitCode, kExitBadInput) << absent.output;
    EXPECT_NE(absent.output.find("absent.exr"), std::string::npos) << absent.output;
}

TEST(CompareCommand, UsageAndQuiet) {
    const fs::path dir = test::freshTempDir("compare", "usage");
    const RunResult help = test::runVkphoton("compare --help");
    EXPECT_EQ(help.exitCode, kExitOk) << help.output;
    EXPECT_NE(help.output.find("Usage"), std::string::npos) << help.output;
    writeExr(dir / "a.exr", pattern());
    writeExr(dir / "small.exr", makeImage(4, 4));
    EXPECT_EQ(test::runVkphoton("compare " + (dir / "a.exr").string()).exitCode, kExitBadInput);
    const RunResult quiet =
        test::runVkphoton("compare --quiet " + (dir / "a.exr").string() + " " + (dir / "small.exr").string());
    EXPECT_EQ(quiet.exitCode, kExitImagesDiffer);
    EXPECT_EQ(quiet.output, "");
}

}  // namespace
}  // namespace vkp
