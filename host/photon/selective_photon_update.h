// Selective photon tracing (Dmitriev, Brabec, Myszkowski, Seidel 2002, §4-5): photon paths kept
// across frames in fixed per-path slots (path i in slots i * maxDeposits + k), so retracing some
// paths never moves the others' photons. Path i belongs to group i mod groups; the Halton
// sequence's periodicity makes a group's paths leave the lights in similar directions, so one
// group is a spatially coherent bundle.
//
// Changes are found two ways. Exactly, for what moves in place (instances, punctual lights):
// every path keeps its track (shared/path_track.glsl: where its segments went, its light), and
// each frame selective_mark.comp tests all tracks against the old and new bounds of every moved
// instance and the moved lights; a path that meets one is stale until retraced (a bit per path),
// and a path that meets none is the same in the new scene. By pilots, for what bounds cannot tell
// (a rebuilt scene: materials, emission): the pilots (the first pilotsPerGroup paths of every group:
// paths 0 .. pilotsPerGroup * groups - 1) are retraced in the new scene and compared with their
// previous photons; a changed pilot the tracks did not explain marks its whole group.
// Within the per-frame path budget stale paths are retraced by priority: the energy of their
// photons weighted by the camera's view (Dmitriev et al. §5.3; a pilot-marked group, retraced
// whole, weighs one photon in view per path per changed pilot), stalest group first on ties.
// Unchanged groups are then refreshed round-robin, so once motion stops the slots converge to a
// full retrace even where detection missed. docs/animation.md.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "photon/photon_tracer.h"
#include "vk/segmented_buffer.h"

namespace vkp {

struct SceneChanges;
struct SceneSnapshot;
struct SelectiveMarkState;

struct SelectiveSettings {
    uint32_t paths = kDefaultPhotonPaths;       // photon paths of the map (Halton indices 0 .. paths - 1)
    uint32_t maxDeposits = kDefaultMaxDeposits;
    uint32_t seed = 0;
    uint32_t requiredFlags = 0;    // the map's kind of photon (PhotonSettings::requiredFlags)
    uint32_t firstPath = 0;        // path i is Halton index firstPath + i (progressive passes)
    uint32_t groups = 2310;        // 2*3*5*7*11: one digit of each of the first five Halton bases (docs)
    uint32_t pilotsPerGroup = 1;
    uint32_t budget = 0;           // paths traced per frame (pilots included); 0: paths / 8
    uint32_t refreshGroups = 1;    // unchanged groups refreshed per frame at least (round-robin)
    bool fillBudget = true;        // the refresh fills the budget (false: refreshGroups groups only, when
                                   // the tracks find what changed and the rest needs no refreshing)
    bool batched = true;           // the frame's groups in one dispatch (false: one per group, the reference)
    bool trackPaths = true;        // exact detection by the paths' tracks (false: pilots only, as in the paper)
    uint32_t segmentShift = 0;     // slots (and tracks) per buffer of the persistent slots: 2^shift (0: the default, 128 MiB)
    uint32_t chunkPaths = 0;       // paths per dispatch at most; 0: 65536, fewer where their slots exceed one storage buffer
};

struct SelectiveFrameStats {
    uint64_t photonPathsTraced = 0;  // pilots and retraced groups' paths
    uint64_t pilotsTraced = 0;
    uint64_t groupsRetraced = 0;
    uint64_t changedPilots = 0;
    uint64_t groupsPending = 0;      // marked groups left for later frames
    uint64_t stalePathsFound = 0;    // tracked paths found stale this frame (their tracks met a change)
    uint64_t stalePathsLeft = 0;     // stale paths the budget left for later frames
    uint64_t changedRegions = 0;     // regions tested (old and new bounds of the moved instances)
    double detectSeconds = 0.0;      // the scene comparison, selective_mark.comp and its read-backs
    bool full = false;               // the whole map was traced (first frame or --photon-update full)
};

// A full retrace compared with the persistent slots (SelectivePhotonUpdate::verify).
struct SelectiveVerification {
    uint64_t paths = 0;
    uint64_t stalePhotons = 0;  // slots whose content differs from the full retrace's
    uint64_t stalePaths = 0;    // paths with at least one such slot
    uint64_t staleGroups = 0;   // groups with at least one such path
    std::vector<uint32_t> differing;  // the stale paths, ascending
};

class SelectivePhotonUpdate {
public:
    SelectivePhotonUpdate(vk::Context& context, const SelectiveSettings& settings);
    ~SelectivePhotonUpdate();

