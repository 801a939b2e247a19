// KHR_materials_pbrSpecularGlossiness (converted to metallic-roughness) and KHR_materials_unlit
// (an emitter of its base colour that reflects nothing): docs/scene-format.md, "Materials".
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

#include "support/base64.h"
#include "support/cli_runner.h"
#include "image/exr.h"
#include "scene/gltf_loader.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The unit right triangle (0,0,0), (1,0,0), (0,1,0) facing +Z with material 0 = `material`.
json triangleWith(const json& material) {
    std::vector<uint8_t> bytes;
    for (float f : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}) {
        const auto* p = reinterpret_cast<const uint8_t*>(&f);
        bytes.insert(bytes.end(), p, p + 4);
    }
    return {{"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}}}},
            {"materials", {material}},
            {"buffers", {{{"byteLength", 36}, {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}}},
            {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
            {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                            {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}}};
}

fs::path write(const fs::path& dir, const json& doc) {
    std::ofstream(dir / "scene.gltf") << doc.dump();
    return dir / "scene.gltf";
}

std::string pngDataUri(int width, int height, const std::vector<uint8_t>& rgba) {
    std::vector<uint8_t> bytes;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<uint8_t>*>(context);
            out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &bytes, width, height, 4, rgba.data(), width * 4);
    return "data:image/png;base64," + test::base64(bytes);
}

TEST(KhronosMaterials, SpecularGlossinessIsConverted) {
    const fs::path dir = test::freshTempDir("khronos-materials", "specgloss");
    // Factors only: the metallic-roughness fallback (a rough metal) must lose to the extension.
    json material = {{"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 1.0}}},
                     {"extensions",
                      {{"KHR_materials_pbrSpecularGlossiness",
                        {{"diffuseFactor", {0.5, 0.4, 0.3, 0.8}},
                         {"specularFactor", {0.2, 0.3, 0.4}},
                         {"glossinessFactor", 0.75}}}}}};
    json doc = triangleWith(material);
    doc["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
    doc["extensionsRequired"] = {"KHR_materials_pbrSpecularGlossiness"};
    Scene s = loadGltf(write(dir, doc));
    Material m = s.materials.at(0);
    EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.4f, 0.3f, 0.8f));
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_FLOAT_EQ(m.roughness, 0.25f);
    EXPECT_EQ(m.specular, 1.0f);
    EXPECT_EQ(m.specularColor, glm::vec3(0.2f, 0.3f, 0.4f));
    EXPECT_EQ(m.ior, 0.0f);  // KHR_materials_ior's specular-glossiness mode: reflectance = specular colour
    EXPECT_EQ(m.metallicRoughnessTexture, -1);

    // Textures: the diffuse texture is the base colour's; the specular-glossiness texture's RGB
    // the specular colour's (sRGB), its A (x glossinessFactor) becomes G = 1 - glossiness.
    doc["images"] = {{{"uri", pngDataUri(2, 1, {255, 0, 0, 255, 0, 0, 255, 255})}},
                     {{"uri", pngDataUri(2, 1, {10, 20, 30, 0, 40, 50, 60, 200})}}};
    doc["textures"] = {{{"source", 0}}, {{"source", 1}}};
    auto& ext = doc["materials"][0]["extensions"]["KHR_materials_pbrSpecularGlossiness"];
    ext["diffuseTexture"] = {{"index", 0}};
    ext["specularGlossinessTexture"] = {{"index", 1}};
    s = loadGltf(write(dir, doc));
    m = s.materials.at(0);
    ASSERT_GE(m.baseColorTexture, 0);
    EXPECT_TRUE(s.textures.at(s.textureViews.at(m.baseColorTexture).image).srgb);
    ASSERT_GE(m.specularColorTexture, 0);
    const Texture& specular = s.textures.at(s.textureViews.at(m.specularColorTexture).image);
    EXPECT_TRUE(specular.srgb);
    EXPECT_EQ(specular.rgba8.at(1) & 0xffffffu, 40u | (50u << 8) | (60u << 16));
    ASSERT_GE(m.metallicRoughnessTexture, 0);
    EXPECT_EQ(m.roughness, 1.0f);
    EXPECT_EQ(m.metallic, 0.0f);
    const Texture& rough = s.textures.at(s.textureViews.at(m.metallicRoughnessTexture).image);
    EXPECT_FALSE(rough.srgb);
    ASSERT_EQ(rough.rgba8.size(), 2u);
    EXPECT_EQ((rough.rgba8[0] >> 8) & 0xffu, 255u);                         // A 0: glossiness 0
    EXPECT_EQ((rough.rgba8[1] >> 8) & 0xffu, uint32_t(std::lround(255.0 * (1.0 - 0.75 * 200.0 / 255.0))));
    EXPECT_EQ((rough.rgba8[1] >> 16) & 0xffu, 0u);                          // B: metallic 0
}

TEST(KhronosMaterials, UnlitShowsItsBaseColour) {
    const fs::path dir = test::freshTempDir("khronos-materials", "unlit");
    json material = {{"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.3, 0.1, 1.0}}, {"metallicFactor", 0.0}}},
                     {"extensions", {{"KHR_materials_unlit", json::object()}}}};
    json doc = triangleWith(material);
    doc["extensionsUsed"] = {"KHR_materials_unlit"};
    doc["extensionsRequired"] = {"KHR_materials_unlit"};
    const fs::path scene = write(dir, doc);
    const Material m = loadGltf(scene).materials.at(0);
    EXPECT_EQ(m.emissive, glm::vec3(0.6f, 0.3f, 0.1f));
    EXPECT_EQ(m.baseColor, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(m.specular, 0.0f);

    // Under a sky of radiance 3 a lit white-ish surface would show 3x its albedo; the unlit one
    // shows its base colour exactly, whatever lights it.
    for (const char* env : {"3", "0.5"}) {
        const fs::path exr = dir / (std::string("unlit-") + env + ".exr");
        const test::RunResult r = test::runVkphoton(
            "render " + scene.string() + " --quiet --env " + env +
            " --spp 4 --width 6 --height 6 --look-from 0.25,0.25,0.5 --look-at 0.25,0.25,0 --fov 20 -o " + exr.string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const ImageRgb image = readExr(exr);
        for (size_t i = 0; i < image.pixels.size(); i += 3) {
            ASSERT_NEAR(image.pixels[i], 0.6f, 1e-5f) << env;
            ASSERT_NEAR(image.pixels[i + 1], 0.3f, 1e-5f) << env;
            ASSERT_NEAR(image.pixels[i + 2], 0.1f, 1e-5f) << env;
        }
    }
}

}  // namespace
}  // namespace vkp
