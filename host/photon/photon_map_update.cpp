#include "photon/photon_map_update.h"

#include "photon/photon_map.h"

namespace vkp {

PhotonMapStats buildFramePhotonMap(const Frame& frame, PhotonMap& map, uint32_t firstPath) {
    if (frame.photonUpdate == nullptr) return map.build(firstPath);
    FrameUpdateInfo info = frame.update;
    info.camera = &frame.gpuCamera;
    return frame.photonUpdate->buildPhotonMap(map, firstPath, info);
}

}  // namespace vkp
