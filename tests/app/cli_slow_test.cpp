// End-to-end tests of the vkphoton binary: exit codes, messages, outputs on disk.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <csignal>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <map>
#include <regex>
#include <set>

#include "support/cli_runner.h"
#include "image/exr.h"
#include "image/image.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

using test::RunResult;
using test::runVkphoton;

fs::path tempDir(const std::string& name) { return test::freshTempDir("cli", name); }

const std::string kBox = std::string(VKPHOTON_SCENES) + "/cornell-box.gltf";

TEST(Cli, HelpOnEveryCommand) {
    for (const char* args : {"--help", "render --help", "photons --help", "devices --help", "info --help"}) {
        const RunResult r = runVkphoton(args);
        EXPECT_EQ(r.exitCode, 0) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("Usage"), std::string::npos) << args;
    }
}

TEST(Cli, BadUsageExitsWithTwo) {
    for (const char* args : {"", "render", "render a.gltf --spp 0", "render a.gltf --spp banana", "frobnicate"}) {
        const RunResult r = runVkphoton(args);
        EXPECT_EQ(r.exitCode, 2) << "'" << args << "'\n" << r.output;
    }
}

TEST(Cli, MissingSceneExitsWithTwoAndNamesTheFile) {
    const RunResult r = runVkphoton("render /nonexistent/scene.gltf --quiet");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/scene.gltf"), std::string::npos) << r.output;
}

TEST(Cli, BadCameraIndexExitsWithTwo) {
    const RunResult r = runVkphoton("render " + kBox + " --camera 7 --quiet --spp 1 --width 8 --height 8 -o " +
                                    (tempDir("camera") / "x.exr").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--camera 7"), std::string::npos) << r.output;
}

// Lavapipe where its driver is installed (as the suite's set-up does); a machine with only
// another driver lists that one.
TEST(Cli, DevicesListsLavapipe) {
    const RunResult r = runVkphoton("devices");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("0: "), std::string::npos) << r.output;
    if (std::filesystem::exists("/usr/share/vulkan/icd.d/lvp_icd.x86_64.json")) {
        EXPECT_NE(r.output.find("llvmpipe"), std::string::npos) << r.output;
    }
}

