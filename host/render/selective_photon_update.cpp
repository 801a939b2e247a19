#include "render/selective_photon_update.h"

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

#include "util/errors.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"
#include "vk/image.h"

namespace vkp {
namespace {

constexpr uint32_t kFullChunkPaths = 1u << 16;  // paths per chunk of a full trace

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
    const uint64_t bytes = uint64_t(settings.paths) * settings.maxDeposits * sizeof(gpu::GpuPhoton);
    if (bytes > context.properties().limits.maxStorageBufferRange)
        throw InputError(fmt::format("selective photon update: {} paths x {} deposits exceed the device's storage-buffer range",
                                     settings.paths, settings.maxDeposits));
    m_slots = vk::Buffer(context, "selective photon slots", bytes, vk::kStorageUsage);
    m_priority.assign(settings.groups, 0);
    m_lastTraced.assign(settings.groups, 0);
}

uint32_t SelectivePhotonUpdate::pathsInGroup(uint32_t group) const {
    return group < m_settings.paths ? (m_settings.paths - group + m_settings.groups - 1) / m_settings.groups : 0;
}

void SelectivePhotonUpdate::copyPaths(PhotonTracer& tracer, uint32_t firstPath, uint32_t stride, uint32_t count) {
    const VkDeviceSize pathBytes = VkDeviceSize(m_settings.maxDeposits) * sizeof(gpu::GpuPhoton);
    std::vector<VkBufferCopy> regions;
    if (stride == 1) {
        regions.push_back({0, firstPath * pathBytes, count * pathBytes});
    } else {
        regions.reserve(count);
        for (uint32_t j = 0; j < count; ++j)
            regions.push_back({j * pathBytes, (firstPath + VkDeviceSize(j) * stride) * pathBytes, pathBytes});
    }
    m_context.submitAndWait([&](VkCommandBuffer cmd) {
        vk::memoryBarrier2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdCopyBuffer(cmd, tracer.photons().handle(), m_slots.handle(), static_cast<uint32_t>(regions.size()),
                        regions.data());
        vk::memoryBarrier2(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
                           VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
    });
}

void SelectivePhotonUpdate::traceGroup(PhotonTracer& tracer, uint32_t group) {
    PhotonSettings s;
    s.paths = pathsInGroup(group);
    s.firstPath = m_settings.firstPath + group;
    s.pathStride = m_settings.groups;
    s.maxDeposits = m_settings.maxDeposits;
    s.seed = m_settings.seed;
    tracer.trace(s);
    copyPaths(tracer, group, m_settings.groups, s.paths);
    m_priority[group] = 0;
    m_lastTraced[group] = m_frame;
    m_retraced.push_back(group);
}

SelectiveFrameStats SelectivePhotonUpdate::update(const Scene& scene, const SceneArrays& arrays,
                                                  const SceneBuffers& buffers, bool full) {
    ++m_frame;
    m_marked.clear();
    m_retraced.clear();
    SelectiveFrameStats stats;
    PhotonTracer tracer(m_context, scene, arrays, buffers);
    const uint32_t groupPaths = pathsInGroup(0);
    tracer.reserve(std::max({std::min(m_settings.paths, kFullChunkPaths), groupPaths, m_pilotPaths}),
                   m_settings.maxDeposits);
    const uint32_t slotsPerPath = m_settings.maxDeposits;
    const size_t pilotSlots = size_t(m_pilotPaths) * slotsPerPath;

    if (full || !m_initialised) {
        for (uint32_t done = 0; done < m_settings.paths; done += kFullChunkPaths) {
            PhotonSettings s;
            s.paths = std::min(kFullChunkPaths, m_settings.paths - done);
            s.firstPath = m_settings.firstPath + done;
            s.maxDeposits = m_settings.maxDeposits;
            s.seed = m_settings.seed;
            tracer.trace(s);
            copyPaths(tracer, done, 1, s.paths);
        }
        m_pilotRecord.resize(pilotSlots);
        m_slots.download(m_pilotRecord.data(), pilotSlots * sizeof(gpu::GpuPhoton));
        std::fill(m_priority.begin(), m_priority.end(), 0u);
        std::fill(m_lastTraced.begin(), m_lastTraced.end(), m_frame);
        m_initialised = true;
        stats.full = true;
        stats.photonPathsTraced = m_settings.paths;
        stats.groupsRetraced = m_settings.groups;
        return stats;
    }

    // Pilots: paths 0 .. m_pilotPaths - 1 (pilot m of group g is path g + m * groups).
    {
        PhotonSettings s;
        s.paths = m_pilotPaths;
        s.firstPath = m_settings.firstPath;
        s.maxDeposits = m_settings.maxDeposits;
        s.seed = m_settings.seed;
        tracer.trace(s);
        // Read-back (docs/photon-mapping.md): the pilots' photons, compared on the host with
        // the last frame's (a few thousand paths).
        std::vector<gpu::GpuPhoton> now(pilotSlots);
        tracer.photons().download(now.data(), pilotSlots * sizeof(gpu::GpuPhoton));
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
        copyPaths(tracer, 0, 1, m_pilotPaths);
        stats.pilotsTraced = m_pilotPaths;
        stats.photonPathsTraced = m_pilotPaths;
    }

    // Marked groups by priority (more changed pilots first, then the stalest), leaving room for
    // the round-robin refresh of refreshGroups groups; then the refresh fills the budget.
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
    for (uint32_t g : pending) {
        if (stats.photonPathsTraced + pathsInGroup(g) + reserve > budget) break;
        traceGroup(tracer, g);
        stats.photonPathsTraced += pathsInGroup(g);
    }
    std::vector<char> done(m_settings.groups, 0);
    for (uint32_t g : m_retraced) done[g] = 1;
    for (uint32_t visited = 0; visited < m_settings.groups; ++visited) {
        const uint32_t g = m_refreshCursor;
        if (done[g]) {
            m_refreshCursor = (m_refreshCursor + 1) % m_settings.groups;
            continue;
        }
        if (!fits(g)) break;
        traceGroup(tracer, g);
        stats.photonPathsTraced += pathsInGroup(g);
        m_refreshCursor = (m_refreshCursor + 1) % m_settings.groups;
    }
    stats.groupsRetraced = m_retraced.size();
    for (uint32_t g = 0; g < m_settings.groups; ++g) stats.groupsPending += m_priority[g] > 0 ? 1 : 0;
    return stats;
}

std::vector<gpu::GpuPhoton> SelectivePhotonUpdate::downloadSlots() const {
    std::vector<gpu::GpuPhoton> photons(size_t(m_settings.paths) * m_settings.maxDeposits);
    m_slots.download(photons.data(), photons.size() * sizeof(gpu::GpuPhoton));
    return photons;
}

}  // namespace vkp
