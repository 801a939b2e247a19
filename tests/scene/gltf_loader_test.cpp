// glTF loading: supported features on small files built here, and the corpus of bad files in
// tests/data/bad/ (each must give its clear message, naming the file and the element).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>
#include <unistd.h>

#include "support/base64.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_uri_policy.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::base64;

template <typename T> void append(std::vector<uint8_t>& bytes, const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    bytes.insert(bytes.end(), p, p + sizeof(T));
}

// One unit right triangle in the z = 0 plane (front face +z), emissive, optionally indexed and
// with normals; the document can be extended by each test.
json triangleDoc(bool indexed, bool withNormals) {
    std::vector<uint8_t> bytes;
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    for (float f : positions) append(bytes, f);
    json views = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}}});
    json accessors = json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                                   {"min", {0, 0, 0}}, {"max", {1, 1, 0}}}});
    json attributes = {{"POSITION", 0}};
    if (withNormals) {
        for (int i = 0; i < 3; ++i) { append(bytes, 0.0f); append(bytes, 0.0f); append(bytes, 1.0f); }
        views.push_back({{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 36}});
        accessors.push_back({{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
        attributes["NORMAL"] = 1;
    }
    json primitive = {{"attributes", attributes}, {"material", 0}};
    if (indexed) {
        const size_t offset = bytes.size();
        for (uint16_t i : {0, 1, 2, 0}) append(bytes, i);
        views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", 6}});
        accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}});
        primitive["indices"] = accessors.size() - 1;
    }
    return {{"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes", {{{"primitives", {primitive}}}}},
            {"materials", {{{"emissiveFactor", {1, 1, 1}}}}},
            {"buffers", {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}},
            {"bufferViews", views},
            {"accessors", accessors}};
}

class GltfLoader : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("vkphoton-gltf-" + std::to_string(::getpid()) + "-" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    fs::path write(const json& doc, const std::string& name = "scene.gltf") {
        const fs::path path = m_dir / name;
        std::ofstream(path) << doc.dump();
        return path;
    }

    fs::path m_dir;
};

TEST_F(GltfLoader, IndexedAndNonIndexedTrianglesWithAndWithoutNormals) {
    for (bool indexed : {false, true})
        for (bool normals : {false, true}) {
            const Scene s = loadGltf(write(triangleDoc(indexed, normals)));
            ASSERT_EQ(s.triangles.size(), 1u);
            for (const auto& n : s.triangles[0].n) EXPECT_NEAR(glm::distance(n, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
            EXPECT_EQ(s.triangles[0].p[1], glm::vec3(1, 0, 0));
        }
}

TEST_F(GltfLoader, NestedTrsAndMatrixTransforms) {
    json doc = triangleDoc(true, true);
    // Parent: translate (10, 0, 0) and rotate 90 degrees about z; child: matrix scaling by 2.
    const float s = std::sqrt(0.5f);
    doc["nodes"] = {{{"translation", {10, 0, 0}}, {"rotation", {0, 0, s, s}}, {"children", {1}}},
                    {{"mesh", 0}, {"matrix", {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1}}}};
    const Scene scene = loadGltf(write(doc));
    ASSERT_EQ(scene.triangles.size(), 1u);
    const Triangle& t = scene.triangles[0];
    // (1,0,0) -> scale (2,0,0) -> rotate (0,2,0) -> translate (10,2,0).
    EXPECT_NEAR(glm::distance(t.p[1], glm::vec3(10, 2, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(t.p[2], glm::vec3(8, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(t.n[0], glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
}

TEST_F(GltfLoader, MirroringTransformKeepsTheFrontFace) {
    json doc = triangleDoc(true, false);
    doc["nodes"] = {{{"mesh", 0}, {"scale", {-1, 1, 1}}}};
    const Triangle t = loadGltf(write(doc)).triangles[0];
    const glm::vec3 n = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    EXPECT_NEAR(n.z, 1.0f, 1e-6f);  // the mirrored triangle still faces +z
}

TEST_F(GltfLoader, MaterialsAndExtensions) {
    json doc = triangleDoc(true, true);
    doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"metallicFactor", 0.2}, {"roughnessFactor", 0.7}}},
                         {"emissiveFactor", {1, 0.5, 0}},
                         {"doubleSided", true},
                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}},
                                         {"KHR_materials_transmission", {{"transmissionFactor", 0.9}}},
                                         {"KHR_materials_ior", {{"ior", 1.33}}},
                                         {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationColor", {0.5, 1, 1}}, {"attenuationDistance", 2}}}}}}};
    const Scene s = loadGltf(write(doc));
    const Material& m = s.materials.at(0);
    EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
    EXPECT_FLOAT_EQ(m.metallic, 0.2f);
    EXPECT_FLOAT_EQ(m.roughness, 0.7f);
    EXPECT_EQ(m.emissive, glm::vec3(4.0f, 2.0f, 0.0f));
    EXPECT_TRUE(m.doubleSided);
    EXPECT_FLOAT_EQ(m.transmission, 0.9f);
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(m.thickness, 0.5f);
    EXPECT_EQ(m.attenuationColor, glm::vec3(0.5f, 1.0f, 1.0f));
    EXPECT_FLOAT_EQ(m.attenuationDistance, 2.0f);
}

// KHR_materials_specular, clearcoat, sheen and dispersion factors (docs/materials.md), read
// without a warning (every KHR_materials_* extension of the table is rendered).
TEST_F(GltfLoader, SpecularClearcoatSheenAndDispersion) {
    json doc = triangleDoc(true, true);
    doc["materials"] = {{{"name", "fancy"},
                         {"emissiveFactor", {1, 1, 1}},  // the scene needs a light
                         {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.25}, {"specularColorFactor", {2, 1, 0.5}}}},
                                         {"KHR_materials_clearcoat", {{"clearcoatFactor", 0.75}, {"clearcoatRoughnessFactor", 0.3}}},
                                         {"KHR_materials_sheen", {{"sheenColorFactor", {0.5, 0.4, 0.3}}, {"sheenRoughnessFactor", 0.6}}},
                                         {"KHR_materials_dispersion", {{"dispersion", 1}}}}}}};
    testing::internal::CaptureStderr();
    const Scene s = loadGltf(write(doc));
    std::istringstream stderrLines(testing::internal::GetCapturedStderr());
    std::vector<std::string> warnings;
    for (std::string line; std::getline(stderrLines, line);) warnings.push_back(line);
    const Material& m = s.materials.at(0);
    EXPECT_FLOAT_EQ(m.specular, 0.25f);
    EXPECT_EQ(m.specularColor, glm::vec3(2.0f, 1.0f, 0.5f));  // not bounded by 1
    EXPECT_FLOAT_EQ(m.clearcoat, 0.75f);
    EXPECT_FLOAT_EQ(m.clearcoatRoughness, 0.3f);
    EXPECT_EQ(m.sheenColor, glm::vec3(0.5f, 0.4f, 0.3f));
    EXPECT_FLOAT_EQ(m.sheenRoughness, 0.6f);
    EXPECT_FLOAT_EQ(m.dispersion, 1.0f);
    for (const std::string& w : warnings) EXPECT_EQ(w.find("not rendered"), std::string::npos) << w;
    // Without the extensions: the glTF defaults (full specular, no coat, no sheen).
    const Material d;
    EXPECT_FLOAT_EQ(d.specular, 1.0f);
    EXPECT_EQ(d.specularColor, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(d.clearcoat, 0.0f);
    EXPECT_EQ(d.sheenColor, glm::vec3(0.0f));
}

TEST_F(GltfLoader, PrimitiveWithoutMaterialGetsTheGltfDefault) {
    json doc = triangleDoc(true, true);
    doc["meshes"][0]["primitives"][0].erase("material");
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 683}}}}}}};
    doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["scenes"][0]["nodes"] = {0, 1};
    const Scene s = loadGltf(write(doc));
    const Material& m = s.materials.at(s.triangles[0].material);
    EXPECT_EQ(m.baseColor, glm::vec4(1.0f));
    EXPECT_FLOAT_EQ(m.metallic, 1.0f);
    EXPECT_FLOAT_EQ(m.roughness, 1.0f);
}

