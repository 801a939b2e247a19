#include "lights/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "shared/light_selection.glsl"
#include "util/check_range.h"
#include "util/errors.h"

namespace vkp {
namespace {

using glm::vec3;

// A node's bounds while building: box, power, emission cone (axis, cos theta_o), spread cos theta_e.
struct Bounds {
    vec3 lo{0.0f};
    vec3 hi{0.0f};
    double power = 0.0;
    vec3 axis{0.0f, 0.0f, 1.0f};
    float cosThetaO = 1.0f;
    float cosThetaE = 1.0f;
    bool twoSided = false;
    vec3 centre() const { return 0.5f * (lo + hi); }
};

float angleBetween(vec3 a, vec3 b) {
    const float d = glm::dot(a, b);
    if (d < 0.0f) return gpu::kPi - 2.0f * std::asin(std::min(glm::length(a + b) * 0.5f, 1.0f));
    return 2.0f * std::asin(std::min(glm::length(b - a) * 0.5f, 1.0f));
}

// The smallest cone holding both cones (pbrt-v4's DirectionCone Union).
void unionCone(vec3 aw, float aCos, vec3 bw, float bCos, vec3& w, float& cosTheta) {
    const float thetaA = std::acos(std::clamp(aCos, -1.0f, 1.0f));
    const float thetaB = std::acos(std::clamp(bCos, -1.0f, 1.0f));
    const float thetaD = angleBetween(aw, bw);
    if (std::min(thetaD + thetaB, gpu::kPi) <= thetaA) { w = aw; cosTheta = aCos; return; }
    if (std::min(thetaD + thetaA, gpu::kPi) <= thetaB) { w = bw; cosTheta = bCos; return; }
    const float thetaO = 0.5f * (thetaA + thetaD + thetaB);
    const vec3 wr = glm::cross(aw, bw);
    if (thetaO >= gpu::kPi || glm::dot(wr, wr) == 0.0f) { w = vec3(0.0f, 0.0f, 1.0f); cosTheta = -1.0f; return; }
    const float thetaR = thetaO - thetaA;
    const vec3 k = glm::normalize(wr);  // perpendicular to aw: Rodrigues without the k(k.v) term
    w = glm::normalize(aw * std::cos(thetaR) + glm::cross(k, aw) * std::sin(thetaR));
    cosTheta = std::cos(thetaO);
}

Bounds unite(const Bounds& a, const Bounds& b) {
    if (a.power <= 0.0) return b;
    if (b.power <= 0.0) return a;
    Bounds u;
    u.lo = glm::min(a.lo, b.lo);
    u.hi = glm::max(a.hi, b.hi);
    u.power = a.power + b.power;
    unionCone(a.axis, a.cosThetaO, b.axis, b.cosThetaO, u.axis, u.cosThetaO);
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;
    return u;
}

// The orientation measure M_Omega of Conty Estevez & Kulla (solid angle weighted by cosine).
double orientationMeasure(const Bounds& b) {
    const double thetaO = std::acos(std::clamp<double>(b.cosThetaO, -1.0, 1.0));
    const double thetaE = std::acos(std::clamp<double>(b.cosThetaE, -1.0, 1.0));
    const double thetaW = std::min(thetaO + thetaE, double(gpu::kPi));
    const double sinO = std::sin(thetaO);
    return 2.0 * gpu::kPi * (1.0 - std::cos(thetaO)) +
           gpu::kPi / 2.0 * (2.0 * thetaW * sinO - std::cos(thetaO - 2.0 * thetaW) - 2.0 * thetaO * sinO + std::cos(thetaO));
}

double surfaceArea(const Bounds& b) {
    const vec3 d = b.hi - b.lo;
    return 2.0 * (double(d.x) * d.y + double(d.y) * d.z + double(d.z) * d.x);
}

// The surface area orientation heuristic cost of a child (pbrt-v4's EvaluateCost).
double cost(const Bounds& b, const Bounds& parent, int axis) {
    const vec3 d = parent.hi - parent.lo;
    const float maxExtent = std::max(d.x, std::max(d.y, d.z));
    const double kr = d[axis] > 0.0f ? maxExtent / d[axis] : 1.0;
    return kr * b.power * orientationMeasure(b) * std::max(surfaceArea(b), 1e-12);
}

bool isTreeLight(uint32_t type) {
    return type == gpu::kLightTriangle || type == gpu::kLightPoint || type == gpu::kLightSpot;
}

Bounds lightBounds(const gpu::GpuLight& l, std::span<const gpu::GpuTriangle> triangles,
                   std::span<const gpu::GpuTriangleShading> shading, std::span<const gpu::GpuMaterial> materials,
                   double power) {
    Bounds b;
    b.power = power;
    b.cosThetaE = 0.0f;  // cos(pi / 2): each emitter lights a hemisphere around its cone
    if (l.type == gpu::kLightTriangle) {
        const gpu::GpuTriangle& t = triangles[l.triangle];
        const vec3 v0(t.v0), v1(t.v1), v2(t.v2);
        b.lo = glm::min(v0, glm::min(v1, v2));
        b.hi = glm::max(v0, glm::max(v1, v2));
        b.axis = glm::normalize(glm::cross(v1 - v0, v2 - v0));
        b.cosThetaO = 1.0f;
        b.twoSided = (materials[shading[l.triangle].material].flags & gpu::kMaterialDoubleSided) != 0u;
    } else if (l.type == gpu::kLightSpot) {
        b.lo = b.hi = l.position;
        b.axis = l.direction;
        // Full intensity inside cos >= (1 - offset) / scale, none outside cos <= -offset / scale.
        const float cosInner = std::clamp((1.0f - l.spotOffset) / l.spotScale, -1.0f, 1.0f);
        const float cosOuter = std::clamp(-l.spotOffset / l.spotScale, -1.0f, 1.0f);
        b.cosThetaO = cosInner;
        b.cosThetaE = std::cos(std::max(0.0f, std::acos(cosOuter) - std::acos(cosInner)));
    } else {  // point
        b.lo = b.hi = l.position;
        b.cosThetaO = -1.0f;
    }
    return b;
}

struct Builder {
    std::vector<Bounds> bounds;  // per light
    LightTree tree;

