// The seam through which an animation's frames (re)build their photon maps (docs/animation.md).
// The frames loop (render/frame_sequence.h) owns one FrameUpdate for the whole sequence and
// hands it to every frame's render through FrameSettings::photonUpdate; the photon integrator
// builds its maps through buildFramePhotonMap(). The base class retraces every path (a full
// rebuild per frame); a selective update (Dmitriev et al. 2002) subclasses it, keeping state
// across frames, and retraces only the paths the motion changed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkp {
namespace gpu { struct GpuCamera; }

class PhotonMap;
struct PhotonMapStats;
struct Frame;

// Which frame of a sequence is being rendered.
struct FrameUpdateInfo {
    uint32_t frame = 0;       // the frame number (--frames FIRST:LAST)
    double time = 0.0;        // seconds: frame / fps
    bool firstFrame = true;   // the first frame of the sequence (or a still render)
    uint64_t sceneGeneration = 0;  // changes when the frames loop rebuilt the scene (new buffers)
    const gpu::GpuCamera* camera = nullptr;  // the frame's view (set by buildFramePhotonMap): what is visible first
};

// --verify-update: one map's persistent photons against a full retrace of the same paths.
struct MapVerification {
    std::string map;            // "global" or "caustic"
    uint64_t paths = 0;
    uint64_t stalePhotons = 0;  // slots whose content differs from the full retrace's
    uint64_t stalePaths = 0;
    uint64_t staleGroups = 0;
};

// What the photon maps of one frame cost, for --stats-json's "frames" array.
struct FramePhotonCounts {
    uint64_t photonPathsTraced = 0;  // every photon path traced for the frame, pilot paths included
    uint64_t groupsRetraced = 0;     // photon groups retraced (0 for a full retrace)
    uint64_t changedPilots = 0;      // selective: pilot paths whose photons changed since the last frame
    uint64_t groupsMarked = 0;       // selective: groups with a changed pilot this frame
    uint64_t groupsPending = 0;      // selective: marked groups left for later frames (budget)
    uint64_t stalePathsFound = 0;    // selective: paths whose tracks met a change this frame
    uint64_t stalePathsLeft = 0;     // selective: stale paths left for later frames (budget)
    double detectSeconds = 0.0;      // selective: finding the changed paths (tracks, marking pass)
    std::vector<MapVerification> verification;  // --verify-update: per map, after the update
};

class FrameUpdate {
public:
    virtual ~FrameUpdate() = default;
    // Builds `map` for the frame `info`: traces its paths with Halton indices firstPath... as
    // PhotonMap::build does. The default retraces every path and counts them.
    virtual PhotonMapStats buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info);
    // The counts since the last call (the frames loop takes them after each frame).
    FramePhotonCounts takeCounts() {
        const FramePhotonCounts counts = m_counts;
        m_counts = {};
        return counts;
    }

protected:
    FramePhotonCounts m_counts;
};

// map.build(firstPath) without a frame update (a still render), else frame.photonUpdate's build.
PhotonMapStats buildFramePhotonMap(const Frame& frame, PhotonMap& map, uint32_t firstPath);

}  // namespace vkp
