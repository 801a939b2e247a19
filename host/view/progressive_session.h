// The viewer's renderer: one scene, integrator and film kept while the user looks around, with
// samples accumulated a bounded batch at a time (so the window is polled between batches) and
// started afresh after each change. It is Renderer::render taken apart: the same frame, raster
// direct light, film and integrator calls, but the sample loop belongs to the view loop.
//
// Photon maps go through the seam `render --frames` uses (animation/frame_update.h): a moved node
// retraces the changed photon groups selectively (animation/selective_frame_update.h), a camera move
// keeps the traced paths (FrameUpdateInfo::retrace false) and rebuilds only what depends on the
// camera (importons, the maps' deposit decision and grids, visible points), and after a move
// further selective rounds refresh the groups the first round's budget left stale, until the
// round-robin has visited every group (then the maps equal a full retrace of the moved scene).
#pragma once

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "image/image.h"
#include "render/film.h"
#include "render/frame.h"
#include "animation/frame_scene.h"
#include "render/integrator_registry.h"
#include "render/raster_direct.h"
#include "animation/selective_frame_update.h"

namespace vkp {

// How a restart treats the photon maps.
enum class PhotonRefresh {
    Reuse,      // the scene did not move: the traced paths as they are (camera changes)
    Selective,  // the scene moved: pilots and the changed groups within the budget
    Full,       // every path traced again (the first build, R, a rebuilt scene)
};

struct SessionSettings {
    FrameSettings frame;               // size, spp (where accumulation stops), seed, camera, --direct
    LightSampling lightSampling;
    SelectiveUpdateOptions selective;  // --photon-budget, --photon-groups
    // Integrators with a preparation (photon maps, guides) show one path-traced sample of the
    // changed scene first, then prepare: the change is on screen before the maps are traced.
    bool preview = true;
    // Samples slower than a loop iteration are recorded in parts of the pixels (step()); false:
    // whole samples always (the same images; the window waits for each sample).
    bool sampleParts = true;
};

class ProgressiveSession {
public:
    ProgressiveSession(vk::Context& context, const SessionSettings& settings);
    ~ProgressiveSession();

    // Makes `scene` current (in place when only instances, lights and cameras moved; else a new
    // GpuScene and integrator). Returns whether it was rebuilt. Call restart() after.
    bool setScene(Scene scene);
    // The integrator samples come from from now on (built for the current scene). Call restart() after.
    void setIntegrator(const IntegratorConfig& config);
    void setView(const ViewOverride& view) { m_settings.frame.view = view; }
    // Images of width x height from the next restart() on (a new film; the camera keeps its
    // vertical field of view). Stops a running preparation. Call restart() after (the
    // view-independent photon maps stay valid: PhotonRefresh::Reuse).
    void resize(uint32_t width, uint32_t height);

    // Starts accumulating afresh: the frame (camera), raster direct light, a cleared film and
    // the integrator's prepare() (photon maps as `refresh` says). The path tracer prepares at
    // once. Integrators with a preparation (photon maps, guides) prepare on a thread of their own,
    // started by the next step(), so the window is polled meanwhile; before it the film gets one
    // path-traced sample (the preview; SessionSettings::preview and `allowPreview`), or, without
    // a preview, keeps the last image until the preparation is done.
    void restart(PhotonRefresh refresh, bool allowPreview = true);
    // One batch of samples, sized towards `targetSeconds`; nothing once the frame's spp are
    // done. Where one sample of every pixel takes longer than that (and 0.1 s) and the integrator
    // can record a sample in parts (Integrator::recordsSampleParts; all built-in ones), one part
    // of the pixels sized towards that time (the first part after a change of integrator or size:
    // 1/16 of them), so the window is polled between bounded submissions. In that mode an
    // integrator's per-sample host work (Integrator::beginsWithHostWork: SPPM's photon pass) runs
    // on a thread of its own, started by one step() and found done by a later one (preparing()
    // meanwhile); the mode is also taken when that work alone takes longer. Elsewhere whole
    // samples, at least one.
    // Returns the samples completed (0 after a part that did not complete one; partRecorded()). After a restart that defers the
    // preparation it starts it (returns 0), while it runs it returns 0 (preparing()), and the
    // call that finds it done returns 0 with preparedNow() true (rethrowing its error).
    // Nothing but step(), cancel() and the accessors may be called while preparing().
    uint32_t step(double targetSeconds);
    // A preparation, or an integrator's per-sample host work (SPPM's photon pass, run on a thread
    // of its own in parts mode: Integrator::beginsWithHostWork), is running.
    bool preparing() const { return m_preparation.valid() || m_begin.valid(); }
    // Stops a running preparation (its photon passes stop between chunks) and waits for it.
    void cancel();
    // Whether the film holds the preview's sample or the last image (the integrator not prepared).
    bool inPreview() const { return m_pendingRefresh.has_value() || m_preparation.valid(); }
    // Whether the last step() found the preparation done (its counts are then new), and whether
    // that preparation was a refresh round.
    bool preparedNow() const { return m_preparedNow; }
    bool lastWasRefresh() const { return m_lastWasRefresh; }
    // Whether the film holds a preview not yet followed by its preparation (show it first).
    bool hasPreviewImage() const { return m_previewImage; }
    // After a selective restart: whether a further round is due to refresh stale photon groups.
    bool refreshDue() const { return m_staleGroups > 0 && !preparing() && !m_pendingRefresh; }
    // Photon groups (over every map) not retraced since the last move.
    uint64_t staleGroups() const { return m_staleGroups; }
    // One such round: a selective restart that does not count as a move.
    void refreshRound();

