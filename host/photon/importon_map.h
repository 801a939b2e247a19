// The importon map (Keller & Wald 2000, §2.2; Peter & Pietrek 1998): camera paths traced on the
// GPU (shaders/photon/importon_trace.comp) store importons at the surfaces they meet, where the renderer
// reads photon maps, and add them to a multi-level importance grid (shaders/photon/importance_splat.comp,
// shared/importance.glsl). It tells photon deposition (photon/photon_deposit.h) how much the
// camera cares about a point: the importance density for Keller & Wald's probability, the path
// importance for Suykens & Willems' required density.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "shared/importance.glsl"
#include "shared/photon.glsl"
#include "vk/buffer.h"

namespace vkp {

struct ImportonSettings {
    uint32_t paths = 1u << 16;   // --importons: camera paths traced
    uint32_t maxDeposits = 2;    // importons stored per path at most: where the renderer reads photon
                                 // maps (the visible point, a final gather ray's hit)
    uint32_t maxDepth = 12;      // bounces per path, delta ones included
    uint32_t k = 8;              // importons a grid cell needs to give the importance (Keller & Wald's n nearest)
    uint32_t testRays = 1024;    // camera rays sensing the importance that sets f
    uint32_t seed = 0;
};

struct ImportonStats {
    uint64_t stored = 0;
    float cellSize = 0.0f;            // of the importance grid's finest level
    uint32_t tableSize = 0;           // importance grid entries
    float importanceScale = 0.0f;     // f: 1 / the least importance density a test ray sensed
    float medianPathImportance = 0.0f;  // over importons seen through a bounce (Suykens & Willems)
    double seconds = 0.0;
};

class ImportonMap {
public:
    // Importons for `camera` looking at a width x height image (its aspect ratio).
    ImportonMap(vk::Context& context, const SceneArrays& arrays, const SceneBuffers& buffers,
                const gpu::GpuCamera& camera, uint32_t width, uint32_t height, const ImportonSettings& settings);

    const vk::Buffer& table() const { return m_table; }
    // What photon deposition's importance lookup needs for a map keeping the photons with the
    // required and none of the rejected flags (slotCount set by the caller).
    gpu::ImportanceGridParams lookupParams(uint32_t requiredFlags = 0, uint32_t rejectedFlags = 0) const;
    const ImportonStats& stats() const { return m_stats; }
    uint64_t bytes() const { return m_slots.size() + m_table.size(); }
    // The importons, slot by slot (empty slots have no kImportonValid flag).
    std::vector<gpu::GpuImporton> downloadImportons() const { return m_slots.download<gpu::GpuImporton>(); }

private:
    void buildTable(vk::Context& context);
    float estimateImportanceScale(vk::Context& context, const std::vector<gpu::GpuImporton>& importons) const;

    ImportonSettings m_settings;
    ImportonStats m_stats;
    vk::Buffer m_slots;
    vk::Buffer m_table;
};

// A cell size for a hash grid over `points` such that a point's cell holds about k points on
// average over the points (they cluster where the camera looks, so the scene's area says
// little): refines the even-spread radius over `area` by the occupancy of its cells.
float occupancyCellSize(const std::vector<glm::vec3>& points, uint32_t k, double area);

}  // namespace vkp