TEST_F(GltfLoader, PunctualLightsInRadiometricUnits) {
    json doc = triangleDoc(true, true);
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"] = {{"KHR_lights_punctual",
                          {{"lights", {{{"type", "point"}, {"intensity", 683}, {"color", {1, 0.5, 0.25}}},
                                       {{"type", "spot"}, {"intensity", 1366}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.5}}}},
                                       {{"type", "directional"}, {"intensity", 6830}}}}}}};
    doc["nodes"].push_back({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["nodes"].push_back({{"rotation", {-std::sqrt(0.5), 0, 0, std::sqrt(0.5)}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    doc["scenes"][0]["nodes"] = {0, 1, 2, 3};
    const Scene s = loadGltf(write(doc));
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[0].type, LightType::Point);
    EXPECT_EQ(s.lights[0].position, glm::vec3(1, 2, 3));
    EXPECT_NEAR(s.lights[0].intensity.x, 1.0f, 1e-6f);   // 683 cd = 1 W/sr
    EXPECT_NEAR(s.lights[0].intensity.z, 0.25f, 1e-6f);
    EXPECT_EQ(s.lights[1].type, LightType::Spot);
    EXPECT_NEAR(s.lights[1].intensity.y, 2.0f, 1e-6f);
    EXPECT_FLOAT_EQ(s.lights[1].outerConeAngle, 0.5f);
    EXPECT_NEAR(glm::distance(s.lights[1].direction, glm::vec3(0, -1, 0)), 0.0f, 1e-5f);  // -z rotated down
    EXPECT_EQ(s.lights[2].type, LightType::Directional);
    EXPECT_NEAR(s.lights[2].intensity.x, 10.0f, 1e-5f);  // 6830 lux = 10 W/m^2
}

TEST_F(GltfLoader, PerspectiveCamerasInNodeOrder) {
    json doc = triangleDoc(true, true);
    doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
                      {{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"aspectRatio", 2.0}, {"znear", 0.1}}}}};
    doc["nodes"].push_back({{"camera", 1}, {"translation", {0, 0, 5}}});
    doc["nodes"].push_back({{"camera", 0}, {"translation", {0, 0, 7}}});
    doc["scenes"][0]["nodes"] = {0, 1, 2};
    const Scene s = loadGltf(write(doc));
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_FLOAT_EQ(s.cameras[0].yfov, 0.9f);
    EXPECT_FLOAT_EQ(s.cameras[0].aspectRatio, 2.0f);
    EXPECT_EQ(s.cameras[0].position, glm::vec3(0, 0, 5));
    EXPECT_EQ(s.cameras[0].forward, glm::vec3(0, 0, -1));
    EXPECT_FLOAT_EQ(s.cameras[1].yfov, 0.5f);
}

