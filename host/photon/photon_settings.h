// Settings of the photon integrators (--integrator photon, the two-pass method, and sppm):
// what they trace, how they estimate, and their command-line options (docs/photon-mapping.md).
#pragma once

#include <cstdint>

#include "photon/deposit_options.h"
#include "photon/photon_path_options.h"
#include "render/stats.h"
#include "scene/scene.h"


namespace vkp {

class IntegratorOptions;

struct PhotonIntegratorSettings {
    uint32_t globalPaths = kDefaultPhotonPaths;  // --photons: paths traced for the global map (per pass of sppm)
    uint32_t causticPaths = 500000;   // --caustic-photons: paths traced for the caustic map (0: none)
    uint32_t gatherRays = 1;          // --gather-rays per sample; 0 reads the global map at the visible point
    uint32_t gatherK = 32;            // --gather-k nearest photons per global-map estimate
    float gatherGuide = 0.5f;         // --gather-guide: probability of a gather direction from the photons'
                                      // guiding grid (else the BSDF's; mixture-weighted); 0: the BSDF's alone
    float gatherReuse = 4.0f;         // --gather-reuse: pixels (footprints) within which rough surfaces share
                                      // their final-gather rays, shrinking with the sample count; 0: not shared
    uint32_t radiancePhotonStride = 8;  // --radiance-photons: about every n-th global photon carries a
                                        // precomputed estimate for final gathers (0: estimate at every hit)
    float radius = 0.0f;              // --radius (world units); 0: 1.5 % of the scene's bounding radius
    float coneK = 1.1f;               // cone filter constant of the caustic estimate
    bool progressive = false;         // --integrator sppm (--progressive): a fresh photon pass per sample
    float alpha = 0.7f;               // --alpha: SPPM's fraction of new photons kept per pass
    uint32_t maxDeposits = kDefaultMaxDeposits;  // --max-deposits: photon slots per global path
    float q = 0.0f;                   // --q: --photons paths fill the caustic map, the first q of them the
                                      // global map (Keller & Wald's N, q); 0: --caustic-photons paths
    DepositOptions deposit;           // --deposit and its flags
    uint32_t mapSegmentShift = 0;     // photons per buffer of a map, log2 (0: 4 M); no flag: tests lower
                                      // it to split small maps over many buffers (PhotonMapSettings)

    // Throws InputError naming the flag of a value out of range.
    void check() const;
    // The gather radius: --radius, or 1.5 % of the scene's bounding radius.
    float radiusFor(const Scene& scene) const;
    // Registers the options, writing into this object: the maps' for photon and sppm, the final
    // gather's for photon, --alpha for sppm.
    void addOptions(IntegratorOptions& options);
    // "settings.photon.*" and "photons.deposit".
    void report(Stats& stats) const;
};

}  // namespace vkp
