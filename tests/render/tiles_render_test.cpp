// Parts of a render (--tile, --crop) and `vkphoton merge`: the merged parts equal a full render
// with the same seed bit for bit (path tracer and photon integrators: the photon maps must be the
// same on every part), and merge refuses parts that do not belong together (exit 2).
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>
#include <sys/wait.h>

#include "support/cli_runner.h"
#include "image/exr.h"
#include "image/image.h"
#include "render/crop_window.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

using test::RunResult;

RunResult vkphoton(const std::string& args) { return test::runVkphoton(args); }

fs::path tempDir(const std::string& name) { return test::freshTempDir("tiles", name); }

const std::string kBox = std::string(VKPHOTON_SCENES) + "/cornell-box.gltf";
const std::string kGlass = std::string(VKPHOTON_SCENES) + "/cornell-glass.gltf";

bool sameBits(const ImageRgb& a, const ImageRgb& b) {
    return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

// Renders `scene` whole and as `parts` (each a --tile or --crop argument), merges the parts and
// compares the merged image with the whole one.
void expectPartsMergeToTheFullRender(const std::string& name, const std::string& render,
                                     const std::vector<std::string>& parts) {
    const fs::path dir = tempDir(name);
    const RunResult full = vkphoton(render + " -o " + (dir / "full.exr").string());
    ASSERT_EQ(full.exitCode, 0) << full.output;
    std::string partFiles;
    for (size_t i = 0; i < parts.size(); ++i) {
        const fs::path part = dir / ("part" + std::to_string(i) + ".exr");
        const RunResult r = vkphoton(render + " " + parts[i] + " -o " + part.string());
        ASSERT_EQ(r.exitCode, 0) << parts[i] << "\n" << r.output;
        partFiles += " " + part.string();
    }
    const RunResult merged = vkphoton("merge" + partFiles + " -o " + (dir / "merged.exr").string());
    ASSERT_EQ(merged.exitCode, 0) << merged.output;
    EXPECT_TRUE(fs::exists(dir / "merged.png"));
    const ImageRgb whole = readExr(dir / "full.exr");
    const ImageRgb joined = readExr(dir / "merged.exr");
    EXPECT_TRUE(sameBits(whole, joined)) << name << ": the merged parts differ from the full render";
    EXPECT_GT(meanValue(whole), 0.0);
    // --exposure auto (the default): each part metered its own window; merge meters the joined
    // image again, so the PNG and the recorded EV are the full render's.
    const auto bytes = [](const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(bytes(dir / "full.png"), bytes(dir / "merged.png")) << name << ": the merged PNG differs";
    ExrAttributes fullHeader, mergedHeader;
    readExr(dir / "full.exr", &fullHeader);
    readExr(dir / "merged.exr", &mergedHeader);
    const auto exposure = [](const ExrAttributes& attributes) {
        for (const auto& [key, value] : attributes)
            if (key == "vkphoton/exposure") return value;
        return std::string("<missing>");
    };
    EXPECT_EQ(exposure(fullHeader), exposure(mergedHeader)) << name;
    fs::remove_all(dir);
}

const std::string kSmall = " --validate --quiet --width 24 --height 20 --seed 7";

TEST(Tiles, PathTracedTilesMergeToTheFullRenderBitForBit) {
    expectPartsMergeToTheFullRender("path", "render " + kBox + kSmall + " --spp 3",
                                    {"--tile 1/3", "--tile 2/3", "--tile 3/3"});
}

TEST(Tiles, CropsThatSplitRowsMergeToTheFullRenderBitForBit) {
    expectPartsMergeToTheFullRender("crop", "render " + kBox + kSmall + " --spp 2",
                                    {"--crop 0,0,9,20", "--crop 9,0,24,7", "--crop 9,7,24,20"});
}

TEST(Tiles, PhotonMappedTilesMergeToTheFullRenderBitForBit) {
    expectPartsMergeToTheFullRender("photon",
                                    "render " + kGlass + kSmall +
                                        " --spp 1 --integrator photon --photons 20000 --caustic-photons 20000 "
                                        "--gather-rays 2",
                                    {"--tile 1/2", "--tile 2/2"});
}

// Shared final gathers read the rays of pixels up to 4 rows around each pixel: a crop traces
// them beyond its window, so windows that split rows merge to the full render too.
TEST(Tiles, PhotonMappedCropsWithSharedGathersMergeToTheFullRenderBitForBit) {
    expectPartsMergeToTheFullRender("photon-crop",
                                    "render " + kBox + kSmall +
                                        " --spp 2 --integrator photon --photons 20000 --gather-reuse 4",
                                    {"--crop 0,0,9,20", "--crop 9,0,24,7", "--crop 9,7,24,20"});
}

TEST(Tiles, ProgressivePhotonTilesMergeToTheFullRenderBitForBit) {
    expectPartsMergeToTheFullRender("sppm",
                                    "render " + kBox + kSmall +
                                        " --spp 2 --integrator photon --progressive --photons 5000",
                                    {"--tile 1/4", "--tile 2/4", "--tile 3/4", "--tile 4/4"});
}

TEST(Tiles, MergeRefusesPartsThatDoNotBelongTogether) {
    const fs::path dir = tempDir("refuse");
    const std::string render = "render " + kBox + " --quiet --width 16 --height 8";
    const auto part = [&](const std::string& file, std::string args) {
        if (args.find("--spp") == std::string::npos) args += " --spp 1";
        const RunResult r = vkphoton(render + " " + args + " -o " + (dir / file).string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
    };
    part("a.exr", "--tile 1/2");
    part("b.exr", "--tile 2/2");
    part("other-seed.exr", "--tile 2/2 --seed 5");
    part("overlap.exr", "--crop 0,3,16,6");
    part("whole.exr", "");
    part("partial.exr", "--tile 2/2 --spp 4096 --time-limit 0.001");
    const auto merge = [&](const std::string& files) {
        std::string args = "merge";
        std::istringstream in(files);
        for (std::string f; in >> f;) args.append(" ").append((dir / f).string());
        return vkphoton(args + " -o " + (dir / "out.exr").string());
    };
    struct Case {
        const char* files;
        const char* says;
    };
    for (const Case& c : {Case{"a.exr", "uncovered"}, Case{"a.exr other-seed.exr", "vkphoton/seed"},
                          Case{"a.exr b.exr overlap.exr", "overlaps"}, Case{"a.exr whole.exr", "not a part"},
                          Case{"partial.exr a.exr", "partial"},
                          Case{"a.exr missing.exr", "missing.exr"}}) {
        const RunResult r = merge(c.files);
        EXPECT_EQ(r.exitCode, 2) << c.files << "\n" << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << c.files << "\n" << r.output;
        EXPECT_FALSE(fs::exists(dir / "out.exr")) << c.files;
    }
    EXPECT_EQ(merge("b.exr a.exr").exitCode, 0);
    fs::remove_all(dir);
}

TEST(Tiles, BadTileAndCropValuesExitWithTwo) {
    const std::string render = "render " + kBox + " --quiet --width 16 --height 8 --spp 1 -o /tmp/never.exr ";
    for (const char* args : {"--tile 0/2", "--tile 3/2", "--tile 1/0", "--tile 1/9", "--tile nan", "--tile 1/2x",
                             "--tile -1/2", "--tile 1/99999999999999999999", "--tile ''", "--crop 0,0,17,8",
                             "--crop 4,4,4,8", "--crop 1,2,3", "--crop nan,0,1,1", "--crop 0,0,1e3,1",
                             "--crop -1,0,4,4", "--tile 1/2 --crop 0,0,4,4",
                             "--tile 1/2 --aov depth", "--crop 0,0,4,4 --aov albedo"}) {
        const RunResult r = vkphoton(render + args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    }
}

TEST(Tiles, TilesAreBandsOfWholeRowsThatCoverTheImageOnce) {
    for (uint32_t count : {1u, 3u, 7u, 20u}) {
        uint32_t next = 0;
        for (uint32_t i = 1; i <= count; ++i) {
            const CropWindow w = parseTile(std::to_string(i) + "/" + std::to_string(count), 33, 20);
            EXPECT_EQ(w.x0, 0u);
            EXPECT_EQ(w.x1, 33u);
            EXPECT_EQ(w.y0, next);
            EXPECT_GT(w.y1, w.y0);
            next = w.y1;
        }
        EXPECT_EQ(next, 20u);
    }
    EXPECT_THROW(parseTile("21/21", 33, 20), InputError);
    const vk::ItemRange r = cropPixels(CropWindow{3, 2, 5, 4}, 10);
    EXPECT_EQ(r.first, 23u);
    EXPECT_EQ(r.count, 35u - 23u);  // to (4, 3), the window's last pixel, inclusive
}

}  // namespace
}  // namespace vkp