TEST(Cli, UnknownDeviceExitsWithTwo) {
    const RunResult r = runVkphoton("render " + kBox + " --device no-such-gpu --quiet --spp 1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("no-such-gpu"), std::string::npos) << r.output;
}

// --light-sampler: without it, the light BVH for many lights (rooms-10x10: 200 triangles) and power
// for few (the Cornell box's quad); given, as told, with the photon cells' statistics.
TEST(Cli, LightSamplerDefaultFollowsTheLightCount) {
    const fs::path dir = tempDir("light-sampler");
    const std::string rooms = std::string(VKPHOTON_SCENES) + "/rooms-10x10.gltf";
    const std::vector<std::tuple<std::string, std::string, std::string>> cases{
        {rooms, "", "bvh"}, {kBox, "", "power"}, {kBox, "--light-sampler bvh", "bvh"},
        {kBox, "--light-sampler photon --light-photons 2000 --light-cell-k 4", "photon"}};
    for (const auto& [scene, flags, mode] : cases) {
        const fs::path stats = dir / "stats.json";
        const RunResult r = runVkphoton("render " + scene + " --quiet --spp 1 --width 8 --height 8 " + flags + " -o " +
                                        (dir / "x.exr").string() + " --stats-json " + stats.string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        std::ifstream in(stats);
        const nlohmann::json j = nlohmann::json::parse(in);
        EXPECT_EQ(j["light_sampler"]["mode"], mode) << scene << " " << flags;
        if (mode == "photon") {
            EXPECT_GT(j["light_sampler"]["cells"]["cells"].get<int>(), 0);
            EXPECT_LE(j["light_sampler"]["cells"]["meanCandidates"].get<double>(), 4.0);
        }
    }
}

TEST(Cli, RenderWritesExrPngAndStats) {
    const fs::path dir = tempDir("render");
    const fs::path exr = dir / "sub" / "box.exr";
    const fs::path stats = dir / "stats.json";
    const RunResult r = runVkphoton("render " + kBox + " --validate --spp 4 --width 32 --height 24 --seed 3 -o " +
                                    exr.string() + " --stats-json " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(exr));
    EXPECT_TRUE(fs::exists(dir / "sub" / "box.png"));
    ExrAttributes attributes;
    const ImageRgb image = readExr(exr, &attributes);
    EXPECT_EQ(image.width, 32u);
    EXPECT_EQ(image.height, 24u);
    bool sawSpp = false, sawPartial = false;
    for (const auto& [key, value] : attributes) {
        if (key == "vkphoton/spp") { sawSpp = true; EXPECT_EQ(value, "4"); }
        if (key == "vkphoton/partial") { sawPartial = true; EXPECT_EQ(value, "false"); }
    }
    EXPECT_TRUE(sawSpp);
    EXPECT_TRUE(sawPartial);
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["counters"]["samplesPerPixel"], 4);
    EXPECT_GT(j["timings"]["renderSeconds"].get<double>(), 0.0);
    // No temporary files left behind.
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

// --no-mipmaps reaches the renderer: on the checker floor (a texture minified to the horizon)
// the two images differ, and the atlas holds no levels (smaller); --mipmaps is the default.
TEST(Cli, NoMipmapsReadsFullResolutionTexels) {
    const fs::path dir = tempDir("mipmaps");
    const std::string floor = std::string(VKPHOTON_SCENES) + "/checker-floor.gltf";
    const auto render = [&](const std::string& flag) {
        const fs::path exr = dir / (flag.empty() ? "default.exr" : flag.substr(2) + ".exr");
        const fs::path stats = dir / (exr.stem().string() + ".json");
        const RunResult r = runVkphoton("render " + floor + " --validate --spp 1 --width 48 --height 27 --seed 3 " +
                                        flag + " -o " + exr.string() + " --stats-json " + stats.string());
        EXPECT_EQ(r.exitCode, 0) << r.output;
        std::ifstream in(stats);
        const nlohmann::json j = nlohmann::json::parse(in);
        return std::make_pair(readExr(exr).pixels, j["scene_stats"]["textureAtlasBytes"].get<uint64_t>());
    };
    const auto [byDefault, defaultBytes] = render("");
    const auto [mipmapped, mipmappedBytes] = render("--mipmaps");
    const auto [levelZero, levelZeroBytes] = render("--no-mipmaps");
    EXPECT_EQ(byDefault, mipmapped);
    EXPECT_NE(mipmapped, levelZero);
    EXPECT_EQ(defaultBytes, mipmappedBytes);
    EXPECT_LT(levelZeroBytes, mipmappedBytes);
}

TEST(Cli, PhotonIntegratorRendersAndReportsItsMaps) {
    const fs::path dir = tempDir("photon");
    const fs::path exr = dir / "box.exr";
    const fs::path stats = dir / "stats.json";
    const RunResult r = runVkphoton("render " + kBox + " --validate --integrator photon --photons 20000 "
                                    "--caustic-photons 1000 --gather-rays 1 --spp 2 --width 24 --height 24 -o " +
                                    exr.string() + " --stats-json " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("photon maps:"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(exr));
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["integrator"], "photon");
    EXPECT_EQ(j["photons"]["pathsTraced"], 21000);
    EXPECT_GT(j["photons"]["globalStored"].get<int>(), 0);
    EXPECT_GT(j["settings"]["photon"]["radius"].get<double>(), 0.0);
}

TEST(Cli, BadPhotonSettingsExitWithTwo) {
    for (const std::string args : {"--integrator bidirectional", "--integrator photon --gather-k 65",
                                   "--integrator photon --radius -1", "--integrator photon --photons 0",
                                   "--integrator photon --alpha 1.5", "--integrator photon --deposit nope",
                                   "--integrator photon --q 0.5 --caustic-photons 10", "--integrator photon --q 2",
                                   "--integrator photon --deposit-epsilon 0", "--integrator photon --density-rounds 0"}) {
        const RunResult r = runVkphoton("render " + kBox + " --quiet --spp 1 --width 8 --height 8 " + args + " -o " +
                                        (tempDir("bad-photon") / "x.exr").string());
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    }
}

TEST(Cli, GuidedIntegratorAndItsGridAtAPixel) {
    const fs::path dir = tempDir("guided");
    const std::string ceiling = std::string(VKPHOTON_SCENES) + "/cornell-ceiling.gltf";
    const fs::path stats = dir / "stats.json";
    RunResult r = runVkphoton("render " + ceiling + " --validate --integrator guided --guide-photons 20000 "
                              "--guide-grid 2x8 --guide-mix 0.7 --guide-rr on --spp 2 --width 16 --height 16 -o " +
                              (dir / "g.exr").string() + " --stats-json " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["integrator"], "guided");
    EXPECT_EQ(j["settings"]["guide"]["grid"], "2x8");
    EXPECT_EQ(j["settings"]["guide"]["roulette"], true);
    EXPECT_GT(j["counters"]["pathSegments"].get<uint64_t>(), j["counters"]["cameraPaths"].get<uint64_t>());
    EXPECT_GT(j["photons"]["globalStored"].get<int>(), 0);

    // A floor pixel: the light faces the ceiling, so indirect light comes from above.
    const fs::path png = dir / "grid.png";
    r = runVkphoton("guide-grid " + ceiling + " --validate --pixel 20 60 --width 64 --height 64 --guide-photons 50000 -o " +
                    png.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(png));
    auto bandProbability = [&](int band) {
        const std::string key = "band " + std::to_string(band) + " (probability ";
        const size_t at = r.output.find(key);
        return at == std::string::npos ? -1.0 : std::stod(r.output.substr(at + key.size()));
    };
    EXPECT_GT(bandProbability(0), 2.0 * bandProbability(3)) << r.output;  // the ceiling is straight above
    EXPECT_GE(bandProbability(3), 0.0) << r.output;

    for (const std::string& args : {"render " + ceiling + " --integrator guided --guide-grid 9x9",
                                   "render " + ceiling + " --integrator guided --guide-mix 2",
                                   "render " + ceiling + " --integrator guided --guide-k 0",
                                   "render " + ceiling + " --integrator guided --guide-cache maybe",
                                   "render " + ceiling + " --integrator guided --guide-rr 1",
                                   "guide-grid " + ceiling + " --pixel 600 1",
                                   "guide-grid " + ceiling + " --pixel 1"}) {
        r = runVkphoton(args + " --quiet -o " + (dir / "bad.png").string());
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    }
}

TEST(Cli, TimeLimitMarksThePartialImage) {
    const fs::path dir = tempDir("partial");
    const fs::path exr = dir / "box.exr";
    const RunResult r = runVkphoton("render " + kBox + " --quiet --spp 100000 --width 16 --height 16 --time-limit 1 -o " +
                                    exr.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::vector<std::pair<std::string, std::string>> attributes;
    readExr(exr, &attributes);
    bool partial = false;
    for (const auto& [key, value] : attributes)
        if (key == "vkphoton/partial") partial = value == "true";
    EXPECT_TRUE(partial);
}

TEST(Cli, InterruptWritesThePartialImage) {
    const fs::path dir = tempDir("sigint");
    const fs::path exr = dir / "box.exr";
    const std::string exrArg = exr.string();
    std::vector<std::string> args{VKPHOTON_BINARY, "render", kBox, "--quiet", "--spp", "1000000", "--width", "16",
                                  "--height", "16", "-o", exrArg};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, VKPHOTON_BINARY, nullptr, nullptr, argv.data(), environ), 0);
    std::this_thread::sleep_for(std::chrono::seconds(3));  // past start-up, into the render loop
    kill(pid, SIGINT);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
    ASSERT_TRUE(fs::exists(exr));
    ExrAttributes attributes;
    readExr(exr, &attributes);
    std::string partial, reason;
    for (const auto& [key, value] : attributes) {
        if (key == "vkphoton/partial") partial = value;
        if (key == "vkphoton/stopReason") reason = value;
    }
    EXPECT_EQ(partial, "true");
    EXPECT_EQ(reason, "interrupted");
}

TEST(Cli, PhotonsWritesAPlyPointCloud) {
    const fs::path dir = tempDir("photons");
    const fs::path ply = dir / "glass.ply";
    const RunResult r = runVkphoton("photons " + std::string(VKPHOTON_SCENES) + "/cornell-glass.gltf --validate --photons 5000 -o " +
                                    ply.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("caustic"), std::string::npos) << r.output;
    std::ifstream in(ply, std::ios::binary);
    std::string header, line;
    while (std::getline(in, line) && line != "end_header") header += line + "\n";
    EXPECT_EQ(header.rfind("ply\nformat binary_little_endian 1.0\n", 0), 0u) << header;
    const auto at = header.find("element vertex ");
    ASSERT_NE(at, std::string::npos);
    const long vertices = std::stol(header.substr(at + 15));
    EXPECT_GT(vertices, 5000);  // primary photons alone are about one per path
    const auto bodyStart = in.tellg();
    in.seekg(0, std::ios::end);
    EXPECT_EQ(static_cast<long>(in.tellg() - bodyStart), vertices * (9 * 4 + 1));
    // Importance deposition keeps fewer photons and says so.
    const RunResult d = runVkphoton("photons " + std::string(VKPHOTON_SCENES) + "/cornell-glass.gltf --validate --photons 5000 "
                                    "--deposit importance --importons 4096 -o " + (dir / "deposit.ply").string());
    ASSERT_EQ(d.exitCode, 0) << d.output;
    EXPECT_NE(d.output.find("deposit importance: kept"), std::string::npos) << d.output;
    // Bad input: wrong extension, bad counts.
    EXPECT_EQ(runVkphoton("photons " + kBox + " -o " + (dir / "x.txt").string()).exitCode, 2);
    EXPECT_EQ(runVkphoton("photons " + kBox + " --photons 0").exitCode, 2);
}

TEST(Cli, UnwritableOutputFailsWithoutLeavingFiles) {
    const fs::path dir = tempDir("unwritable");
    std::ofstream(dir / "file") << "x";
    const RunResult r = runVkphoton("render " + kBox + " --quiet --spp 1 --width 8 --height 8 -o " +
                                    (dir / "file" / "out.exr").string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_FALSE(fs::exists(dir / "file" / "out.exr"));
}

TEST(Cli, RasterDirectRendersAndReportsItsPass) {
    const fs::path dir = tempDir("raster");
    const fs::path exr = dir / "box.exr";
    const fs::path stats = dir / "stats.json";
    const RunResult r = runVkphoton("render " + kBox + " --validate --direct raster --area-light-samples 4 --spp 2 "
                                    "--width 24 --height 24 -o " + exr.string() + " --stats-json " + stats.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(fs::exists(exr));
    std::ifstream in(stats);
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["settings"]["direct"], "raster");
    EXPECT_EQ(j["raster"]["lights"], 8);  // the ceiling light's two triangles, 4 samples each
}

TEST(Cli, BadDirectSettingsExitWithTwo) {
    for (const std::string args : {"--direct rasterized", "--direct raster --area-light-samples -1",
                                   "--direct raster --area-light-samples 5000"}) {
        const RunResult r = runVkphoton("render " + kBox + " --quiet --spp 1 --width 8 --height 8 " + args + " -o " +
                                        (tempDir("bad-direct") / "x.exr").string());
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        // The message names the offending option.
        EXPECT_TRUE(r.output.find("--direct") != std::string::npos ||
                    r.output.find("--area-light-samples") != std::string::npos) << args << "\n" << r.output;
    }
}

// --- output: display settings, framing, view override, info ---------------------------------

std::string exrAttribute(const ExrAttributes& attributes, const std::string& key) {
    for (const auto& [name, value] : attributes)
        if (name == key) return value;
    return "(absent)";
}

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Cli, ExposureAndTonemapChangeThePngNotTheExr) {
    const fs::path dir = tempDir("display");
    const std::string common = "render " + kBox + " --quiet --spp 2 --width 16 --height 12 --seed 5 ";
    RunResult r = runVkphoton(common + "-o " + (dir / "a.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runVkphoton(common + "--exposure 2.5 --tonemap clamp -o " + (dir / "b.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ExrAttributes a, b;
    const ImageRgb imageA = readExr(dir / "a.exr", &a), imageB = readExr(dir / "b.exr", &b);
    EXPECT_EQ(imageA.pixels, imageB.pixels);  // linear, whatever the PNG shows
    EXPECT_EQ(exrAttribute(a, "vkphoton/exposureMode"), "auto");  // metered: AutoExposure.*
    EXPECT_EQ(exrAttribute(a, "vkphoton/tonemap"), "agx");
    EXPECT_EQ(exrAttribute(b, "vkphoton/exposure"), "2.5");
    EXPECT_EQ(exrAttribute(b, "vkphoton/exposureMode"), "fixed");
    EXPECT_EQ(exrAttribute(b, "vkphoton/tonemap"), "clamp");
    EXPECT_NE(fileBytes(dir / "a.png"), fileBytes(dir / "b.png"));

    for (const std::string args : {"--exposure nan", "--exposure 100", "--exposure banana", "--tonemap filmic"}) {
        r = runVkphoton(common + args + " -o " + (dir / "bad.exr").string());
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find(args.substr(0, args.find(' '))), std::string::npos) << args << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(dir / "bad.exr"));
}

TEST(Cli, ViewOverrideIsCheckedByEveryCommandThatHasACamera) {
    const fs::path dir = tempDir("view");
    const std::pair<std::string, std::string> bad[] = {
        {"--look-from nan,0,0", "--look-from"}, {"--look-from=-1,inf,0", "--look-from"}, {"--look-at 1,2", "--look-at"},
        {"--look-at 1,2,3,4", "--look-at"},     {"--fov 0", "--fov"},                    {"--fov 180", "--fov"},
        {"--fov nan", "--fov"},                 {"--look-from 1,2,3 --look-at 1,2,3", "--look-from"},
    };
    for (const std::string& command : {"render " + kBox + " -o " + (dir / "x.exr").string(),
                                      "photons " + kBox + " --photons 100 -o " + (dir / "x.ply").string(),
                                      "guide-grid " + kBox + " --pixel 1 1 -o " + (dir / "x.png").string()})
        for (const auto& [args, flag] : bad) {
            const RunResult r = runVkphoton(command + " --quiet " + args);
            EXPECT_EQ(r.exitCode, 2) << command << " " << args << "\n" << r.output;
            EXPECT_NE(r.output.find(flag), std::string::npos) << command << " " << args << "\n" << r.output;
        }
    EXPECT_TRUE(fs::is_empty(dir));
    // Negative coordinates parse as values, not as options.
    const RunResult r = runVkphoton("render " + kBox + " --quiet --spp 1 --width 8 --height 8 --look-from -0.5,1.5,3 "
                                    "--look-at 0,1,-1 --fov 55 -o " + (dir / "ok.exr").string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

const std::string kAnnotated = std::string(VKPHOTON_TEST_DATA) + "/info/annotated.gltf";

TEST(Cli, ACameraLessSceneIsFramed) {
    const fs::path dir = tempDir("framing");
    const RunResult r = runVkphoton("render " + kAnnotated + " --quiet --spp 4 --width 24 --height 16 -o " +
                                    (dir / "a.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const ImageRgb image = readExr(dir / "a.exr");
    // The emissive triangle faces +Z: from the three-quarter view it is seen, so the image is lit.
    EXPECT_GT(meanValue(image), 0.0);
}

TEST(Cli, InfoDescribesTheSceneWithoutAVulkanDevice) {
    const std::string noVulkan = "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json";
    RunResult r = runVkphoton("info " + kAnnotated, noVulkan);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* expected : {"triangles    2", "materials    2", "glowing coat (emissive)", "1 point, 1 spot, 0 directional",
                                 "cameras      0", "animations   2 (3 channels): played by render --frames", "nodes        4",
                                 "KHR_texture_transform", "textures     1, 8 bytes decoded", "EXT_vkphoton_test_unknown"})
        EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;

    r = runVkphoton("info --json " + kAnnotated, noVulkan);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const size_t start = r.output.find('{');  // after any loader warnings
    ASSERT_NE(start, std::string::npos) << r.output;
    const nlohmann::json j = nlohmann::json::parse(r.output.substr(start));
    EXPECT_EQ(j["triangles"], 2);
    EXPECT_EQ(j["animations"]["channels"], 3);
    EXPECT_EQ(j["extensions"].size(), 5u);

    r = runVkphoton("info " + kBox, noVulkan);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("KHR_materials_emissive_strength"), std::string::npos) << r.output;
    for (const std::string& bad : {std::string("/nonexistent/scene.gltf"), std::string(VKPHOTON_TEST_DATA) + "/bad/accessor_missing.gltf"}) {
        r = runVkphoton("info " + bad, noVulkan);
        EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r.output;
        EXPECT_NE(r.output.find(bad), std::string::npos) << r.output;
    }
    EXPECT_EQ(runVkphoton("info").exitCode, 2);
}

// --- hostile command lines, signals --- -------------------------------------------------

const std::string kTriangle = std::string(VKPHOTON_TEST_DATA) + "/good/triangle.gltf";

std::map<std::string, std::string> exrAttributes(const fs::path& exr) {
    ExrAttributes attributes;
    readExr(exr, &attributes);
    return {attributes.begin(), attributes.end()};
}

bool hasTemporaryFiles(const fs::path& dir) {
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
    return false;
}

// Every numeric flag of every subcommand, and how to reach a check of it (the integrator).
const std::map<std::string, std::vector<std::string>> kNumericFlags = {
    {"render", {"--spp", "--width", "--height", "--seed", "--max-depth", "--time-limit", "--camera",
                "--max-memory", "--max-texture-size", "--exposure", "--fov", "--env-strength", "--env-rotation", "--scene"}},
    {"render --direct raster", {"--area-light-samples"}},
    {"render --light-sampler photon", {"--light-photons", "--light-cell-k", "--light-cell-floor", "--light-cell-size"}},
    {"render --integrator photon", {"--photons", "--caustic-photons", "--gather-rays", "--max-deposits", "--gather-k", "--gather-guide", "--gather-reuse", "--radiance-photons",
                                    "--radius", "--q", "--importons", "--deposit-epsilon", "--density-accuracy",
                                    "--density-rounds"}},
    {"render --integrator sppm", {"--alpha"}},
    {"render --integrator guided", {"--guide-photons", "--guide-k", "--guide-adapt", "--guide-mix"}},
    {"render --frames 0:0", {"--fps", "--animation", "--photon-budget", "--photon-groups"}},
    {"photons", {"--photons", "--max-deposits", "--seed", "--importons", "--deposit-epsilon", "--density-accuracy",
                 "--density-rounds", "--width", "--height", "--camera", "--max-memory", "--max-texture-size", "--fov",
                 "--env-strength", "--env-rotation", "--scene"}},
    {"guide-grid --pixel 1 1", {"--width", "--height", "--camera", "--seed", "--guide-photons", "--guide-k", "--max-memory",
                                "--max-texture-size", "--fov", "--env-strength", "--env-rotation", "--scene"}},
};

// Flags for which a value of the hostile list is valid: exposure is in stops, -1 EV halves.
// --env-rotation is an angle: -1 degree turns the other way.
const std::map<std::string, std::string> kValidHostileValues = {{"--exposure", "-1"}, {"--env-rotation", "-1"}};

// Options whose help names their unit instead of a numeric type (checked with the table anyway).
const std::map<std::string, std::string> kNumericTypeNames = {
    {"--fov", "FLOAT"}, {"--env-rotation", "FLOAT"}, {"--exposure", "FLOAT"}};  // --exposure: auto or EV

// The table above must list every option whose help gives a numeric type: a new flag fails here
// until it is added (and so tested below).
std::map<std::string, std::string> numericOptions(const std::string& command);

TEST(CliHostile, TheNumericFlagTableCoversEveryNumericOption) {
    for (const std::string command : {"render", "photons", "guide-grid"}) {
        const auto types = numericOptions(command);
        EXPECT_GT(types.size(), 5u) << command;  // the help was read
        for (const auto& [flag, type] : types) {
            if (flag == "--pixel") continue;  // GuideGridRefusesOverflowingGridsAndPixels
            bool listed = false;
            for (const auto& [prefix, flags] : kNumericFlags)
                if (prefix.rfind(command, 0) == 0)
                    listed = listed || std::find(flags.begin(), flags.end(), flag) != flags.end();
            EXPECT_TRUE(listed) << command << " " << flag << " (" << type << ") is missing from kNumericFlags";
        }
    }
}

// The numeric type (UINT, INT, FLOAT) of every option of `command`, read from its --help.
std::map<std::string, std::string> numericOptions(const std::string& command) {
    const std::regex numeric(R"(^\s+(--[a-z-]+)\s+(UINT|INT|FLOAT))");
    std::map<std::string, std::string> types;
    const std::string help = runVkphoton(command + " --help").output;
    std::istringstream lines(help);
    std::string line;
    std::smatch m;
    while (std::getline(lines, line))
        if (std::regex_search(line, m, numeric)) types[m[1]] = m[2];
    for (const auto& [flag, type] : kNumericTypeNames)
        if (help.find(flag + " ") != std::string::npos) types[flag] = type;
    return types;
}

// NaN, infinities, numbers beyond double, negatives, trailing junk, empty values, and for
// integers values beyond 64 and 32 bits: every numeric flag refuses them with exit 2, naming
// itself, before any work (the small image settings keep a wrongly accepted value cheap).
TEST(CliHostile, EveryNumericFlagRefusesNanInfinityAndOverflow) {
    const fs::path dir = tempDir("numeric");
    for (const auto& [command, flags] : kNumericFlags) {
        const std::string verb = command.substr(0, command.find(' '));
        const auto types = numericOptions(verb);
        const std::map<std::string, std::string> cheap = {{"--spp", "1"}, {"--width", "4"}, {"--height", "4"},
                                                          {"--photons", "100"}, {"--guide-photons", "100"}};
        for (const std::string& flag : flags) {
            ASSERT_TRUE(types.count(flag)) << verb << " has no numeric " << flag;
            std::vector<std::string> values{"nan", "inf", "-inf", "1e400", "-1", "2x", "''"};
            if (types.at(flag) != "FLOAT") values.insert(values.end(), {"99999999999999999999", "4294967296", "1.5"});
            for (const std::string& value : values) {
                if (kValidHostileValues.count(flag) && kValidHostileValues.at(flag) == value) continue;
                const std::string rest = command.size() > verb.size() ? command.substr(verb.size()) : "";
                std::string args = verb + " " + kTriangle + rest + " --quiet " + flag + " " + value;
                for (const auto& [option, setting] : cheap)
                    if (option != flag && types.count(option) && (option != "--photons" || rest.empty()) &&
                        (option != "--guide-photons" || verb == "guide-grid"))
                        args += " " + option + " " + setting;
                args += " -o " + (dir / (verb == "photons" ? "x.ply" : verb == "render" ? "x.exr" : "x.png")).string();
                const RunResult r = runVkphoton(args);
                EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
                EXPECT_NE(r.output.find(flag), std::string::npos) << args << "\n" << r.output;
            }
        }
    }
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
    EXPECT_FALSE(fs::exists(dir / "x.ply"));
}

// Regression tests of the three guide-grid crashes and silent misreadings the probe found.
TEST(CliHostile, GuideGridRefusesOverflowingGridsAndPixels) {
    const fs::path png = tempDir("guide-hostile") / "g.png";
    for (const std::string args : {"--pixel 1 1 --guide-grid 33554432x128", "--pixel 1 1 --guide-grid 4294967297x1",
                                   "--pixel 1 1 --guide-grid -4x16", "--pixel 1 1 --guide-grid 4x16x",
                                   "--pixel 99999999999999999999 0", "--pixel 1e3 5", "--pixel nan 1", "--pixel 1 1 1"}) {
        const RunResult r = runVkphoton("guide-grid " + kBox + " --quiet --width 8 --height 8 " + args + " -o " + png.string());
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_TRUE(r.output.find("--guide-grid") != std::string::npos || r.output.find("--pixel") != std::string::npos)
            << args << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(png));
}

// Output paths are checked before loading and rendering: a render of 10^5 spp would take
// minutes, so a quick refusal shows nothing was rendered.
TEST(CliHostile, OutputPathsAreCheckedBeforeTheWork) {
    const fs::path dir = tempDir("outputs");
    fs::create_directories(dir / "folder.exr");
    const std::string longName = (dir / (std::string(300, 'n') + ".exr")).string();
    for (const auto& [args, code] : std::vector<std::pair<std::string, int>>{
             {"-o " + (dir / "folder.exr").string(), 1},
             {"-o /proc/vkphoton.exr", 1},
             {"-o " + longName, 1},
             {"-o " + (dir / "ok.exr").string() + " --stats-json /proc/vkphoton.json", 1},
             {"-o ''", 2},
             {"-o " + (dir / "ok.exr").string() + " --stats-json ''", 2}}) {
        const auto start = std::chrono::steady_clock::now();
        const RunResult r = runVkphoton("render " + kBox + " --quiet --spp 100000 --width 64 --height 64 " + args);
        EXPECT_EQ(r.exitCode, code) << args << "\n" << r.output;
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 20.0) << args;
    }
    EXPECT_FALSE(fs::exists(dir / "ok.exr"));
    EXPECT_FALSE(hasTemporaryFiles(dir));
}

// Control characters in what a message echoes (a path, a URI) reach the terminal escaped.
TEST(CliHostile, MessagesEscapeControlCharacters) {
    const fs::path dir = tempDir("escape");
    const std::string uri = "tri\x1b[2J\x07angle\n.bin";
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(kTriangle));
    doc["buffers"][0]["uri"] = uri;
    std::ofstream(dir / "scene.gltf") << doc.dump();
    for (const std::string& scene : {(dir / "scene.gltf").string(), (dir / "sc\x1b]0;owned\x07.gltf").string()}) {
        const RunResult r = runVkphoton("render '" + scene + "' --quiet -o " + (dir / "x.exr").string());
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find('\x07'), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("\\x1b"), std::string::npos) << r.output;
    }
}

pid_t spawnVkphoton(std::vector<std::string> args) {
    args.insert(args.begin(), VKPHOTON_BINARY);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    return posix_spawn(&pid, VKPHOTON_BINARY, nullptr, nullptr, argv.data(), environ) == 0 ? pid : -1;
}

int waitExitCode(pid_t pid) {
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) return -2;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// SIGTERM during the photon pass (once ignored for 24 s): the pass stops between chunks — far
// fewer photon paths than asked for are traced — and the partial image is written, marked, exit
// 143, no temporary files. Judged by the work done, not by wall time, so a loaded machine cannot
// fail it.
TEST(CliHostile, SigtermDuringThePhotonPassWritesThePartialImage) {
    const fs::path dir = tempDir("sigterm");
    const fs::path exr = dir / "box.exr";
    const fs::path stats = dir / "stats.json";
    constexpr long kPhotonsAsked = 50000000;
    const pid_t pid = spawnVkphoton({"render", kBox, "--quiet", "--integrator", "photon", "--photons",
                                     std::to_string(kPhotonsAsked), "--spp", "4", "--width", "16", "--height",
                                     "16", "-o", exr.string(), "--stats-json", stats.string()});
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::seconds(4));  // into the photon pass
    kill(pid, SIGTERM);
    EXPECT_EQ(waitExitCode(pid), 128 + SIGTERM);
    ASSERT_TRUE(fs::exists(stats));
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
    EXPECT_LT(j["photons"]["pathsTraced"].get<double>(), 0.5 * kPhotonsAsked) << j.dump();
    ASSERT_TRUE(fs::exists(exr));
    EXPECT_TRUE(fs::exists(dir / "box.png"));
    const auto attributes = exrAttributes(exr);
    EXPECT_EQ(attributes.at("vkphoton/partial"), "true");
    EXPECT_EQ(attributes.at("vkphoton/stopReason"), "interrupted");
    EXPECT_EQ(attributes.at("vkphoton/spp"), "1");  // one sample, always
    EXPECT_FALSE(hasTemporaryFiles(dir));
}