TEST_F(GltfLoader, DegenerateTrianglesAreDroppedAndCounted) {
    json doc = triangleDoc(false, false);
    // Append a second primitive whose triangle has all vertices equal (index buffer 0,0,0).
    std::vector<uint8_t> extra;
    for (uint16_t i : {0, 0, 0, 0}) append(extra, i);
    doc["buffers"].push_back({{"byteLength", extra.size()}, {"uri", "data:application/octet-stream;base64," + base64(extra)}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 6}});
    doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}});
    doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 0}}}, {"indices", doc["accessors"].size() - 1}, {"material", 0}});
    const Scene s = loadGltf(write(doc));
    EXPECT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.droppedDegenerateTriangles, 1u);
}

TEST_F(GltfLoader, BinaryGlbWithExternalBufferInTheSameFolder) {
    json doc = triangleDoc(true, true);
    // Move the buffer to a file next to the scene and store the JSON as a .glb.
    const std::string uri = doc["buffers"][0]["uri"];
    const std::string encoded = uri.substr(uri.find(',') + 1);
    std::vector<uint8_t> raw;
    {
        std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        uint32_t buffer = 0;
        int bits = 0;
        for (char c : encoded) {
            if (c == '=') break;
            buffer = (buffer << 6) | static_cast<uint32_t>(table.find(c));
            bits += 6;
            if (bits >= 8) { bits -= 8; raw.push_back(static_cast<uint8_t>((buffer >> bits) & 0xff)); }
        }
    }
    std::ofstream(m_dir / "mesh data.bin", std::ios::binary).write(reinterpret_cast<const char*>(raw.data()), raw.size());
    doc["buffers"][0]["uri"] = "mesh%20data.bin";
    std::string text = doc.dump();
    while (text.size() % 4) text += ' ';
    std::vector<uint8_t> glb;
    append(glb, 0x46546C67u);
    append(glb, 2u);
    append(glb, static_cast<uint32_t>(12 + 8 + text.size()));
    append(glb, static_cast<uint32_t>(text.size()));
    append(glb, 0x4E4F534Au);
    glb.insert(glb.end(), text.begin(), text.end());
    const fs::path path = m_dir / "scene.glb";
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(glb.data()), glb.size());
    const Scene s = loadGltf(path);
    EXPECT_EQ(s.triangles.size(), 1u);
}

TEST_F(GltfLoader, TextureFromAPngDataUri) {
    // A 2x1 RGB PNG: red, green.
    const uint8_t pixels[6] = {255, 0, 0, 0, 255, 0};
    std::vector<uint8_t> pngBytes;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<uint8_t>*>(context);
            out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &pngBytes, 2, 1, 3, pixels, 6);
    const std::string png = base64(pngBytes);
    json doc = triangleDoc(true, true);
    doc["images"] = {{{"uri", "data:image/png;base64," + png}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 0}}}};
    const Scene s = loadGltf(write(doc));
    ASSERT_EQ(s.textures.size(), 2u);  // the same image as sRGB colour and as linear data
    const Texture& t = s.textures[s.textureViews[s.materials[0].baseColorTexture].image];
    EXPECT_TRUE(t.srgb);
    EXPECT_FALSE(s.textures[s.textureViews[s.materials[0].metallicRoughnessTexture].image].srgb);
    ASSERT_EQ(t.width, 2u);
    ASSERT_EQ(t.height, 1u);
    EXPECT_EQ(t.rgba8[0] & 0xffffffu, 0x0000ffu);  // red in the low byte
    EXPECT_EQ(t.rgba8[1] & 0xffffffu, 0x00ff00u);
}

// Adds a buffer holding `bytes` (as a data: URI), a view of it and an accessor over the view;
// returns the accessor's index.
int addAccessor(json& doc, const std::vector<uint8_t>& bytes, int componentType, size_t count, const std::string& type,
                bool normalized = false, size_t stride = 0) {
    doc["buffers"].push_back({{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}});
    json view = {{"buffer", doc["buffers"].size() - 1}, {"byteLength", bytes.size()}};
    if (stride) view["byteStride"] = stride;
    doc["bufferViews"].push_back(view);
    doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1}, {"componentType", componentType},
                                {"count", count}, {"type", type}, {"normalized", normalized}});
    return static_cast<int>(doc["accessors"].size() - 1);
}

template <typename T> std::vector<uint8_t> bytesOf(std::initializer_list<T> values) {
    std::vector<uint8_t> bytes;
    for (const T& v : values) append(bytes, v);
    while (bytes.size() % 4) bytes.push_back(0);
    return bytes;
}

std::vector<uint8_t> encodePng(int width, int height, int channels, const std::vector<uint8_t>& pixels) {
    std::vector<uint8_t> out;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* bytes = static_cast<std::vector<uint8_t>*>(context);
            bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &out, width, height, channels, pixels.data(), width * channels);
    return out;
}

