// BVH (host/bvh) and the shared intersection tests (shaders/shared/intersect.glsl), CPU side:
// closest and any hit through the tree equal brute force over every triangle with the same
// intersection function; the triangle test is watertight on closed meshes; the tree is a valid
// partition with nested boxes; SAH beats a median split; degenerate inputs build valid trees.
// closestHit/anyHit run the shaders' own traversal (shaders/shared/bvh_traverse.glsl compiled as
// C++), so these brute-force comparisons check it; tests/bvh/bvh_gpu_test.cpp checks that the GPU
// build gives the same hits (on lavapipe bit-identical).
#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "bvh/bvh.h"
#include "shared/bvh_constants.glsl"
#include "shared/constants.glsl"
#include "shared/intersect.glsl"

namespace vkp {
namespace {

// ---------------------------------------------------------------------------------------------
// Test geometry

struct Mesh {
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> faces;  // counter-clockwise seen from outside
};

// Icosphere: an icosahedron with every face split into four, `levels` times, vertices pushed to
// the sphere. Shared edges reuse the exact same vertex values (midpoints are cached per edge), so
// the mesh is closed and watertight in floating point.
Mesh icosphere(int levels, glm::vec3 center, float radius) {
    const float p = (1.0f + std::sqrt(5.0f)) / 2.0f;
    Mesh m;
    m.vertices = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                  {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
    for (auto& v : m.vertices) v = glm::normalize(v);
    m.faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
               {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
               {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            const auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            m.vertices.push_back(glm::normalize(m.vertices[a] + m.vertices[b]));
            const auto index = static_cast<uint32_t>(m.vertices.size() - 1);
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<glm::uvec3> next;
        for (const auto& f : m.faces) {
            const uint32_t ab = midpoint(f.x, f.y), bc = midpoint(f.y, f.z), ca = midpoint(f.z, f.x);
            next.push_back({f.x, ab, ca});
            next.push_back({f.y, bc, ab});
            next.push_back({f.z, ca, bc});
            next.push_back({ab, bc, ca});
        }
        m.faces = std::move(next);
    }
    for (auto& v : m.vertices) v = center + radius * v;
    return m;
}

void appendMesh(const Mesh& mesh, std::vector<Triangle>& out) {
    for (const auto& f : mesh.faces) {
        Triangle t{};
        t.p[0] = mesh.vertices[f.x];
        t.p[1] = mesh.vertices[f.y];
        t.p[2] = mesh.vertices[f.z];
        out.push_back(t);
    }
}

// Random triangles of mixed sizes (slivers, small, large) in [-extent, extent]^3.
void appendSoup(uint32_t count, float extent, uint32_t seed, std::vector<Triangle>& out) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-extent, extent);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_real_distribution<float> logSize(-3.0f, 0.5f);
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 c(pos(rng), pos(rng), pos(rng));
        const float size = std::pow(10.0f, logSize(rng));
        Triangle t{};
        for (auto& p : t.p) p = c + size * glm::vec3(unit(rng), unit(rng), unit(rng));
        out.push_back(t);
    }
}

// A non-trivial scene: two closed icospheres (one inside a box of clutter), a random soup of 400
// triangles and a large two-triangle floor.
std::vector<Triangle> testScene() {
    std::vector<Triangle> tris;
    appendMesh(icosphere(3, glm::vec3(0.0f), 1.0f), tris);                // 1280 triangles
    appendMesh(icosphere(2, glm::vec3(2.5f, 0.5f, -1.0f), 0.6f), tris);   // 320 triangles
    appendSoup(400, 3.0f, 7, tris);
    Triangle floor0{}, floor1{};
    floor0.p[0] = {-4, -2, -4}; floor0.p[1] = {4, -2, -4}; floor0.p[2] = {4, -2, 4};
    floor1.p[0] = {-4, -2, -4}; floor1.p[1] = {4, -2, 4}; floor1.p[2] = {-4, -2, 4};
    tris.push_back(floor0);
    tris.push_back(floor1);
    return tris;
}

// ---------------------------------------------------------------------------------------------
// References

RayHit bruteForceClosest(std::span<const gpu::GpuTriangle> tris, glm::vec3 org, glm::vec3 dir, float tMax) {
    RayHit best;
    best.t = tMax;
    for (uint32_t i = 0; i < tris.size(); ++i) {
        float t, b1, b2;
        if (gpu::intersectTriangle(org, dir, glm::vec3(tris[i].v0), glm::vec3(tris[i].v1), glm::vec3(tris[i].v2),
                                   best.t, t, b1, b2))
            best = {true, t, i, b1, b2};
    }
    return best;
}

struct Ray {
    glm::vec3 org;
    glm::vec3 dir;
    float tMax;
};

glm::vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> n;
    glm::vec3 d;
    do d = glm::vec3(n(rng), n(rng), n(rng)); while (glm::length(d) < 1e-3f);
    return glm::normalize(d);
}

