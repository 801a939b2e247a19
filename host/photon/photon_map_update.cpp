#include "photon/photon_map_update.h"

#include "photon/photon_map.h"

namespace vkp {

PhotonMapStats buildFramePhotonMap(const Frame& frame, PhotonMap& map, uint32_t firstPath) {
    if (frame.photonUpdate == nullptr) return map.build(firstPath);
    return frame.photonUpdate->buildPhotonMap(map, firstPath, frame.update);
}

}  // namespace vkp