// stb writes only 8-bit PNGs: a 16-bit one is assembled here, its zlib stream made of stored
// (uncompressed) deflate blocks.
std::vector<uint8_t> encodePng16(int width, int height, int channels, const std::vector<uint16_t>& samples) {
    const auto crc32 = [](const uint8_t* data, size_t n) {
        uint32_t crc = 0xffffffffu;
        for (size_t i = 0; i < n; ++i) {
            crc ^= data[i];
            for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
        }
        return crc ^ 0xffffffffu;
    };
    const auto bigEndian = [](std::vector<uint8_t>& v, uint32_t x, int bytes) {
        for (int i = bytes - 1; i >= 0; --i) v.push_back(static_cast<uint8_t>(x >> (8 * i)));
    };
    std::vector<uint8_t> raw;  // scanlines, each led by filter type 0
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);
        for (int i = 0; i < width * channels; ++i) bigEndian(raw, samples[size_t(y) * width * channels + i], 2);
    }
    std::vector<uint8_t> zlib = {0x78, 0x01};
    uint32_t a = 1, b = 0;
    for (uint8_t byte : raw) { a = (a + byte) % 65521; b = (b + a) % 65521; }
    zlib.push_back(1);  // final stored block (raw stays under 64 KiB here)
    const uint16_t length = static_cast<uint16_t>(raw.size());
    append(zlib, length);
    append(zlib, static_cast<uint16_t>(~length));
    zlib.insert(zlib.end(), raw.begin(), raw.end());
    bigEndian(zlib, (b << 16) | a, 4);
    std::vector<uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const auto chunk = [&](const char* type, const std::vector<uint8_t>& body) {
        bigEndian(png, static_cast<uint32_t>(body.size()), 4);
        std::vector<uint8_t> typed(type, type + 4);
        typed.insert(typed.end(), body.begin(), body.end());
        png.insert(png.end(), typed.begin(), typed.end());
        bigEndian(png, crc32(typed.data(), typed.size()), 4);
    };
    std::vector<uint8_t> header;
    bigEndian(header, width, 4);
    bigEndian(header, height, 4);
    header.insert(header.end(), {16, static_cast<uint8_t>(channels == 1 ? 0 : channels == 3 ? 2 : 6), 0, 0, 0});
    chunk("IHDR", header);
    chunk("IDAT", zlib);
    chunk("IEND", {});
    return png;
}

json texturedDoc(const std::vector<uint8_t>& image, const char* mime = "image/png") {
    json doc = triangleDoc(true, true);
    doc["images"] = {{{"uri", std::string("data:") + mime + ";base64," + base64(image)}}};
    doc["textures"] = {{{"source", 0}}};
    doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
    doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
    return doc;
}

TEST_F(GltfLoader, GreySixteenBitAndJpegImagesBecomeRgba8) {
    {
        const Scene s = loadGltf(write(texturedDoc(encodePng(2, 1, 1, {10, 200}))));
        ASSERT_EQ(s.textures.size(), 1u);  // base colour and emission share one sRGB texture
        EXPECT_TRUE(s.textures[0].srgb);
        EXPECT_EQ(s.materials[0].emissiveTexture, s.materials[0].baseColorTexture);
        EXPECT_EQ(s.textures[0].rgba8[0], 0xff0a0a0au);  // grey replicated, opaque
        EXPECT_EQ(s.textures[0].rgba8[1], 0xffc8c8c8u);
    }
    {
        const Scene s = loadGltf(write(texturedDoc(encodePng(1, 1, 2, {7, 128}))));
        EXPECT_EQ(s.textures[0].rgba8[0], 0x80070707u);  // grey + alpha
    }
    {
        // 16-bit RGBA: 0xffff -> 255, 0x8080 -> 128, 0 -> 0, 0x0101 -> 1 (rounded, not truncated).
        const Scene s = loadGltf(write(texturedDoc(encodePng16(1, 1, 4, {0xffff, 0x8080, 0x0000, 0x0101}))));
        ASSERT_EQ(s.textures.size(), 1u);
        EXPECT_EQ(s.textures[0].rgba8[0], 0x010080ffu);
    }
    {
        std::vector<uint8_t> jpeg;
        const std::vector<uint8_t> grey(64, 128);
        stbi_write_jpg_to_func(
            [](void* context, void* data, int size) {
                auto* bytes = static_cast<std::vector<uint8_t>*>(context);
                bytes->insert(bytes->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
            },
            &jpeg, 8, 8, 1, grey.data(), 90);
        const Scene s = loadGltf(write(texturedDoc(jpeg, "image/jpeg")));
        ASSERT_EQ(s.textures[0].width, 8u);
        EXPECT_NEAR(double(s.textures[0].rgba8[27] & 0xff), 128.0, 2.0);
    }
}

TEST_F(GltfLoader, GoodFilesWithExternalBuffersAndImages) {
    const fs::path good = fs::path(VKPHOTON_TEST_DATA) / "good";
    for (const char* name : {"triangle.gltf", "triangle.glb", "textured.gltf"}) {
        const Scene s = loadGltf(good / name);
        ASSERT_EQ(s.triangles.size(), 1u) << name;
        EXPECT_EQ(s.triangles[0].p[2], glm::vec3(0, 1, 0)) << name;
        EXPECT_EQ(s.materials[0].emissive, glm::vec3(1.0f)) << name;
        EXPECT_EQ(s.bounds.min, glm::vec3(0.0f)) << name;
        EXPECT_EQ(s.bounds.max, glm::vec3(1, 1, 0)) << name;
    }
    const Scene s = loadGltf(good / "textured.gltf");
    ASSERT_EQ(s.textures.size(), 1u);
    const Texture& t = s.textures[0];
    ASSERT_EQ(t.width * t.height, 4u);
    EXPECT_EQ(t.rgba8, (std::vector<uint32_t>{0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xffffffffu}));  // top row first
    EXPECT_EQ(s.triangles[0].uv[1], glm::vec2(1, 0));
}

TEST_F(GltfLoader, ExternalBufferMayBeLongerThanItsByteLength) {
    json doc = triangleDoc(false, false);
    const std::vector<uint8_t> bytes = bytesOf<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 99, 99});
    std::ofstream(m_dir / "long.bin", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    doc["buffers"][0]["uri"] = "long.bin";
    EXPECT_EQ(loadGltf(write(doc)).triangles.size(), 1u);
}

