// Traces photon paths on the GPU into one photon buffer (caustic, global and primary photons
// together, told apart by their flags) and reads back the counters.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <memory>
#include <vector>

#include "photon/photon_path_options.h"
#include "photon/photon_trace_pass.h"
#include "gpu_scene/scene_buffers.h"
#include "shared/path_track.glsl"
#include "shared/photon.glsl"
#include "vk/buffer.h"

namespace vkp {

struct PhotonSettings {
    uint32_t paths = 100000;      // photon paths emitted (Halton indices firstPath ...)
    uint32_t firstPath = 0;       // progressive passes use fresh Halton ranges
    uint32_t maxDeposits = kDefaultMaxDeposits;     // stored photons per path at most
    uint32_t seed = 0;
    uint32_t pathStride = 1;      // Halton indices firstPath + j * pathStride (a selective-update group)
    uint32_t requiredFlags = 0;   // gpu::kPhotonPrimary or kPhotonCaustic: store only that kind (PhotonTraceParams)
    bool trackPaths = false;      // also write each path's track (tracks(), shared/path_track.glsl)
};

struct PhotonCounters {
    uint64_t emitted = 0;
    uint64_t storedCaustic = 0;
    uint64_t storedGlobal = 0;
    uint64_t storedPrimary = 0;
    uint64_t absorbed = 0;
    uint64_t lost = 0;
    uint64_t truncated = 0;  // cut at kPhotonMaxBounces, or unable to make more of the map's kind
    uint64_t sampled = 0;    // more deposits than slots: the slots hold a reweighted sample of them

    PhotonCounters& operator+=(const PhotonCounters& o) {
        emitted += o.emitted;
        storedCaustic += o.storedCaustic;
        storedGlobal += o.storedGlobal;
        storedPrimary += o.storedPrimary;
        absorbed += o.absorbed;
        lost += o.lost;
        truncated += o.truncated;
        sampled += o.sampled;
        return *this;
    }
};

class PhotonTracer {
public:
    PhotonTracer(vk::Context& context, const Scene& scene, const SceneArrays& arrays, const SceneBuffers& buffers);

    // Traces `settings.paths` paths; the first paths * maxDeposits slots of the photon buffer hold
    // their photons (empty slots have no kPhotonValid flag). The buffer only grows, so a shorter
    // trace keeps it (and what is bound to it). Refuses (InputError) a buffer beyond the device's
    // storage-buffer range.
    PhotonCounters trace(const PhotonSettings& settings);
    // Traces paths.size() paths in one dispatch, path j with Halton index settings.firstPath +
    // paths[j] (settings.paths and pathStride are ignored), into slots j * maxDeposits + k; then
    // records `after` (may be empty: e.g. copies out of photons()) into the same submission.
    PhotonCounters traceList(const PhotonSettings& settings, std::span<const uint32_t> paths,
                             const std::function<void(VkCommandBuffer)>& after = {});

    // Allocates the slots (and with `tracks` the tracks) of `paths` paths now, so traces of up to
    // that many never reallocate.
    void reserve(uint32_t paths, uint32_t maxDeposits, bool tracks = false);

    const vk::Buffer& photons() const { return m_photons; }
    // GpuPathTrack per path of the last trace with PhotonSettings::trackPaths (path j at j).
    const vk::Buffer& tracks() const { return m_tracks; }
    // Watts carried by a photon of relative power 1: total light power / paths.
    double nominalPhotonPower() const { return m_nominalPower; }
    uint64_t slotCount() const { return m_slotCount; }  // slots written by the last trace
    std::vector<gpu::GpuPhoton> downloadPhotons() const;

private:
    vk::Context& m_context;
    const SceneBuffers& m_buffers;
    glm::vec3 m_sceneCenter;
    float m_sceneRadius;
    double m_totalPower;
    vk::Buffer m_photons;
    vk::Buffer m_counters;
    vk::Buffer m_pathList;                    // PhotonTraceParams.pathList's offsets (traceList)
    vk::Buffer m_tracks;                      // PhotonTraceParams.trackPaths's tracks (one placeholder until asked)
    std::unique_ptr<PhotonTracePass> m_pass;  // bound to m_photons, m_pathList and m_tracks: rebuilt when one is reallocated
    PhotonCounters run(const PhotonSettings& settings, uint32_t paths, bool listed,
                       const std::function<void(VkCommandBuffer)>& after);
    void ensureCapacity(uint64_t photonBytes, uint64_t listBytes, uint64_t trackBytes = 0);
    double m_nominalPower = 0.0;
    uint64_t m_slotCount = 0;
};

}  // namespace vkp
