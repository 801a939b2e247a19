// Morph targets with their static weights and skins posed by their joints (docs/scene-format.md,
// "Geometry"), on small files built here with positions computed by hand; bad morph targets and
// skins are refused naming the element; joint animation is played per frame.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "support/base64.h"
#include "scene/gltf_loader.h"
#include "util/errors.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedByte = 5121, kUnsignedShort = 5123;

// A glTF document whose accessors all live in one data: buffer.
class Doc {
public:
    Doc() {
        m_doc["asset"] = {{"version", "2.0"}};
        m_doc["scene"] = 0;
        m_doc["materials"] = {{{"emissiveFactor", {1, 1, 1}}}};  // a light, so nothing else is needed
        m_doc["accessors"] = json::array();
        m_doc["bufferViews"] = json::array();
    }

    template <typename T> int accessor(const std::vector<T>& values, int componentType, const char* type, bool normalized = false) {
        const size_t components = std::string(type) == "SCALAR" ? 1 : std::string(type) == "MAT4" ? 16 : std::string(type)[3] - '0';
        const int view = this->view(values.data(), values.size() * sizeof(T));
        json a = {{"bufferView", view}, {"componentType", componentType}, {"count", values.size() / components}, {"type", type}};
        if (normalized) a["normalized"] = true;
        m_doc["accessors"].push_back(a);
        return int(m_doc["accessors"].size()) - 1;
    }

    int view(const void* data, size_t size) {
        while (m_bin.size() % 4) m_bin.push_back(0);
        m_doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", m_bin.size()}, {"byteLength", size}});
        const auto* p = static_cast<const uint8_t*>(data);
        m_bin.insert(m_bin.end(), p, p + size);
        return int(m_doc["bufferViews"].size()) - 1;
    }

    json& operator[](const char* key) { return m_doc[key]; }

    json finish() {
        json doc = m_doc;
        doc["buffers"] = {{{"byteLength", m_bin.size()}, {"uri", "data:application/octet-stream;base64," + test::base64(m_bin)}}};
        return doc;
    }

private:
    json m_doc;
    std::vector<uint8_t> m_bin;
};

class GltfDeformation : public ::testing::Test {
protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("vkphoton-deform-" + std::to_string(::getpid()) + "-" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    fs::path write(const json& doc) {
        const fs::path path = m_dir / "scene.gltf";
        std::ofstream(path) << doc.dump();
        return path;
    }

    // The error loadGltf gives ("" when it loads).
    std::string error(const json& doc) {
        try {
            loadGltf(write(doc));
        } catch (const InputError& e) {
            return e.what();
        }
        return "";
    }

    fs::path m_dir;
};

void expectNear(const glm::vec3& got, const glm::vec3& want, const std::string& what) {
    EXPECT_NEAR(glm::distance(got, want), 0.0f, 1e-5f)
        << what << ": (" << got.x << ", " << got.y << ", " << got.z << ") instead of (" << want.x << ", " << want.y << ", "
        << want.z << ")";
}

// Corner k of triangle t is vertex indices[3t + k]: the loader keeps the file's order (no mirroring here).
void expectVertices(const std::vector<Triangle>& triangles, const std::vector<uint16_t>& indices,
                    const std::vector<glm::vec3>& expected) {
    ASSERT_EQ(triangles.size(), indices.size() / 3);
    for (size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            expectNear(triangles[t].p[k], expected[indices[3 * t + k]], "triangle " + std::to_string(t) + " corner " + std::to_string(k));
}

// ---------------------------------------------------------------------------------------------
// Morph targets: the unit quad in z = 0 (front +z), one target moving three of its corners.

const std::vector<uint16_t> kQuadIndices = {0, 1, 2, 0, 2, 3};
const std::vector<float> kQuad = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
const std::vector<float> kQuadTarget = {0, 0, 2, 0, 0, 0, 0, 0, -2, 1, 0, 0};

// base + w * target, by hand.
std::vector<glm::vec3> quadMorphedBy(float w) {
    return {{0, 0, 2 * w}, {1, 0, 0}, {1, 1, -2 * w}, {w, 1, 0}};
}

Doc morphQuad(const std::vector<float>& target = kQuadTarget) {
    Doc doc;
    const int position = doc.accessor(kQuad, kFloat, "VEC3");
    const std::vector<float> normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    const int normal = doc.accessor(normals, kFloat, "VEC3");
    const int indices = doc.accessor(kQuadIndices, kUnsignedShort, "SCALAR");
    const int displacement = doc.accessor(target, kFloat, "VEC3");
    doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", position}, {"NORMAL", normal}}}, {"indices", indices},
                                       {"material", 0}, {"targets", {{{"POSITION", displacement}}}}}}},
                      {"weights", {0.5}}}};
    doc["nodes"] = {{{"mesh", 0}}};
    doc["scenes"] = {{{"nodes", {0}}}};
    return doc;
}

