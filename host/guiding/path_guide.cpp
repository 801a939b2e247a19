#include "guiding/path_guide.h"

#include <algorithm>
#include <charconv>
#include <numbers>
#include <string_view>

#include <cstdio>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "util/check_range.h"
#include "util/cli_choice.h"
#include "util/errors.h"
#include "util/stopwatch.h"
#include "vk/compute_kernel.h"
#include "vk/context.h"

namespace vkp {
namespace {

// Gathers search up to this many times the map's even-spread radius for k photons.
constexpr float kGuideRadiusFactor = 2.0f;

}  // namespace

void GuideSettings::check() const {
    checkRange("--guide-photons", photons, 1u, 1u << 26);
    checkRange("--guide-k", k, 1u, gpu::kMaxGatherK);
    // Each factor on its own first: their product must not wrap around.
    if (gridU == 0 || gridV == 0 || gridU > gpu::kMaxGuideCells || gridV > gpu::kMaxGuideCells ||
        gridU * gridV > gpu::kMaxGuideCells)
        throw InputError(fmt::format("--guide-grid {}x{}: needs 1 <= m * n <= {}", gridU, gridV, gpu::kMaxGuideCells));
    checkRange("--guide-adapt", adaptPhotons, 0u, 0xffffu);
    checkRange("--guide-mix", mix, 0.0f, 1.0f);
}

void GuideSettings::addOptions(CLI::App& group, bool sampling) {
    group.add_option("--guide-photons", photons, "Photon paths for the guiding map")->capture_default_str();
    group.add_option("--guide-k", k, "Nearest photons per guiding grid")->capture_default_str();
    group.add_option_function<std::string>(
             "--guide-grid",
             [this](const std::string& value) {
                 // Digits only, each factor read whole: sscanf's %u wraps 4294967297 to 1.
                 const auto factor = [&](std::string_view digits) {
                     uint64_t v = 0;
                     const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
                     if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || v > 0xffffffffu)
                         throw CLI::ValidationError("--guide-grid", "expected MxN with M, N from 1 to 64, e.g. 4x16");
                     return static_cast<uint32_t>(v);
                 };
                 const size_t x = value.find('x');
                 if (x == std::string::npos) throw CLI::ValidationError("--guide-grid", "expected MxN, e.g. 4x16");
                 gridU = factor(std::string_view(value).substr(0, x));
                 gridV = factor(std::string_view(value).substr(x + 1));
             },
             "Guiding grid MxN over the unit square (theta bands x phi sectors, M*N <= 64)")
        ->default_str(fmt::format("{}x{}", gridU, gridV));
    if (!sampling) return;
    const std::vector<std::pair<std::string, bool>> onOff{{"on", true}, {"off", false}};
    group.add_option("--guide-cache", cache,
                     "on: grids built once per cache cell and normal bin; off: a k-nearest gather at every vertex "
                     "(the paper)")
        ->transform(oneOf(onOff))
        ->option_text(choiceText(onOff, cache));
    group.add_option("--guide-adapt", adaptPhotons,
                     "Coarsen a guiding-cache grid whose photons are too few, down to this many photons per direction "
                     "cell (0: every grid at --guide-grid)")
        ->capture_default_str();
    group.add_option("--guide-rr", roulette,
                     "on: Russian roulette by the guide's estimate of the light a path still brings against the "
                     "pixel's (adjoint-driven); off: by the path's throughput")
        ->transform(oneOf(onOff))
        ->option_text(choiceText(onOff, roulette));
    group.add_option("--guide-learn", learn,
                     "on: refine the guiding cache's grids from the path tracer's own samples, at every doubling of "
                     "the samples; off: the photons' grids throughout (needs --guide-cache on)")
        ->transform(oneOf(onOff))
        ->option_text(choiceText(onOff, learn));
    group.add_option("--guide-mix", mix, "Probability of sampling the guiding grid rather than the BSDF (1: the paper's "
                                         "method)")
        ->capture_default_str();
}

void GuideSettings::report(Stats& stats) const {
    stats.set("settings.guide.photons", photons);
    stats.set("settings.guide.k", k);
    stats.set("settings.guide.grid", fmt::format("{}x{}", gridU, gridV));
    stats.set("settings.guide.mix", mix);
    stats.set("settings.guide.cache", cache);
    stats.set("settings.guide.roulette", roulette);
    stats.set("settings.guide.adapt", adaptPhotons);
    stats.set("settings.guide.learn", learn && cache);
}

PathGuide::PathGuide(const GpuScene& scene, const GuideSettings& g, uint32_t seed, const RenderControl* control) {
    g.check();
    vk::Context& context = scene.context();
    const SceneArrays& arrays = scene.arrays();
    const auto start = Clock::now();
    PhotonMapSettings mapSettings;
    mapSettings.paths = g.photons;
    mapSettings.seed = seed;
    mapSettings.rejectedFlags = gpu::kPhotonPrimary;
    mapSettings.control = control;
    const double area = sceneSurfaceArea(arrays);
    mapSettings.cellSizeFor = [&](uint64_t stored) { return evenSpreadRadius(g.k, stored, area); };
    m_map = std::make_unique<PhotonMap>(context, scene.scene(), arrays, scene.buffers(), mapSettings);
    m_mapStats = m_map->build(0);
    m_searchRadius = kGuideRadiusFactor * m_mapStats.cellSize;
    m_params.grid = m_map->grid().view(m_map->photonPower());
    m_params.mix = g.mix;
    m_params.k = g.k;
    m_params.maxRadius = m_searchRadius;
    m_params.gridSize = g.gridU | (g.gridV << 8) | (g.adaptPhotons << 16);
    m_shader = "guided_pathtrace.comp";
    // No indirect photons (a scene lit only directly): nothing to guide by, sample the BSDF.
    if (m_mapStats.stored == 0) m_params.mix = 0.0f;
    if (g.cache && m_mapStats.stored > 0) {
        m_cache = makeGuideCache(context, m_map->grid().photonArray(), m_mapStats.stored, m_mapStats.stored, g.k, area,
                                 m_params, 0);
        context.submitAndWait([&](VkCommandBuffer cmd) {
            vk::computeBarrier(cmd);
            m_cache->record(cmd);
        });
        m_params = m_cache->params();
        m_shader = "guided_cached_pathtrace.comp";
        if (g.learn) {
            const double meanRadiance = arrays.totalLightPower / (std::numbers::pi * area);
            m_learning = std::make_unique<GuideLearning>(context, *m_cache, meanRadiance);
            m_shader = "guided_learning_pathtrace.comp";
        }
    }
    m_seconds = secondsSince(start);
}

std::vector<const vk::Buffer*> PathGuide::buffers() const {
    if (m_learning) return {&m_cache->cells(), &m_cache->cdfs(), &m_cache->irradiance(), &m_learning->sums()};
    if (m_cache) return {&m_cache->cells(), &m_cache->cdfs(), &m_cache->irradiance()};
    return {&m_map->grid().cellStart(), &m_map->grid().photons()};
}

void PathGuide::report(Stats& stats) const {
    stats.add("photons.pathsTraced", m_mapStats.traced.emitted);
    stats.set("photons.globalStored", m_mapStats.stored);
    stats.add("photons.dropped", m_mapStats.dropped);
    stats.add("photons.seconds", m_seconds);
    stats.add("photons.mapBytes", m_map->bytes() + (m_cache ? m_cache->bytes() : 0) + (m_learning ? m_learning->bytes() : 0));
    stats.set("settings.guide.searchRadius", m_searchRadius);
}

}  // namespace vkp
