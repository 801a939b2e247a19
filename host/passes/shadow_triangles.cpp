#include "passes/shadow_triangles.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <tuple>

namespace vkp {
namespace {

struct EdgeUse {
    uint32_t triangle;
    uint32_t edge;      // 0: v0v1, 1: v1v2, 2: v2v0
    bool forward;       // the triangle walks the edge from the lower to the higher vertex id
};

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

}  // namespace

ShadowTriangles buildShadowTriangles(const std::vector<gpu::GpuTriangle>& triangles) {
    const uint32_t count = static_cast<uint32_t>(triangles.size());
    // Weld by exact position: glTF meshes share vertices through indices, so shared corners have
    // bit-identical positions after the (deterministic) world transform.
    std::map<std::tuple<float, float, float>, uint32_t> ids;
    std::vector<std::array<uint32_t, 3>> corners(count);
    for (uint32_t t = 0; t < count; ++t) {
        const glm::vec4 v[3] = {triangles[t].v0, triangles[t].v1, triangles[t].v2};
        for (int k = 0; k < 3; ++k) {
            const auto key = std::make_tuple(v[k].x, v[k].y, v[k].z);
            corners[t][k] = ids.emplace(key, static_cast<uint32_t>(ids.size())).first->second;
        }
    }
    std::map<std::pair<uint32_t, uint32_t>, std::vector<EdgeUse>> edges;
    for (uint32_t t = 0; t < count; ++t)
        for (uint32_t e = 0; e < 3; ++e) {
            const uint32_t a = corners[t][e], b = corners[t][(e + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back({t, e, a < b});
        }

    ShadowTriangles out;
    out.triangles.resize(count);
    std::vector<uint32_t> parent(count);
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<bool> bad(count, false);
    for (uint32_t t = 0; t < count; ++t) {
        auto& s = out.triangles[t];
        s.v0 = glm::vec4(glm::vec3(triangles[t].v0), 1.0f);
        s.v1 = glm::vec4(glm::vec3(triangles[t].v1), 1.0f);
        s.v2 = glm::vec4(glm::vec3(triangles[t].v2), 1.0f);
        s.neighbor0 = s.neighbor1 = s.neighbor2 = gpu::kShadowNoNeighbor;
        // A triangle with a repeated corner has a zero-length edge: no well-defined neighbours.
        if (corners[t][0] == corners[t][1] || corners[t][1] == corners[t][2] || corners[t][2] == corners[t][0])
            bad[t] = true;
    }
    for (const auto& [key, uses] : edges) {
        const bool manifold = uses.size() == 2 && uses[0].forward != uses[1].forward &&
                              uses[0].triangle != uses[1].triangle;
        if (!manifold) {
            for (const EdgeUse& u : uses) bad[u.triangle] = true;
            continue;
        }
        for (int k = 0; k < 2; ++k) {
            const EdgeUse& u = uses[k];
            const uint32_t other = uses[1 - k].triangle;
            auto& s = out.triangles[u.triangle];
            (u.edge == 0 ? s.neighbor0 : u.edge == 1 ? s.neighbor1 : s.neighbor2) = other;
        }
        parent[findRoot(parent, uses[0].triangle)] = findRoot(parent, uses[1].triangle);
    }
    // A component is closed only if none of its triangles touches a non-manifold edge.
    std::vector<bool> badRoot(count, false);
    for (uint32_t t = 0; t < count; ++t)
        if (bad[t]) badRoot[findRoot(parent, t)] = true;
    for (uint32_t t = 0; t < count; ++t) {
        auto& s = out.triangles[t];
        const bool closed = !badRoot[findRoot(parent, t)];
        s.closed = closed ? 1u : 0u;
        if (!closed) s.neighbor0 = s.neighbor1 = s.neighbor2 = gpu::kShadowNoNeighbor;
        ++(closed ? out.closedTriangles : out.openTriangles);
    }
    return out;
}

}  // namespace vkp
