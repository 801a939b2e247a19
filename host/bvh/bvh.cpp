#include "bvh/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "shared/bvh_traverse.glsl"
#include "shared/intersect.glsl"

namespace vkp {
namespace {
// Node boxes are padded outward by at least this and one ulp, so that no triangle touches a box
// face: a ray with a zero direction component running exactly in a face plane would otherwise be
// culled by the slab test (see safeInverseDirection in shaders/shared/intersect.glsl). Padding is
// monotone in the coordinate, so a child box stays inside its parent's.
constexpr float kBoxPadding = 1.0e-20f;
}  // namespace

glm::vec3 padBoxMin(glm::vec3 v) {
    for (int k = 0; k < 3; ++k) v[k] = std::nextafter(v[k] - kBoxPadding, -std::numeric_limits<float>::infinity());
    return v;
}

glm::vec3 padBoxMax(glm::vec3 v) {
    for (int k = 0; k < 3; ++k) v[k] = std::nextafter(v[k] + kBoxPadding, std::numeric_limits<float>::infinity());
    return v;
}

namespace {

// Wald 2007 finds 16-32 bins within a few percent of the full sweep SAH; 16 is the cheaper end.
constexpr int kBins = 16;

glm::vec3 padDown(glm::vec3 v) { return padBoxMin(v); }
glm::vec3 padUp(glm::vec3 v) { return padBoxMax(v); }

// Half the surface area; only ratios of areas are used.
float halfArea(const Bounds& b) {
    if (b.empty()) return 0.0f;
    const glm::vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

// A primitive as the builder sees it; the array of these is reordered in place so the binning
// passes stream through memory instead of chasing indices.
struct PrimRef {
    glm::vec3 min;
    glm::vec3 max;
    glm::vec3 centroid;
    uint32_t index;
};

struct Task {
    uint32_t node;
    uint32_t begin;
    uint32_t end;
    uint32_t depth;  // of this node, root = 1
    Bounds bounds;
    Bounds centroidBounds;
};

struct Bin {
    Bounds bounds;
    Bounds centroidBounds;
    uint32_t count = 0;
};

// Bin of a centroid coordinate. NaN (possible only for non-finite input) lands in bin 0 instead of
// being converted to int, which would be undefined.
int binIndex(float c, float lo, float scale) {
    const float f = (c - lo) * scale;
    return f > 0.0f ? static_cast<int>(std::min(f, static_cast<float>(kBins - 1))) : 0;
}

int largestAxis(const glm::vec3& e) {
    return e.x >= e.y ? (e.x >= e.z ? 0 : 2) : (e.y >= e.z ? 1 : 2);
}

// Levels a subtree over `count` primitives needs below its root when every split halves the
// count: the smallest k with maxLeaf * 2^k >= count.
uint32_t balancedLevels(uint32_t count, uint32_t maxLeaf) {
    uint32_t k = 0;
    uint64_t capacity = maxLeaf;
    while (capacity < count) {
        capacity *= 2;
        ++k;
    }
    return k;
}

class Builder {
public:
    Builder(std::span<const Bounds> primitiveBounds, const BvhBuildOptions& options) : m_options(options) {
        if (m_options.maxLeafSize == 0) throw std::invalid_argument("BVH maxLeafSize must be at least 1");
        m_options.maxDepth = std::clamp(m_options.maxDepth, 1u, gpu::kBvhMaxDepth);
        if (primitiveBounds.size() >= std::numeric_limits<uint32_t>::max() / 2)
            throw std::length_error("BVH: too many primitives for 32-bit node indices");
        m_refs.resize(primitiveBounds.size());
        for (size_t i = 0; i < primitiveBounds.size(); ++i) {
            PrimRef& r = m_refs[i];
            r.min = primitiveBounds[i].min;
            r.max = primitiveBounds[i].max;
            r.centroid = 0.5f * (r.min + r.max);
            r.index = static_cast<uint32_t>(i);
        }
    }

    Bvh build() {
        Bvh bvh;
        const auto count = static_cast<uint32_t>(m_refs.size());
        if (count == 0) {
            gpu::GpuBvhNode empty{};
            empty.boundsMin = glm::vec3(0.0f);
            empty.boundsMax = glm::vec3(0.0f);
            empty.leftOrFirst = 0;
            empty.count = 0;
            bvh.nodes.push_back(empty);
            bvh.depth = 1;
            return bvh;
        }
        Task root{0, 0, count, 1, {}, {}};
        for (const PrimRef& r : m_refs) {
            root.bounds.grow(r.min);
            root.bounds.grow(r.max);
            root.centroidBounds.grow(r.centroid);
        }
        m_nodes.reserve(2 * size_t(count) - 1);
        m_nodes.emplace_back();
        // Explicit LIFO instead of recursion: the left child is built first, so each subtree's
        // node pairs are contiguous (depth-first layout, good locality for near-first traversal).
        std::vector<Task> tasks{root};
        while (!tasks.empty()) {
            const Task task = tasks.back();
            tasks.pop_back();
            m_depth = std::max(m_depth, task.depth);
            process(task, tasks);
        }
        bvh.nodes = std::move(m_nodes);
        bvh.depth = m_depth;
        bvh.triangleOrder.resize(count);
        for (uint32_t i = 0; i < count; ++i) bvh.triangleOrder[i] = m_refs[i].index;
        return bvh;
    }

private:
    struct Split {
        uint32_t mid = 0;
        Bounds leftBounds, leftCentroids, rightBounds, rightCentroids;
    };

    void process(const Task& task, std::vector<Task>& tasks) {
        gpu::GpuBvhNode& node = m_nodes[task.node];
        node.boundsMin = padDown(task.bounds.min);
        node.boundsMax = padUp(task.bounds.max);
        const uint32_t count = task.end - task.begin;
        const uint32_t maxLeaf = m_options.maxLeafSize;

        Split split;
        bool haveSplit = false;
        if (count > 1 && task.depth < m_options.maxDepth) {
            // Depth budget: once SAH splits could leave too few levels for balanced splits to
            // reach leaves of maxLeaf, split by count (each child then needs one level fewer).
            const bool depthBound = task.depth + balancedLevels(count, maxLeaf) >= m_options.maxDepth;
            if (m_options.split == BvhBuildOptions::Split::Median || depthBound) {
                if (count > maxLeaf || depthBound) haveSplit = medianSplit(task, split);
            } else {
                haveSplit = sahSplit(task, split);
            }
            // Coincident centroids (no binned split) but too many primitives for one leaf.
            if (!haveSplit && count > maxLeaf) haveSplit = countSplit(task, split);
        }
        if (!haveSplit) {
            node.leftOrFirst = task.begin;
            node.count = count;
            return;
        }
        const auto left = static_cast<uint32_t>(m_nodes.size());
        m_nodes.emplace_back();
        m_nodes.emplace_back();
        m_nodes[task.node].leftOrFirst = left;  // `node` may dangle after emplace_back
        m_nodes[task.node].count = 0;
        tasks.push_back({left + 1, split.mid, task.end, task.depth + 1, split.rightBounds, split.rightCentroids});
        tasks.push_back({left, task.begin, split.mid, task.depth + 1, split.leftBounds, split.leftCentroids});
    }

    // Binned SAH (Wald 2007, section 3): bin centroids into kBins slabs per axis, sweep the
    // kBins - 1 planes between bins, and take the cheapest of
    //   C_split = C_trav + (A_left N_left + A_right N_right) / A_parent      (C_tri = 1)
    // over all three axes; keep a leaf (cost N) if that is cheaper and fits in maxLeafSize.
    bool sahSplit(const Task& task, Split& out) {
        const uint32_t count = task.end - task.begin;
        const glm::vec3 lo = task.centroidBounds.min;
        const glm::vec3 extent = task.centroidBounds.extent();
        const float parentArea = halfArea(task.bounds);

        float bestCost = std::numeric_limits<float>::max();
        int bestAxis = -1;
        int bestPlane = -1;  // split after bin bestPlane
        std::array<Bin, kBins> bestBins;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(extent[axis] > 0.0f)) continue;
            const float scale = kBins / extent[axis];
            std::array<Bin, kBins> bins;
            for (uint32_t i = task.begin; i < task.end; ++i) {
                const PrimRef& r = m_refs[i];
                Bin& bin = bins[binIndex(r.centroid[axis], lo[axis], scale)];
                bin.bounds.grow(r.min);
                bin.bounds.grow(r.max);
                bin.centroidBounds.grow(r.centroid);
                ++bin.count;
            }
            // Right-to-left prefix: area * count of everything right of plane p.
            std::array<float, kBins - 1> rightCost{};
            Bounds acc;
            uint32_t n = 0;
            for (int p = kBins - 2; p >= 0; --p) {
                acc.grow(bins[p + 1].bounds);
                n += bins[p + 1].count;
                rightCost[p] = halfArea(acc) * static_cast<float>(n);
            }
            acc = Bounds{};
            n = 0;
            for (int p = 0; p < kBins - 1; ++p) {
                acc.grow(bins[p].bounds);
                n += bins[p].count;
                if (n == 0 || n == count) continue;  // one side empty: not a split
                const float cost = halfArea(acc) * static_cast<float>(n) + rightCost[p];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestPlane = p;
                    bestBins = bins;
                }
            }
        }
        if (bestAxis < 0) return false;
        const float splitCost = m_options.traversalCost +
                                (parentArea > 0.0f ? bestCost / parentArea : static_cast<float>(count));
        if (count <= m_options.maxLeafSize && splitCost >= static_cast<float>(count)) return false;

