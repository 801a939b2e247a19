// KHR_materials_anisotropy and KHR_materials_iridescence from glTF to the image
// (docs/scene-format.md, "Materials"): the factors are read with the extensions' defaults, no
// "not rendered" warning is left, a strength or factor of 0 renders the same bits as the material
// without the extension, and a non-zero one renders differently (so the GPU reads it).
#include <cstring>
#include <filesystem>
#include <fstream>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/base64.h"
#include "support/cli_runner.h"
#include "image/exr.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A unit square in the XY plane facing +Z (two triangles, normals and TEXCOORD_0), material 0.
json squareWith(const json& material) {
    std::vector<float> floats = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,   // positions
                                 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1,   // normals
                                 0, 1, 1, 1, 1, 0, 0, 0};              // uvs (v down)
    std::vector<uint16_t> indices = {0, 1, 2, 0, 2, 3};
    std::vector<uint8_t> bytes(floats.size() * 4 + indices.size() * 2);
    std::memcpy(bytes.data(), floats.data(), floats.size() * 4);
    std::memcpy(bytes.data() + floats.size() * 4, indices.data(), indices.size() * 2);
    return {{"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes",
             {{{"primitives",
                {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}}, {"indices", 3}, {"material", 0}}}}}}},
            {"materials", {material}},
            {"buffers", {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}}},
            {"bufferViews",
             {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
              {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
              {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 32}},
              {{"buffer", 0}, {"byteOffset", 128}, {"byteLength", 12}}}},
            {"accessors",
             {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}, {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
              {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
              {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
              {{"bufferView", 3}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}}};
}

json material(const json& extensions) {
    json m = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.8, 0.6, 1.0}}, {"metallicFactor", 1.0}, {"roughnessFactor", 0.3}}}};
    if (!extensions.empty()) m["extensions"] = extensions;
    return m;
}

fs::path write(const fs::path& dir, const std::string& name, const json& doc) {
    std::ofstream(dir / name) << doc.dump();
    return dir / name;
}

// Renders the square under the sun-and-sky environment, seen at an angle; returns the EXR's
// pixels and the command's output.
std::vector<float> render(const fs::path& scene, std::string& output) {
    const fs::path exr = scene.parent_path() / (scene.stem().string() + ".exr");
    const test::RunResult r = test::runVkphoton("render " + scene.string() + " --env " + std::string(VKPHOTON_SCENES) +
                                                "/sun-sky.hdr --spp 4 --width 8 --height 8 --look-from 0.5,-0.6,0.9 "
                                                "--look-at 0.5,0.5,0 --fov 30 -o " + exr.string());
    output = r.output;
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r.exitCode == 0 ? readExr(exr).pixels : std::vector<float>{};
}

TEST(AnisotropyIridescence, FactorsAreReadWithTheDefaults) {
    const fs::path dir = test::freshTempDir("anisotropy-iridescence", "read");
    json doc = squareWith(material({{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6}, {"anisotropyRotation", 0.5}}},
                                    {"KHR_materials_iridescence", {{"iridescenceFactor", 0.7}}}}));
    doc["extensionsUsed"] = {"KHR_materials_anisotropy", "KHR_materials_iridescence"};
    const Material m = loadGltf(write(dir, "scene.gltf", doc)).materials.at(0);
    EXPECT_FLOAT_EQ(m.anisotropy, 0.6f);
    EXPECT_FLOAT_EQ(m.anisotropyRotation, 0.5f);
    EXPECT_EQ(m.anisotropyTexture, -1);
    EXPECT_FLOAT_EQ(m.iridescence, 0.7f);
    EXPECT_FLOAT_EQ(m.iridescenceIor, 1.3f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMin, 100.0f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMax, 400.0f);
    EXPECT_EQ(m.iridescenceTexture, -1);
    EXPECT_EQ(m.iridescenceThicknessTexture, -1);
    const Scene s = loadGltf(write(dir, "scene.gltf", doc));
    ASSERT_FALSE(s.triangles.empty());
    EXPECT_NE(s.triangles[0].tangent[0].w, 0.0f);  // tangents generated from TEXCOORD_0 for the direction

    json bad = doc;
    bad["materials"][0]["extensions"]["KHR_materials_iridescence"]["iridescenceIor"] = 0.5;
    EXPECT_THROW(loadGltf(write(dir, "bad.gltf", bad)), InputError);
}

// Strength 0 and factor 0 render the bits of the plain material; strength 1 and factor 1 do not,
// and neither leaves a "not rendered" warning.
TEST(AnisotropyIridescence, ZeroIsThePlainMaterialAndNonZeroIsNot) {
    const fs::path dir = test::freshTempDir("anisotropy-iridescence", "render");
    std::string output;
    const std::vector<float> plain = render(write(dir, "plain.gltf", squareWith(material(json::object()))), output);
    ASSERT_FALSE(plain.empty());
    const auto withExtensions = [&](const char* name, double strength, double factor) {
        json doc = squareWith(material({{"KHR_materials_anisotropy", {{"anisotropyStrength", strength}, {"anisotropyRotation", 0.7}}},
                                        {"KHR_materials_iridescence", {{"iridescenceFactor", factor}}}}));
        doc["extensionsUsed"] = {"KHR_materials_anisotropy", "KHR_materials_iridescence"};
        std::vector<float> pixels = render(write(dir, name, doc), output);
        EXPECT_EQ(output.find("not rendered"), std::string::npos) << output;
        return pixels;
    };
    const std::vector<float> zero = withExtensions("zero.gltf", 0.0, 0.0);
    ASSERT_EQ(zero.size(), plain.size());
    EXPECT_EQ(std::memcmp(zero.data(), plain.data(), plain.size() * sizeof(float)), 0);
    for (const auto& [name, strength, factor] : {std::tuple{"anisotropic.gltf", 1.0, 0.0}, std::tuple{"iridescent.gltf", 0.0, 1.0}}) {
        const std::vector<float> pixels = withExtensions(name, strength, factor);
        ASSERT_EQ(pixels.size(), plain.size());
        double difference = 0.0, sum = 0.0;
        for (size_t i = 0; i < pixels.size(); ++i) {
            difference += std::abs(pixels[i] - plain[i]);
            sum += plain[i];
        }
        EXPECT_GT(difference, 0.05 * sum) << name;
    }
}

}  // namespace
}  // namespace vkp
