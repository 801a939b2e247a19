#include "photon/selective_photon_update.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include <fmt/format.h>

#include "photon/selective_mark_pass.h"
#include "photon/scene_changes.h"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"
#include "vk/image.h"

namespace vkp {
namespace {

constexpr uint32_t kFullChunkPaths = 1u << 16;  // paths per trace at most (fewer when a path has many slots)
constexpr size_t kCopyRegions = 256;             // copy regions per vkCmdCopyBuffer (recordCopy)

}  // namespace

// selective_mark.comp and its buffers (made at the first frame that needs them).
struct SelectiveMarkState {
    vk::Buffer regions;   // kSelectiveMaxRegions pairs of vec4
    vk::Buffer lights;    // bit per light
    vk::Buffer stale;     // bit per path
    vk::Buffer weights;   // uint per path
    vk::Buffer counters;
    uint32_t lightWords = 0;
    std::unique_ptr<SelectiveMarkPass> pass;
};

SelectivePhotonUpdate::SelectivePhotonUpdate(vk::Context& context, const SelectiveSettings& settings)
    : m_context(context), m_settings(settings) {
    if (settings.paths == 0 || settings.maxDeposits == 0)
        throw InputError("a selective photon update needs at least one path and one deposit per path");
    if (settings.groups == 0 || settings.groups > settings.paths)
        throw InputError(fmt::format("selective photon update: {} groups for {} paths (need 1 .. paths)",
                                     settings.groups, settings.paths));
    if (settings.pilotsPerGroup == 0) throw InputError("selective photon update: at least one pilot per group");
    m_pilotPaths = std::min(settings.paths, settings.pilotsPerGroup * settings.groups);
    if (m_settings.budget == 0) m_settings.budget = m_pilotPaths + settings.paths / 8;
    uint64_t pathBytes = uint64_t(settings.maxDeposits) * sizeof(gpu::GpuPhoton);
    if (settings.trackPaths) pathBytes = std::max<uint64_t>(pathBytes, sizeof(gpu::GpuPathTrack));
    m_chunkPaths = static_cast<uint32_t>(std::min<uint64_t>(settings.chunkPaths ? settings.chunkPaths : kFullChunkPaths,
                                                            context.properties().limits.maxStorageBufferRange / pathBytes));
    if (m_chunkPaths == 0)
        throw InputError(fmt::format("selective photon update: --max-deposits {}: one path's slots exceed the device's "
                                     "storage-buffer range",
                                     settings.maxDeposits));
    const uint64_t slots = uint64_t(settings.paths) * settings.maxDeposits;
    m_slots = vk::SegmentedBuffer(context, "selective photon slots", sizeof(gpu::GpuPhoton), slots, settings.segmentShift);
    m_slots.reserve(slots);
    if (settings.trackPaths) {
        m_tracks = vk::SegmentedBuffer(context, "selective photon tracks", sizeof(gpu::GpuPathTrack), settings.paths,
                                       settings.segmentShift);
        m_tracks.reserve(settings.paths);
        m_stale.assign((uint64_t(settings.paths) + 31) / 32, 0u);
    }
    m_priority.assign(settings.groups, 0);
    m_lastTraced.assign(settings.groups, 0);
}

SelectivePhotonUpdate::~SelectivePhotonUpdate() = default;

uint32_t SelectivePhotonUpdate::pathsInGroup(uint32_t group) const {
    return group < m_settings.paths ? (m_settings.paths - group + m_settings.groups - 1) / m_settings.groups : 0;
}

void SelectivePhotonUpdate::recordCopy(VkCommandBuffer cmd, const PhotonTracer& tracer, std::span<const uint32_t> paths) const {
    // Path j of the trace (slots j * maxDeposits ...) to its persistent slots; runs of consecutive
    // paths in one copy each.
    const uint32_t slotsPerPath = m_settings.maxDeposits;
    std::vector<vk::SegmentedBuffer::ElementCopy> copies;
    for (uint32_t j = 0; j < paths.size(); ++j) {
        const uint64_t slot = uint64_t(paths[j]) * slotsPerPath;
        const VkDeviceSize traced = VkDeviceSize(j) * slotsPerPath * sizeof(gpu::GpuPhoton);
        if (!copies.empty() && copies.back().first + copies.back().count == slot &&
            copies.back().bufferOffset + copies.back().count * sizeof(gpu::GpuPhoton) == traced) {
            copies.back().count += slotsPerPath;
            continue;
        }
        copies.push_back({traced, slot, slotsPerPath});
    }
    vk::memoryBarrier2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // Scattered paths (stale ones) make a region per path: recorded in commands of kCopyRegions
    // regions, since a command's regions are checked against each other (the validation layer's
    // overlap test is quadratic in them: 10,000 regions took seconds).
    auto record = [&](const vk::SegmentedBuffer& to, const vk::Buffer& from,
                      std::span<const vk::SegmentedBuffer::ElementCopy> all) {
        for (size_t first = 0; first < all.size(); first += kCopyRegions)
            to.recordCopyFrom(cmd, from, all.subspan(first, std::min(kCopyRegions, all.size() - first)));
    };
    record(m_slots, tracer.photons(), copies);
    if (m_settings.trackPaths) {  // track j to path paths[j]'s track, runs as above
        std::vector<vk::SegmentedBuffer::ElementCopy> trackCopies;
        for (uint32_t j = 0; j < paths.size(); ++j) {
            const VkDeviceSize traced = VkDeviceSize(j) * sizeof(gpu::GpuPathTrack);
            if (!trackCopies.empty() && trackCopies.back().first + trackCopies.back().count == paths[j] &&
                trackCopies.back().bufferOffset + trackCopies.back().count * sizeof(gpu::GpuPathTrack) == traced) {
                trackCopies.back().count += 1;
                continue;
            }
            trackCopies.push_back({traced, paths[j], 1});
        }
        record(m_tracks, tracer.tracks(), trackCopies);
    }
    vk::memoryBarrier2(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                       VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
}

void SelectivePhotonUpdate::traceIntoSlots(std::span<const uint32_t> paths,
                                           const std::function<void(size_t first, size_t count)>& traced) {
    for (size_t first = 0; first < paths.size(); first += m_chunkPaths) {
        const std::span<const uint32_t> chunk = paths.subspan(first, std::min<size_t>(m_chunkPaths, paths.size() - first));
        PhotonSettings s = traceSettings();
        s.paths = static_cast<uint32_t>(chunk.size());
        m_tracer->traceList(s, chunk, [&](VkCommandBuffer cmd) { recordCopy(cmd, *m_tracer, chunk); });
        if (traced) traced(first, chunk.size());
    }
}

PhotonSettings SelectivePhotonUpdate::traceSettings() const {
    PhotonSettings s;
    s.firstPath = m_settings.firstPath;
    s.maxDeposits = m_settings.maxDeposits;
    s.seed = m_settings.seed;
    s.requiredFlags = m_settings.requiredFlags;
    s.trackPaths = m_settings.trackPaths;
    return s;
}

void SelectivePhotonUpdate::appendGroupPaths(uint32_t group, std::vector<uint32_t>& paths) const {
    for (uint32_t path = group; path < m_settings.paths; path += m_settings.groups) paths.push_back(path);
}

void SelectivePhotonUpdate::traceGroups(const std::vector<uint32_t>& groups, const std::vector<uint32_t>& stalePaths) {
    std::vector<uint32_t> paths;
    if (m_settings.batched) {  // every group in one dispatch and one submission (per chunk)
        for (uint32_t g : groups) appendGroupPaths(g, paths);
        const size_t grouped = paths.size();
        paths.insert(paths.end(), stalePaths.begin(), stalePaths.end());
        // In path order (chosen by weight): neighbours copy into their slots as one region.
        std::sort(paths.begin() + static_cast<std::ptrdiff_t>(grouped), paths.end());
        if (!paths.empty()) traceIntoSlots(paths);
    } else {  // one strided dispatch and submission per group (per chunk): the reference for the batched trace
        for (uint32_t g : groups) {
            paths.clear();
            appendGroupPaths(g, paths);
            for (size_t first = 0; first < paths.size(); first += m_chunkPaths) {
                const std::span<const uint32_t> chunk(paths.data() + first, std::min<size_t>(m_chunkPaths, paths.size() - first));
                PhotonSettings s = traceSettings();
                s.paths = static_cast<uint32_t>(chunk.size());
                s.firstPath = m_settings.firstPath + chunk[0];
                s.pathStride = m_settings.groups;
                m_tracer->trace(s);
                m_context.submitAndWait([&](VkCommandBuffer cmd) { recordCopy(cmd, *m_tracer, chunk); });
            }
        }
        if (!stalePaths.empty()) traceIntoSlots(stalePaths);
    }
    for (uint32_t g : groups) {
        m_priority[g] = 0;
        m_lastTraced[g] = m_frame;
        m_retraced.push_back(g);
        for (uint32_t path = g; path < m_settings.paths; path += m_settings.groups) clearStale(path);
    }
    for (uint32_t path : stalePaths) clearStale(path);
}

std::vector<uint32_t> SelectivePhotonUpdate::markStalePaths(const SceneChanges& changes, const gpu::GpuCamera* camera,
                                                            SelectiveFrameStats& stats) {
    const uint32_t lightCount = static_cast<uint32_t>(m_snapshot ? m_snapshot->lights.size() : 0);
    const uint32_t lightWords = std::max(1u, (lightCount + 31) / 32);
    if (!m_mark || m_mark->lightWords < lightWords) {
        auto mark = std::make_unique<SelectiveMarkState>();
        mark->regions = vk::Buffer(m_context, "selective changed regions", gpu::kSelectiveMaxRegions * 2 * sizeof(glm::vec4),
                                   vk::kStorageUsage);
        mark->lights = vk::Buffer(m_context, "selective changed lights", lightWords * sizeof(uint32_t), vk::kStorageUsage);
        mark->stale = vk::Buffer(m_context, "selective stale paths", m_stale.size() * sizeof(uint32_t), vk::kStorageUsage);
        mark->weights = vk::Buffer(m_context, "selective path weights", uint64_t(m_settings.paths) * sizeof(uint32_t),
                                   vk::kStorageUsage);
        mark->counters = vk::Buffer(m_context, "selective mark counters", gpu::kSelectiveMarkCounterCount * sizeof(uint32_t),
                                    vk::kStorageUsage);
        mark->lightWords = lightWords;
        mark->pass = std::make_unique<SelectiveMarkPass>(m_context, m_tracks, m_slots, mark->regions, mark->lights,
                                                         mark->stale, mark->weights, mark->counters);
        m_mark = std::move(mark);
    }
    const std::vector<Bounds> regions = mergeRegions(changes.regions, gpu::kSelectiveMaxRegions);
    std::vector<glm::vec4> corners;
    for (const Bounds& r : regions) {
        corners.emplace_back(r.min, 0.0f);
        corners.emplace_back(r.max, 0.0f);
    }
    if (!corners.empty()) m_mark->regions.upload(corners);
    std::vector<uint32_t> lightBits(m_mark->lightWords, 0u);
    for (uint32_t l : changes.lights) lightBits[l >> 5] |= 1u << (l & 31);
    m_mark->lights.upload(lightBits);
    m_mark->stale.upload(m_stale);

    gpu::SelectiveMarkParams params{};
    if (camera) params.camera = *camera;
    params.useCamera = camera ? 1u : 0u;
    params.pathCount = m_settings.paths;
    params.maxDeposits = m_settings.maxDeposits;
    params.regionCount = static_cast<uint32_t>(regions.size());
    params.lightCount = changes.lights.empty() ? 0u : lightCount;
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        m_mark->weights.fillZero(cmd);
        m_mark->counters.fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
        m_mark->pass->record(cmd, params);
        vk::computeToHostBarrier(cmd);
    });
    // Read-backs (one per map and frame with changes): the bits, the paths' weights, the counts.
    m_mark->stale.download(m_stale.data(), m_stale.size() * sizeof(uint32_t));
    std::vector<uint32_t> weights(m_settings.paths);
    m_mark->weights.download(weights.data(), weights.size() * sizeof(uint32_t));
    const auto counters = m_mark->counters.download<uint32_t>();
    stats.stalePathsFound = counters[gpu::kSelectiveMarkCounterFound];
    stats.changedRegions = regions.size();
    return weights;
}