// Rays of every kind the renderer makes: from inside the spheres, from inside the clutter, from far
// outside, towards vertices and shared edges, axis-aligned (exact zero direction components),
// unnormalised, with infinite and short tMax.
std::vector<Ray> testRays(std::span<const Triangle> tris, uint32_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::uniform_real_distribution<float> box(-5.0f, 5.0f);
    std::uniform_int_distribution<size_t> pickTriangle(0, tris.size() - 1);
    std::vector<Ray> rays;
    rays.reserve(count);
    for (uint32_t i = 0; i < count; ++i) {
        Ray r{};
        switch (i % 8) {
        case 0: r.org = 0.9f * u(rng) * randomDirection(rng); r.dir = randomDirection(rng); break;  // in sphere
        case 1: r.org = glm::vec3(box(rng), box(rng), box(rng)); r.dir = randomDirection(rng); break;
        case 2: {  // far away, aimed at the scene
            r.org = 30.0f * randomDirection(rng);
            r.dir = glm::normalize(glm::vec3(box(rng), box(rng), box(rng)) * 0.6f - r.org);
            break;
        }
        case 3: {  // at a vertex of a random triangle
            const Triangle& t = tris[pickTriangle(rng)];
            r.org = glm::vec3(box(rng), box(rng), box(rng));
            r.dir = t.p[i % 3] - r.org;
            break;
        }
        case 4: {  // at a point on an edge of a random triangle
            const Triangle& t = tris[pickTriangle(rng)];
            const glm::vec3 target = t.p[0] + u(rng) * (t.p[1] - t.p[0]);
            r.org = glm::vec3(box(rng), box(rng), box(rng));
            r.dir = glm::normalize(target - r.org);
            break;
        }
        case 5: {  // axis-aligned: two exact zero components
            r.org = glm::vec3(box(rng), box(rng), box(rng));
            r.dir = glm::vec3(0.0f);
            r.dir[static_cast<int>(i / 8) % 3] = u(rng) < 0.5f ? -1.0f : 1.0f;
            break;
        }
        case 6: {  // one exact zero component, unnormalised
            r.org = glm::vec3(box(rng), box(rng), box(rng));
            r.dir = 3.0f * randomDirection(rng);
            r.dir[static_cast<int>(i / 8) % 3] = 0.0f;
            if (glm::length(r.dir) < 1e-3f) r.dir = glm::vec3(1.0f, 0.0f, 0.0f);
            break;
        }
        default: {  // interior point of a random triangle from a random origin
            const Triangle& t = tris[pickTriangle(rng)];
            float a = u(rng), b = u(rng);
            if (a + b > 1.0f) { a = 1.0f - a; b = 1.0f - b; }
            r.org = glm::vec3(box(rng), box(rng), box(rng));
            r.dir = glm::normalize(t.p[0] + a * (t.p[1] - t.p[0]) + b * (t.p[2] - t.p[0]) - r.org);
            break;
        }
        }
        r.tMax = i % 5 == 0 ? 0.5f + 4.0f * u(rng) : gpu::kInfinity;
        rays.push_back(r);
    }
    return rays;
}

