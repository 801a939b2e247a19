// Importance-driven deposition set up from --deposit and its flags (photon/deposit_options.h):
// the importon map for the frame's camera and the settings a photon map's deposit pass takes.
// Shared by the photon integrators and `vkphoton photons`.
#pragma once

#include <memory>

#include "gpu_scene/gpu_scene.h"
#include "photon/deposit_options.h"
#include "render/frame.h"
#include "photon/importon_map.h"
#include "photon/photon_map.h"
#include "render/stats.h"

namespace vkp {

// The importon pass for the frame's camera and image, or null when every photon is kept.
std::unique_ptr<ImportonMap> makeImportonMap(const GpuScene& scene, const Frame& frame, const DepositOptions& options);

// "photons.importonsStored", "photons.importonBytes", "photons.importanceScale" and the
// importon pass's seconds added to "photons.seconds" (importons may be null).
void reportImportons(Stats& stats, const ImportonMap* importons);

DepositSettings depositSettings(const DepositOptions& options, DepositMode mode, const ImportonMap* importons);

// Density control's map cells: the radius holding k photons at the median required density.
float densityCellSize(const DepositOptions& options, uint32_t k, const ImportonMap& importons);

}  // namespace vkp
