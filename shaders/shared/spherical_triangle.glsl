// Sampling an emissive triangle as seen from a shading point: uniformly over the solid angle it
// subtends (Arvo, "Stratified Sampling of Spherical Triangles", SIGGRAPH 1995, in the form of
// pbrt-v4's SampleSphericalTriangle), or uniformly over its area where the solid angle is too
// small (float cancellation in the angle sum) or nearly a hemisphere (the warp degenerates).
// Next-event estimation (sampleLight) and the MIS weight of emission found by BSDF sampling
// (emissionMisWeight) both take the pdf from triangleLightPdf, so the two always agree on which
// strategy was used.
#ifndef VKP_SPHERICAL_TRIANGLE_GLSL
#define VKP_SPHERICAL_TRIANGLE_GLSL
#include "compat.glsl"
#include "constants.glsl"
#include "sampling.glsl"
SHARED_BEGIN

// Solid angles (steradians) outside which a triangle light is sampled by area instead.
// Below 3e-3 sr (a triangle seen under ~3 degrees) area sampling's pdf hardly varies over the
// triangle, and Arvo's warp loses float precision (on lavapipe, whose sin and cos are polynomials,
// samples of 3e-4..1e-3 sr triangles moved by 0.1-1 % of the triangle against the C++ build).
const float kMinSphericalSolidAngle = 3.0e-3f;
const float kMaxSphericalSolidAngle = 6.22f;

// Solid angle of the spherical triangle of unit directions a, b, c (Van Oosterom & Strackee 1983).
INLINE float sphericalTriangleArea(vec3 a, vec3 b, vec3 c) {
    float num = abs(dot(a, cross(b, c)));
    float den = 1.0f + dot(a, b) + dot(a, c) + dot(b, c);
    return abs(2.0f * atan(num, den));
}

// Solid angle the triangle v0 v1 v2 subtends at p (0 when p lies in its plane or on a vertex).
INLINE float triangleSolidAngle(vec3 v0, vec3 v1, vec3 v2, vec3 p) {
    vec3 a = v0 - p;
    vec3 b = v1 - p;
    vec3 c = v2 - p;
    float la = length(a);
    float lb = length(b);
    float lc = length(c);
    if (la <= 0.0f || lb <= 0.0f || lc <= 0.0f) return 0.0f;
    return sphericalTriangleArea(a / la, b / lb, c / lc);
}

// Whether a triangle subtending `solidAngle` at the shading point is sampled by solid angle.
INLINE bool useSphericalSampling(float solidAngle) {
    return solidAngle >= kMinSphericalSolidAngle && solidAngle <= kMaxSphericalSolidAngle;
}

// The same, where `allowed` is false (--triangle-sampling area, the old behaviour) never.
INLINE bool useSphericalSampling(float solidAngle, bool allowed) {
    return allowed && useSphericalSampling(solidAngle);
}

// v - (v.w) w, normalized (w unit).
INLINE vec3 orthogonalizedAgainst(vec3 v, vec3 w) {
    vec3 r = v - dot(v, w) * w;
    float l = length(r);
    return l > 0.0f ? r / l : r;
}