        const float scale = kBins / extent[bestAxis];
        const float axisLo = lo[bestAxis];
        out.mid = partition(task.begin, task.end, [&](const PrimRef& r) {
            return binIndex(r.centroid[bestAxis], axisLo, scale) <= bestPlane;
        });
        for (int b = 0; b < kBins; ++b) {
            Bounds& bounds = b <= bestPlane ? out.leftBounds : out.rightBounds;
            Bounds& centroids = b <= bestPlane ? out.leftCentroids : out.rightCentroids;
            bounds.grow(bestBins[b].bounds);
            centroids.grow(bestBins[b].centroidBounds);
        }
        return true;
    }

    // Splits at the median centroid along the largest centroid axis (ties by input index, so the
    // result does not depend on the standard library's nth_element).
    bool medianSplit(const Task& task, Split& out) {
        const int axis = largestAxis(task.centroidBounds.extent());
        const uint32_t mid = task.begin + (task.end - task.begin) / 2;
        std::nth_element(m_refs.begin() + task.begin, m_refs.begin() + mid, m_refs.begin() + task.end,
                         [axis](const PrimRef& a, const PrimRef& b) {
                             return a.centroid[axis] < b.centroid[axis] ||
                                    (a.centroid[axis] == b.centroid[axis] && a.index < b.index);
                         });
        out.mid = mid;
        boundsOfHalves(task, out);
        return true;
    }

