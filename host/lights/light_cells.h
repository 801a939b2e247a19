// --light-sampler photon (Keller & Wald 2000, section 3): the lights whose primary photons arrive in
// each spatial cell, weighted by the power they deliver there, kept as a top-K distribution per
// cell in the light-selection buffer (shared/light_selection.glsl, lightCellsStart). Next-event
// estimation mixes it with the light BVH at a floor probability, so lights whose photons never
// reach a cell are still chosen there (unbiased), and cells without photons use the BVH alone.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "lights/light_tree.h"
#include "lights/light_reach.h"
#include "shared/photon.glsl"

namespace vkp {

class GpuScene;

struct LightCellStats {
    uint64_t photons = 0;          // primary photons binned
    uint32_t cells = 0;            // cells holding candidates (after hash collisions)
    uint32_t buckets = 0;          // table size
    double meanCandidates = 0.0;   // lights per occupied cell
    uint64_t bytes = 0;            // the table in the light-selection buffer
    float cellSize = 0.0f;
    double seconds = 0.0;          // photon tracing and table build
    bool sameBuffer = true;        // uploaded into the scene's light-selection buffer in place
};

// Replaces the cell table at the end of `data` (a SceneArrays::lightCdf of lightCount lights) by
// the cells of `photons` (primary photons; their power is relative, as stored).
LightCellStats buildLightCells(std::vector<float>& data, uint32_t lightCount, std::span<const gpu::GpuPhoton> photons,
                               float cellSize, uint32_t k, float floorProbability);

// Traces sampling.cellPhotons photon paths in the scene as it is now (instances and punctual
// lights where they last moved), keeps their primary photons and uploads the cells into the
// scene's light-selection buffer (GpuScene::replaceLightSelection: in place when they fit).
// With `reach`, also keeps which lights reach which cells (lights/light_reach.h).
LightCellStats prepareLightCells(GpuScene& scene, const LightSampling& sampling, LightReach* reach = nullptr);

}  // namespace vkp