// Same triangle at the same t, or, where several triangles share the hit point exactly (rays
// through shared edges and vertices), another one at the identical t.
void expectSameHit(const RayHit& expected, const RayHit& actual, const Ray& ray, size_t index) {
    const auto where = [&] {
        std::ostringstream s;
        s << std::setprecision(9) << "ray " << index << " org (" << ray.org.x << ", " << ray.org.y << ", " << ray.org.z << ") dir ("
          << ray.dir.x << ", " << ray.dir.y << ", " << ray.dir.z << ") tMax " << ray.tMax;
        return s.str();
    };
    ASSERT_EQ(expected.hit, actual.hit) << where();
    if (!expected.hit) return;
    EXPECT_NEAR(actual.t, expected.t, 1e-5f * expected.t) << where();
    if (actual.triangle != expected.triangle) {
        EXPECT_EQ(actual.t, expected.t) << "different triangle at a different distance, " << where();
    } else {
        EXPECT_EQ(actual.b1, expected.b1) << where();
        EXPECT_EQ(actual.b2, expected.b2) << where();
    }
}

void checkAgainstBruteForce(std::span<const Triangle> triangles, std::span<const Ray> rays,
                            const BvhBuildOptions& options = {}) {
    const Bvh bvh = buildBvh(triangles, options);
    const auto tris = gpuTriangles(triangles, bvh);
    size_t hits = 0;
    size_t anyHitOnlyShort = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const Ray& r = rays[i];
        const RayHit expected = bruteForceClosest(tris, r.org, r.dir, r.tMax);
        const RayHit actual = closestHit(bvh, tris, r.org, r.dir, r.tMax);
        expectSameHit(expected, actual, r, i);
        ASSERT_EQ(anyHit(bvh, tris, r.org, r.dir, r.tMax), expected.hit) << "any hit, ray " << i;
        if (::testing::Test::HasFailure()) return;
        hits += expected.hit;
        anyHitOnlyShort += expected.hit && r.tMax < gpu::kInfinity;
    }
    // Only meaningful if both outcomes (and short rays that hit) are common.
    EXPECT_GT(hits, rays.size() / 5);
    EXPECT_LT(hits, rays.size() * 19 / 20);
    EXPECT_GT(anyHitOnlyShort, rays.size() / 100);
}

// ---------------------------------------------------------------------------------------------
// Structure

void checkStructure(std::span<const Triangle> triangles, const Bvh& bvh, uint32_t maxLeafSize) {
    const size_t n = triangles.size();
    ASSERT_EQ(bvh.triangleOrder.size(), n);
    std::vector<int> isTarget(n, 0);
    for (uint32_t index : bvh.triangleOrder) {
        ASSERT_LT(index, n);
        ASSERT_EQ(isTarget[index]++, 0) << "triangleOrder is not a permutation";
    }
    ASSERT_FALSE(bvh.nodes.empty());
    ASSERT_LE(bvh.nodes.size(), std::max<size_t>(1, 2 * n - 1));
    std::vector<int> slotSeen(n, 0);
    std::vector<int> nodeSeen(bvh.nodes.size(), 0);
    struct Item { uint32_t node; uint32_t depth; };
    std::vector<Item> stack{{0, 1}};
    uint32_t maxDepth = 0;
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        ASSERT_LT(item.node, bvh.nodes.size());
        ASSERT_EQ(nodeSeen[item.node]++, 0) << "node " << item.node << " reached twice";
        maxDepth = std::max(maxDepth, item.depth);
        const gpu::GpuBvhNode& node = bvh.nodes[item.node];
        if (node.count > 0) {
            ASSERT_LE(node.count, maxLeafSize);
            ASSERT_LE(size_t(node.leftOrFirst) + node.count, n);
            for (uint32_t i = node.leftOrFirst; i < node.leftOrFirst + node.count; ++i) {
                ++slotSeen[i];
                // Leaf boxes are exact unions of the triangles' boxes: plain comparisons.
                for (const glm::vec3& p : triangles[bvh.triangleOrder[i]].p) {
                    EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, node.boundsMin)));
                    EXPECT_TRUE(glm::all(glm::lessThanEqual(p, node.boundsMax)));
                }
            }
            continue;
        }
        ASSERT_GT(node.leftOrFirst, item.node) << "children must follow their parent";
        ASSERT_LT(size_t(node.leftOrFirst) + 1, bvh.nodes.size());
        for (uint32_t c = node.leftOrFirst; c < node.leftOrFirst + 2; ++c) {
            EXPECT_TRUE(glm::all(glm::greaterThanEqual(bvh.nodes[c].boundsMin, node.boundsMin))) << "node " << c;
            EXPECT_TRUE(glm::all(glm::lessThanEqual(bvh.nodes[c].boundsMax, node.boundsMax))) << "node " << c;
            stack.push_back({c, item.depth + 1});
        }
    }
    for (size_t i = 0; i < n; ++i) ASSERT_EQ(slotSeen[i], 1) << "triangle slot " << i << " not in exactly one leaf";
    for (size_t i = 0; i < nodeSeen.size(); ++i) ASSERT_EQ(nodeSeen[i], 1) << "node " << i << " unreachable";
    EXPECT_EQ(maxDepth, bvh.depth);
    EXPECT_LE(bvh.depth, gpu::kBvhMaxDepth);
}

