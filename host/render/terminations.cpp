#include "render/terminations.h"

#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "render/stats.h"
#include "vk/buffer.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {
namespace {

// countTerminations (shaders/common/termination_counters.glsl) adds one slot per kind, written out.
static_assert(gpu::kTerminationKindCount == 3, "termination_counters.glsl: countTerminations lists every kind");

struct Named {
    const char* key;    // stats key
    const char* words;  // in a warning
};

constexpr std::array<Named, gpu::kTerminationKindCount> kKinds{{
    {"stackOverflow", "the BVH traversal stack overflowed (subtrees skipped)"},
    {"loopLimit", "a loop ended early (lavapipe's 65535-iteration loop budget)"},
    {"loopBound", "a loop reached its own bound (64 bounces of a photon path, 2^22 nodes of one traversal)"},
}};
constexpr std::array<Named, gpu::kTerminationSubjectCount> kSubjects{{
    {"samples", "camera sample(s)"},
    {"gathers", "photon-map lookup(s)"},
    {"photonPaths", "photon path(s)"},
    {"importonPaths", "importon path(s)"},
    {"gridCells", "photon-grid cell(s)"},
}};

}  // namespace

uint64_t TerminationCounts::total() const {
    uint64_t sum = 0;
    for (uint32_t c : counts) sum += c;
    return sum;
}

std::string terminationKindName(uint32_t kind) { return kKinds.at(kind).key; }
std::string terminationSubjectName(uint32_t subject) { return kSubjects.at(subject).key; }

void clearTerminations(vk::Context& context) {
    context.submitAndWait([&](VkCommandBuffer cmd) {
        context.terminationCounters().fillZero(cmd);
        vk::transferToComputeBarrier(cmd);
    });
}

TerminationCounts readTerminations(const vk::Context& context) {
    TerminationCounts out;
    context.terminationCounters().download(out.counts.data(), sizeof(out.counts));
    return out;
}

void reportTerminations(const TerminationCounts& counts, Stats& stats) {
    for (uint32_t kind = 0; kind < gpu::kTerminationKindCount; ++kind) {
        std::vector<std::string> cut;
        for (uint32_t subject = 0; subject < gpu::kTerminationSubjectCount; ++subject) {
            const uint32_t n = counts.at(kind, subject);
            stats.set(fmt::format("terminations.{}.{}", kKinds[kind].key, kSubjects[subject].key), n);
            if (n > 0) cut.push_back(fmt::format("{} {}", n, kSubjects[subject].words));
        }
        if (!cut.empty())
            stats.warn(fmt::format("{} cut short: {}", fmt::join(cut, ", "), kKinds[kind].words));
    }
}

}  // namespace vkp
