// Compressed glTF geometry: KHR_draco_mesh_compression and EXT_meshopt_compression.
// Each test writes a small grid mesh three ways (plain, Draco, meshopt; the streams made with the
// libraries' encoders) and checks that the loader's triangles are the same, and that corrupt or
// truncated streams are InputErrors (exit 2) that name the element.
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>
#include <unistd.h>

#include "support/base64.h"
#include "support/cli_runner.h"
#include "image/exr.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::base64;

struct Vertex {
    float p[3], n[3], uv[2];
};

// An n x n grid of quads on a bumpy surface (so positions and normals are not trivial).
struct Grid {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
};

Grid makeGrid(int n) {
    Grid g;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = float(i) / n, z = float(j) / n;
            const float y = 0.1f * std::sin(3.0f * x) * std::cos(2.0f * z);
            const float l = std::sqrt(1.0f + 0.01f * (x * x + z * z));
            g.vertices.push_back({{x, y, z}, {-0.1f * x / l, 1.0f / l, -0.1f * z / l}, {x, 1.0f - z}});
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            g.indices.insert(g.indices.end(), {a, c, b, b, c, d});
        }
    return g;
}

template <typename T>
std::vector<uint8_t> bytesOf(const std::vector<T>& v) {
    std::vector<uint8_t> out(v.size() * sizeof(T));
    std::memcpy(out.data(), v.data(), out.size());
    return out;
}

std::string dataUri(const std::vector<uint8_t>& bytes) { return "data:application/octet-stream;base64," + base64(bytes); }

// Accessors 0..2: POSITION, NORMAL, TEXCOORD_0; 3: indices. Without bufferViews (filled in by the caller).
json baseDoc(const Grid& g) {
    json doc;
    doc["asset"] = {{"version", "2.0"}};
    doc["scene"] = 0;
    doc["scenes"] = json::array({{{"nodes", {0}}}});
    doc["nodes"] = json::array({{{"mesh", 0}}});
    doc["meshes"] = json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                                              {"indices", 3}}})}}});
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const Vertex& v : g.vertices) {
        lo = glm::min(lo, glm::vec3(v.p[0], v.p[1], v.p[2]));
        hi = glm::max(hi, glm::vec3(v.p[0], v.p[1], v.p[2]));
    }
    const size_t n = g.vertices.size();
    doc["accessors"] = json::array({
        {{"componentType", 5126}, {"count", n}, {"type", "VEC3"}, {"min", {lo.x, lo.y, lo.z}}, {"max", {hi.x, hi.y, hi.z}}},
        {{"componentType", 5126}, {"count", n}, {"type", "VEC3"}},
        {{"componentType", 5126}, {"count", n}, {"type", "VEC2"}},
        {{"componentType", 5125}, {"count", g.indices.size()}, {"type", "SCALAR"}},
    });
    return doc;
}

// Positions, normals and texture coordinates interleaved (stride 32), then the indices.
json plainDoc(const Grid& g) {
    json doc = baseDoc(g);
    std::vector<uint8_t> bytes = bytesOf(g.vertices);
    const size_t vertexBytes = bytes.size();
    const std::vector<uint8_t> idx = bytesOf(g.indices);
    bytes.insert(bytes.end(), idx.begin(), idx.end());
    doc["buffers"] = json::array({{{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}}});
    doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteLength", vertexBytes}, {"byteStride", 32}},
                                      {{"buffer", 0}, {"byteOffset", vertexBytes}, {"byteLength", idx.size()}}});
    for (int a = 0; a < 3; ++a) {
        doc["accessors"][a]["bufferView"] = 0;
        doc["accessors"][a]["byteOffset"] = a * 12;
    }
    doc["accessors"][3]["bufferView"] = 1;
    return doc;
}