// ---------------------------------------------------------------------------------------------
// Tests

TEST(BvhTraversal, ClosestAndAnyHitEqualBruteForce) {
    const auto tris = testScene();
    ASSERT_GT(tris.size(), 2000u);
    const auto rays = testRays(tris, 12000, 42);
    checkAgainstBruteForce(tris, rays);
}

TEST(BvhTraversal, MedianTreeEqualsBruteForceToo) {
    const auto tris = testScene();
    BvhBuildOptions options;
    options.split = BvhBuildOptions::Split::Median;
    options.maxLeafSize = 3;
    checkAgainstBruteForce(tris, testRays(tris, 3000, 9), options);
}

// Closed mesh, rays from inside aimed exactly at vertices (shared by 5-6 triangles) and at points
// on shared edges: every one must hit, through the tree and by brute force. A non-watertight test
// (e.g. Moeller-Trumbore with its epsilon) loses some of these.
TEST(Intersect, WatertightOnClosedMesh) {
    const Mesh sphere = icosphere(3, glm::vec3(0.3f, -0.2f, 0.1f), 1.7f);
    std::vector<Triangle> tris;
    appendMesh(sphere, tris);
    const Bvh bvh = buildBvh(tris);
    const auto gpuTris = gpuTriangles(tris, bvh);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::uniform_int_distribution<size_t> pickFace(0, sphere.faces.size() - 1);
    size_t rays = 0, misses = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::uvec3 f = sphere.faces[pickFace(rng)];
        const glm::vec3 a = sphere.vertices[f[i % 3]];
        const glm::vec3 b = sphere.vertices[f[(i + 1) % 3]];
        // Vertices, edge midpoints and random points on edges.
        const float s = i % 3 == 0 ? 0.0f : i % 3 == 1 ? 0.5f : u(rng);
        const glm::vec3 target = a + s * (b - a);
        const glm::vec3 org = glm::vec3(0.3f, -0.2f, 0.1f) + 1.2f * u(rng) * randomDirection(rng);
        const glm::vec3 dir = target - org;
        const RayHit brute = bruteForceClosest(gpuTris, org, dir, gpu::kInfinity);
        const RayHit tree = closestHit(bvh, gpuTris, org, dir, gpu::kInfinity);
        misses += !brute.hit;
        ++rays;
        ASSERT_EQ(brute.hit, tree.hit) << i;
        ASSERT_TRUE(anyHit(bvh, gpuTris, org, dir, gpu::kInfinity)) << i;
        if (brute.hit) {
            EXPECT_EQ(brute.t, tree.t) << i;
        }
    }
    EXPECT_EQ(misses, 0u) << "of " << rays << " rays from inside a closed mesh";
}

