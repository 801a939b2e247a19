#include "view/progressive_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "render/path_integrator.h"
#include "render/stats.h"
#include "render/terminations.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {

ProgressiveSession::ProgressiveSession(vk::Context& context, const SessionSettings& settings)
    : m_context(context), m_settings(settings), m_frameScene(context, settings.lightSampling),
      m_update(std::make_unique<SelectiveFrameUpdate>(context, settings.selective)) {
    m_settings.frame.check();
    m_film = std::make_unique<Film>(context, m_settings.frame.width, m_settings.frame.height);
}

ProgressiveSession::~ProgressiveSession() {
    cancel();
    // The integrator and the raster pass refer to the scene's buffers: release them first.
    m_integrator.reset();
    m_preview.reset();
    m_raster.reset();
}

bool ProgressiveSession::setScene(Scene scene) {
    const FrameSceneChange change = m_frameScene.set(std::move(scene));
    if (change.rebuilt) {
        m_raster.reset();
        m_integrator.reset();
        m_preview.reset();
        if (m_config) m_integrator = m_config->create(m_frameScene.renderer().gpuScene());
        m_needFull = true;
    }
    return change.rebuilt;
}

void ProgressiveSession::setIntegrator(const IntegratorConfig& config) {
    m_config = &config;
    m_secondsPerSample = 0.0;
    m_secondsPerBegin = 0.0;
    m_integrator.reset();
    m_integrator = config.create(m_frameScene.renderer().gpuScene());
    m_needFull = true;  // its maps are new (the selective update keys them by their settings)
}

void ProgressiveSession::resize(uint32_t width, uint32_t height) {
    // A preparation stopped half way (or not yet started) leaves maps that must be traced again.
    if (preparing() || m_pendingRefresh) m_needFull = true;
    cancel();
    m_pendingRefresh.reset();
    FrameSettings frame = m_settings.frame;
    frame.width = width;
    frame.height = height;
    frame.check();
    m_settings.frame = frame;
    m_film = std::make_unique<Film>(m_context, width, height);
    m_secondsPerSample = 0.0;
    m_secondsPerBegin = 0.0;
}

void ProgressiveSession::restart(PhotonRefresh refresh, bool allowPreview) {
    const auto start = Clock::now();
    if (m_needFull) refresh = PhotonRefresh::Full;
    Renderer& renderer = m_frameScene.renderer();
    FrameSettings settings = m_settings.frame;
    settings.photonUpdate = m_update.get();
    settings.update.frame = m_round++;
    settings.update.firstFrame = refresh == PhotonRefresh::Full;
    settings.update.sceneGeneration = m_frameScene.generation();
    settings.update.retrace = refresh != PhotonRefresh::Reuse;
    m_raster.reset();
    m_frame = makeFrame(m_frameScene.scene(), settings);
    clearTerminations(m_context);
    m_raster = std::make_unique<RasterDirectLight>(renderer.gpuScene(), settings, m_frame.gpuCamera,
                                                   renderer.lightReach() ? &*renderer.lightReach() : nullptr);
    m_frame.rasterDirect = &m_raster->direct();
    m_frame.rasterFlags = m_raster->pathFlags();
    if (refresh == PhotonRefresh::Selective && !m_refreshing) {  // a move: its groups are stale from now on
        m_update->sceneMoved();
        m_refreshRounds = 0;
    }
    m_needFull = false;
    m_samples = 0;
    m_batch = 1;
    m_partDone = 0;
    m_begun = false;
    m_pendingRefresh.reset();
    m_preparedNow = false;
    m_previewImage = false;
    m_stop = false;
    m_frame.control.stop = &m_stop;  // cancel(): the photon passes stop between chunks
    m_clearFilm = true;
    const bool prepares = m_integrator->name() != "path";  // photon maps, guides: seconds on lavapipe
    if (m_settings.preview && allowPreview && prepares) {
        // One path-traced sample of the changed scene: on screen before the maps are traced.
        m_context.submitAndWait([&](VkCommandBuffer cmd) { m_film->recordClear(cmd); });
        if (!m_preview) m_preview = std::make_unique<PathIntegrator>(renderer.gpuScene());
        m_preview->prepare(m_frame, *m_film);
        m_context.submitAndWait([&](VkCommandBuffer cmd) {
            m_preview->recordSamples(cmd, 0, 1);
            vk::computeToHostBarrier(cmd);
        });
        m_pendingRefresh = refresh;
        m_previewImage = true;
    } else if (prepares) {
        // A refresh round: the film keeps the last image until the preparation is done.
        m_pendingRefresh = refresh;
    } else {
        prepareIntegrator(refresh);
        m_refreshing = false;
    }
    m_lastPrepareSeconds = secondsSince(start);
}