// A second signal stops at once: nothing new is written, the previous run's EXR and PNG stay as
// they were (both), no temporary files.
TEST(CliHostile, SecondSignalLeavesThePreviousOutputsAndNoTemporaryFiles) {
    const fs::path dir = tempDir("sigterm-twice");
    const fs::path exr = dir / "box.exr";
    std::ofstream(exr) << "previous exr";
    std::ofstream(dir / "box.png") << "previous png";
    const pid_t pid = spawnVkphoton({"render", kBox, "--quiet", "--spp", "1000000", "--width", "16", "--height", "16",
                                     "-o", exr.string()});
    ASSERT_GT(pid, 0);
    std::this_thread::sleep_for(std::chrono::seconds(3));
    kill(pid, SIGTERM);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    kill(pid, SIGHUP);
    EXPECT_EQ(waitExitCode(pid), 128 + SIGTERM);
    std::ifstream a(exr), b(dir / "box.png");
    std::string exrText, pngText;
    std::getline(a, exrText);
    std::getline(b, pngText);
    // Either both are the previous files or both are new (the renames hold signals): never mixed.
    EXPECT_EQ(exrText == "previous exr", pngText == "previous png") << exrText << " / " << pngText;
    EXPECT_FALSE(hasTemporaryFiles(dir));
}