TEST_F(GltfLoader, SymbolicLinkOutOfTheFolderIsRefused) {
    const fs::path outside = m_dir / "outside";
    const fs::path scene = m_dir / "scene";
    fs::create_directories(outside);
    fs::create_directories(scene);
    const std::vector<uint8_t> bytes = bytesOf<float>({0, 0, 0, 1, 0, 0, 0, 1, 0});
    std::ofstream(outside / "secret.bin", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    fs::create_symlink(outside / "secret.bin", scene / "link.bin");
    json doc = triangleDoc(false, false);
    doc["buffers"][0]["uri"] = "link.bin";
    const fs::path path = write(doc, "scene/scene.gltf");
    try {
        loadGltf(path);
        FAIL() << "a link leaving the folder was followed";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("buffers[0].uri: file \"link.bin\" not found inside the scene's folder"),
                  std::string::npos) << e.what();
    }
    // A link that stays inside the folder is fine.
    fs::copy_file(outside / "secret.bin", scene / "data.bin");
    fs::remove(scene / "link.bin");
    fs::create_symlink("data.bin", scene / "link.bin");
    EXPECT_EQ(loadGltf(path).triangles.size(), 1u);
}

TEST_F(GltfLoader, NormalsUseTheInverseTransposeAndMirroringKeepsThemOutward) {
    json doc = triangleDoc(false, false);
    // Normals tilted in x; a non-uniform scale of 2 in x must tilt them back (inverse transpose).
    const float r = std::sqrt(0.5f);
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] =
        addAccessor(doc, bytesOf<float>({r, 0, r, r, 0, r, r, 0, r}), 5126, 3, "VEC3");
    doc["nodes"][0]["scale"] = {2, 1, 1};
    Triangle t = loadGltf(write(doc)).triangles.at(0);
    const glm::vec3 expected = glm::normalize(glm::vec3(0.5f, 0, 1));
    for (const glm::vec3& n : t.n) EXPECT_NEAR(glm::distance(n, expected), 0.0f, 1e-6f);

    doc["nodes"][0]["scale"] = {-1, 1, 1};  // mirror: normals and the winding flip together
    t = loadGltf(write(doc)).triangles.at(0);
    const glm::vec3 geometric = glm::normalize(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
    for (const glm::vec3& n : t.n) {
        EXPECT_NEAR(glm::distance(n, glm::normalize(glm::vec3(-r, 0, r))), 0.0f, 1e-6f);
        EXPECT_GT(glm::dot(n, geometric), 0.0f);
    }
}

TEST_F(GltfLoader, TrianglesWithoutAUnitNormalAreDropped) {
    json doc = triangleDoc(false, false);
    // Two triangles: the second has a zero-length normal at one vertex (NaN once normalised).
    const std::vector<uint8_t> positions = bytesOf<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1});
    const std::vector<uint8_t> normals = bytesOf<float>({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 1});
    doc["meshes"][0]["primitives"][0]["attributes"] = {{"POSITION", addAccessor(doc, positions, 5126, 6, "VEC3")},
                                                       {"NORMAL", addAccessor(doc, normals, 5126, 6, "VEC3")}};
    const Scene s = loadGltf(write(doc));
    EXPECT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.droppedDegenerateTriangles, 1u);
    EXPECT_EQ(s.bounds.max, glm::vec3(1, 1, 0));  // bounds cover the kept triangles only
}