// From outside, rays aimed at shared edges roughly along the inward normal (both neighbours face
// the ray, so the line certainly enters the mesh there): must hit.
TEST(Intersect, WatertightOnSharedEdgesFromOutside) {
    const Mesh sphere = icosphere(4, glm::vec3(0.0f), 1.0f);
    std::vector<Triangle> tris;
    appendMesh(sphere, tris);
    std::vector<gpu::GpuTriangle> gpuTris;
    for (const auto& t : tris) {
        gpu::GpuTriangle g{};
        g.v0 = glm::vec4(t.p[0], 0.0f);
        g.v1 = glm::vec4(t.p[1], 0.0f);
        g.v2 = glm::vec4(t.p[2], 0.0f);
        gpuTris.push_back(g);
    }
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::uniform_int_distribution<size_t> pickFace(0, sphere.faces.size() - 1);
    size_t misses = 0;
    for (int i = 0; i < 5000; ++i) {
        const glm::uvec3 f = sphere.faces[pickFace(rng)];
        const glm::vec3 a = sphere.vertices[f[i % 3]];
        const glm::vec3 b = sphere.vertices[f[(i + 1) % 3]];
        const glm::vec3 target = i % 4 == 0 ? a : a + u(rng) * (b - a);
        const glm::vec3 normal = glm::normalize(target);
        const glm::vec3 org = target + (2.0f + u(rng)) * glm::normalize(normal + 0.3f * randomDirection(rng));
        misses += !bruteForceClosest(gpuTris, org, target - org, gpu::kInfinity).hit;
    }
    EXPECT_EQ(misses, 0u);
}

// A fan around an interior vertex, rays from above through the shared vertex and shared edges.
TEST(Intersect, WatertightOnTriangleFan) {
    const int n = 16;
    std::vector<glm::vec3> ring;
    for (int i = 0; i < n; ++i) {
        const float a = gpu::kTwoPi * static_cast<float>(i) / n;
        ring.emplace_back(std::cos(a), std::sin(a), 0.37f * std::sin(3.0f * a));
    }
    const glm::vec3 center(0.1f, -0.05f, 0.02f);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int misses = 0;
    for (int r = 0; r < 20000; ++r) {
        const int e = r % n;
        const float s = r % 50 == 0 ? 0.0f : u(rng);
        const glm::vec3 target = center + s * (ring[e] - center);
        const glm::vec3 org(u(rng) - 0.5f, u(rng) - 0.5f, 3.0f + u(rng));
        const glm::vec3 dir = glm::normalize(target - org);
        bool hit = false;
        for (int k = 0; k < n && !hit; ++k) {
            float t, b1, b2;
            hit = gpu::intersectTriangle(org, dir, center, ring[k], ring[(k + 1) % n], gpu::kInfinity, t, b1, b2);
        }
        misses += !hit;
    }
    EXPECT_EQ(misses, 0);
}