// A render stopped during the photon pass equals a complete render of the paths it traced: the
// photon power is normalised by those paths, not by --photons.
TEST(CliHostile, AStoppedPhotonPassEqualsACompleteOneOfThePathsTraced) {
    const fs::path dir = tempDir("stopped-photons");
    const std::string common = "render " + kBox + " --quiet --integrator photon --caustic-photons 0 --spp 1 "
                               "--width 16 --height 16 --deposit all ";
    RunResult r = runVkphoton(common + "--photons 20000000 --time-limit 0.001 -o " + (dir / "a.exr").string() +
                              " --stats-json " + (dir / "a.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json a = nlohmann::json::parse(std::ifstream(dir / "a.json"));
    EXPECT_EQ(a["partial"], true);
    EXPECT_EQ(a["stopReason"], "time limit");
    const uint64_t traced = a["photons"]["pathsTraced"].get<uint64_t>();
    EXPECT_LT(traced, 20000000u);
    // The stopped render skipped the radiance photons: compare with per-hit estimates.
    r = runVkphoton(common + "--photons " + std::to_string(traced) + " --radiance-photons 0 -o " + (dir / "b.exr").string() +
                    " --stats-json " + (dir / "b.json").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const nlohmann::json b = nlohmann::json::parse(std::ifstream(dir / "b.json"));
    for (int c = 0; c < 3; ++c)
        EXPECT_DOUBLE_EQ(a["meanRadiance"][c].get<double>(), b["meanRadiance"][c].get<double>()) << c;
}

}  // namespace
}  // namespace vkp

namespace vkp {
namespace {

// A copy of the triangle scene without its emission: a scene without lights.
fs::path unlitTriangle(const fs::path& dir) {
    std::ifstream in(kTriangle);
    std::stringstream text;
    text << in.rdbuf();
    std::string json = text.str();
    const size_t at = json.find("\"emissiveFactor\"");
    json.replace(at, json.find(']', at) + 1 - at, "\"doubleSided\": true");
    fs::copy_file(fs::path(VKPHOTON_TEST_DATA) / "good" / "triangle.bin", dir / "triangle.bin",
                  fs::copy_options::overwrite_existing);
    std::ofstream(dir / "unlit.gltf") << json;
    return dir / "unlit.gltf";
}

TEST(CliEnvironment, SceneWithoutLightsRendersUnderAWhiteSkyUnlessEnvZero) {
    const fs::path dir = tempDir("env");
    const std::string scene = unlitTriangle(dir).string();
    const std::string common = "render " + scene + " --spp 2 --width 8 --height 8 -o " + (dir / "a.exr").string();
    RunResult r = runVkphoton(common);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("uniform white environment"), std::string::npos) << r.output;
    EXPECT_EQ(exrAttributes(dir / "a.exr").at("vkphoton/environment"), "constant");
    EXPECT_GT(meanValue(readExr(dir / "a.exr")), 0.1);  // the sky is seen around the triangle
    r = runVkphoton(common + " --env 0");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("no lights"), std::string::npos) << r.output;
    r = runVkphoton(common + " --env 1,0.9,0.8 --env-strength 2 --quiet");
    EXPECT_EQ(r.exitCode, 0) << r.output;
}

TEST(CliEnvironment, AovsAreExrChannels) {
    const fs::path dir = tempDir("aov");
    const fs::path exr = dir / "a.exr";
    RunResult r = runVkphoton("render " + kBox + " --spp 1 --width 8 --height 8 --quiet --aov albedo,normal,depth -o " +
                              exr.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::vector<std::string> names = exrChannelNames(exr);
    for (const char* name : {"R", "G", "B", "Albedo.R", "Albedo.G", "Albedo.B", "N.X", "N.Y", "N.Z", "Z"})
        EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
    for (float z : readExrChannel(exr, "Z")) EXPECT_TRUE(z > 0.0f && z < 10.0f) << z;  // inside the 5 m box
    for (float a : readExrChannel(exr, "Albedo.G")) EXPECT_TRUE(a >= 0.0f && a <= 1.0f) << a;
    r = runVkphoton("render " + kBox + " --spp 1 --width 8 --height 8 --aov albedo,colour -o " + exr.string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--aov"), std::string::npos) << r.output;
}

TEST(CliEnvironment, BadMapsExitWithTwo) {
    const fs::path dir = tempDir("env-bad");
    std::ofstream(dir / "bad.hdr") << "not an image";
    for (const std::string& env : {(dir / "missing.hdr").string(), (dir / "bad.hdr").string(), std::string("1,2"),
                                  std::string("-1"), std::string("nan")}) {
        const RunResult r = runVkphoton("render " + kTriangle + " --spp 1 --width 4 --height 4 --env " + env + " -o " +
                                        (dir / "x.exr").string());
        EXPECT_EQ(r.exitCode, 2) << env << "\n" << r.output;
        EXPECT_NE(r.output.find("--env"), std::string::npos) << env << "\n" << r.output;
    }
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

}  // namespace
}  // namespace vkp