TEST_F(GltfLoader, InterleavedSparseAndQuantizedAttributes) {
    json doc = triangleDoc(false, false);
    // Positions interleaved with other data (stride 24); UVs as normalized unsigned shorts and
    // normals as normalized signed bytes (KHR_mesh_quantization, stride 4); a sparse accessor
    // moves vertex 2.
    std::vector<uint8_t> interleaved;
    for (const glm::vec3& p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}) {
        append(interleaved, p);
        append(interleaved, glm::vec3(-7.0f));  // other data in between
    }
    const int position = addAccessor(doc, interleaved, 5126, 3, "VEC3", false, 24);
    const int uv = addAccessor(doc, bytesOf<uint16_t>({0, 0, 65535, 0, 0, 65535}), 5123, 3, "VEC2", true);
    const int normal = addAccessor(doc, bytesOf<int8_t>({0, 0, 127, 0, 127, 0, 0, 0, -128, 0, 0, 0}), 5120, 3, "VEC3", true, 4);
    auto& primitive = doc["meshes"][0]["primitives"][0];
    primitive["attributes"] = {{"POSITION", position}, {"TEXCOORD_0", uv}, {"NORMAL", normal}};
    // Sparse: vertex 2 moves to (0, 2, 0).
    std::vector<uint8_t> sparse = bytesOf<uint32_t>({2});
    for (float f : {0.0f, 2.0f, 0.0f}) append(sparse, f);
    doc["buffers"].push_back({{"byteLength", sparse.size()}, {"uri", "data:application/octet-stream;base64," + base64(sparse)}});
    const size_t buffer = doc["buffers"].size() - 1;
    doc["bufferViews"].push_back({{"buffer", buffer}, {"byteLength", 4}});
    doc["bufferViews"].push_back({{"buffer", buffer}, {"byteOffset", 4}, {"byteLength", 12}});
    doc["accessors"][position]["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", doc["bufferViews"].size() - 2}, {"componentType", 5125}}},
        {"values", {{"bufferView", doc["bufferViews"].size() - 1}}}};
    const Triangle t = loadGltf(write(doc)).triangles.at(0);
    EXPECT_EQ(t.p[1], glm::vec3(1, 0, 0));
    EXPECT_EQ(t.p[2], glm::vec3(0, 2, 0));
    EXPECT_EQ(t.uv[1], glm::vec2(1, 0));
    EXPECT_EQ(t.uv[2], glm::vec2(0, 1));
    EXPECT_NEAR(glm::distance(t.n[0], glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(t.n[1], glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(t.n[2], glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);  // -128 clamps to -1
}

TEST_F(GltfLoader, NonTrianglePrimitivesAreSkippedAndTheDefaultMaterialAddedOnlyWhenUsed) {
    json doc = triangleDoc(true, false);
    json lines = doc["meshes"][0]["primitives"][0];
    lines["mode"] = 1;
    doc["meshes"][0]["primitives"].push_back(lines);
    Scene s = loadGltf(write(doc));
    EXPECT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.materials.size(), 1u);  // every primitive has a material: no default appended

    doc["materials"].push_back({{"name", "unused"}});
    json plain = doc["meshes"][0]["primitives"][0];
    plain.erase("material");
    // Elsewhere: the same triangle at the same place would be dropped as a duplicate.
    doc["meshes"].push_back({{"primitives", {plain}}});
    doc["nodes"].push_back({{"mesh", 1}, {"translation", {2, 0, 0}}});
    doc["scenes"][0]["nodes"].push_back(1);
    s = loadGltf(write(doc));
    ASSERT_EQ(s.materials.size(), 3u);
    EXPECT_EQ(s.materials[2].name, "default");
    EXPECT_EQ(s.triangles.at(1).material, 2u);
}

// A million nodes of one triangle made rays run out of the device's loop budget; exact
// copies (also listed from another vertex) are dropped and counted, moved copies are kept.
TEST_F(GltfLoader, DuplicateTrianglesAreDroppedAndCounted) {
    json doc = triangleDoc(true, false);
    doc["nodes"] = json::array();
    for (int i = 0; i < 1000; ++i) doc["nodes"].push_back({{"mesh", 0}});
    doc["nodes"].push_back({{"mesh", 0}, {"translation", {0, 0, 1}}});
    doc["nodes"].push_back({{"mesh", 0}, {"rotation", {0, 0, 0, 1}}});  // identity: a copy
    json roots = json::array();
    for (int i = 0; i < 1002; ++i) roots.push_back(i);
    doc["scenes"][0]["nodes"] = roots;
    Scene s = loadGltf(write(doc));
    EXPECT_EQ(s.triangles.size(), 2u);
    EXPECT_EQ(s.droppedDuplicateTriangles, 1000u);

    // The same vertices in another rotation of the index order are the same triangle.
    json rotated = triangleDoc(true, false);
    rotated["meshes"][0]["primitives"].push_back(rotated["meshes"][0]["primitives"][0]);
    s = loadGltf(write(rotated));
    EXPECT_EQ(s.droppedDuplicateTriangles, 1u);
}

// Device and memory limits are checked from the accessors' counts before anything is
// decoded, every mesh reference counted, and refused as RuntimeError (exit 1), not bad input.
TEST_F(GltfLoader, DeviceAndMemoryLimitsAreCheckedBeforeDecoding) {
    json doc = triangleDoc(false, false);
    doc["accessors"].push_back({{"componentType", 5126}, {"count", 3 << 20}, {"type", "VEC3"}});  // zeros: no data
    doc["meshes"][0]["primitives"] = json::array();
    for (int i = 0; i < 16; ++i) doc["meshes"][0]["primitives"].push_back({{"attributes", {{"POSITION", 1}}}, {"material", 0}});
    const fs::path path = write(doc);
    GltfLimits device;
    device.deviceMaxTriangles = 1u << 20;
    try {
        loadGltf(path, device);
        ADD_FAILURE() << "not refused";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("scenes[0]: 16777216 triangles (counting every mesh reference) exceed what the "
                                             "device holds (1048576"), std::string::npos) << e.what();
    }
    GltfLimits memory;
    memory.maxMemoryBytes = uint64_t(1) << 30;
    try {
        loadGltf(path, memory);
        ADD_FAILURE() << "not refused";
    } catch (const RuntimeError& e) {
        EXPECT_NE(std::string(e.what()).find("GiB of memory; 1.0 GiB are allowed"), std::string::npos) << e.what();
    }
}

