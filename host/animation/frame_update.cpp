#include "animation/frame_update.h"

#include "photon/photon_map.h"

namespace vkp {

PhotonMapStats FrameUpdate::buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info) {
    (void)info;  // a full retrace does not depend on what moved
    const PhotonMapStats stats = map.build(firstPath);
    m_counts.photonPathsTraced += stats.traced.emitted;
    m_counts.fullPhotonPaths += map.settings().paths;
    return stats;
}

}  // namespace vkp
