// Importance-driven deposition set up from the render settings (--deposit and its flags): the
// importon map for the render's camera and the settings a photon map's deposit pass takes.
// Shared by the photon integrator and `vkphoton photons`.
#pragma once

#include <memory>

#include "render/importon_map.h"
#include "render/photon_map.h"
#include "render/renderer.h"

namespace vkp {

const char* depositModeName(DepositMode mode);

// The importon pass for the render's camera and image, or null when every photon is kept.
std::unique_ptr<ImportonMap> makeImportonMap(vk::Context& context, const Scene& scene, const SceneArrays& arrays,
                                             const SceneBuffers& buffers, const RenderSettings& settings);

// Adds the importon pass's counts, time and memory (importons may be null).
void addImportonStats(RenderStats& stats, const ImportonMap* importons);

DepositSettings depositSettings(const PhotonRenderSettings& photon, DepositMode mode, const ImportonMap* importons);

// Density control's map cells: the radius holding k photons at the median required density.
float densityCellSize(const PhotonRenderSettings& photon, uint32_t k, const ImportonMap& importons);

}  // namespace vkp