std::vector<uint8_t> dracoStream(const Grid& g, int ids[3]) {
    draco::Mesh mesh;
    mesh.set_num_points(static_cast<uint32_t>(g.vertices.size()));
    const int components[3] = {3, 3, 2};
    const draco::GeometryAttribute::Type types[3] = {draco::GeometryAttribute::POSITION, draco::GeometryAttribute::NORMAL,
                                                     draco::GeometryAttribute::TEX_COORD};
    for (int a = 0; a < 3; ++a) {
        draco::GeometryAttribute attribute;
        attribute.Init(types[a], nullptr, components[a], draco::DT_FLOAT32, false, sizeof(float) * components[a], 0);
        const int index = mesh.AddAttribute(attribute, true, static_cast<uint32_t>(g.vertices.size()));
        draco::PointAttribute* pa = mesh.attribute(index);
        for (size_t v = 0; v < g.vertices.size(); ++v) {
            const float* value = a == 0 ? g.vertices[v].p : a == 1 ? g.vertices[v].n : g.vertices[v].uv;
            pa->SetAttributeValue(draco::AttributeValueIndex(static_cast<uint32_t>(v)), value);
        }
        ids[a] = static_cast<int>(pa->unique_id());
    }
    for (size_t f = 0; f < g.indices.size(); f += 3)
        mesh.AddFace({draco::PointIndex(g.indices[f]), draco::PointIndex(g.indices[f + 1]), draco::PointIndex(g.indices[f + 2])});
    draco::Encoder encoder;  // no quantization: lossless floats
    encoder.SetSpeedOptions(10, 10);
    encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
    draco::EncoderBuffer out;
    const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &out);
    EXPECT_TRUE(status.ok()) << status.error_msg_string();
    return std::vector<uint8_t>(out.data(), out.data() + out.size());
}

json dracoDoc(const Grid& g, std::vector<uint8_t>* streamOut = nullptr) {
    json doc = baseDoc(g);
    int ids[3];
    const std::vector<uint8_t> stream = dracoStream(g, ids);
    if (streamOut) *streamOut = stream;
    doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    doc["buffers"] = json::array({{{"byteLength", stream.size()}, {"uri", dataUri(stream)}}});
    doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteLength", stream.size()}}});
    doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", 0}, {"attributes", {{"POSITION", ids[0]}, {"NORMAL", ids[1]}, {"TEXCOORD_0", ids[2]}}}};
    return doc;
}

// Buffer 0: the compressed streams; buffer 1: the uri-less fallback the views decode into.
json meshoptDoc(const Grid& g, const char* indexMode) {
    json doc = plainDoc(g);
    std::vector<uint8_t> vertices(meshopt_encodeVertexBufferBound(g.vertices.size(), sizeof(Vertex)));
    vertices.resize(meshopt_encodeVertexBuffer(vertices.data(), vertices.size(), g.vertices.data(), g.vertices.size(),
                                               sizeof(Vertex)));
    std::vector<uint8_t> indices(meshopt_encodeIndexBufferBound(g.indices.size(), g.vertices.size()));
    indices.resize(std::string(indexMode) == "TRIANGLES"
                       ? meshopt_encodeIndexBuffer(indices.data(), indices.size(), g.indices.data(), g.indices.size())
                       : meshopt_encodeIndexSequence(indices.data(), indices.size(), g.indices.data(), g.indices.size()));
    std::vector<uint8_t> stream = vertices;
    stream.resize((stream.size() + 3) & ~size_t(3));
    const size_t indexOffset = stream.size();
    stream.insert(stream.end(), indices.begin(), indices.end());
    const size_t fallbackLength = doc["buffers"][0]["byteLength"].get<size_t>();
    doc["extensionsUsed"] = {"EXT_meshopt_compression"};
    doc["extensionsRequired"] = {"EXT_meshopt_compression"};
    doc["buffers"] = json::array({{{"byteLength", stream.size()}, {"uri", dataUri(stream)}},
                                  {{"byteLength", fallbackLength}, {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}});
    for (auto& view : doc["bufferViews"]) view["buffer"] = 1;
    doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"] = {
        {"buffer", 0}, {"byteLength", vertices.size()}, {"byteStride", 32}, {"count", g.vertices.size()}, {"mode", "ATTRIBUTES"}};
    doc["bufferViews"][1]["extensions"]["EXT_meshopt_compression"] = {
        {"buffer", 0}, {"byteOffset", indexOffset}, {"byteLength", indices.size()}, {"byteStride", 4},
        {"count", g.indices.size()}, {"mode", indexMode}};
    return doc;
}