TEST_F(GltfDeformation, MorphTargetWithMeshWeightLandsWhereComputed) {
    const Scene scene = loadGltf(write(morphQuad().finish()));
    expectVertices(scene.triangles, kQuadIndices, quadMorphedBy(0.5f));
}

TEST_F(GltfDeformation, MorphTargetsBeforeTheNodeTransform) {
    Doc doc = morphQuad();
    doc["nodes"][0]["translation"] = {10, 0, 0};
    doc["nodes"][0]["scale"] = {2, 2, 2};
    const Scene scene = loadGltf(write(doc.finish()));
    std::vector<glm::vec3> expected = quadMorphedBy(0.5f);
    for (glm::vec3& p : expected) p = glm::vec3(10, 0, 0) + 2.0f * p;
    expectVertices(scene.triangles, kQuadIndices, expected);
}

TEST_F(GltfDeformation, NoWeightsIsTheBaseShape) {
    Doc doc = morphQuad();
    doc["meshes"][0].erase("weights");
    expectVertices(loadGltf(write(doc.finish())).triangles, kQuadIndices, quadMorphedBy(0.0f));
}

TEST_F(GltfDeformation, NodeWeightsOverrideMeshWeights) {
    Doc doc = morphQuad();
    // Node 0 draws the mesh with its own weight 1, node 1 (moved up by 5) with the mesh's 0.5.
    doc["nodes"] = {{{"mesh", 0}, {"weights", {1.0}}}, {{"mesh", 0}, {"translation", {0, 5, 0}}}};
    doc["scenes"] = {{{"nodes", {0, 1}}}};
    doc["materials"][0].erase("emissiveFactor");  // emissive meshes are never instanced
    GltfLimits limits;
    limits.instanceMinTriangles = 0;  // a repeated mesh would be instanced; different weights must not share it
    const Scene scene = loadGltf(write(doc.finish()), limits);
    ASSERT_TRUE(scene.instances.empty());
    ASSERT_EQ(scene.triangles.size(), 4u);
    const std::vector<Triangle> first(scene.triangles.begin(), scene.triangles.begin() + 2);
    std::vector<Triangle> second(scene.triangles.begin() + 2, scene.triangles.end());
    for (Triangle& t : second)
        for (glm::vec3& p : t.p) p -= glm::vec3(0, 5, 0);
    expectVertices(first, kQuadIndices, quadMorphedBy(1.0f));
    expectVertices(second, kQuadIndices, quadMorphedBy(0.5f));
}

TEST_F(GltfDeformation, InstancedMeshKeepsItsMorphedShape) {
    Doc doc = morphQuad();
    doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"translation", {0, 5, 0}}}};  // both with the mesh's weight
    doc["scenes"] = {{{"nodes", {0, 1}}}};
    doc["materials"][0].erase("emissiveFactor");  // emissive meshes are never instanced
    GltfLimits limits;
    limits.instanceMinTriangles = 0;
    const Scene scene = loadGltf(write(doc.finish()), limits);
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    expectVertices(scene.meshes[0].triangles, kQuadIndices, quadMorphedBy(0.5f));
}

