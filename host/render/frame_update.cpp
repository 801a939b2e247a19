#include "render/frame_update.h"

#include "render/frame.h"
#include "render/photon_map.h"

namespace vkp {

PhotonMapStats FrameUpdate::buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info) {
    (void)info;  // a full retrace does not depend on what moved
    const PhotonMapStats stats = map.build(firstPath);
    m_counts.photonPathsTraced += stats.traced.emitted;
    m_counts.fullPhotonPaths += map.settings().paths;
    return stats;
}

PhotonMapStats buildFramePhotonMap(const Frame& frame, PhotonMap& map, uint32_t firstPath) {
    if (frame.photonUpdate == nullptr) return map.build(firstPath);
    return frame.photonUpdate->buildPhotonMap(map, firstPath, frame.update);
}

}  // namespace vkp