// The triangles, each rotated to start at its smallest corner, sorted: equal geometry compares
// equal even when an encoder rotated or reordered triangles.
std::vector<std::string> canonical(const Scene& scene) {
    std::vector<std::string> out;
    for (const Triangle& t : scene.triangles) {
        int first = 0;
        for (int k = 1; k < 3; ++k)
            if (std::memcmp(&t.p[k], &t.p[first], sizeof(glm::vec3)) < 0) first = k;
        std::string key;
        for (int k = 0; k < 3; ++k) {
            const int c = (first + k) % 3;
            key.append(reinterpret_cast<const char*>(&t.p[c]), sizeof(glm::vec3));
            key.append(reinterpret_cast<const char*>(&t.n[c]), sizeof(glm::vec3));
            key.append(reinterpret_cast<const char*>(&t.uv[c]), sizeof(glm::vec2));
        }
        out.push_back(key);
    }
    std::sort(out.begin(), out.end());
    return out;
}

class GltfCompression : public ::testing::Test {
protected:
    fs::path m_dir = fs::temp_directory_path() / ("vkp_compression_" + std::to_string(::getpid()));
    void SetUp() override { fs::create_directories(m_dir); }
    void TearDown() override { fs::remove_all(m_dir); }
    fs::path write(const json& doc, const std::string& name = "scene.gltf") {
        const fs::path path = m_dir / name;
        std::ofstream(path) << doc.dump();
        return path;
    }
    // Loading `doc` fails with an InputError containing `what`.
    void expectError(const json& doc, const std::string& what) {
        try {
            loadGltf(write(doc, "bad.gltf"));
            ADD_FAILURE() << "loaded without error; expected " << what;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    }
};

TEST_F(GltfCompression, DracoDecodesToTheSameTriangles) {
    const Grid g = makeGrid(6);
    const Scene plain = loadGltf(write(plainDoc(g), "plain.gltf"));
    const Scene draco = loadGltf(write(dracoDoc(g), "draco.gltf"));
    ASSERT_EQ(plain.triangles.size(), 72u);
    EXPECT_EQ(canonical(draco), canonical(plain));
}

TEST_F(GltfCompression, MeshoptDecodesToTheSameTriangles) {
    const Grid g = makeGrid(6);
    const Scene plain = loadGltf(write(plainDoc(g), "plain.gltf"));
    for (const char* mode : {"TRIANGLES", "INDICES"}) {
        const Scene meshopt = loadGltf(write(meshoptDoc(g, mode), "meshopt.gltf"));
        EXPECT_EQ(canonical(meshopt), canonical(plain)) << mode;
    }
}

TEST_F(GltfCompression, CorruptDracoStreamsAreInputErrors) {
    const Grid g = makeGrid(4);
    std::vector<uint8_t> stream;
    const json good = dracoDoc(g, &stream);
    const std::string element = "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression";
    for (const size_t keep : {size_t(0), size_t(8), stream.size() / 2, stream.size() - 1}) {  // truncated
        json doc = good;
        std::vector<uint8_t> cut(stream.begin(), stream.begin() + std::max<size_t>(keep, 1));
        if (keep == 0) cut = {'X'};
        doc["buffers"][0] = {{"byteLength", cut.size()}, {"uri", dataUri(cut)}};
        doc["bufferViews"][0]["byteLength"] = cut.size();
        expectError(doc, element);
    }
    json doc = good;
    doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["NORMAL"] = 7;
    expectError(doc, element + ".attributes.NORMAL: the Draco stream has no attribute 7");
    doc = good;
    doc["accessors"][0]["count"] = 3;
    expectError(doc, element + ".attributes.POSITION: the Draco mesh has 25 points, accessors[0] count 3");
    doc = good;
    doc["accessors"][3]["count"] = 6;
    expectError(doc, "the Draco mesh has 96 indices, accessors[3] count 6");
    doc = good;
    doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"] = 5;
    expectError(doc, "bufferViews[5]");
}

TEST_F(GltfCompression, CorruptMeshoptStreamsAreInputErrors) {
    const Grid g = makeGrid(4);
    const json good = meshoptDoc(g, "TRIANGLES");
    const std::string element = "bufferViews[0].extensions.EXT_meshopt_compression";
    json doc = good;
    doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 10;  // truncated
    expectError(doc, element + ": the ATTRIBUTES stream does not decode");
    doc = good;
    doc["bufferViews"][1]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 5;
    expectError(doc, "bufferViews[1].extensions.EXT_meshopt_compression: the TRIANGLES stream does not decode");
    doc = good;
    doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 1u << 20;
    expectError(doc, element + ": compressed bytes");
    doc = good;
    doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["count"] = 1000;
    expectError(doc, element + ": count 1000 x byteStride 32 exceeds");
    doc = good;
    doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["mode"] = "POINTS";
    expectError(doc, element + ".mode");
    doc = good;
    doc["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["filter"] = "QUATERNION";
    expectError(doc, "QUATERNION needs a byteStride of 8");
    doc = good;
    doc["buffers"][1].erase("extensions");  // a uri-less buffer is only allowed as a meshopt fallback
    expectError(doc, "buffers[1]: no uri");
}

// The OCTAHEDRAL filter: normals stored as 4 signed bytes decode to unit vectors near the originals.
TEST_F(GltfCompression, MeshoptOctahedralNormals) {
    const Grid g = makeGrid(4);
    json doc = meshoptDoc(g, "TRIANGLES");
    std::vector<float> normals;
    for (const Vertex& v : g.vertices) normals.insert(normals.end(), {v.n[0], v.n[1], v.n[2], 0.0f});
    std::vector<int8_t> oct(g.vertices.size() * 4);
    meshopt_encodeFilterOct(oct.data(), g.vertices.size(), 4, 8, normals.data());
    std::vector<uint8_t> encoded(meshopt_encodeVertexBufferBound(g.vertices.size(), 4));
    encoded.resize(meshopt_encodeVertexBuffer(encoded.data(), encoded.size(), oct.data(), g.vertices.size(), 4));
    // A third buffer with the octahedral stream, decoded into a new view of the fallback's end.
    const size_t fallback = doc["buffers"][1]["byteLength"].get<size_t>();
    doc["buffers"].push_back({{"byteLength", encoded.size()}, {"uri", dataUri(encoded)}});
    doc["buffers"][1]["byteLength"] = fallback + oct.size();
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", fallback}, {"byteLength", oct.size()}, {"byteStride", 4},
                                  {"extensions", {{"EXT_meshopt_compression", {{"buffer", 2}, {"byteLength", encoded.size()},
                                                  {"byteStride", 4}, {"count", g.vertices.size()}, {"mode", "ATTRIBUTES"},
                                                  {"filter", "OCTAHEDRAL"}}}}}});
    doc["accessors"][1] = {{"bufferView", 2}, {"componentType", 5120}, {"normalized", true}, {"count", g.vertices.size()},
                           {"type", "VEC3"}};
    const Scene scene = loadGltf(write(doc));
    const Scene plain = loadGltf(write(plainDoc(g), "plain.gltf"));
    ASSERT_EQ(scene.triangles.size(), plain.triangles.size());
    for (size_t t = 0; t < scene.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_GT(glm::dot(scene.triangles[t].n[k], plain.triangles[t].n[k]), 0.999f) << t;
}

// The CLI: the renders of the plain, Draco and meshopt files are the same image (the decoded
// triangles are the same; Draco without quantization is lossless), and a corrupt stream is exit 2.
TEST_F(GltfCompression, RendersEqualTheUncompressedFileAndCorruptStreamsExitWith2) {
    const Grid g = makeGrid(6);
    const std::string view = " --spp 2 --width 24 --height 24 --look-from 0.5,1.5,-1 --look-at 0.5,0,0.5 --env 1 --quiet";
    std::vector<ImageRgb> images;
    for (const auto& [name, doc] : {std::pair{"plain", plainDoc(g)}, std::pair{"draco", dracoDoc(g)},
                                     std::pair{"meshopt", meshoptDoc(g, "INDICES")}}) {
        const fs::path exr = m_dir / (std::string(name) + ".exr");
        const test::RunResult r = test::runVkphoton("render " + write(doc, std::string(name) + ".gltf").string() + view +
                                                    " -o " + exr.string());
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.output;
        images.push_back(readExr(exr));
    }
    double sum = 0.0;
    for (float v : images[0].pixels) sum += v;
    EXPECT_GT(sum, 0.0);  // the grid is lit: the comparison means something
    EXPECT_EQ(images[1].pixels, images[0].pixels) << "Draco";
    EXPECT_EQ(images[2].pixels, images[0].pixels) << "meshopt";
    json doc = dracoDoc(g);
    doc["bufferViews"][0]["byteLength"] = 10;  // a truncated stream
    const test::RunResult r = test::runVkphoton("render " + write(doc, "bad.gltf").string() + view + " -o " +
                                                (m_dir / "bad.exr").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("KHR_draco_mesh_compression: the Draco stream does not decode"), std::string::npos) << r.output;
}

// TEXCOORD_n for any n: the set a texture reads (here TEXCOORD_2, as the texture transform's
// texCoord override names it) becomes the triangle's second set (Triangle::uv1) and the view's
// device slot 1; a set the primitive lacks is refused.
TEST_F(GltfCompression, AnyTexCoordSet) {
    const Grid g = makeGrid(2);
    json doc = plainDoc(g);
    std::vector<glm::vec2> set2;
    for (const Vertex& v : g.vertices) set2.emplace_back(3.0f * v.uv[0] + 7.0f, v.uv[1] - 5.0f);
    std::vector<uint8_t> bytes = bytesOf(set2);
    doc["buffers"].push_back({{"byteLength", bytes.size()}, {"uri", dataUri(bytes)}});
    doc["bufferViews"].push_back({{"buffer", 1}, {"byteLength", bytes.size()}});
    doc["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", set2.size()}, {"type", "VEC2"}});
    doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_2"] = 4;
    doc["meshes"][0]["primitives"][0]["material"] = 0;
    std::vector<uint8_t> png;
    const uint8_t texel[4] = {200, 100, 50, 255};
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<uint8_t>*>(context);
            out->insert(out->end(), static_cast<uint8_t*>(data), static_cast<uint8_t*>(data) + size);
        },
        &png, 1, 1, 4, texel, 4);
    doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(png)}}});
    doc["textures"] = json::array({{{"source", 0}}});
    doc["extensionsUsed"] = {"KHR_texture_transform"};
    json reference = {{"index", 0}, {"texCoord", 1}};
    reference["extensions"]["KHR_texture_transform"]["texCoord"] = 2;
    json material;
    material["pbrMetallicRoughness"]["baseColorTexture"] = reference;
    doc["materials"] = json::array({material});
    const Scene scene = loadGltf(write(doc));
    ASSERT_EQ(scene.textureViews.size(), 1u);
    EXPECT_EQ(scene.textureViews[0].texCoord, 1);  // the device slot holding TEXCOORD_2
    ASSERT_EQ(scene.triangles.size(), 8u);
    for (size_t t = 0; t < scene.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const glm::vec2 uv0 = scene.triangles[t].uv[k], uv2 = scene.triangles[t].uv1[k];
            EXPECT_EQ(uv2, glm::vec2(3.0f * uv0.x + 7.0f, uv0.y - 5.0f)) << t;
        }
    doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]["texCoord"] = 3;
    expectError(doc, "reads TEXCOORD_3, which the primitive does not have");
}

}  // namespace
}  // namespace vkp
