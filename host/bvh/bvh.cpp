#include "bvh/bvh.h"

#include <algorithm>
#include <array>
#include <numeric>

#include "shared/bvh_constants.glsl"
#include "shared/intersect.glsl"

namespace vkp {
namespace {

constexpr int kBins = 16;
constexpr float kTraversalCost = 1.0f;
constexpr float kIntersectionCost = 1.0f;

float surfaceArea(const Bounds& b) {
    if (b.empty()) return 0.0f;
    const glm::vec3 e = b.extent();
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

struct BuildTask {
    uint32_t node;
    uint32_t begin;
    uint32_t end;
    uint32_t depth;
};

class Builder {
public:
    explicit Builder(std::span<const Triangle> triangles) {
        m_bounds.resize(triangles.size());
        m_centroids.resize(triangles.size());
        for (size_t i = 0; i < triangles.size(); ++i) {
            for (const auto& p : triangles[i].p) m_bounds[i].grow(p);
            m_centroids[i] = m_bounds[i].center();
        }
        m_bvh.triangleOrder.resize(triangles.size());
        std::iota(m_bvh.triangleOrder.begin(), m_bvh.triangleOrder.end(), 0u);
    }

    Bvh build() {
        const auto count = static_cast<uint32_t>(m_bounds.size());
        m_bvh.nodes.reserve(std::max<size_t>(1, 2 * size_t(count)));
        m_bvh.nodes.push_back({});
        std::vector<BuildTask> tasks{{0, 0, count, 1}};
        while (!tasks.empty()) {
            const BuildTask task = tasks.back();
            tasks.pop_back();
            split(task, tasks);
        }
        return std::move(m_bvh);
    }

private:
    Bounds rangeBounds(uint32_t begin, uint32_t end, bool centroids) const {
        Bounds b;
        for (uint32_t i = begin; i < end; ++i) {
            const uint32_t t = m_bvh.triangleOrder[i];
            if (centroids) b.grow(m_centroids[t]); else b.grow(m_bounds[t]);
        }
        return b;
    }

    void makeLeaf(const BuildTask& task) {
        gpu::GpuBvhNode& node = m_bvh.nodes[task.node];
        node.leftOrFirst = task.begin;
        // Empty input: a leaf with no triangles is encoded as count 0 + an empty box, which
        // the traversal's root box test rejects.
        node.count = task.end - task.begin;
    }

    void split(const BuildTask& task, std::vector<BuildTask>& tasks) {
        const Bounds bounds = rangeBounds(task.begin, task.end, false);
        gpu::GpuBvhNode& node = m_bvh.nodes[task.node];
        node.boundsMin = bounds.empty() ? glm::vec3(0.0f) : bounds.min;
        node.boundsMax = bounds.empty() ? glm::vec3(-1.0f) : bounds.max;
        m_bvh.depth = std::max(m_bvh.depth, task.depth);
        const uint32_t count = task.end - task.begin;
        if (count <= 1 || task.depth >= gpu::kBvhMaxDepth) { makeLeaf(task); return; }

        const Bounds centroidBounds = rangeBounds(task.begin, task.end, true);
        const glm::vec3 extent = centroidBounds.extent();
        const int axis = extent.x >= extent.y ? (extent.x >= extent.z ? 0 : 2) : (extent.y >= extent.z ? 1 : 2);
        uint32_t mid = task.begin;
        const float leafCost = kIntersectionCost * count;
        if (extent[axis] > 0.0f) {
            std::array<Bounds, kBins> binBounds;
            std::array<uint32_t, kBins> binCounts{};
            const float scale = kBins / extent[axis];
            auto binOf = [&](uint32_t t) {
                return std::min(kBins - 1, static_cast<int>((m_centroids[t][axis] - centroidBounds.min[axis]) * scale));
            };
            for (uint32_t i = task.begin; i < task.end; ++i) {
                const uint32_t t = m_bvh.triangleOrder[i];
                const int b = binOf(t);
                binBounds[b].grow(m_bounds[t]);
                ++binCounts[b];
            }
            // Sweep: cost of splitting after bin s = Ct + (A_L N_L + A_R N_R) / A * Ci.
            std::array<float, kBins - 1> leftArea{}, rightArea{};
            std::array<uint32_t, kBins - 1> leftCount{}, rightCount{};
            Bounds acc;
            uint32_t n = 0;
            for (int s = 0; s < kBins - 1; ++s) {
                acc.grow(binBounds[s]);
                n += binCounts[s];
                leftArea[s] = surfaceArea(acc);
                leftCount[s] = n;
            }
            acc = Bounds{};
            n = 0;
            for (int s = kBins - 1; s > 0; --s) {
                acc.grow(binBounds[s]);
                n += binCounts[s];
                rightArea[s - 1] = surfaceArea(acc);
                rightCount[s - 1] = n;
            }
            const float parentArea = std::max(surfaceArea(bounds), 1e-30f);
            float bestCost = std::numeric_limits<float>::max();
            int bestSplit = -1;
            for (int s = 0; s < kBins - 1; ++s) {
                if (leftCount[s] == 0 || rightCount[s] == 0) continue;
                const float cost = kTraversalCost + kIntersectionCost *
                    (leftArea[s] * leftCount[s] + rightArea[s] * rightCount[s]) / parentArea;
                if (cost < bestCost) { bestCost = cost; bestSplit = s; }
            }
            if (bestSplit >= 0 && (bestCost < leafCost || count > gpu::kBvhMaxLeafSize)) {
                auto* first = m_bvh.triangleOrder.data() + task.begin;
                auto* last = m_bvh.triangleOrder.data() + task.end;
                mid = static_cast<uint32_t>(std::stable_partition(first, last, [&](uint32_t t) {
                          return binOf(t) <= bestSplit;
                      }) - m_bvh.triangleOrder.data());
            } else if (count <= gpu::kBvhMaxLeafSize) {
                makeLeaf(task);
                return;
            }
        } else if (count <= gpu::kBvhMaxLeafSize) {
            makeLeaf(task);
            return;
        }
        if (mid == task.begin || mid == task.end) mid = task.begin + count / 2;  // coincident centroids

        const auto left = static_cast<uint32_t>(m_bvh.nodes.size());
        m_bvh.nodes.push_back({});
        m_bvh.nodes.push_back({});
        m_bvh.nodes[task.node].leftOrFirst = left;
        m_bvh.nodes[task.node].count = 0;
        tasks.push_back({left + 1, mid, task.end, task.depth + 1});
        tasks.push_back({left, task.begin, mid, task.depth + 1});
    }

    std::vector<Bounds> m_bounds;
    std::vector<glm::vec3> m_centroids;
    Bvh m_bvh;
};

}  // namespace

Bvh buildBvh(std::span<const Triangle> triangles) { return Builder(triangles).build(); }

std::vector<gpu::GpuTriangle> gpuTriangles(std::span<const Triangle> triangles, const Bvh& bvh) {
    std::vector<gpu::GpuTriangle> out;
    out.reserve(bvh.triangleOrder.size());
    for (uint32_t index : bvh.triangleOrder) {
        const Triangle& t = triangles[index];
        gpu::GpuTriangle g{};
        g.v0 = glm::vec4(t.p[0], 0.0f);
        g.v1 = glm::vec4(t.p[1], 0.0f);
        g.v2 = glm::vec4(t.p[2], 0.0f);
        out.push_back(g);
    }
    return out;
}

RayHit closestHit(const Bvh& bvh, std::span<const gpu::GpuTriangle> triangles, glm::vec3 org, glm::vec3 dir,
                  float tMax) {
    RayHit hit;
    hit.t = tMax;
    const glm::vec3 invDir = gpu::safeInverseDirection(dir);
    const auto& root = bvh.nodes[0];
    if (gpu::intersectAabb(org, invDir, root.boundsMin, root.boundsMax, hit.t) >= gpu::kInfinity) return hit;
    std::vector<uint32_t> stack{0};
    while (!stack.empty()) {
        const gpu::GpuBvhNode& node = bvh.nodes[stack.back()];
        stack.pop_back();
        if (gpu::intersectAabb(org, invDir, node.boundsMin, node.boundsMax, hit.t) >= gpu::kInfinity) continue;
        if (node.count > 0) {
            for (uint32_t i = node.leftOrFirst; i < node.leftOrFirst + node.count; ++i) {
                float t, b1, b2;
                const auto& tri = triangles[i];
                if (gpu::intersectTriangle(org, dir, glm::vec3(tri.v0), glm::vec3(tri.v1), glm::vec3(tri.v2), hit.t,
                                           t, b1, b2)) {
                    hit = {true, t, i, b1, b2};
                }
            }
        } else {
            stack.push_back(node.leftOrFirst + 1);
            stack.push_back(node.leftOrFirst);
        }
    }
    return hit;
}

double sahCost(const Bvh& bvh) {
    auto area = [](const gpu::GpuBvhNode& n) {
        Bounds b;
        b.min = n.boundsMin;
        b.max = n.boundsMax;
        return double(surfaceArea(b));
    };
    const double rootArea = std::max(area(bvh.nodes[0]), 1e-30);
    double cost = 0.0;
    for (const auto& n : bvh.nodes)
        cost += area(n) / rootArea * (n.count > 0 ? kIntersectionCost * n.count : kTraversalCost);
    return cost;
}

}  // namespace vkp