    // Coincident centroids: no plane separates them, so split in the middle of the range.
    bool countSplit(const Task& task, Split& out) {
        out.mid = task.begin + (task.end - task.begin) / 2;
        boundsOfHalves(task, out);
        return true;
    }

    void boundsOfHalves(const Task& task, Split& out) const {
        for (uint32_t i = task.begin; i < task.end; ++i) {
            const PrimRef& r = m_refs[i];
            Bounds& bounds = i < out.mid ? out.leftBounds : out.rightBounds;
            Bounds& centroids = i < out.mid ? out.leftCentroids : out.rightCentroids;
            bounds.grow(r.min);
            bounds.grow(r.max);
            centroids.grow(r.centroid);
        }
    }

    // In-place two-way partition with a fixed, library-independent order (determinism).
    template <typename GoesLeft>
    uint32_t partition(uint32_t begin, uint32_t end, GoesLeft goesLeft) {
        uint32_t i = begin;
        uint32_t j = end;
        while (i < j) {
            if (goesLeft(m_refs[i])) {
                ++i;
            } else {
                --j;
                std::swap(m_refs[i], m_refs[j]);
            }
        }
        return i;
    }

    BvhBuildOptions m_options;
    std::vector<PrimRef> m_refs;
    std::vector<gpu::GpuBvhNode> m_nodes;
    uint32_t m_depth = 0;
};

