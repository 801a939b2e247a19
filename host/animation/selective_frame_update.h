// --photon-update selective: the frames loop's FrameUpdate (animation/frame_update.h) that keeps one
// SelectivePhotonUpdate per photon map of the integrator (told apart by their paths, deposits,
// seed and first Halton index) across the frames, and fills each frame's PhotonMap from its
// persistent slots (PhotonMap::buildFromSlots, which redoes an importance deposit decision
// against the frame's importons). Density-controlled maps are retraced in full every frame.
#pragma once

#include <map>
#include <memory>
#include <tuple>

#include "animation/frame_update.h"
#include "photon/selective_photon_update.h"

namespace vkp {
namespace vk { class Context; }

struct SelectiveUpdateOptions {
    uint32_t budget = 0;          // --photon-budget: paths per map and frame, pilots included; 0: paths / 8 + pilots
    uint32_t groups = 2310;       // --photon-groups
    uint32_t pilotsPerGroup = 1;
    bool trackPaths = true;       // --photon-detect tracks (exact for moved instances and lights) or pilots
    bool verify = false;          // --verify-update: compare each updated map with a full retrace
};

class SelectiveFrameUpdate : public FrameUpdate {
public:
    SelectiveFrameUpdate(vk::Context& context, const SelectiveUpdateOptions& options);
    ~SelectiveFrameUpdate() override;
    PhotonMapStats buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info) override;
    // `vkphoton view`: the scene has moved since the maps' last update. staleGroups() then counts
    // the groups, over every map, not retraced since (0: the maps hold what a full retrace of the
    // scene as it is now traces).
    void sceneMoved();
    uint64_t staleGroups() const;

private:
    vk::Context& m_context;
    SelectiveUpdateOptions m_options;
    // (firstPath, paths, maxDeposits, seed) -> that map's persistent paths
    std::map<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t, uint32_t>, std::unique_ptr<SelectivePhotonUpdate>> m_maps;
    // per map: its first update after the last sceneMoved()
    std::map<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t, uint32_t>, uint64_t> m_movedAt;
};

}  // namespace vkp
