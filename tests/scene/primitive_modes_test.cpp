// TRIANGLE_STRIP (5) and TRIANGLE_FAN (6) primitives: turned into triangle lists with the
// winding of the glTF 2.0 specification (scene/gltf_primitive_modes.h). The hand-written files
// in tests/data/good/modes (made by make_modes.py there) hold a strip and a fan, and the same
// triangles written out as TRIANGLES from the specification's table.
#include <filesystem>

#include <gtest/gtest.h>

#include "scene/gltf_loader.h"
#include "scene/gltf_primitive_modes.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;

TEST(PrimitiveModes, StripsAndFansFollowTheSpecificationsTable) {
    const std::vector<uint32_t> v{10, 11, 12, 13, 14};
    EXPECT_EQ(triangleListIndices(5, v), (std::vector<uint32_t>{10, 11, 12, 11, 13, 12, 12, 13, 14}));
    EXPECT_EQ(triangleListIndices(6, v), (std::vector<uint32_t>{11, 12, 10, 12, 13, 10, 13, 14, 10}));
    EXPECT_EQ(triangleListIndices(4, v), v);  // a list is left as it is
    EXPECT_EQ(triangleListIndices(-1, v), v);
    EXPECT_TRUE(triangleListIndices(5, {1, 2}).empty());
    EXPECT_EQ(triangleCountOfMode(5, 5), 3u);
    EXPECT_EQ(triangleCountOfMode(6, 2), 0u);
    EXPECT_EQ(triangleCountOfMode(4, 7), 2u);
    EXPECT_EQ(triangleCountOfMode(1, 6), 0u);
    for (int mode : {0, 1, 2, 3}) EXPECT_FALSE(isTriangleMode(mode)) << mode;
    for (int mode : {-1, 4, 5, 6}) EXPECT_TRUE(isTriangleMode(mode)) << mode;
}

TEST(PrimitiveModes, AStripAndAFanLoadAsTheirTrianglesFacingTheSameWay) {
    const fs::path dir = fs::path(VKPHOTON_TEST_DATA) / "good" / "modes";
    const Scene modes = loadGltf(dir / "strip_fan.gltf");
    const Scene list = loadGltf(dir / "strip_fan_as_triangles.gltf");
    ASSERT_EQ(list.triangles.size(), 8u);
    ASSERT_EQ(modes.triangles.size(), list.triangles.size());
    for (size_t i = 0; i < list.triangles.size(); ++i) {
        const Triangle& a = modes.triangles[i];
        const Triangle& b = list.triangles[i];
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(a.p[k], b.p[k]) << "triangle " << i << " vertex " << k;
            EXPECT_EQ(a.n[k], b.n[k]) << "triangle " << i << " vertex " << k;
        }
        // Every triangle of the strip (odd ones included) faces the first one's way, +Z; so do
        // the fan's, whose arc runs counter-clockwise seen from +Z.
        const glm::vec3 facing = glm::cross(a.p[1] - a.p[0], a.p[2] - a.p[0]);
        EXPECT_GT(facing.z, 0.0f) << "triangle " << i;
        EXPECT_GT(a.n[0].z, 0.99f) << "triangle " << i;
    }
    EXPECT_EQ(modes.bounds.min, list.bounds.min);
    EXPECT_EQ(modes.bounds.max, list.bounds.max);
}

}  // namespace
}  // namespace vkp
