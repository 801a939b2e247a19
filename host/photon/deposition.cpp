#include "photon/deposition.h"

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

std::unique_ptr<ImportonMap> makeImportonMap(const GpuScene& scene, const Frame& frame, const DepositOptions& options) {
    if (options.mode == DepositMode::All) return nullptr;
    ImportonSettings settings;
    settings.paths = options.importonPaths;
    settings.seed = frame.seed;
    return std::make_unique<ImportonMap>(scene.context(), scene.arrays(), scene.buffers(), frame.gpuCamera, frame.width,
                                         frame.height, settings);
}

void reportImportons(Stats& stats, const ImportonMap* importons) {
    if (!importons) return;
    stats.set("photons.importonsStored", importons->stats().stored);
    stats.set("photons.importanceScale", importons->stats().importanceScale);
    stats.add("photons.seconds", importons->stats().seconds);
    stats.add("timings.photon.importonSeconds", importons->stats().seconds);
    stats.add("photons.importonBytes", importons->bytes());
}

DepositSettings depositSettings(const DepositOptions& options, DepositMode mode, const ImportonMap* importons) {
    DepositSettings d;
    d.mode = depositModeCode(mode);
    d.importons = importons;
    d.epsilon = options.epsilon;
    d.cutoff = options.cutoff;
    d.densityAccuracy = options.densityAccuracy;
    d.rounds = options.densityRounds;
    d.redistribute = !options.densityRoulette;
    return d;
}

float densityCellSize(const DepositOptions& options, uint32_t k, const ImportonMap& importons) {
    const double required = double(options.densityAccuracy) * importons.stats().medianPathImportance;
    if (!(required > 0.0)) throw InputError("--deposit density: no importon sees the scene through a bounce");
    return static_cast<float>(std::sqrt(k / (gpu::kPi * required)));
}

}  // namespace vkp