SelectiveFrameStats SelectivePhotonUpdate::update(const Scene& scene, const SceneArrays& arrays,
                                                  const SceneBuffers& buffers, bool full, uint64_t sceneGeneration,
                                                  const gpu::GpuCamera* camera) {
    ++m_frame;
    m_marked.clear();
    m_retraced.clear();
    SelectiveFrameStats stats;
    // The same scene object as the last update's (moved in place): its static part is unchanged.
    const bool sameScene = m_tracer && m_tracerBuffers == &buffers && m_tracerGeneration == sceneGeneration;
    // The tracer (its kernel, photon and path-list buffers) lives across frames; a new one only
    // for new scene buffers (the frames loop rebuilt the scene) or another total light power.
    if (!m_tracer || m_tracerBuffers != &buffers || m_tracerGeneration != sceneGeneration ||
        m_tracerPower != arrays.totalLightPower) {
        m_tracer.reset();
        m_tracer = std::make_unique<PhotonTracer>(m_context, scene, arrays, buffers);
        m_tracerBuffers = &buffers;
        m_tracerGeneration = sceneGeneration;
        m_tracerPower = arrays.totalLightPower;
        m_tracer->reserve(std::min(m_settings.paths, m_chunkPaths), m_settings.maxDeposits, m_settings.trackPaths);
    }
    // What moved since the last update (exact detection needs the tracks of every path).
    const auto detectStart = Clock::now();
    auto snapshot = std::make_unique<SceneSnapshot>(
        snapshotScene(scene, arrays, sceneGeneration, sameScene ? m_snapshot.get() : nullptr));
    SceneChanges changes;
    if (m_snapshot) changes = sceneChanges(*m_snapshot, *snapshot);
    m_snapshot = std::move(snapshot);

    const uint32_t groupPaths = pathsInGroup(0);
    const uint32_t slotsPerPath = m_settings.maxDeposits;
    const size_t pilotSlots = size_t(m_pilotPaths) * slotsPerPath;
    auto contiguous = [](uint32_t first, uint32_t count) {
        std::vector<uint32_t> paths(count);
        for (uint32_t j = 0; j < count; ++j) paths[j] = first + j;
        return paths;
    };

    if (full || !m_initialised) {
        for (uint32_t done = 0; done < m_settings.paths; done += m_chunkPaths)
            traceIntoSlots(contiguous(done, std::min(m_chunkPaths, m_settings.paths - done)));
        m_pilotRecord.resize(pilotSlots);
        m_slots.download(m_pilotRecord.data(), 0, pilotSlots);
        std::fill(m_priority.begin(), m_priority.end(), 0u);
        std::fill(m_lastTraced.begin(), m_lastTraced.end(), m_frame);
        std::fill(m_stale.begin(), m_stale.end(), 0u);
        m_initialised = true;
        stats.full = true;
        stats.photonPathsTraced = m_settings.paths;
        stats.groupsRetraced = m_settings.groups;
        return stats;
    }

    // Exact detection: the tracks against what moved. A change no region bounds (a rebuilt scene
    // whose triangles or materials differ) makes every path stale: retraced by priority over the
    // next frames, as the budget allows.
    std::vector<uint32_t> weight;  // per path (stale paths only)
    bool anyStale = false;
    if (m_settings.trackPaths) {
        uint64_t foundOnHost = 0;
        if (changes.unknown) {
            uint64_t before = 0;
            for (uint32_t w : m_stale) before += std::popcount(w);
            std::fill(m_stale.begin(), m_stale.end(), ~0u);
            if (m_settings.paths % 32 != 0) m_stale.back() = (1u << (m_settings.paths % 32)) - 1u;
            foundOnHost = m_settings.paths - before;
            changes.regions.clear();
            changes.lights.clear();
        }
        for (uint32_t w : m_stale) anyStale = anyStale || w != 0;
        if (anyStale || changes.any()) weight = markStalePaths(changes, camera, stats);
        stats.stalePathsFound += foundOnHost;
    }
    stats.detectSeconds = secondsSince(detectStart);

    // Pilots: paths 0 .. m_pilotPaths - 1 (pilot m of group g is path g + m * groups), traced and
    // copied into their slots in one submission (per chunk of m_chunkPaths).
    {
        std::vector<gpu::GpuPhoton> now(pilotSlots);
        traceIntoSlots(contiguous(0, m_pilotPaths), [&](size_t first, size_t count) {
            // One read-back per chunk of pilots (one per frame but for huge maps;
            // docs/photon-mapping.md): their photons, compared on the host with the last frame's.
            m_tracer->photons().download(now.data() + first * slotsPerPath, count * slotsPerPath * sizeof(gpu::GpuPhoton));
        });
        std::vector<char> groupMarked(m_settings.groups, 0);
        for (uint32_t p = 0; p < m_pilotPaths; ++p) {
            const size_t first = size_t(p) * slotsPerPath;
            const bool explained = stale(p);  // the tracks found it: its group's stale paths are known
            clearStale(p);                    // traced now
            if (std::memcmp(&now[first], &m_pilotRecord[first], slotsPerPath * sizeof(gpu::GpuPhoton)) == 0) continue;
            stats.changedPilots += 1;
            groupMarked[groupOf(p)] = 1;
            if (!explained) m_priority[groupOf(p)] += 1;
        }
        for (uint32_t g = 0; g < m_settings.groups; ++g)
            if (groupMarked[g]) m_marked.push_back(g);
        m_pilotRecord = std::move(now);
        stats.pilotsTraced = m_pilotPaths;
        stats.photonPathsTraced = m_pilotPaths;
    }

    // What to retrace, the most visible change first (Dmitriev et al. §5.3's energy and view
    // criteria): each stale path by its weight (selective_mark.comp: the light its photons carry,
    // weighted by the camera's view), a group marked by a pilot the tracks did not explain as a
    // whole, weighing per path one photon in view per changed pilot (pilots only: the paper's count
    // of pilot hits). Ordered by weight per path traced, ties to the longest unrefreshed group and
    // the lower path; what does not fit is passed over for smaller ones. Detection is per path, so
    // the order is too: a Halton group's paths meet a small object in several places. Room for
    // refreshGroups groups of the round-robin refresh is kept; then the refresh fills the budget
    // (SelectiveSettings::fillBudget) or takes those groups only.
    struct Unit {
        double weight;  // per path traced
        uint32_t group;
        uint32_t path;  // ~0u: the whole group
    };
    std::vector<Unit> units;
    for (uint32_t g = 0; g < m_settings.groups; ++g)
        if (m_priority[g] > 0) units.push_back({double(m_priority[g]) * gpu::kSelectiveWeightScale, g, ~0u});
    for (uint32_t word = 0; word < m_stale.size(); ++word)
        for (uint32_t bits = m_stale[word]; bits != 0; bits &= bits - 1) {
            const uint32_t path = word * 32 + static_cast<uint32_t>(std::countr_zero(bits));
            if (path >= m_settings.paths || m_priority[groupOf(path)] > 0) continue;  // in a whole group
            units.push_back({double(weight.empty() ? 0u : weight[path]) + 1.0, groupOf(path), path});
        }
    std::sort(units.begin(), units.end(), [&](const Unit& a, const Unit& b) {
        if (a.weight != b.weight) return a.weight > b.weight;
        if (m_lastTraced[a.group] != m_lastTraced[b.group]) return m_lastTraced[a.group] < m_lastTraced[b.group];
        return a.path < b.path;
    });
    const uint64_t budget = m_settings.budget;
    auto fits = [&](uint32_t g) { return stats.photonPathsTraced + pathsInGroup(g) <= budget; };
    const uint64_t reserve = uint64_t(m_settings.refreshGroups) * groupPaths;
    std::vector<uint32_t> chosen;        // retraced whole
    std::vector<uint32_t> chosenPaths;   // stale paths
    std::vector<char> done(m_settings.groups, 0);
    for (const Unit& unit : units) {
        const uint64_t cost = unit.path == ~0u ? pathsInGroup(unit.group) : 1;
        if (stats.photonPathsTraced + cost + reserve > budget) continue;
        stats.photonPathsTraced += cost;
        if (unit.path == ~0u) {
            chosen.push_back(unit.group);
            done[unit.group] = 1;
        } else {
            chosenPaths.push_back(unit.path);
        }
    }
    uint32_t refreshed = 0;
    for (uint32_t visited = 0; visited < m_settings.groups; ++visited) {
        const uint32_t g = m_refreshCursor;
        if (done[g]) {
            m_refreshCursor = (m_refreshCursor + 1) % m_settings.groups;
            continue;
        }
        if (!fits(g) || (!m_settings.fillBudget && refreshed >= m_settings.refreshGroups)) break;
        refreshed += 1;
        chosen.push_back(g);
        done[g] = 1;
        stats.photonPathsTraced += pathsInGroup(g);
        m_refreshCursor = (m_refreshCursor + 1) % m_settings.groups;
    }
    // A stale path of a group the refresh retraces whole is traced once.
    std::erase_if(chosenPaths, [&](uint32_t path) {
        if (!done[groupOf(path)]) return false;
        stats.photonPathsTraced -= 1;
        return true;
    });
    traceGroups(chosen, chosenPaths);
    stats.groupsRetraced = m_retraced.size();
    // Left for later frames: what traceGroups did not clear.
    stats.stalePathsLeft = 0;
    std::vector<char> pendingGroup(m_settings.groups, 0);
    for (uint32_t g = 0; g < m_settings.groups; ++g) pendingGroup[g] = m_priority[g] > 0 ? 1 : 0;
    for (uint32_t word = 0; word < m_stale.size(); ++word)
        for (uint32_t bits = m_stale[word]; bits != 0; bits &= bits - 1) {
            const uint32_t path = word * 32 + static_cast<uint32_t>(std::countr_zero(bits));
            if (path >= m_settings.paths) continue;
            stats.stalePathsLeft += 1;
            pendingGroup[groupOf(path)] = 1;
        }
    for (char g : pendingGroup) stats.groupsPending += g ? 1 : 0;
    return stats;
}