TEST_F(GltfDeformation, NormalTargetsMoveNormals) {
    Doc doc = morphQuad();
    const std::vector<float> normalTarget = {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0};
    doc["meshes"][0]["primitives"][0]["targets"][0]["NORMAL"] = doc.accessor(normalTarget, kFloat, "VEC3");
    const Scene scene = loadGltf(write(doc.finish()));
    ASSERT_EQ(scene.triangles.size(), 2u);
    // (0, 0, 1) + 0.5 (1, 0, 0), renormalised.
    for (const Triangle& t : scene.triangles)
        for (const glm::vec3& n : t.n) expectNear(n, glm::normalize(glm::vec3(0.5f, 0, 1)), "normal");
}

TEST_F(GltfDeformation, SparseMorphTargetWithoutBufferView) {
    Doc doc = morphQuad();
    // Only vertex 2 moves, by (0, 0, -2): a sparse accessor over zeros, as exporters write targets.
    const std::vector<uint16_t> index = {2};
    const std::vector<float> value = {0, 0, -2};
    const int indexView = doc.view(index.data(), 2);
    const int valueView = doc.view(value.data(), 12);
    doc["accessors"].push_back({{"componentType", kFloat}, {"count", 4}, {"type", "VEC3"},
                                {"sparse", {{"count", 1}, {"indices", {{"bufferView", indexView}, {"componentType", kUnsignedShort}}},
                                            {"values", {{"bufferView", valueView}}}}}});
    doc["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = doc["accessors"].size() - 1;
    const Scene scene = loadGltf(write(doc.finish()));
    expectVertices(scene.triangles, kQuadIndices, {{0, 0, 0}, {1, 0, 0}, {1, 1, -1}, {0, 1, 0}});
}

TEST_F(GltfDeformation, BadMorphTargetsAreRefused) {
    {   // three displacements for four vertices
        Doc doc = morphQuad({0, 0, 1, 0, 0, 1, 0, 0, 1});
        const std::string e = error(doc.finish());
        EXPECT_NE(e.find("meshes[0].primitives[0].targets[0].POSITION: accessors[3] has 3 elements but POSITION has 4"),
                  std::string::npos) << e;
    }
    {   // a NaN displacement, refused even where its weight is 0
        std::vector<float> target = kQuadTarget;
        target[4] = std::numeric_limits<float>::quiet_NaN();
        Doc doc = morphQuad(target);
        doc["meshes"][0]["weights"] = {0.0};
        const std::string e = error(doc.finish());
        EXPECT_NE(e.find("meshes[0].primitives[0].targets[0].POSITION: element 1 is NaN or infinite"), std::string::npos) << e;
    }
    {   // two weights for one target
        Doc doc = morphQuad();
        doc["meshes"][0]["weights"] = {0.5, 0.5};
        const std::string e = error(doc.finish());
        EXPECT_NE(e.find("meshes[0].primitives[0]: has 1 morph target(s) but meshes[0].weights has 2 weight(s)"),
                  std::string::npos) << e;
    }
    {   // a target accessor reaching past its buffer view
        Doc doc = morphQuad();
        doc["accessors"][3]["count"] = 5;
        const std::string e = error(doc.finish());
        EXPECT_NE(e.find("meshes[0].primitives[0].targets[0].POSITION: accessors[3]: 5 elements"), std::string::npos) << e;
    }
}

TEST_F(GltfDeformation, WeightsChannelsIgnoredButStaticWeightsApplyInEveryFrame) {
    Doc doc = morphQuad();
    const std::vector<float> times = {0, 1}, values = {0, 1};
    const int input = doc.accessor(times, kFloat, "SCALAR");
    const int output = doc.accessor(values, kFloat, "SCALAR");
    doc["accessors"][input]["min"] = {0};
    doc["accessors"][input]["max"] = {1};
    doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "weights"}}}}}},
                          {"samplers", {{{"input", input}, {"output", output}}}}}};
    GltfSceneSource source(write(doc.finish()));
    for (double t : {0.0, 0.5, 1.0}) expectVertices(source.sceneAt(t).triangles, kQuadIndices, quadMorphedBy(0.5f));
}