    // What the image of the samples so far is made of, on the device (view/display_pass.h resolves
    // it): the film, and the estimates the integrator adds at the end (SPPM's; null in the
    // preview or for the others).
    const Film& film() const { return *m_film; }
    const vk::Buffer* progressiveEstimates() const {
        return m_integrator && !inPreview() ? m_integrator->progressiveEstimates() : nullptr;
    }
    uint32_t samples() const { return m_samples; }
    // Whether the last step() recorded a part of a sample (the film changed, samples() did not).
    bool partRecorded() const { return m_partRecorded; }
    // Submissions that recorded a part of a sample, since the session began.
    uint64_t partsRecorded() const { return m_partsRecorded; }
    bool complete() const { return m_samples >= m_settings.frame.samplesPerPixel; }
    std::string integratorName() const { return m_integrator ? m_integrator->name() : std::string(); }
    // The photon paths the last restart traced, and what a full retrace of its maps traces.
    uint64_t lastPhotonPaths() const { return m_lastPhotonPaths; }
    uint64_t lastFullPhotonPaths() const { return m_lastFullPhotonPaths; }
    double lastPrepareSeconds() const { return m_lastPrepareSeconds; }

    const Scene& scene() { return m_frameScene.scene(); }
    const SceneArrays& arrays() { return m_frameScene.renderer().gpuScene().arrays(); }
    const Frame& frame() const { return m_frame; }
    const SessionSettings& settings() const { return m_settings; }
    vk::Context& context() { return m_context; }

private:
    vk::Context& m_context;
    SessionSettings m_settings;
    FrameScene m_frameScene;
    const IntegratorConfig* m_config = nullptr;
    std::unique_ptr<Integrator> m_integrator;
    std::unique_ptr<Integrator> m_preview;          // the path tracer, for previews
    std::optional<PhotonRefresh> m_pendingRefresh;  // a preparation to start at the next step()
    std::future<void> m_preparation;                // the preparation's thread
    Clock::time_point m_prepareStart;
    std::atomic<bool> m_stop{false};                // the frame's stop flag: cancel()
    bool m_clearFilm = false;                       // the preparation clears the film first
    bool m_refreshing = false;                      // the restart was a refresh round
    bool m_lastWasRefresh = false;
    bool m_preparedNow = false;
    bool m_previewImage = false;
    std::unique_ptr<SelectiveFrameUpdate> m_update;
    std::unique_ptr<Film> m_film;
    std::unique_ptr<RasterDirectLight> m_raster;
    Frame m_frame;
    bool m_needFull = true;          // the next restart traces every path (new scene or integrator)
    uint32_t m_round = 0;
    uint32_t m_samples = 0;
    uint32_t m_batch = 1;
    uint64_t m_partDone = 0;           // pixels of sample m_samples recorded in parts so far
    std::future<void> m_begin;         // beginSamples(m_samples, 1) on its own thread (parts mode)
    bool m_begun = false;              // beginSamples ran for sample m_samples (parts mode)
    double m_secondsPerSample = 0.0;   // the last measured cost of one sample of every pixel (0: none yet)
    double m_secondsPerBegin = 0.0;    // ... of the integrator's beginSamples for one sample
    bool m_partRecorded = false;
    uint64_t m_partsRecorded = 0;
    uint32_t stepPart(double targetSeconds);
    uint64_t m_staleGroups = 0;
    uint32_t m_refreshRounds = 0;      // refresh rounds since the last move
    uint32_t m_refreshRoundCap = 0;
    void prepareIntegrator(PhotonRefresh refresh);
    uint64_t m_lastPhotonPaths = 0;
    uint64_t m_lastFullPhotonPaths = 0;
    double m_lastPrepareSeconds = 0.0;
};

}  // namespace vkp
