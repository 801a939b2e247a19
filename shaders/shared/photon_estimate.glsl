// Photon-map radiance estimation (Jensen; shared/papers/004) and the progressive radius update of
// stochastic progressive photon mapping (Hachisuka & Jensen 2009).
#ifndef VKP_PHOTON_ESTIMATE_GLSL
#define VKP_PHOTON_ESTIMATE_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

// Cone filter (Jensen 1996): photon at distance d from the query, gather radius r, k >= 1:
// w = 1 - d / (k r). Normalised by the filter's integral over the disk relative to the disk
// area, 1 - 2 / (3 k), so L = sum(f_r * dPhi * w) / ((1 - 2/(3k)) * pi * r^2).
INLINE float coneFilterWeight(float d, float r, float k) {
    return max(0.0f, 1.0f - d / (k * r));
}

INLINE float coneFilterNormalization(float k) {
    return 1.0f - 2.0f / (3.0f * k);
}

// Density estimate denominator for a disk of radius r with the cone filter.
INLINE float coneFilterArea(float r, float k) {
    return coneFilterNormalization(k) * kPi * r * r;
}

// k-nearest density estimates (Jensen: sum dPhi / (pi r^2), r the distance of the k-th nearest
// photon) overestimate a smooth density by k / (k - 1): the k-th photon sits on the disk's edge
// (for Poisson points of density lambda around a query point, E[1 / (pi r_k^2)] = lambda / (k - 1)).
// This factor makes such an estimate unbiased where the density is locally uniform: (k - 1) / k
// when the k-th photon set the radius (found == k), 1 when fewer were found within the search's
// fixed radius. Radiance photons take it as well: their estimates are made at a photon (one of the
// k) but read at the nearest one to a gather hit, which favours photons with sparse surroundings,
// and measured they carry the same k / (k - 1) (docs/photon-mapping.md).
INLINE float nearestEstimateScale(uint found, uint k) {
    return found >= k && k > 1u ? float(k - 1u) / float(k) : 1.0f;
}

// Progressive radius reduction (Hachisuka & Jensen 2009, eq. 5-7): a query point that has
// accumulated n photons with squared radius r2 and receives m new ones inside it keeps
// n + alpha m of them and shrinks its area in proportion. The accumulated flux is scaled by the
// same area ratio. Returns the new squared radius; n and the flux scale are updated.
INLINE float progressiveRadiusUpdate(float r2, INOUT(float) n, float m, float alpha, INOUT(float) fluxScale) {
    if (m <= 0.0f) {
        fluxScale = 1.0f;
        return r2;
    }
    float nNew = n + alpha * m;
    float ratio = nNew / (n + m);
    n = nNew;
    fluxScale = ratio;
    return r2 * ratio;
}

SHARED_END
#endif