void ProgressiveSession::prepareIntegrator(PhotonRefresh refresh) {
    if (m_clearFilm) m_context.submitAndWait([&](VkCommandBuffer cmd) { m_film->recordClear(cmd); });
    m_clearFilm = false;
    m_integrator->prepare(m_frame, *m_film);
    const FramePhotonCounts counts = m_update->takeCounts();
    if (counts.fullPhotonPaths > 0) {  // maps built through the seam (the photon integrator)
        m_lastPhotonPaths = counts.photonPathsTraced;
        m_lastFullPhotonPaths = counts.fullPhotonPaths;
    } else {
        Stats stats;
        m_integrator->report(stats);
        if (stats.getOr<bool>("photons.mapsKept", false))
            m_lastPhotonPaths = 0;  // maps kept as they were (--deposit all): the last full count stands
        else  // maps outside the seam (the guide's, progressive photon mapping's per sample) or none
            m_lastPhotonPaths = m_lastFullPhotonPaths = stats.getOr<uint64_t>("photons.pathsTraced", 0);
    }
    // After a move the first round retraced the changed groups within the budget; the rounds
    // that follow refresh the rest (round-robin) until no group of any map was last traced before
    // the move: then the maps are what a full retrace of the moved scene traces. A round cap
    // (twice the rounds the budget needs to cover every path, and 4 more) ends it should a budget
    // too small for a group keep some group from ever being retraced.
    const bool selective = refresh == PhotonRefresh::Selective || (refresh == PhotonRefresh::Reuse && m_staleGroups > 0);
    if (refresh == PhotonRefresh::Full) {
        m_staleGroups = 0;
    } else if (selective) {
        m_staleGroups = m_update->staleGroups();
        if (!m_refreshing && counts.photonPathsTraced > 0)
            m_refreshRoundCap =
                2 * uint32_t(std::ceil(double(counts.fullPhotonPaths) / double(counts.photonPathsTraced))) + 4;
        if (m_refreshRounds >= m_refreshRoundCap) m_staleGroups = 0;
    }
}

void ProgressiveSession::refreshRound() {
    m_refreshing = true;
    ++m_refreshRounds;
    restart(PhotonRefresh::Selective, false);  // the image is already the moved scene's
}

void ProgressiveSession::cancel() {
    if (m_begin.valid()) {  // a per-sample photon pass: stopped between chunks, its sample begun again
        m_stop = true;
        try {
            m_begin.get();
        } catch (...) {
        }
        m_begun = false;
        m_partDone = 0;
    }
    if (!m_preparation.valid()) return;
    m_stop = true;
    try {
        m_preparation.get();
    } catch (...) {
    }
}