bool isEmptyTree(const Bvh& bvh) {
    return bvh.nodes.empty() || gpu::bvhIsEmptyRoot(bvh.nodes[0]);
}

}  // namespace

Bvh buildBvh(std::span<const Bounds> primitiveBounds, const BvhBuildOptions& options) {
    return Builder(primitiveBounds, options).build();
}

Bvh buildBvh(std::span<const Triangle> triangles, const BvhBuildOptions& options) {
    std::vector<Bounds> bounds(triangles.size());
    for (size_t i = 0; i < triangles.size(); ++i)
        for (const glm::vec3& p : triangles[i].p) bounds[i].grow(p);
    return buildBvh(std::span<const Bounds>(bounds), options);
}

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

// The traversal is the shaders' own (shaders/shared/bvh_traverse.glsl compiled as C++).
RayHit closestHit(const Bvh& bvh, std::span<const gpu::GpuTriangle> triangles, glm::vec3 org, glm::vec3 dir,
                  float tMax, bool cullBackFaces) {
    RayHit hit;
    hit.t = tMax;
    if (bvh.nodes.empty()) return hit;  // a default-constructed Bvh; built trees have a root
    const gpu::BvhArrays arrays{bvh.nodes, triangles};
    uint32_t triangle = gpu::kBvhNoTriangle;
    hit.hit = gpu::traceClosest(arrays, org, dir, tMax, cullBackFaces, hit.t, triangle, hit.b1, hit.b2);
    if (hit.hit) hit.triangle = triangle;
    return hit;
}

bool anyHit(const Bvh& bvh, std::span<const gpu::GpuTriangle> triangles, glm::vec3 org, glm::vec3 dir,
            float tMax) {
    if (bvh.nodes.empty()) return false;
    const gpu::BvhArrays arrays{bvh.nodes, triangles};
    return gpu::traceAny(arrays, org, dir, tMax);
}

double sahCost(const Bvh& bvh, float traversalCost) {
    return bvhStats(bvh, traversalCost).sahCost;
}

BvhStats bvhStats(const Bvh& bvh, float traversalCost) {
    BvhStats stats;
    stats.nodeCount = static_cast<uint32_t>(bvh.nodes.size());
    stats.depth = bvh.depth;
    if (isEmptyTree(bvh)) return stats;
    auto area = [](const gpu::GpuBvhNode& n) {
        Bounds b;
        b.min = n.boundsMin;
        b.max = n.boundsMax;
        return static_cast<double>(halfArea(b));
    };
    const double rootArea = area(bvh.nodes[0]);
    uint64_t leafTriangles = 0;
    for (const gpu::GpuBvhNode& n : bvh.nodes) {
        const double relativeArea = rootArea > 0.0 ? area(n) / rootArea : 1.0;
        if (n.count > 0) {
            ++stats.leafCount;
            leafTriangles += n.count;
            stats.maxLeafSize = std::max(stats.maxLeafSize, n.count);
            stats.sahCost += relativeArea * n.count;
        } else {
            stats.sahCost += relativeArea * traversalCost;
        }
    }
    stats.averageLeafSize = static_cast<double>(leafTriangles) / stats.leafCount;
    return stats;
}

}  // namespace vkp
