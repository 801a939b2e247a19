#include "render/selective_frame_update.h"

#include <algorithm>

#include "render/photon_map.h"
#include "util/stopwatch.h"

namespace vkp {
namespace {

// Persistent maps at most (progressive passes each have their own Halton range): beyond it a
// map is retraced in full every frame.
constexpr size_t kMaxPersistentMaps = 8;

}  // namespace

SelectiveFrameUpdate::SelectiveFrameUpdate(vk::Context& context, const SelectiveUpdateOptions& options)
    : m_context(context), m_options(options) {}

SelectiveFrameUpdate::~SelectiveFrameUpdate() = default;

PhotonMapStats SelectiveFrameUpdate::buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info) {
    const PhotonMapSettings& ms = map.settings();
    const auto key = std::make_tuple(firstPath, ms.paths, ms.maxDeposits, ms.seed);
    auto it = m_maps.find(key);
    if (ms.deposit.mode != gpu::kDepositAll || (it == m_maps.end() && m_maps.size() >= kMaxPersistentMaps))
        return FrameUpdate::buildPhotonMap(map, firstPath, info);
    if (it == m_maps.end()) {
        SelectiveSettings s;
        s.paths = ms.paths;
        s.maxDeposits = ms.maxDeposits;
        s.seed = ms.seed;
        s.firstPath = firstPath;
        s.groups = std::min(m_options.groups, ms.paths);
        s.pilotsPerGroup = m_options.pilotsPerGroup;
        s.budget = m_options.budget;
        it = m_maps.emplace(key, std::make_unique<SelectivePhotonUpdate>(m_context, s)).first;
    }
    const auto start = Clock::now();
    const SelectiveFrameStats frame = it->second->update(map.scene(), map.arrays(), map.buffers(), info.firstFrame);
    const double traceSeconds = secondsSince(start);
    PhotonMapStats stats = map.buildFromSlots(it->second->slots());
    stats.traced.emitted = frame.photonPathsTraced;
    stats.traceSeconds += traceSeconds;
    m_counts.photonPathsTraced += frame.photonPathsTraced;
    m_counts.groupsRetraced += frame.groupsRetraced;
    return stats;
}

}  // namespace vkp
