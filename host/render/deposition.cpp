#include "render/deposition.h"

#include <cmath>

#include "util/errors.h"

namespace vkp {
namespace {

uint32_t depositModeCode(DepositMode mode) {
    switch (mode) {
        case DepositMode::Importance: return gpu::kDepositImportance;
        case DepositMode::Density: return gpu::kDepositDensity;
        default: return gpu::kDepositAll;
    }
}

}  // namespace

const char* depositModeName(DepositMode mode) {
    switch (mode) {
        case DepositMode::Importance: return "importance";
        case DepositMode::Density: return "density";
        default: return "all";
    }
}

std::unique_ptr<ImportonMap> makeImportonMap(vk::Context& context, const Scene& scene, const SceneArrays& arrays,
                                             const SceneBuffers& buffers, const RenderSettings& s) {
    if (s.photon.deposit == DepositMode::All) return nullptr;
    ImportonSettings settings;
    settings.paths = s.photon.importonPaths;
    settings.seed = s.seed;
    return std::make_unique<ImportonMap>(context, arrays, buffers,
                                         makeGpuCamera(chooseCamera(scene, s.cameraIndex), s.width, s.height), s.width,
                                         s.height, settings);
}

void addImportonStats(RenderStats& stats, const ImportonMap* importons) {
    if (!importons) return;
    stats.importons = importons->stats().stored;
    stats.importanceScale = importons->stats().importanceScale;
    stats.photonSeconds += importons->stats().seconds;
    stats.importonBytes += importons->bytes();
}

DepositSettings depositSettings(const PhotonRenderSettings& p, DepositMode mode, const ImportonMap* importons) {
    DepositSettings d;
    d.mode = depositModeCode(mode);
    d.importons = importons;
    d.epsilon = p.depositEpsilon;
    d.cutoff = p.depositCutoff;
    d.densityAccuracy = p.densityAccuracy;
    d.rounds = p.densityRounds;
    d.redistribute = !p.densityRoulette;
    return d;
}

float densityCellSize(const PhotonRenderSettings& p, uint32_t k, const ImportonMap& importons) {
    const double required = double(p.densityAccuracy) * importons.stats().medianPathImportance;
    if (!(required > 0.0)) throw InputError("--deposit density: no importon sees the scene through a bounce");
    return static_cast<float>(std::sqrt(k / (gpu::kPi * required)));
}

}  // namespace vkp