// ---------------------------------------------------------------------------------------------
// Skins: a strip along x from 0 to 2 (y in [0, 0.1], front +z) on two bones: joint 0 (nodes[2])
// at the origin, joint 1 (nodes[3], its child) at x = 1. The armature's root nodes[1] lifts
// everything by z = 3; the skinned mesh's own node (nodes[0], translation 5, 5, 5) is ignored.
// Vertices at x = 0 follow joint 0, at x = 2 joint 1, at x = 1 both equally (weights 1 and 1:
// renormalised to 0.5 each).

const std::vector<uint16_t> kStripIndices = {0, 2, 3, 0, 3, 1, 2, 4, 5, 2, 5, 3};
const std::vector<float> kStrip = {0, 0, 0, 0, 0.1f, 0, 1, 0, 0, 1, 0.1f, 0, 2, 0, 0, 2, 0.1f, 0};

Doc skinnedStrip(const std::vector<uint8_t>& joints, double jointAngle) {
    Doc doc;
    const int position = doc.accessor(kStrip, kFloat, "VEC3");
    const int indices = doc.accessor(kStripIndices, kUnsignedShort, "SCALAR");
    const int jointAccessor = doc.accessor(joints, kUnsignedByte, "VEC4");
    const std::vector<float> weights = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    const int weightAccessor = doc.accessor(weights, kFloat, "VEC4");
    // Inverse bind matrices (column-major): joint 0 bound at the origin, joint 1 at x = 1 (in
    // the armature's space: its lift by z = 3 is in neither).
    const std::vector<float> ibm = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                    1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, 0, 0, 1};
    const int inverseBind = doc.accessor(ibm, kFloat, "MAT4");
    doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", position}, {"JOINTS_0", jointAccessor},
                                                       {"WEIGHTS_0", weightAccessor}}},
                                       {"indices", indices}, {"material", 0}}}}}};
    const double s = std::sin(jointAngle / 2), c = std::cos(jointAngle / 2);
    doc["nodes"] = {{{"mesh", 0}, {"skin", 0}, {"translation", {5, 5, 5}}},
                    {{"translation", {0, 0, 3}}, {"children", {2}}},
                    {{"children", {3}}},
                    {{"translation", {1, 0, 0}}, {"rotation", {0, 0, s, c}}}};
    doc["skins"] = {{{"joints", {2, 3}}, {"inverseBindMatrices", inverseBind}}};
    doc["scenes"] = {{{"nodes", {0, 1}}}};
    return doc;
}

const std::vector<uint8_t> kStripJoints = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};

// The strip with joint 1 turned by `angle` about z, by hand: a vertex on joint 1 goes to
// (1, 0) + R(angle) (x - 1, y); the middle ones halfway between that and where they are.
std::vector<glm::vec3> bentStrip(double angle) {
    const auto onJoint1 = [&](double x, double y) {
        return glm::vec3(float(1 + std::cos(angle) * (x - 1) - std::sin(angle) * y),
                         float(std::sin(angle) * (x - 1) + std::cos(angle) * y), 3.0f);
    };
    const auto middle = [&](double x, double y) { return 0.5f * (glm::vec3(float(x), float(y), 3.0f) + onJoint1(x, y)); };
    return {{0, 0, 3}, {0, 0.1f, 3}, middle(1, 0), middle(1, 0.1), onJoint1(2, 0), onJoint1(2, 0.1)};
}

