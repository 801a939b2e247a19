// The photon-map updates of an animation's frames (docs/animation.md). The frames loop
// (animation/frame_sequence.h) owns one FrameUpdate for the whole sequence and hands it to every
// frame's render through FrameSettings::photonUpdate. This base class retraces every path (a full
// rebuild per frame) and counts the work; the selective update (Dmitriev et al. 2002,
// animation/selective_frame_update.h) subclasses it, keeping state across frames, and retraces
// only the paths the motion changed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "photon/photon_map_update.h"

namespace vkp {

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
    std::vector<MapVerification> verification;  // --verify-update: per map, after the update
    uint64_t fullPhotonPaths = 0;    // the paths of the maps built: what a full retrace traces
    double detectSeconds = 0.0;      // selective: finding the changed paths (tracks, marking pass)
};

class FrameUpdate : public PhotonMapUpdate {
public:
    // Retraces every path of `map` and counts them.
    PhotonMapStats buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info) override;
    // The counts since the last call (the frames loop takes them after each frame).
    FramePhotonCounts takeCounts() {
        const FramePhotonCounts counts = m_counts;
        m_counts = {};
        return counts;
    }

protected:
    FramePhotonCounts m_counts;
};

}  // namespace vkp
