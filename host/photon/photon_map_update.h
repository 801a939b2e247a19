// How a photon integrator (re)builds its maps for a frame of an animation. The frames loop
// (animation/frame_sequence.h) hands the integrators an implementation through
// Frame::photonUpdate: a full retrace per frame, or a selective update that keeps the maps across
// frames and retraces only the paths the motion changed (animation/selective_frame_update.h,
// Dmitriev et al. 2002). A still render has none, and the maps are built by PhotonMap::build.
#pragma once

#include <cstdint>

#include "render/frame.h"

namespace vkp {

class PhotonMap;
struct PhotonMapStats;

class PhotonMapUpdate {
public:
    virtual ~PhotonMapUpdate() = default;
    // Builds `map` for the frame `info`: traces its paths with Halton indices firstPath... as
    // PhotonMap::build does, or keeps what the motion left unchanged.
    virtual PhotonMapStats buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info) = 0;
};

// map.build(firstPath) without an update (a still render), else frame.photonUpdate's build.
PhotonMapStats buildFramePhotonMap(const Frame& frame, PhotonMap& map, uint32_t firstPath);

}  // namespace vkp