// A direction from p uniformly distributed over the solid angle of triangle v0 v1 v2, returned as
// the barycentrics (b1, b2) of v1 and v2 of the point it reaches on the triangle. `ok` is false
// when the triangle is degenerate as seen from p.
INLINE vec2 sampleSphericalTriangle(vec3 v0, vec3 v1, vec3 v2, vec3 p, vec2 u, OUT(bool) ok) {
    ok = false;
    vec3 a = normalize(v0 - p);
    vec3 b = normalize(v1 - p);
    vec3 c = normalize(v2 - p);
    vec3 nab = cross(a, b);
    vec3 nbc = cross(b, c);
    vec3 nca = cross(c, a);
    if (dot(nab, nab) <= 0.0f || dot(nbc, nbc) <= 0.0f || dot(nca, nca) <= 0.0f) return vec2(0.0f);
    nab = normalize(nab);
    nca = normalize(nca);
    // The angle alpha at a only through its cosine and sine, and the area A = alpha + beta +
    // gamma - pi from Van Oosterom & Strackee's formula (the pdf's own, triangleSolidAngle): no
    // inverse sine. With A = alpha + beta + gamma - pi from three asin-based angles (a small
    // difference of large angles for small triangles), lavapipe's samples landed up to 2 % of the
    // triangle away from the C++ build's, in 30 % of the harness's cases; this form cut that to
    // 0.3 % (tests/lights/light_selection_test.cpp, LightSelectionGpu). The cause is lavapipe's asin
    // precision (not measured on its own).
    float cosAlpha = clamp(-dot(nab, nca), -1.0f, 1.0f);
    float sinAlpha = length(cross(nab, nca));
    float area = sphericalTriangleArea(a, b, c);

    // Area A' = u0 * A of the sub-triangle a b' c' that the sample's arc ends on.
    float apPi = kPi + u.x * area;
    float sinPhi = sin(apPi) * cosAlpha - cos(apPi) * sinAlpha;
    float cosPhi = cos(apPi) * cosAlpha + sin(apPi) * sinAlpha;
    float k1 = cosPhi + cosAlpha;
    float k2 = sinPhi - sinAlpha * dot(a, b);
    float cosBp = (k2 + (k2 * cosPhi - k1 * sinPhi) * cosAlpha) / ((k2 * sinPhi + k1 * cosPhi) * sinAlpha);
    if (!(cosBp == cosBp)) return vec2(0.0f);  // NaN: the triangle covers nearly a hemisphere
    cosBp = clamp(cosBp, -1.0f, 1.0f);
    float sinBp = sqrt(max(0.0f, 1.0f - cosBp * cosBp));
    vec3 cp = cosBp * a + sinBp * orthogonalizedAgainst(c, a);

    // Uniform in solid angle along the arc from b to c'.
    float cosTheta = 1.0f - u.y * (1.0f - dot(cp, b));
    float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
    vec3 w = cosTheta * b + sinTheta * orthogonalizedAgainst(cp, b);

    // Where w meets the triangle's plane (Moeller-Trumbore), as barycentrics.
    vec3 e1 = v1 - v0;
    vec3 e2 = v2 - v0;
    vec3 s1 = cross(w, e2);
    float divisor = dot(s1, e1);
    if (divisor == 0.0f) return vec2(0.0f);
    float inv = 1.0f / divisor;
    vec3 s = p - v0;
    float b1 = clamp(dot(s, s1) * inv, 0.0f, 1.0f);
    float b2 = clamp(dot(w, cross(s, e1)) * inv, 0.0f, 1.0f);
    float sum = b1 + b2;
    if (sum > 1.0f) {
        b1 = b1 / sum;
        b2 = b2 / sum;
    }
    ok = true;
    return vec2(b1, b2);
}

// Solid-angle density (selection excluded) with which a triangle light's sample reaches the
// point q on it from p: 1 / solid angle where useSphericalSampling(.., solidAngleAllowed) holds,
// else the area density 1 / area converted to solid angle (distance^2 / (area |cos|)). 0 when q
// is seen edge-on.
INLINE float triangleLightPdf(vec3 v0, vec3 v1, vec3 v2, vec3 p, vec3 q, bool solidAngleAllowed) {
    if (solidAngleAllowed) {
        float solidAngle = triangleSolidAngle(v0, v1, v2, p);
        if (useSphericalSampling(solidAngle)) return 1.0f / solidAngle;
    }
    vec3 c = cross(v1 - v0, v2 - v0);
    float twiceArea = length(c);
    vec3 d = q - p;
    float dist2 = dot(d, d);
    if (twiceArea <= 0.0f || dist2 <= 0.0f) return 0.0f;
    float cosLight = abs(dot(d, c)) / (sqrt(dist2) * twiceArea);
    if (cosLight < 1.0e-7f) return 0.0f;
    return 2.0f * dist2 / (twiceArea * cosLight);
}

SHARED_END
#endif