TEST_F(GltfLoader, CamerasAreOrthonormalAndOrthographicOnesKept) {
    json doc = triangleDoc(true, true);
    doc["cameras"] = {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
                      {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
    // Parent rotates 90 degrees about y (the camera then looks down -x) and scales unevenly.
    const double r = std::sqrt(0.5);
    doc["nodes"].push_back({{"camera", 0}});
    doc["nodes"].push_back({{"rotation", {0, r, 0, r}}, {"scale", {3, 0.5, 2}}, {"translation", {1, 2, 3}}, {"children", {3}}});
    doc["nodes"].push_back({{"camera", 1}});
    doc["scenes"][0]["nodes"] = {0, 1, 2};
    const Scene s = loadGltf(write(doc));
    ASSERT_EQ(s.cameras.size(), 2u);
    EXPECT_FLOAT_EQ(s.cameras[0].orthoHalfHeight, 1.0f);
    const Camera& c = s.cameras[1];
    EXPECT_FLOAT_EQ(c.orthoHalfHeight, 0.0f);
    EXPECT_EQ(c.position, glm::vec3(1, 2, 3));
    EXPECT_NEAR(glm::distance(c.forward, glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::distance(c.up, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(c.aspectRatio, 0.0f);  // absent
    EXPECT_FLOAT_EQ(c.yfov, 0.7f);
}

TEST_F(GltfLoader, LimitsAreEnforced) {
    const fs::path path = write(texturedDoc(encodePng(2, 1, 1, {1, 2})));
    EXPECT_NO_THROW(loadGltf(path));
    const auto expectRefused = [&](void (*change)(GltfLimits&), const std::string& substring) {
        GltfLimits limits;
        change(limits);
        try {
            loadGltf(path, limits);
            ADD_FAILURE() << "not refused: " << substring;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(substring), std::string::npos) << e.what();
        }
    };
    expectRefused([](GltfLimits& l) { l.maxTriangles = 0; }, "scenes[0]: 1 triangles (counting every mesh reference) exceed the limit of 0");
    expectRefused([](GltfLimits& l) { l.maxImageDimension = 1; }, "images[0]: 2x1 pixels exceeds the image size limit");
    expectRefused([](GltfLimits& l) { l.maxImagePixels = 1; }, "images[0]: 2x1 pixels exceeds the image size limit");
    expectRefused([](GltfLimits& l) { l.maxTotalImagePixels = 1; }, "images[0]: the file's images add up to more than");
    expectRefused([](GltfLimits& l) { l.maxFileBytes = 100; }, "bytes is more than the 100-byte limit");
}

#ifdef VKPHOTON_SCENES
TEST(ShippedScenes, AllLoad) {
    int scenes = 0;
    for (const auto& entry : fs::directory_iterator(VKPHOTON_SCENES)) {
        if (entry.path().extension() != ".gltf" && entry.path().extension() != ".glb") continue;
        ++scenes;
        EXPECT_NO_THROW({
            const Scene s = loadGltf(entry.path());
            EXPECT_GT(s.triangles.size(), 0u);
        }) << entry.path();
    }
    EXPECT_GT(scenes, 0);
}
#endif

// '+' is a literal in URIs (RFC 3986), though tinygltf decodes it as a space; "%20" is a space.
TEST_F(GltfLoader, PlusInAUriIsALiteral) {
    json doc = triangleDoc(false, false);
    const std::string data = doc["buffers"][0]["uri"];
    const std::string payload = data.substr(data.find(',') + 1);
    std::vector<uint8_t> bytes;  // decode the base64 written above
    const std::string table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    uint32_t acc = 0;
    int bits = 0;
    for (char c : payload) {
        if (c == '=') break;
        acc = (acc << 6) | uint32_t(table.find(c));
        bits += 6;
        if (bits >= 8) { bits -= 8; bytes.push_back(uint8_t(acc >> bits)); }
    }
    std::ofstream(m_dir / "Cesium+Logo mesh.bin", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    doc["buffers"][0]["uri"] = "Cesium+Logo%20mesh.bin";
    EXPECT_EQ(loadGltf(write(doc)).triangles.size(), 1u);
    doc["buffers"][0]["uri"] = "Cesium%20Logo%20mesh.bin";  // the space spelling names another file
    EXPECT_THROW(loadGltf(write(doc)), InputError);
}

// --scene N (GltfLimits::sceneIndex) picks the glTF scene; the default is the file's `scene`.
TEST_F(GltfLoader, SceneIndexPicksTheScene) {
    json doc = triangleDoc(true, true);
    doc["nodes"].push_back({{"mesh", 0}, {"translation", {5, 0, 0}}});
    doc["scenes"].push_back({{"nodes", {1}}});
    doc["scene"] = 1;
    EXPECT_EQ(loadGltf(write(doc)).triangles[0].p[0], glm::vec3(5, 0, 0));
    GltfLimits limits;
    limits.sceneIndex = 0;
    EXPECT_EQ(loadGltf(write(doc), limits).triangles[0].p[0], glm::vec3(0, 0, 0));
    limits.sceneIndex = 2;
    try {
        loadGltf(write(doc), limits);
        ADD_FAILURE() << "not refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--scene 2: does not exist (the file has 2 scene(s))"), std::string::npos) << e.what();
    }
    doc.erase("scene");
    EXPECT_EQ(loadGltf(write(doc)).triangles[0].p[0], glm::vec3(0, 0, 0));
}

TEST(UriPolicy, AcceptsRelativePathsAndDataUris) {
    for (const char* ok : {"data:application/octet-stream;base64,AAAA", "buffer.bin", "sub/dir/a%20b.png", "a..b.bin"})
        EXPECT_EQ(uriRefusalReason(ok), "") << ok;
    for (const char* bad : {"/abs.bin", "../x.bin", "a/../../x.bin", "a\\..\\x.bin", "%2e%2e/x", "$(rm)", "`x`", "~/x",
                            "C:/x.bin", "file:///etc/passwd", ""})
        EXPECT_NE(uriRefusalReason(bad), "") << bad;
}

TEST(UriPolicy, RefusesEncodedTricksAndDecodesLikeTinygltf) {
    for (const char* bad : {"%24HOME/x.bin", "sub%2F..%2Fx", "..%5Cx", "x%00y.bin", "a%zz.bin", "a%2", "x\ny",
                            "http:x", "\\server\\share"})
        EXPECT_NE(uriRefusalReason(bad), "") << bad;
    EXPECT_EQ(uriToRelativePath("mesh%20data.bin"), "mesh data.bin");
    EXPECT_EQ(uriToRelativePath("a+b.bin"), "a+b.bin");  // RFC 3986: '+' is a literal
    EXPECT_EQ(uriToRelativePath("sub/%41.png"), "sub/A.png");
}

TEST(BadGltfCorpus, EveryFileGivesItsMessage) {
    const fs::path dir = fs::path(VKPHOTON_TEST_DATA) / "bad";
    std::ifstream expected(dir / "expected.txt");
    ASSERT_TRUE(expected) << "missing " << (dir / "expected.txt");
    std::string line;
    int cases = 0;
    while (std::getline(expected, line)) {
        if (line.empty() || line[0] == '#') continue;
        const auto tab = line.find('\t');
        ASSERT_NE(tab, std::string::npos) << line;
        const std::string file = line.substr(0, tab), substring = line.substr(tab + 1);
        const fs::path path = dir / file;
        ++cases;
        try {
            loadGltf(path);
            ADD_FAILURE() << file << ": loaded without error";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << file << ": message does not start with the file: " << message;
            EXPECT_NE(message.find(substring), std::string::npos) << file << ": expected '" << substring << "' in: " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << file << ": one line expected: " << message;
        } catch (const std::exception& e) {
            ADD_FAILURE() << file << ": wrong exception type (exit code would be 1, not 2): " << e.what();
        }
    }
    EXPECT_GE(cases, 15);
}

TEST(BadGltfCorpus, MissingFile) {
    try {
        loadGltf("/nonexistent/dir/scene.gltf");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/scene.gltf: no such file"), std::string::npos) << e.what();
    }
}

// Random mutations of good files (bytes, JSON punctuation, hostile numbers): each must load or
// throw InputError; never crash, hang or throw anything else. Deterministic: a fixed seed.
TEST(BadGltfCorpus, RandomMutationsNeverCrash) {
    const fs::path good = fs::path(VKPHOTON_TEST_DATA) / "good";
    const fs::path dir = fs::temp_directory_path() / ("vkphoton-gltf-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const char* name : {"triangle.bin", "uv.bin", "checker.png"})
        fs::copy_file(good / name, dir / name, fs::copy_options::overwrite_existing);
    const std::vector<std::string> tokens = {"9999999999", "-1", "1e308", "0", "[", "}", "\"x\"", "null", "4294967295"};
    // VKPHOTON_FUZZ_ITERATIONS raises the count for a longer local run (e.g. under sanitizers).
    const char* requested = std::getenv("VKPHOTON_FUZZ_ITERATIONS");
    const int iterations = requested ? std::max(1, std::atoi(requested)) : 1000;
    std::mt19937 rng(20240611);
    int loaded = 0, refused = 0;
    for (const char* name : {"textured.gltf", "triangle.glb"}) {
        std::ifstream in(good / name, std::ios::binary);
        const std::string original((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        for (int iteration = 0; iteration < iterations; ++iteration) {
            std::string bytes = original;
            for (int edit = 0, edits = 1 + int(rng() % 3); edit < edits && !bytes.empty(); ++edit) {
                const size_t at = rng() % bytes.size();
                switch (rng() % 4) {
                case 0: bytes[at] = static_cast<char>(rng()); break;
                case 1: bytes.erase(at, 1 + rng() % 8); break;
                case 2: bytes.insert(at, tokens[rng() % tokens.size()]); break;
                default: bytes.replace(at, std::min<size_t>(bytes.size() - at, 1 + rng() % 4), tokens[rng() % tokens.size()]);
                }
            }
            const fs::path path = dir / name;
            std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
            try {
                loadGltf(path);
                ++loaded;
            } catch (const InputError& e) {
                ++refused;
                ASSERT_EQ(std::string(e.what()).rfind(path.string() + ": ", 0), 0u) << e.what();
            }
        }
    }
    EXPECT_GT(refused, iterations);  // most mutations break something
    EXPECT_GT(loaded, 0);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vkp
