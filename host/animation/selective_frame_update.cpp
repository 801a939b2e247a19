#include "animation/selective_frame_update.h"

#include <algorithm>

#include "photon/photon_map.h"
#include "util/stopwatch.h"

namespace vkp {
namespace {

// Persistent maps at most (progressive passes each have their own Halton range): beyond it a
// map is retraced in full every frame.
constexpr size_t kMaxPersistentMaps = 8;

// At least this many paths per group: fewer groups for small maps (else every path would be a pilot).
constexpr uint32_t kMinGroupPaths = 16;

// `groups`, divided by its smallest prime factors until every group holds kMinGroupPaths paths
// (2310 -> 1155 -> 385 -> 77 -> 11 -> 1): it stays a product of the Halton bases (Eq. 5).
uint32_t groupsFor(uint32_t groups, uint32_t paths) {
    while (groups > 1 && uint64_t(groups) * kMinGroupPaths > paths) {
        uint32_t factor = 2;
        while (groups % factor != 0) ++factor;
        groups /= factor;
    }
    return std::max(groups, 1u);
}

}  // namespace

SelectiveFrameUpdate::SelectiveFrameUpdate(vk::Context& context, const SelectiveUpdateOptions& options)
    : m_context(context), m_options(options) {}

SelectiveFrameUpdate::~SelectiveFrameUpdate() = default;

void SelectiveFrameUpdate::sceneMoved() {
    for (const auto& [key, update] : m_maps) m_movedAt[key] = update->frame() + 1;
}

uint64_t SelectiveFrameUpdate::staleGroups() const {
    uint64_t stale = 0;
    for (const auto& [key, movedAt] : m_movedAt) {
        const SelectivePhotonUpdate& update = *m_maps.at(key);
        for (uint32_t g = 0; g < update.settings().groups; ++g)
            if (update.lastTraced(g) < movedAt) ++stale;
    }
    return stale;
}

PhotonMapStats SelectiveFrameUpdate::buildPhotonMap(PhotonMap& map, uint32_t firstPath, const FrameUpdateInfo& info) {
    const PhotonMapSettings& ms = map.settings();
    const auto key = std::make_tuple(firstPath, ms.paths, ms.maxDeposits, ms.seed, ms.requiredFlags);
    auto it = m_maps.find(key);
    if (ms.deposit.mode == gpu::kDepositDensity || (it == m_maps.end() && m_maps.size() >= kMaxPersistentMaps))
        return FrameUpdate::buildPhotonMap(map, firstPath, info);
    if (it == m_maps.end()) {
        SelectiveSettings s;
        s.paths = ms.paths;
        s.maxDeposits = ms.maxDeposits;
        s.seed = ms.seed;
        s.requiredFlags = ms.requiredFlags;
        s.firstPath = firstPath;
        s.groups = groupsFor(m_options.groups, ms.paths);
        s.pilotsPerGroup = m_options.pilotsPerGroup;
        s.budget = m_options.budget;
        s.segmentShift = ms.segmentShift;  // the slots split as the map does
        s.trackPaths = m_options.trackPaths;
        // With the tracks every change of moved instances and lights is found and a rebuilt scene
        // marks every path: the round-robin refresh only has to catch what neither sees, one group
        // per frame; with pilots alone it fills the budget, as the paper's update does.
        s.fillBudget = !m_options.trackPaths;
        it = m_maps.emplace(key, std::make_unique<SelectivePhotonUpdate>(m_context, s)).first;
    }
    if (!info.retrace && !info.firstFrame && it->second->frame() > 0) {
        // Nothing moved (a camera change in `vkphoton view`): the slots as they are, none traced.
        PhotonMapStats stats = map.buildFromSlots(it->second->slots(), firstPath);
        stats.traced.emitted = 0;
        m_counts.fullPhotonPaths += ms.paths;
        return stats;
    }
    const auto start = Clock::now();
    const SelectiveFrameStats frame = it->second->update(map.scene(), map.arrays(), map.buffers(), info.firstFrame,
                                                         info.sceneGeneration, info.camera);
    const double traceSeconds = secondsSince(start);
    if (m_options.verify) {  // a diagnostic: the full retrace is neither counted nor timed
        const SelectiveVerification v = it->second->verify();
        m_counts.verification.push_back({(ms.requiredFlags & gpu::kPhotonCaustic) != 0 ? "caustic" : "global", v.paths,
                                         v.stalePhotons, v.stalePaths, v.staleGroups});
    }
    PhotonMapStats stats = map.buildFromSlots(it->second->slots(), firstPath);
    stats.traced.emitted = frame.photonPathsTraced;
    stats.traceSeconds += traceSeconds;
    m_counts.photonPathsTraced += frame.photonPathsTraced;
    m_counts.groupsRetraced += frame.groupsRetraced;
    m_counts.changedPilots += frame.changedPilots;
    m_counts.groupsMarked += it->second->markedGroups().size();
    m_counts.groupsPending += frame.groupsPending;
    m_counts.stalePathsFound += frame.stalePathsFound;
    m_counts.stalePathsLeft += frame.stalePathsLeft;
    m_counts.fullPhotonPaths += ms.paths;
    m_counts.detectSeconds += frame.detectSeconds;
    return stats;
}

}  // namespace vkp