    void setNode(uint32_t index, const Bounds& b, uint32_t childOrLight, uint32_t flags) {
        gpu::GpuLightNode& n = tree.nodes[index];
        n.boundsMin = b.lo;
        n.boundsMax = b.hi;
        n.power = static_cast<float>(b.power);
        n.axis = b.axis;
        n.cosThetaO = b.cosThetaO;
        n.cosThetaE = b.cosThetaE;
        n.childOrLight = childOrLight;
        n.flags = flags | (b.twoSided ? gpu::kLightNodeTwoSided : 0u);
    }

    // Splits ids[begin, end) and returns the position of the split.
    size_t split(std::vector<uint32_t>& ids, size_t begin, size_t end, const Bounds& all, bool median) {
        vec3 cLo(std::numeric_limits<float>::max()), cHi(-std::numeric_limits<float>::max());
        for (size_t i = begin; i < end; ++i) {
            cLo = glm::min(cLo, bounds[ids[i]].centre());
            cHi = glm::max(cHi, bounds[ids[i]].centre());
        }
        const vec3 extent = cHi - cLo;
        const int longest = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
        auto medianSplit = [&] {
            const size_t mid = (begin + end) / 2;
            std::nth_element(ids.begin() + begin, ids.begin() + mid, ids.begin() + end, [&](uint32_t a, uint32_t b) {
                return bounds[a].centre()[longest] < bounds[b].centre()[longest];
            });
            return mid;
        };
        if (median || extent[longest] <= 0.0f) return medianSplit();
        constexpr int kBins = 12;
        double bestCost = std::numeric_limits<double>::infinity();
        int bestAxis = -1;
        int bestBin = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (extent[axis] <= 0.0f) continue;
            std::array<Bounds, kBins> bins{};
            auto binOf = [&](uint32_t id) {
                const int k = int(kBins * (bounds[id].centre()[axis] - cLo[axis]) / extent[axis]);
                return std::clamp(k, 0, kBins - 1);
            };
            for (size_t i = begin; i < end; ++i) bins[binOf(ids[i])] = unite(bins[binOf(ids[i])], bounds[ids[i]]);
            for (int s = 0; s < kBins - 1; ++s) {
                Bounds left, right;
                for (int k = 0; k <= s; ++k) left = unite(left, bins[k]);
                for (int k = s + 1; k < kBins; ++k) right = unite(right, bins[k]);
                if (left.power <= 0.0 || right.power <= 0.0) continue;
                const double c = cost(left, all, axis) + cost(right, all, axis);
                if (c < bestCost) { bestCost = c; bestAxis = axis; bestBin = s; }
            }
        }
        if (bestAxis < 0) return medianSplit();
        const auto mid = std::partition(ids.begin() + begin, ids.begin() + end, [&](uint32_t id) {
            const int k = int(kBins * (bounds[id].centre()[bestAxis] - cLo[bestAxis]) / extent[bestAxis]);
            return std::clamp(k, 0, kBins - 1) <= bestBin;
        });
        const size_t m = size_t(mid - ids.begin());
        if (m == begin || m == end) return medianSplit();
        return m;
    }

