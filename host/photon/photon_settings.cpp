#include "photon/photon_settings.h"

#include <algorithm>
#include <cmath>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "shared/photon_render.glsl"
#include "util/check_range.h"
#include "photon/photon_path_options.h"
#include "render/integrator_registry.h"
#include "util/errors.h"

namespace vkp {

void PhotonIntegratorSettings::check() const {
    checkPhotonPaths(globalPaths, maxDeposits);
    checkRange("--caustic-photons", causticPaths, 0u, 1u << 30);
    checkRange("--gather-rays", gatherRays, 0u, 1024u);
    checkRange("--gather-k", gatherK, 1u, gpu::kMaxGatherK);
    checkRange("--radiance-photons", radiancePhotonStride, 0u, 1024u);
    checkRange("--gather-guide", gatherGuide, 0.0f, 1.0f);
    checkRange("--gather-reuse", gatherReuse, 0.0f, float(gpu::kMaxGatherReuseWindow));
    if (radius != 0.0f) checkPositive("--radius", radius);
    if (!(coneK >= 1.0f)) throw InputError(fmt::format("cone filter k {}: must be at least 1", coneK));
    checkRange("--alpha", alpha, 0.01f, 0.99f);
    if (q != 0.0f) checkRange("--q", q, 1.0e-6f, 1.0f);
    deposit.check();
}

float PhotonIntegratorSettings::radiusFor(const Scene& scene) const {
    if (radius > 0.0f) return radius;
    const float r = 0.015f * std::max(0.5f * glm::length(scene.bounds.extent()), 1e-6f);
    if (!(r > 0.0f) || !std::isfinite(r))
        throw InputError(fmt::format("the scene's extent gives no usable gather radius ({}): give --radius", r));
    return r;
}

void PhotonIntegratorSettings::report(Stats& stats) const {
    stats.set("settings.photon.photons", globalPaths);
    stats.set("settings.photon.causticPhotons", causticPaths);
    stats.set("settings.photon.gatherRays", gatherRays);
    stats.set("settings.photon.gatherK", gatherK);
    stats.set("settings.photon.gatherGuide", gatherGuide);
    stats.set("settings.photon.gatherReuse", gatherReuse);
    stats.set("settings.photon.radiancePhotons", radiancePhotonStride);
    stats.set("settings.photon.progressive", progressive);
    stats.set("settings.photon.alpha", alpha);
    stats.set("settings.photon.q", q);
    stats.set("settings.photon.deposit", depositModeName(deposit.mode));
    stats.set("settings.photon.importons", deposit.importonPaths);
    stats.set("settings.photon.depositEpsilon", deposit.epsilon);
    stats.set("settings.photon.depositCutoff", deposit.cutoff);
    stats.set("settings.photon.densityAccuracy", deposit.densityAccuracy);
    stats.set("settings.photon.densityRounds", deposit.densityRounds);
    stats.set("settings.photon.densityRoulette", deposit.densityRoulette);
    stats.set("photons.deposit", depositModeName(deposit.mode));
}

void PhotonIntegratorSettings::addOptions(IntegratorOptions& options) {
    CLI::App& maps = options.group("photon maps", {"photon", "sppm"});
    addPhotonPathOptions(maps, globalPaths, maxDeposits, "Photon paths for the global map (per pass of sppm)");
    maps.add_option("--radius", radius,
                    "Caustic gather radius and sppm's initial radius, world units [default: 1.5% of the scene's "
                    "bounding radius]");
    deposit.addOptions(maps);

    CLI::App& group = options.group("final gathering", {"photon"});
    CLI::Option* caustic =
        group.add_option("--caustic-photons", causticPaths, "Photon paths for the caustic map (0: no caustic map)")
            ->capture_default_str();
    group.add_option("--gather-rays", gatherRays,
                     "Final gather rays per sample (0: read the global map at the visible point)")
        ->capture_default_str();
    group.add_option("--gather-k", gatherK, "Nearest photons per global-map estimate")->capture_default_str();
    group.add_option("--gather-guide", gatherGuide,
                     "Probability of a final-gather direction importance-sampled from the global map's indirect photons "
                     "(a guiding grid per cell, Jensen 1995), else from the BSDF; weighted by the mixture density "
                     "(0: the BSDF's alone)")
        ->capture_default_str();
    group.add_option("--gather-reuse", gatherReuse,
                     "Pixels within which rough surfaces share their final-gather rays, each weighting the others' "
                     "by its own BSDF (in pixel footprints, shrinking as samples grow; 0: each pixel its own rays)")
        ->capture_default_str();
    group.add_option("--radiance-photons", radiancePhotonStride,
                     "About every n-th global photon carries a precomputed irradiance estimate that final gathers read "
                     "(0: a k-nearest estimate at every gather hit)")
        ->capture_default_str();
    group.add_option("--q", q,
                     "Keller & Wald's ratio: --photons paths fill the caustic map and the first q of them the global "
                     "map (instead of --caustic-photons)")
        ->excludes(caustic);

    options.group("progressive photon mapping", {"sppm"})
        .add_option("--alpha", alpha, "sppm's radius reduction: fraction of new photons kept per pass")
        ->capture_default_str();
}

}  // namespace vkp