TEST(Intersect, TriangleBasics) {
    const glm::vec3 v0(0, 0, 0), v1(1, 0, 0), v2(0, 1, 0);
    float t = -1, b1 = -1, b2 = -1;
    ASSERT_TRUE(gpu::intersectTriangle({0.25f, 0.5f, 2.0f}, {0, 0, -1}, v0, v1, v2, 10.0f, t, b1, b2));
    EXPECT_FLOAT_EQ(t, 2.0f);
    EXPECT_FLOAT_EQ(b1, 0.25f);
    EXPECT_FLOAT_EQ(b2, 0.5f);
    // Back side (no culling), unnormalised direction: t is in units of the direction's length.
    ASSERT_TRUE(gpu::intersectTriangle({0.25f, 0.25f, -3.0f}, {0, 0, 2}, v0, v1, v2, 10.0f, t, b1, b2));
    EXPECT_FLOAT_EQ(t, 1.5f);
    // tMax is exclusive; behind the origin is a miss; parallel and zero directions miss.
    EXPECT_FALSE(gpu::intersectTriangle({0.25f, 0.5f, 2.0f}, {0, 0, -1}, v0, v1, v2, 2.0f, t, b1, b2));
    EXPECT_FALSE(gpu::intersectTriangle({0.25f, 0.5f, 2.0f}, {0, 0, 1}, v0, v1, v2, 10.0f, t, b1, b2));
    EXPECT_FALSE(gpu::intersectTriangle({0.25f, 0.5f, 0.0f}, {1, 0, 0}, v0, v1, v2, 10.0f, t, b1, b2));
    EXPECT_FALSE(gpu::intersectTriangle({0.25f, 0.5f, 2.0f}, {0, 0, 0}, v0, v1, v2, 10.0f, t, b1, b2));
    EXPECT_FALSE(gpu::intersectTriangle({1.0f, 1.0f, 2.0f}, {0, 0, -1}, v0, v1, v2, 10.0f, t, b1, b2));
    // Degenerate triangle.
    EXPECT_FALSE(gpu::intersectTriangle({0.0f, 0.0f, 2.0f}, {0, 0, -1}, v0, v1, v1, 10.0f, t, b1, b2));
}

TEST(Intersect, AabbWithZeroDirectionComponents) {
    const glm::vec3 lo(-1, -1, -1), hi(1, 1, 1);
    const auto entry = [&](glm::vec3 org, glm::vec3 dir, float tMax = gpu::kInfinity) {
        return gpu::intersectAabb(org, gpu::safeInverseDirection(dir), lo, hi, tMax);
    };
    EXPECT_FLOAT_EQ(entry({-3, 0, 0}, {1, 0, 0}), 2.0f);
    EXPECT_EQ(entry({0, 0, 0}, {0, 0, 1}), 0.0f);                  // inside
    EXPECT_EQ(entry({-3, 2, 0}, {1, 0, 0}), gpu::kInfinity);       // parallel, outside the y slab
    EXPECT_EQ(entry({-3, 1.0001f, 0}, {1, 0, 0}), gpu::kInfinity);  // parallel, just outside
    EXPECT_FLOAT_EQ(entry({-3, 0.999f, -0.999f}, {1, 0, 0}), 2.0f);  // just inside two faces
    EXPECT_FLOAT_EQ(entry({-3, -0.5f, 0}, {1, -0.0f, 0}), 2.0f);  // negative zero
    EXPECT_EQ(entry({-3, 0, 0}, {1, 0, 0}, 1.5f), gpu::kInfinity);  // box beyond tMax
    EXPECT_EQ(entry({-3, 0, 0}, {-1, 0, 0}), gpu::kInfinity);      // box behind
    EXPECT_EQ(entry({0, 0, 0}, {0, 0, 0}), 0.0f);                  // zero direction inside: no NaN
    EXPECT_EQ(entry({0, 0, 5}, {0, 0, 0}), gpu::kInfinity);        // zero direction outside
    EXPECT_FLOAT_EQ(entry({-0.5f, 0, -3}, {1e-35f, 0, 1}), 2.0f);   // tiny component
}