    uint32_t build(std::vector<uint32_t>& ids, size_t begin, size_t end, uint32_t trail, uint32_t depth) {
        const uint32_t index = static_cast<uint32_t>(tree.nodes.size());
        tree.nodes.push_back({});
        tree.depth = std::max(tree.depth, depth);
        if (end - begin == 1) {
            const uint32_t light = ids[begin];
            tree.trails[light] = trail;
            setNode(index, bounds[light], light, gpu::kLightNodeLeaf);
            return index;
        }
        Bounds all;
        for (size_t i = begin; i < end; ++i) all = unite(all, bounds[ids[i]]);
        // Keep every leaf within kLightTreeMaxDepth - 1 (its path fits a uint): median splits
        // once the remaining depth only just suffices for a balanced tree.
        const uint32_t balancedDepth = static_cast<uint32_t>(std::ceil(std::log2(double(end - begin))));
        const bool median = depth + balancedDepth + 2 >= gpu::kLightTreeMaxDepth;
        const size_t mid = split(ids, begin, end, all, median);
        build(ids, begin, mid, trail, depth + 1);
        const uint32_t second = build(ids, mid, end, trail | (1u << depth), depth + 1);
        setNode(index, all, second, 0u);
        return index;
    }
};

float bitsFloat(uint32_t u) {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

}  // namespace


LightTree buildLightTree(std::span<const gpu::GpuLight> lights, std::span<const gpu::GpuTriangle> triangles,
                         std::span<const gpu::GpuTriangleShading> shading, std::span<const gpu::GpuMaterial> materials,
                         std::span<const double> power) {
    Builder b;
    b.tree.trails.assign(lights.size(), 0u);
    b.bounds.resize(lights.size());
    std::vector<uint32_t> ids;
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (!isTreeLight(lights[i].type)) {
            b.tree.infinite.push_back(i);
            continue;
        }
        b.bounds[i] = lightBounds(lights[i], triangles, shading, materials, power[i]);
        ids.push_back(i);
    }
    if (!ids.empty()) b.build(ids, 0, ids.size(), 0u, 0u);
    return b.tree;
}

LightTreeStats appendLightSelection(std::vector<float>& data, const LightTree& tree, uint32_t lightCount,
                                    LightSampling sampling) {
    data.resize(lightCount);
    const uint32_t mode = sampling.sampler == LightSampler::Bvh      ? gpu::kLightSamplerBvh
                          : sampling.sampler == LightSampler::Photon ? gpu::kLightSamplerPhoton
                                                                     : gpu::kLightSamplerPower;
    data.push_back(bitsFloat(mode));
    data.push_back(bitsFloat(static_cast<uint32_t>(tree.nodes.size())));
    data.push_back(bitsFloat(static_cast<uint32_t>(tree.infinite.size())));
    data.push_back(bitsFloat(sampling.triangles == TriangleSampling::Area ? 1u : 0u));
    for (uint32_t i = 0; i < lightCount; ++i) data.push_back(bitsFloat(i < tree.trails.size() ? tree.trails[i] : 0u));
    for (uint32_t id : tree.infinite) data.push_back(bitsFloat(id));
    for (const gpu::GpuLightNode& n : tree.nodes) {
        const size_t o = data.size();
        data.resize(o + gpu::kLightNodeFloats);
        std::memcpy(&data[o], &n, sizeof n);
    }
    // An empty photon cell table (one empty bucket): --light-sampler photon falls back to the light
    // BVH until render/light_cells replaces it with the cells its photons found.
    const float empty[] = {0.0f, bitsFloat(0u), bitsFloat(1u), 1.0f, 0.0f, 0.0f, 0.0f, bitsFloat(0u), 0.0f, 0.0f};
    data.insert(data.end(), std::begin(empty), std::end(empty));
    LightTreeStats s;
    s.nodes = static_cast<uint32_t>(tree.nodes.size());
    s.infiniteLights = static_cast<uint32_t>(tree.infinite.size());
    s.treeLights = lightCount - s.infiniteLights;
    s.depth = tree.depth;
    s.bytes = (data.size() - lightCount) * sizeof(float);
    return s;
}

}  // namespace vkp