uint32_t ProgressiveSession::step(double targetSeconds) {
    m_preparedNow = false;
    m_partRecorded = false;
    if (m_preparation.valid()) {
        // The preparation runs on its own thread; the window keeps being polled meanwhile.
        if (m_preparation.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return 0;
        m_preparation.get();  // rethrows its error
        m_lastPrepareSeconds += secondsSince(m_prepareStart);
        m_preparedNow = true;
        m_lastWasRefresh = m_refreshing;
        m_refreshing = false;
        m_samples = 0;
        m_batch = 1;
        m_partDone = 0;
        m_begun = false;
        return 0;
    }
    if (m_pendingRefresh) {
        const PhotonRefresh refresh = *m_pendingRefresh;
        m_pendingRefresh.reset();
        m_previewImage = false;
        m_prepareStart = Clock::now();
        m_preparation = std::async(std::launch::async, [this, refresh] { prepareIntegrator(refresh); });
        return 0;
    }
    if (m_begin.valid()) {  // the sample's host work (parts mode), on its own thread
        if (m_begin.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return 0;
        m_begin.get();  // rethrows its error
        m_begun = true;
    }
    if (complete() || !m_integrator) return 0;
    // A whole sample within this long keeps the window responsive enough; longer ones go in parts
    // of about this long (shorter parts would spend more of the time submitting and showing).
    constexpr double kPartSeconds = 0.1;
    const double longest = std::max(targetSeconds, kPartSeconds);
    const bool slow = !(m_secondsPerSample > 0.0) || m_secondsPerSample > longest || m_secondsPerBegin > longest;
    if (m_settings.sampleParts && m_integrator->recordsSampleParts() && (m_partDone > 0 || m_begun || slow))
        return stepPart(longest);
    const uint32_t count =
        std::min({m_batch, m_integrator->maxSamplesPerBatch(), m_settings.frame.samplesPerPixel - m_samples});
    const auto start = Clock::now();
    m_integrator->beginSamples(m_samples, count);
    m_secondsPerBegin = secondsSince(start);
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        m_integrator->recordSamples(cmd, m_samples, count);
        vk::computeToHostBarrier(cmd);
    });
    m_samples += count;
    // Grow or shrink the next batch towards the target time (the window waits for it).
    const double perSample = secondsSince(start) / count;
    m_secondsPerSample = perSample;
    const double next = perSample > 0.0 ? targetSeconds / perSample : 2.0 * m_batch;
    m_batch = uint32_t(std::clamp(next, 1.0, 4096.0));
    return count;
}

uint32_t ProgressiveSession::stepPart(double targetSeconds) {
    constexpr uint64_t kMinPartPixels = 1024;  // below this a submission's own cost dominates
    const vk::ItemRange window = m_frame.pixelRange();
    const uint64_t left = window.count - m_partDone;
    const double estimate = m_secondsPerSample > 0.0 ? double(window.count) * targetSeconds / m_secondsPerSample
                                                     : double(window.count) / 16.0;
    // Parts start at multiples of kSamplePartGranule pixels from the window's first (pixels near
    // a cut elsewhere came out differently, 2026-11-28).
    uint64_t size = std::clamp<uint64_t>(uint64_t(estimate), std::min(left, kMinPartPixels), left);
    if (size < left) size = std::max<uint64_t>(kSamplePartGranule, size / kSamplePartGranule * kSamplePartGranule);
    if (!m_begun) {
        if (m_integrator->beginsWithHostWork()) {
            m_begin = std::async(std::launch::async, [this, sample = m_samples] {
                const auto begin = Clock::now();
                m_integrator->beginSamples(sample, 1);
                m_secondsPerBegin = secondsSince(begin);  // read after the future's get()
            });
            return 0;
        }
        const auto begin = Clock::now();
        m_integrator->beginSamples(m_samples, 1);
        m_secondsPerBegin = secondsSince(begin);
        m_begun = true;
    }
    const auto start = Clock::now();
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        m_integrator->recordSamplePart(cmd, m_samples, vk::ItemRange{window.first + m_partDone, size});
        vk::computeToHostBarrier(cmd);
    });
    m_secondsPerSample = secondsSince(start) * double(window.count) / double(size);
    m_partDone += size;
    m_partRecorded = true;
    ++m_partsRecorded;
    if (m_partDone < window.count) return 0;
    m_partDone = 0;
    m_begun = false;
    ++m_samples;
    m_batch = 1;
    return 1;
}

}  // namespace vkp
