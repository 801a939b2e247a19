// Selective photon tracing (Dmitriev, Brabec, Myszkowski, Seidel 2002, §4-5): photon paths kept
// across frames in fixed per-path slots (path i in slots i * maxDeposits + k), so retracing some
// paths never moves the others' photons. Path i belongs to group i mod groups; the Halton
// sequence's periodicity makes a group's paths leave the lights in similar directions, so one
// group is a spatially coherent bundle. Each frame the pilots (the first pilotsPerGroup paths of
// every group: paths 0 .. pilotsPerGroup * groups - 1) are retraced in the new scene and compared
// with their previous photons; a changed pilot raises its group's priority. Groups are retraced
// by priority (changed pilots, stalest first on ties) within the per-frame path budget, then
// unchanged groups round-robin, so once motion stops the slots converge to a full retrace.
// docs/photon-mapping.md "Selective update".
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "photon/photon_tracer.h"
#include "vk/segmented_buffer.h"

namespace vkp {

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
    bool batched = true;           // the frame's groups in one dispatch (false: one per group, the reference)
    uint32_t segmentShift = 0;     // slots per buffer of the persistent slots: 2^shift (0: the default, 128 MiB)
    uint32_t chunkPaths = 0;       // paths per dispatch at most; 0: 65536, fewer where their slots exceed one storage buffer
};

struct SelectiveFrameStats {
    uint64_t photonPathsTraced = 0;  // pilots and retraced groups' paths
    uint64_t pilotsTraced = 0;
    uint64_t groupsRetraced = 0;
    uint64_t changedPilots = 0;
    uint64_t groupsPending = 0;      // marked groups left for later frames
    bool full = false;               // the whole map was traced (first frame or --photon-update full)
};

class SelectivePhotonUpdate {
public:
    SelectivePhotonUpdate(vk::Context& context, const SelectiveSettings& settings);

    // One frame in a new scene (its GpuScene may be rebuilt every frame): a full trace when
    // `full` or on the first call, else the pilots and the selected groups.
    // The photon tracer is kept across calls with the same `buffers` and `sceneGeneration` (the
    // frames loop's count of scene rebuilds), so its kernel is built once per scene.
    SelectiveFrameStats update(const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers, bool full,
                               uint64_t sceneGeneration = 0);

    // paths * maxDeposits slots, path i at i * maxDeposits (PhotonMap::buildFromSlots): a
    // segmented array, so the slots are bound by memory, not by one storage buffer's range.
    const vk::SegmentedBuffer& slots() const { return m_slots; }
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
    // Retraces `groups` (SelectiveSettings::batched: in one dispatch per chunk) into their slots.
    void traceGroups(const std::vector<uint32_t>& groups);
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