    // One frame in a new scene (its GpuScene may be rebuilt every frame): a full trace when
    // `full` or on the first call, else the pilots and the selected groups.
    // The photon tracer is kept across calls with the same `buffers` and `sceneGeneration` (the
    // frames loop's count of scene rebuilds), so its kernel is built once per scene.
    // `camera` (may be null): the frame's view, which weighs the groups' priorities.
    SelectiveFrameStats update(const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers, bool full,
                               uint64_t sceneGeneration = 0, const gpu::GpuCamera* camera = nullptr);
    // Diagnostic (--verify-update): retraces every path in the scene of the last update, with the
    // same Halton indices, and counts the slots that differ from the persistent ones. Traces
    // nothing into the slots; the paths it traces are not counted by update().
    SelectiveVerification verify();

    // paths * maxDeposits slots, path i at i * maxDeposits (PhotonMap::buildFromSlots): a
    // segmented array, so the slots are bound by memory, not by one storage buffer's range.
    const vk::SegmentedBuffer& slots() const { return m_slots; }
    // GpuPathTrack per path (SelectiveSettings::trackPaths).
    const vk::SegmentedBuffer& tracks() const { return m_tracks; }
    bool stale(uint32_t path) const { return !m_stale.empty() && (m_stale[path >> 5] >> (path & 31)) & 1u; }
    const SelectiveSettings& settings() const { return m_settings; }
    uint32_t groupOf(uint32_t path) const { return path % m_settings.groups; }
    uint32_t pathsInGroup(uint32_t group) const;
    // Groups whose pilots changed in the last update (before retracing), ascending.
    const std::vector<uint32_t>& markedGroups() const { return m_marked; }
    // Groups retraced by the last update, in the order traced.
    const std::vector<uint32_t>& retracedGroups() const { return m_retraced; }
    std::vector<gpu::GpuPhoton> downloadSlots() const;
    uint64_t frame() const { return m_frame; }                                // updates so far
    uint64_t lastTraced(uint32_t group) const { return m_lastTraced[group]; } // frame of its last retrace

private:
    // Retraces `groups` (SelectiveSettings::batched: in one dispatch per chunk) into their slots,
    // and `paths` (stale paths of other groups) with them.
    void traceGroups(const std::vector<uint32_t>& groups, const std::vector<uint32_t>& paths = {});
    // Runs selective_mark.comp: sets the bits of paths whose tracks meet `changes` and returns every
    // path's weight (stale paths; kSelectiveWeightScale), counting into `stats`.
    std::vector<uint32_t> markStalePaths(const SceneChanges& changes, const gpu::GpuCamera* camera,
                                         SelectiveFrameStats& stats);
    void clearStale(uint32_t path) {
        if (!m_stale.empty()) m_stale[path >> 5] &= ~(1u << (path & 31));
    }
    void appendGroupPaths(uint32_t group, std::vector<uint32_t>& paths) const;
    // Traces the map's `paths` in chunks of m_chunkPaths (one dispatch and submission each), each
    // copied into its slots; `traced(first, count)` then sees the chunk's photons in the tracer.
    void traceIntoSlots(std::span<const uint32_t> paths,
                        const std::function<void(size_t first, size_t count)>& traced = {});
    // Copies path j of the tracer's last trace into the slots of path paths[j].
    void recordCopy(VkCommandBuffer cmd, const PhotonTracer& tracer, std::span<const uint32_t> paths) const;
    PhotonSettings traceSettings() const;

    vk::Context& m_context;
    SelectiveSettings m_settings;
    vk::SegmentedBuffer m_slots;
    vk::SegmentedBuffer m_tracks;               // GpuPathTrack per path (trackPaths)
    std::vector<uint32_t> m_stale;              // bit per path: stale (tracked), until retraced
    std::unique_ptr<SelectiveMarkState> m_mark;  // the detection kernel and its buffers
    std::unique_ptr<SceneSnapshot> m_snapshot;  // what the last update's scene looked like
    uint32_t m_chunkPaths;  // paths per trace: their slots fit the tracer's one storage buffer
    uint32_t m_pilotPaths;
    std::vector<gpu::GpuPhoton> m_pilotRecord;  // the pilots' photons of the last frame
    std::vector<uint32_t> m_priority;           // changed pilots seen since the group's last retrace
    std::vector<uint64_t> m_lastTraced;         // frame of the group's last retrace
    uint32_t m_refreshCursor = 0;
    uint64_t m_frame = 0;
    bool m_initialised = false;
    std::vector<uint32_t> m_marked;
    std::vector<uint32_t> m_retraced;
    std::unique_ptr<PhotonTracer> m_tracer;
    const SceneBuffers* m_tracerBuffers = nullptr;
    uint64_t m_tracerGeneration = 0;
    double m_tracerPower = 0.0;
};

}  // namespace vkp
