#include "photon/progressive_photon_integrator.h"

#include <algorithm>
#include <cmath>

#include "photon/deposition.h"
#include "photon/photon_integrator.h"
#include "vk/context.h"

namespace vkp {

ProgressivePhotonIntegrator::ProgressivePhotonIntegrator(const GpuScene& scene, const PhotonIntegratorSettings& settings)
    : m_scene(scene), m_settings(settings) {
    m_settings.check();
    requireLightPower(scene);
    m_radius = m_settings.radiusFor(scene.scene());
}

void ProgressivePhotonIntegrator::prepare(const Frame& frame, const Film& film) {
    const PhotonIntegratorSettings& p = m_settings;
    vk::Context& context = m_scene.context();
    m_stats = Stats();
    m_pixels = frame.pixels();
    m_window = frame.pixelRange();

    // One map of every non-direct photon (caustic and global alike), rebuilt each pass; radii only
    // shrink, so cells of twice the initial radius serve every pass.
    PhotonMapSettings mapSettings;
    mapSettings.paths = p.globalPaths;
    mapSettings.maxDeposits = p.maxDeposits;
    mapSettings.seed = frame.seed;
    mapSettings.segmentShift = m_settings.mapSegmentShift;
    mapSettings.rejectedFlags = gpu::kPhotonPrimary;
    mapSettings.cellSize = 2.0f * m_radius;
    mapSettings.control = &frame.control;  // a stopped pass keeps its paths, normalised by their number
    m_stopReason.clear();
    m_importons = makeImportonMap(m_scene, frame, p.deposit);
    reportImportons(m_stats, m_importons.get());
    mapSettings.deposit = depositSettings(p.deposit, p.deposit.mode, m_importons.get());
    mapSettings.fitGridTable = false;  // the update pass binds the grid before the first pass builds it
    m_map = std::make_unique<PhotonMap>(context, m_scene.scene(), m_scene.arrays(), m_scene.buffers(), mapSettings);

    m_points = std::make_unique<vk::Buffer>(context, "visible points", m_pixels * sizeof(gpu::GpuVisiblePoint),
                                            vk::kStorageUsage);
    std::vector<gpu::SppmPixel> initial(m_pixels);
    for (auto& px : initial) px.radius2 = m_radius * m_radius;
    m_sppm = std::make_unique<vk::Buffer>(vk::makeStorageBuffer(context, "sppm pixels", initial));
    m_visiblePass = std::make_unique<VisiblePointPass>(context, m_scene.buffers(), film.sums(), *m_points,
                                                       *frame.rasterDirect);
    m_updatePass = std::make_unique<SppmUpdatePass>(context, m_scene.buffers(), *m_sppm, *m_points, m_map->grid());
    m_visibleParams = visiblePointParams(frame, m_scene.buffers().lightCount());
    m_sppmParams = {};
    m_sppmParams.grid = m_map->grid().view(m_map->photonPower());
    m_sppmParams.width = frame.width;
    m_sppmParams.height = frame.height;
    m_sppmParams.alpha = p.alpha;
    m_stats.set("settings.photon.radius", m_radius);
}

void ProgressivePhotonIntegrator::beginSamples(uint32_t first, uint32_t count) {
    (void)count;  // one pass per batch (maxSamplesPerBatch)
    const PhotonMapStats mapStats = m_map->build(first * m_settings.globalPaths);
    reportMapBuild(m_stats, mapStats);
    if (!mapStats.stopReason.empty()) m_stopReason = mapStats.stopReason;
    m_sppmParams.grid = m_map->grid().view(m_map->photonPower());  // the paths this pass traced
    m_stats.set("photons.globalStored", mapStats.stored);
    m_stats.set("photons.globalDeposits", mapStats.candidates);
}

void ProgressivePhotonIntegrator::recordSamples(VkCommandBuffer cmd, uint32_t first, uint32_t count) {
    (void)count;
    recordSamplePart(cmd, first, m_window);
}

// The pass's visible points and their SPPM update, per pixel: a part of the pixels reads the
// photon map beginSamples built for this pass, as the whole frame does.
void ProgressivePhotonIntegrator::recordSamplePart(VkCommandBuffer cmd, uint32_t sample, vk::ItemRange part) {
    m_visibleParams.sampleIndex = sample;
    vk::computeBarrier(cmd);
    m_visiblePass->record(cmd, m_visibleParams, part);
    vk::computeBarrier(cmd);
    m_updatePass->record(cmd, m_sppmParams, part);
}

// Direct light (the film's mean) plus tau / (passes pi R^2).
void ProgressivePhotonIntegrator::finish(ImageRgb& image, uint32_t samplesDone) {
    const auto state = m_sppm->download<gpu::SppmPixel>();
    const float passes = static_cast<float>(std::max(1u, samplesDone));
    for (uint64_t i = 0; i < m_pixels; ++i) {
        const glm::vec3 l = gpu::sppmRadiance(state[i], passes);
        for (int c = 0; c < 3; ++c) image.pixels[3 * i + c] += l[c];
    }
    m_stats.set("photons.mapBytes", m_map->bytes());
}

void ProgressivePhotonIntegrator::report(Stats& stats) const {
    m_settings.report(stats);
    stats.merge(m_stats);
    reportPhotonSummary(stats);
}

}  // namespace vkp