TEST_F(GltfDeformation, TwoBoneStripBentByItsJoint) {
    constexpr double kRightAngle = 1.5707963267948966;
    const Scene scene = loadGltf(write(skinnedStrip(kStripJoints, kRightAngle).finish()));
    const std::vector<glm::vec3> expected = bentStrip(kRightAngle);
    // Spelled out for the right angle: the tip (2, 0) goes to (1, 1), (2, 0.1) to (0.9, 1), the
    // middle (1, 0.1) to ((1 + 0.9) / 2, (0.1 + 0) / 2).
    expectNear(expected[4], {1, 1, 3}, "hand formula");
    expectNear(expected[5], {0.9f, 1, 3}, "hand formula");
    expectNear(expected[3], {0.95f, 0.05f, 3}, "hand formula");
    expectVertices(scene.triangles, kStripIndices, expected);
    for (const Triangle& t : scene.triangles)  // no NORMAL: flat, and the bend is about z
        for (const glm::vec3& n : t.n) expectNear(n, {0, 0, 1}, "normal");
}

TEST_F(GltfDeformation, TwoSkinsDrawingOneMeshAreNotShared) {
    constexpr double kRightAngle = 1.5707963267948966;
    Doc doc = skinnedStrip(kStripJoints, kRightAngle);
    // nodes[4] draws the strip with skins[1], joints nodes[5] and [6] (both up by 10, no inverse binds):
    // every vertex moves by (0, 10, 0). A repeated mesh would be instanced; its skins differ.
    doc["nodes"].push_back({{"mesh", 0}, {"skin", 1}});
    doc["nodes"].push_back({{"translation", {0, 10, 0}}});
    doc["nodes"].push_back({{"translation", {0, 10, 0}}});
    doc["skins"].push_back({{"joints", {5, 6}}});
    doc["scenes"][0]["nodes"] = {0, 1, 4, 5, 6};
    doc["materials"][0].erase("emissiveFactor");  // emissive meshes are never instanced
    GltfLimits limits;
    limits.instanceMinTriangles = 0;
    const Scene scene = loadGltf(write(doc.finish()), limits);
    ASSERT_TRUE(scene.instances.empty());
    ASSERT_EQ(scene.triangles.size(), 8u);
    expectVertices({scene.triangles.begin(), scene.triangles.begin() + 4}, kStripIndices, bentStrip(kRightAngle));
    std::vector<glm::vec3> lifted;
    for (size_t i = 0; i < kStrip.size(); i += 3) lifted.emplace_back(kStrip[i], kStrip[i + 1] + 10, kStrip[i + 2]);
    expectVertices({scene.triangles.begin() + 4, scene.triangles.end()}, kStripIndices, lifted);
}

TEST_F(GltfDeformation, MirroringJointsKeepFrontFacesAndNormalsTogether) {
    // The armature's root mirrors x (scale -1, 1, 1): the skinned strip lies in x <= 0, its
    // NORMALs (+z) go through the inverse transpose (still +z), and each triangle is turned so
    // that its counter-clockwise face points along them, as a mirrored node's triangles are.
    Doc doc = skinnedStrip(kStripJoints, 0.0);
    const std::vector<float> normals(18, 0.0f);
    std::vector<float> up = normals;
    for (size_t i = 2; i < up.size(); i += 3) up[i] = 1.0f;
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = doc.accessor(up, kFloat, "VEC3");
    doc["nodes"][1]["scale"] = {-1, 1, 1};
    const Scene scene = loadGltf(write(doc.finish()));
    ASSERT_EQ(scene.triangles.size(), 4u);
    for (const Triangle& t : scene.triangles) {
        const glm::vec3 face = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
        EXPECT_GT(face.z, 0.0f);
        for (const glm::vec3& p : t.p) EXPECT_LE(p.x, 0.0f);
        for (const glm::vec3& n : t.n) expectNear(n, {0, 0, 1}, "normal");
    }
}