SelectiveVerification SelectivePhotonUpdate::verify() {
    SelectiveVerification v;
    if (!m_initialised || !m_tracer) return v;
    const uint32_t slotsPerPath = m_settings.maxDeposits;
    std::vector<char> groupStale(m_settings.groups, 0);
    std::vector<gpu::GpuPhoton> fresh, kept;
    for (uint32_t done = 0; done < m_settings.paths; done += m_chunkPaths) {
        const uint32_t count = std::min(m_chunkPaths, m_settings.paths - done);
        PhotonSettings s = traceSettings();
        s.trackPaths = false;
        s.paths = count;
        s.firstPath = m_settings.firstPath + done;
        m_tracer->trace(s);
        fresh.resize(size_t(count) * slotsPerPath);
        kept.resize(fresh.size());
        m_tracer->photons().download(fresh.data(), fresh.size() * sizeof(gpu::GpuPhoton));
        m_slots.download(kept.data(), uint64_t(done) * slotsPerPath, kept.size());
        for (uint32_t j = 0; j < count; ++j) {
            uint64_t differing = 0;
            for (uint32_t k = 0; k < slotsPerPath; ++k) {
                const size_t i = size_t(j) * slotsPerPath + k;
                differing += std::memcmp(&fresh[i], &kept[i], sizeof(gpu::GpuPhoton)) != 0 ? 1 : 0;
            }
            if (differing == 0) continue;
            v.stalePhotons += differing;
            v.stalePaths += 1;
            v.differing.push_back(done + j);
            groupStale[groupOf(done + j)] = 1;
        }
    }
    v.paths = m_settings.paths;
    for (char g : groupStale) v.staleGroups += g ? 1 : 0;
    return v;
}

std::vector<gpu::GpuPhoton> SelectivePhotonUpdate::downloadSlots() const {
    return m_slots.download<gpu::GpuPhoton>(uint64_t(m_settings.paths) * m_settings.maxDeposits);
}

}  // namespace vkp
