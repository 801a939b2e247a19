// Warps from the unit square to directions and surfaces, with their pdfs. Local frames have the
// normal along +z.
#ifndef VKP_SAMPLING_GLSL
#define VKP_SAMPLING_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

// Orthonormal basis around a unit normal (Duff et al., "Building an Orthonormal Basis, Revisited",
// JCGT 2017).
INLINE void orthonormalBasis(vec3 n, INOUT(vec3) t, INOUT(vec3) b) {
    float s = n.z >= 0.0f ? 1.0f : -1.0f;
    float a = -1.0f / (s + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0f + s * n.x * n.x * a, s * c, -s * n.x);
    b = vec3(c, s + n.y * n.y * a, -n.y);
}

INLINE vec3 toWorld(vec3 local, vec3 t, vec3 b, vec3 n) {
    return local.x * t + local.y * b + local.z * n;
}

INLINE vec3 toLocal(vec3 v, vec3 t, vec3 b, vec3 n) {
    return vec3(dot(v, t), dot(v, b), dot(v, n));
}

// Cosine-weighted hemisphere: theta = acos(sqrt(1 - u.x)), phi = 2 pi u.y (the mapping Jensen 1995
// builds the guiding grid on), pdf = cos(theta) / pi.
INLINE vec3 sampleCosineHemisphere(vec2 u) {
    float r = sqrt(u.x);
    float phi = kTwoPi * u.y;
    return vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0f, 1.0f - u.x)));
}

INLINE float cosineHemispherePdf(float cosTheta) {
    return max(cosTheta, 0.0f) * kInvPi;
}

// Inverse of sampleCosineHemisphere for a local direction with z > 0.
INLINE vec2 invertCosineHemisphere(vec3 w) {
    float u = clamp(w.x * w.x + w.y * w.y, 0.0f, kOneMinusEpsilon);
    float phi = atan(w.y, w.x);
    if (phi < 0.0f) phi = phi + kTwoPi;
    return vec2(u, min(phi / kTwoPi, kOneMinusEpsilon));
}

INLINE vec3 sampleUniformSphere(vec2 u) {
    float z = 1.0f - 2.0f * u.x;
    float r = sqrt(max(0.0f, 1.0f - z * z));
    float phi = kTwoPi * u.y;
    return vec3(r * cos(phi), r * sin(phi), z);
}

// Uniform point on a triangle as barycentrics (b1, b2) of v1 and v2 (Osada et al. 2002).
INLINE vec2 sampleTriangleBarycentrics(vec2 u) {
    float s = sqrt(u.x);
    return vec2(s * (1.0f - u.y), s * u.y);
}

// Uniform direction in a cone around +z with cos(half angle) = cosMax.
INLINE vec3 sampleUniformCone(vec2 u, float cosMax) {
    float cosTheta = 1.0f - u.x * (1.0f - cosMax);
    float sinTheta = sqrt(max(0.0f, 1.0f - cosTheta * cosTheta));
    float phi = kTwoPi * u.y;
    return vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

INLINE float powerHeuristic(float pdfA, float pdfB) {
    float a = pdfA * pdfA;
    float b = pdfB * pdfB;
    return a + b > 0.0f ? a / (a + b) : 0.0f;
}

INLINE float luminance(vec3 c) {
    return dot(c, vec3(0.2126f, 0.7152f, 0.0722f));
}

SHARED_END
#endif