TEST_F(GltfDeformation, JointAnimationIsPlayedPerFrame) {
    Doc doc = skinnedStrip(kStripJoints, 0.0);
    // joint 1 (nodes[3]) turns from 0 to 90 degrees about z over one second.
    const double h = std::sqrt(0.5);
    const std::vector<float> times = {0, 1}, rotations = {0, 0, 0, 1, 0, 0, float(h), float(h)};
    const int input = doc.accessor(times, kFloat, "SCALAR");
    const int output = doc.accessor(rotations, kFloat, "VEC4");
    doc["accessors"][input]["min"] = {0};
    doc["accessors"][input]["max"] = {1};
    doc["animations"] = {{{"channels", {{{"sampler", 0}, {"target", {{"node", 3}, {"path", "rotation"}}}}}},
                          {"samplers", {{{"input", input}, {"output", output}}}}}};
    GltfSceneSource source(write(doc.finish()));
    expectVertices(source.stillScene().triangles, kStripIndices, bentStrip(0.0));
    expectVertices(source.sceneAt(0.5).triangles, kStripIndices, bentStrip(0.7853981633974483));
    expectVertices(source.sceneAt(1.0).triangles, kStripIndices, bentStrip(1.5707963267948966));
}

TEST_F(GltfDeformation, BadSkinsAreRefused) {
    {   // joint 2 of a two-joint skin
        std::vector<uint8_t> joints = kStripJoints;
        joints[8] = 2;
        const std::string e = error(skinnedStrip(joints, 0.0).finish());
        EXPECT_NE(e.find("meshes[0].primitives[0]: JOINTS_0 element 2 names joint 2, but the skin has 2 joints"),
                  std::string::npos) << e;
    }
    {   // fewer inverse bind matrices than joints
        Doc doc = skinnedStrip(kStripJoints, 0.0);
        doc["accessors"][4]["count"] = 1;
        const std::string e = error(doc.finish());
        EXPECT_NE(e.find("skins[0].inverseBindMatrices: accessors[4] has 1 matrices for 2 joints"), std::string::npos) << e;
    }
    {   // WEIGHTS_0 without JOINTS_0
        Doc doc = skinnedStrip(kStripJoints, 0.0);
        doc["meshes"][0]["primitives"][0]["attributes"].erase("JOINTS_0");
        const std::string e = error(doc.finish());
        EXPECT_NE(e.find("meshes[0].primitives[0]: has WEIGHTS_0 without JOINTS_0"), std::string::npos) << e;
    }
    {   // a negative weight
        Doc doc = skinnedStrip(kStripJoints, 0.0);
        const std::vector<float> weights = {1, 0, 0, 0, -1, 0, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
        doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = doc.accessor(weights, kFloat, "VEC4");
        const std::string e = error(doc.finish());
        EXPECT_NE(e.find("meshes[0].primitives[0]: WEIGHTS_0 element 1 is negative or not finite"), std::string::npos) << e;
    }
}

TEST_F(GltfDeformation, NormalizedByteWeightsAndASecondInfluenceSet) {
    // The same strip with its middle vertices' second influence moved to JOINTS_1/WEIGHTS_1, and
    // weights as normalized unsigned bytes (255 = 1).
    constexpr double kRightAngle = 1.5707963267948966;
    Doc doc = skinnedStrip(kStripJoints, kRightAngle);
    const std::vector<uint8_t> joints0 = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    const std::vector<uint8_t> weights0 = {255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0};
    const std::vector<uint8_t> joints1 = {0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    const std::vector<uint8_t> weights1 = {0, 0, 0, 0, 0, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    json& attributes = doc["meshes"][0]["primitives"][0]["attributes"];
    attributes["JOINTS_0"] = doc.accessor(joints0, kUnsignedByte, "VEC4");
    attributes["WEIGHTS_0"] = doc.accessor(weights0, kUnsignedByte, "VEC4", true);
    attributes["JOINTS_1"] = doc.accessor(joints1, kUnsignedByte, "VEC4");
    attributes["WEIGHTS_1"] = doc.accessor(weights1, kUnsignedByte, "VEC4", true);
    expectVertices(loadGltf(write(doc.finish())).triangles, kStripIndices, bentStrip(kRightAngle));
}

}  // namespace
}  // namespace vkp
