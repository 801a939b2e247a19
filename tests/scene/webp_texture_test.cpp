// EXT_texture_webp: WebP images decoded by libwebp (scene/gltf_files.cpp), the texture's WebP
// source preferred to its PNG fallback (scene/gltf_materials.cpp).
#include <filesystem>
#include <fstream>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>
#include <webp/encode.h>

#include "support/base64.h"
#include "support/cli_runner.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Lossless WebP of a 2x2 RGBA image (top row first), as the file dir/name (tinygltf decodes no
// image/webp data: URIs; WebP images come as files or bufferViews).
std::string webpFile(const fs::path& dir, const std::string& name, const std::vector<uint8_t>& rgba) {
    uint8_t* out = nullptr;
    const size_t size = WebPEncodeLosslessRGBA(rgba.data(), 2, 2, 8, &out);
    std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(out), std::streamsize(size));
    WebPFree(out);
    return name;
}

std::string pngDataUri(const std::vector<uint8_t>& rgba) {
    std::vector<uint8_t> bytes;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* o = static_cast<std::vector<uint8_t>*>(context);
            o->insert(o->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &bytes, 2, 2, 4, rgba.data(), 8);
    return "data:image/png;base64," + test::base64(bytes);
}

json texturedTriangle(const json& images, const json& texture) {
    std::vector<uint8_t> bytes;
    for (float f : {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f}) {
        const auto* p = reinterpret_cast<const uint8_t*>(&f);
        bytes.insert(bytes.end(), p, p + 4);
    }
    return {{"asset", {{"version", "2.0"}}},
            {"extensionsUsed", {"EXT_texture_webp"}},
            {"extensionsRequired", {"EXT_texture_webp"}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"material", 0}}}}}}},
            {"materials", {{{"emissiveFactor", {1, 1, 1}}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
            {"images", images},
            {"textures", {texture}},
            {"buffers", {{{"byteLength", 60}, {"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}}},
            {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}, {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}}}},
            {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                            {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                           {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}}};
}

TEST(WebpTextures, TheWebpSourceIsDecodedAndPreferredToTheFallback) {
    const fs::path dir = test::freshTempDir("webp", "decode");
    // Distinct texels with alpha, lossless: every byte must come back.
    const std::vector<uint8_t> texels{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 10, 20, 30, 40};
    const std::vector<uint8_t> fallback(16, 200);
    const json doc = texturedTriangle({{{"uri", pngDataUri(fallback)}}, {{"uri", webpFile(dir, "texels.webp", texels)}}},
                                      {{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}});
    std::ofstream(dir / "webp.gltf") << doc.dump();
    const Scene s = loadGltf(dir / "webp.gltf");
    const Material& m = s.materials.at(0);
    ASSERT_GE(m.baseColorTexture, 0);
    const Texture& t = s.textures.at(s.textureViews.at(m.baseColorTexture).image);
    ASSERT_EQ(t.width, 2u);
    ASSERT_EQ(t.height, 2u);
    for (size_t i = 0; i < 4; ++i)
        EXPECT_EQ(t.rgba8[i], uint32_t(texels[4 * i]) | uint32_t(texels[4 * i + 1]) << 8 |
                                  uint32_t(texels[4 * i + 2]) << 16 | uint32_t(texels[4 * i + 3]) << 24)
            << i;

    // Without a fallback source, and a WebP that is not one: refused naming the image.
    json only = texturedTriangle({{{"uri", "texels.webp"}}}, {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}});
    std::ofstream(dir / "only.gltf") << only.dump();
    EXPECT_EQ(loadGltf(dir / "only.gltf").textures.at(0).rgba8.at(3) >> 24, 40u);
    const char raw[] = "RIFF\x10\0\0\0WEBPVP8 garbage";
    std::ofstream(dir / "broken.webp", std::ios::binary).write(raw, sizeof(raw) - 1);
    json bad = texturedTriangle({{{"uri", "broken.webp"}}}, {{"extensions", {{"EXT_texture_webp", {{"source", 0}}}}}});
    std::ofstream(dir / "bad.gltf") << bad.dump();
    try {
        loadGltf(dir / "bad.gltf");
        ADD_FAILURE() << "a broken WebP loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("WebP"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vkp