// Axis-aligned geometry and axis-aligned rays running exactly in its planes (the case the box
// padding exists for): a floor at y = 0 and a wall at x = 2 whose bottom edge lies on the floor;
// rays in the floor plane hit the wall's bottom edge, rays in the wall plane hit the floor edge.
TEST(BvhTraversal, RaysInFacePlanesOfAxisAlignedGeometry) {
    std::vector<Triangle> tris;
    auto quad = [&](glm::vec3 o, glm::vec3 a, glm::vec3 b) {
        Triangle t0{}, t1{};
        t0.p[0] = o; t0.p[1] = o + a; t0.p[2] = o + a + b;
        t1.p[0] = o; t1.p[1] = o + a + b; t1.p[2] = o + b;
        tris.push_back(t0);
        tris.push_back(t1);
    };
    quad({-2, 0, -2}, {4, 0, 0}, {0, 0, 4});   // floor
    quad({2, 0, -2}, {0, 0, 4}, {0, 2, 0});    // wall
    quad({-1, 1, -1}, {1, 0, 0}, {0, 0, 1});   // a small shelf, so the tree has several levels
    appendSoup(60, 1.5f, 4, tris);
    const Bvh bvh = buildBvh(tris);
    const auto g = gpuTriangles(tris, bvh);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(-1.9f, 1.9f);
    for (int i = 0; i < 500; ++i) {
        const float z = i % 10 == 0 ? 0.0f : u(rng);  // z = 0: through the diagonal of two quads
        const Ray inFloor{{-1.0f, 0.0f, z}, {1.0f, 0.0f, 0.0f}, gpu::kInfinity};
        const Ray inWall{{2.0f, 1.5f, z}, {0.0f, -1.0f, 0.0f}, gpu::kInfinity};
        for (const Ray& r : {inFloor, inWall}) {
            const RayHit brute = bruteForceClosest(g, r.org, r.dir, r.tMax);
            ASSERT_TRUE(brute.hit) << i;  // the floor-wall edge is always in the way
            expectSameHit(brute, closestHit(bvh, g, r.org, r.dir, r.tMax), r, i);
            EXPECT_EQ(anyHit(bvh, g, r.org, r.dir, r.tMax), brute.hit) << i;
        }
        if (HasFailure()) return;
    }
}

TEST(BvhBuild, StructureOfSceneTree) {
    const auto tris = testScene();
    const Bvh bvh = buildBvh(tris);
    checkStructure(tris, bvh, gpu::kBvhMaxLeafSize);
    const BvhStats stats = bvhStats(bvh);
    EXPECT_EQ(stats.nodeCount, 2 * stats.leafCount - 1);
    EXPECT_GT(stats.averageLeafSize, 1.0);
}

TEST(BvhBuild, IsDeterministic) {
    std::vector<Triangle> tris = testScene();
    appendSoup(3000, 10.0f, 99, tris);
    const Bvh a = buildBvh(tris);
    const Bvh b = buildBvh(tris);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(gpu::GpuBvhNode)), 0);
    EXPECT_EQ(a.triangleOrder, b.triangleOrder);
    EXPECT_EQ(a.depth, b.depth);
}

TEST(BvhBuild, EmptyInput) {
    const Bvh bvh = buildBvh(std::span<const Triangle>());
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].count, 0u);
    EXPECT_EQ(bvh.nodes[0].leftOrFirst, 0u);
    EXPECT_TRUE(bvh.triangleOrder.empty());
    const std::vector<gpu::GpuTriangle> none;
    // Rays through the (zero-size) root box at the origin must still miss.
    EXPECT_FALSE(closestHit(bvh, none, {0, 0, 5}, {0, 0, -1}, gpu::kInfinity).hit);
    EXPECT_FALSE(anyHit(bvh, none, {0, 0, 5}, {0, 0, -1}, gpu::kInfinity));
    EXPECT_EQ(sahCost(bvh), 0.0);
}

TEST(BvhBuild, SingleTriangle) {
    std::vector<Triangle> tris(1);
    tris[0].p[0] = {0, 0, 0};
    tris[0].p[1] = {1, 0, 0};
    tris[0].p[2] = {0, 1, 0};
    const Bvh bvh = buildBvh(tris);
    ASSERT_EQ(bvh.nodes.size(), 1u);
    EXPECT_EQ(bvh.nodes[0].count, 1u);
    EXPECT_EQ(bvh.nodes[0].leftOrFirst, 0u);
    EXPECT_EQ(bvh.depth, 1u);
    const auto g = gpuTriangles(tris, bvh);
    const RayHit hit = closestHit(bvh, g, {0.2f, 0.2f, 1.0f}, {0, 0, -1}, gpu::kInfinity);
    ASSERT_TRUE(hit.hit);
    EXPECT_FLOAT_EQ(hit.t, 1.0f);
    EXPECT_EQ(hit.triangle, 0u);
    checkStructure(tris, bvh, 1);
}

