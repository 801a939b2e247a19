#include "photon/selective_photon_update.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "util/errors.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"
#include "vk/image.h"

namespace vkp {
namespace {

constexpr uint32_t kFullChunkPaths = 1u << 16;  // paths per trace at most (fewer when a path has many slots)

}  // namespace

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
    const uint64_t pathBytes = uint64_t(settings.maxDeposits) * sizeof(gpu::GpuPhoton);
    m_chunkPaths = static_cast<uint32_t>(std::min<uint64_t>(settings.chunkPaths ? settings.chunkPaths : kFullChunkPaths,
                                                            context.properties().limits.maxStorageBufferRange / pathBytes));
    if (m_chunkPaths == 0)
        throw InputError(fmt::format("selective photon update: --max-deposits {}: one path's slots exceed the device's "
                                     "storage-buffer range",
                                     settings.maxDeposits));
    const uint64_t slots = uint64_t(settings.paths) * settings.maxDeposits;
    m_slots = vk::SegmentedBuffer(context, "selective photon slots", sizeof(gpu::GpuPhoton), slots, settings.segmentShift);
    m_slots.reserve(slots);
    m_priority.assign(settings.groups, 0);
    m_lastTraced.assign(settings.groups, 0);
}

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
    m_slots.recordCopyFrom(cmd, tracer.photons(), copies);
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
    return s;
}

void SelectivePhotonUpdate::appendGroupPaths(uint32_t group, std::vector<uint32_t>& paths) const {
    for (uint32_t path = group; path < m_settings.paths; path += m_settings.groups) paths.push_back(path);
}

void SelectivePhotonUpdate::traceGroups(const std::vector<uint32_t>& groups) {
    std::vector<uint32_t> paths;
    if (m_settings.batched) {  // every group in one dispatch and one submission (per chunk)
        for (uint32_t g : groups) appendGroupPaths(g, paths);
        traceIntoSlots(paths);
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
    }
    for (uint32_t g : groups) {
        m_priority[g] = 0;
        m_lastTraced[g] = m_frame;
        m_retraced.push_back(g);
    }
}

SelectiveFrameStats SelectivePhotonUpdate::update(const Scene& scene, const SceneArrays& arrays,
                                                  const SceneBuffers& buffers, bool full, uint64_t sceneGeneration) {
    ++m_frame;
    m_marked.clear();
    m_retraced.clear();
    SelectiveFrameStats stats;
    // The tracer (its kernel, photon and path-list buffers) lives across frames; a new one only
    // for new scene buffers (the frames loop rebuilt the scene) or another total light power.
    if (!m_tracer || m_tracerBuffers != &buffers || m_tracerGeneration != sceneGeneration ||
        m_tracerPower != arrays.totalLightPower) {
        m_tracer.reset();
        m_tracer = std::make_unique<PhotonTracer>(m_context, scene, arrays, buffers);
        m_tracerBuffers = &buffers;
        m_tracerGeneration = sceneGeneration;
        m_tracerPower = arrays.totalLightPower;
        m_tracer->reserve(std::min(m_settings.paths, m_chunkPaths), m_settings.maxDeposits);
    }
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
        m_initialised = true;
        stats.full = true;
        stats.photonPathsTraced = m_settings.paths;
        stats.groupsRetraced = m_settings.groups;
        return stats;
    }

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
            if (std::memcmp(&now[first], &m_pilotRecord[first], slotsPerPath * sizeof(gpu::GpuPhoton)) == 0) continue;
            stats.changedPilots += 1;
            m_priority[groupOf(p)] += 1;
            groupMarked[groupOf(p)] = 1;
        }
        for (uint32_t g = 0; g < m_settings.groups; ++g)
            if (groupMarked[g]) m_marked.push_back(g);
        m_pilotRecord = std::move(now);
        stats.pilotsTraced = m_pilotPaths;
        stats.photonPathsTraced = m_pilotPaths;
    }

    // Marked groups by priority (more changed pilots first, then the stalest), leaving room for
    // the round-robin refresh of refreshGroups groups; then the refresh fills the budget. The
    // groups chosen are then traced together (traceGroups).
    const uint64_t budget = m_settings.budget;
    auto fits = [&](uint32_t g) { return stats.photonPathsTraced + pathsInGroup(g) <= budget; };
    std::vector<uint32_t> pending;
    for (uint32_t g = 0; g < m_settings.groups; ++g)
        if (m_priority[g] > 0) pending.push_back(g);
    std::stable_sort(pending.begin(), pending.end(), [&](uint32_t a, uint32_t b) {
        if (m_priority[a] != m_priority[b]) return m_priority[a] > m_priority[b];
        return m_lastTraced[a] < m_lastTraced[b];
    });
    const uint64_t reserve = uint64_t(m_settings.refreshGroups) * groupPaths;
    std::vector<uint32_t> chosen;
    std::vector<char> done(m_settings.groups, 0);
    for (uint32_t g : pending) {
        if (stats.photonPathsTraced + pathsInGroup(g) + reserve > budget) break;
        chosen.push_back(g);
        done[g] = 1;
        stats.photonPathsTraced += pathsInGroup(g);
    }
    for (uint32_t visited = 0; visited < m_settings.groups; ++visited) {
        const uint32_t g = m_refreshCursor;
        if (done[g]) {
            m_refreshCursor = (m_refreshCursor + 1) % m_settings.groups;
            continue;
        }
        if (!fits(g)) break;
        chosen.push_back(g);
        done[g] = 1;
        stats.photonPathsTraced += pathsInGroup(g);
        m_refreshCursor = (m_refreshCursor + 1) % m_settings.groups;
    }
    traceGroups(chosen);
    stats.groupsRetraced = m_retraced.size();
    for (uint32_t g = 0; g < m_settings.groups; ++g) stats.groupsPending += m_priority[g] > 0 ? 1 : 0;
    return stats;
}

std::vector<gpu::GpuPhoton> SelectivePhotonUpdate::downloadSlots() const {
    return m_slots.download<gpu::GpuPhoton>(uint64_t(m_settings.paths) * m_settings.maxDeposits);
}

}  // namespace vkp
