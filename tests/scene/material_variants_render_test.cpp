// KHR_materials_variants (scene/gltf_variants.h): --variant picks a primitive's mapped material,
// info lists the names, an unknown name or a malformed mapping is refused.
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/info_command.h"
#include "support/base64.h"
#include "support/cli_runner.h"
#include "image/exr.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A triangle whose material is "plain" (0) and, in variant "red" or "blue", material 1 or 2.
json variantDoc() {
    std::vector<uint8_t> bytes;
    for (float f : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}) {
        const auto* p = reinterpret_cast<const uint8_t*>(&f);
        bytes.insert(bytes.end(), p, p + 4);
    }
    json primitive = {{"attributes", {{"POSITION", 0}}},
                      {"material", 0},
                      {"extensions",
                       {{"KHR_materials_variants",
                         {{"mappings", {{{"material", 1}, {"variants", {0}}}, {{"material", 2}, {"variants", {1}}}}}}}}}};
    return {{"asset", {{"version", "2.0"}}},
            {"extensionsUsed", {"KHR_materials_variants"}},
            {"extensions", {{"KHR_materials_variants", {{"variants", {{{"name", "red"}}, {{"name", "blue"}}}}}}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes", {{{"primitives", {primitive}}}}},
            {"materials",
             {{{"name", "plain"}, {"emissiveFactor", {1, 1, 1}}},
              {{"name", "red"}, {"emissiveFactor", {1, 0, 0}}},
              {{"name", "blue"}, {"emissiveFactor", {0, 0, 1}}}}},
            {"buffers", {{{"byteLength", 36}, {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}}},
            {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
            {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                            {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}}};
}

fs::path write(const fs::path& dir, const json& doc) {
    std::ofstream(dir / "variants.gltf") << doc.dump();
    return dir / "variants.gltf";
}

Scene load(const fs::path& path, const std::string& variant) {
    GltfLimits limits;
    limits.materialVariant = variant;
    return loadGltf(path, limits);
}

TEST(MaterialVariants, TheChosenVariantsMaterialIsRendered) {
    const fs::path dir = test::freshTempDir("variants", "choose");
    const fs::path path = write(dir, variantDoc());
    EXPECT_EQ(load(path, "").triangles.at(0).material, 0u);
    EXPECT_EQ(load(path, "red").triangles.at(0).material, 1u);
    const Scene blue = load(path, "blue");
    EXPECT_EQ(blue.triangles.at(0).material, 2u);
    EXPECT_EQ(blue.materials.at(2).emissive, glm::vec3(0, 0, 1));
    EXPECT_EQ(blue.file.materialVariants, (std::vector<std::string>{"red", "blue"}));
    EXPECT_EQ(sceneReport(blue)["materialVariants"], json({"red", "blue"}));
    try {
        load(path, "green");
        ADD_FAILURE() << "an unknown variant loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--variant green"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("red, blue"), std::string::npos) << e.what();
    }
    // A mapping to a variant the file does not list is refused, naming it.
    json bad = variantDoc();
    bad["meshes"][0]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"][1]["variants"] = {5};
    try {
        load(write(dir, bad), "");
        ADD_FAILURE() << "a bad mapping loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("mappings[1].variants[0]"), std::string::npos) << e.what();
    }
}

TEST(MaterialVariants, RenderTakesVariantAndRefusesAnUnknownOne) {
    const fs::path dir = test::freshTempDir("variants", "cli");
    const fs::path path = write(dir, variantDoc());
    const std::string common = "render " + path.string() + " --quiet --env 0 --spp 1 --width 4 --height 4 "
                               "--look-from 0.25,0.25,0.5 --look-at 0.25,0.25,0 --fov 20 --exposure 0 ";
    test::RunResult r = test::runVkphoton(common + "--variant blue -o " + (dir / "blue.exr").string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const ImageRgb blue = readExr(dir / "blue.exr");  // the camera sees only the emitter: blue 1
    for (size_t i = 0; i < blue.pixels.size(); i += 3)
        ASSERT_EQ(glm::vec3(blue.pixels[i], blue.pixels[i + 1], blue.pixels[i + 2]), glm::vec3(0, 0, 1));
    r = test::runVkphoton(common + "--variant green -o " + (dir / "green.exr").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("red, blue"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "green.exr"));
    r = test::runVkphoton("info " + path.string());
    EXPECT_NE(r.output.find("variants     2: red, blue"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace vkp
