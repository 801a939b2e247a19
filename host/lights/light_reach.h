// Which lights' primary photons arrive in which cells of the photon light cells' grid (all of them,
// not only the K strongest), and from that the lights that can reach the region the camera sees:
// --direct raster skips the shadow volumes of the others (Keller & Wald 2000, section 3).
// The test is statistical: a light whose photons miss every visible cell (and its neighbours) is
// taken as unable to light it, so its direct light there is dropped; docs/light-sampling.md
// gives the measured cost in time and image difference.
#pragma once

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "gpu_scene/scene_buffers.h"
#include "shared/photon.glsl"

namespace vkp {

struct LightReach {
    float cellSize = 0.0f;
    uint32_t lightCount = 0;
    // Cell key (gridCell packed by cellKey) -> sorted light indices whose primary photons arrived.
    std::unordered_map<uint64_t, std::vector<uint32_t>> lightsOfCell;
};

LightReach buildLightReach(std::span<const gpu::GpuPhoton> photons, uint32_t lightCount, float cellSize);

// Per light of arrays.lights: whether it may light what the camera sees. A grid of `rays` x `rays`
// camera rays (traced on the host) finds the visible cells; a light counts when its photons reached
// one of them or a neighbouring cell (3 x 3 x 3). Lights of other types than emissive triangles and
// point and spot lights (directional, environment) always count.
std::vector<bool> lightsReachingView(const SceneArrays& arrays, const LightReach& reach, const gpu::GpuCamera& camera,
                                     uint32_t width, uint32_t height, uint32_t rays = 64);

}  // namespace vkp