TEST(BvhBuild, CoincidentCentroids) {
    // 1000 copies of one triangle plus triangles of other sizes around the same centroid: no
    // plane separates them, the build splits by count and keeps leaves within maxLeafSize.
    std::vector<Triangle> tris(1000);
    for (size_t i = 0; i < tris.size(); ++i) {
        const float s = i % 2 ? 1.0f : 1.0f + static_cast<float>(i % 7);
        tris[i].p[0] = glm::vec3(-s, -s, 0.0f);
        tris[i].p[1] = glm::vec3(s, -s, 0.0f);
        tris[i].p[2] = glm::vec3(0.0f, 2.0f * s, 0.0f);
    }
    const Bvh bvh = buildBvh(tris);
    checkStructure(tris, bvh, gpu::kBvhMaxLeafSize);
    const auto g = gpuTriangles(tris, bvh);
    const RayHit hit = closestHit(bvh, g, {0.0f, 0.0f, 1.0f}, {0, 0, -1}, gpu::kInfinity);
    ASSERT_TRUE(hit.hit);
    EXPECT_FLOAT_EQ(hit.t, 1.0f);
    EXPECT_TRUE(anyHit(bvh, g, {0.0f, 0.0f, 1.0f}, {0, 0, -1}, gpu::kInfinity));
}

TEST(BvhBuild, DepthBudget) {
    // SAH alone makes this scene about twice as deep as a balanced tree; with a budget of 12
    // levels the build must switch to splits by count in time: depth <= 12 with leaves still
    // within maxLeafSize, and answers still equal brute force. (The renderer's budget is
    // kBvhMaxDepth, the GPU stack size, which real inputs only approach through such skew.)
    std::vector<Triangle> tris = testScene();
    appendSoup(1000, 0.2f, 17, tris);  // a dense cluster inside the sphere
    const Bvh unlimited = buildBvh(tris);
    BvhBuildOptions options;
    options.maxDepth = 12;
    const Bvh bvh = buildBvh(tris, options);
    EXPECT_GT(unlimited.depth, options.maxDepth) << "the input should need the budget";
    checkStructure(tris, bvh, gpu::kBvhMaxLeafSize);
    EXPECT_LE(bvh.depth, options.maxDepth);
    checkAgainstBruteForce(tris, testRays(tris, 3000, 21), options);
}

TEST(BvhBuild, SahBeatsMedianSplitOnClusteredInput) {
    // Uneven clusters (2000, 200, 20, 2 triangles) far apart plus a few large triangles spanning
    // the scene: a median split cuts through the big cluster and mixes the small ones with it.
    std::vector<Triangle> tris;
    const glm::vec3 centres[] = {{-40, 0, 0}, {30, 5, 0}, {0, 40, 10}, {10, -30, -20}};
    const uint32_t counts[] = {2000, 200, 20, 2};
    for (int c = 0; c < 4; ++c) {
        std::vector<Triangle> cluster;
        appendSoup(counts[c], 1.0f, 100 + c, cluster);
        for (auto& t : cluster)
            for (auto& p : t.p) p = centres[c] + 0.5f * p;
        tris.insert(tris.end(), cluster.begin(), cluster.end());
    }
    appendSoup(10, 30.0f, 5, tris);
    const Bvh sah = buildBvh(tris);
    BvhBuildOptions medianOptions;
    medianOptions.split = BvhBuildOptions::Split::Median;
    const Bvh median = buildBvh(tris, medianOptions);
    checkStructure(tris, sah, gpu::kBvhMaxLeafSize);
    checkStructure(tris, median, gpu::kBvhMaxLeafSize);
    const double sahTree = sahCost(sah);
    const double medianTree = sahCost(median);
    RecordProperty("sah_cost", std::to_string(sahTree));
    RecordProperty("median_cost", std::to_string(medianTree));
    EXPECT_LT(sahTree, 0.8 * medianTree) << "SAH " << sahTree << " vs median " << medianTree;
}

}  // namespace
}  // namespace vkp
