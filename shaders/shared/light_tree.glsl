// The light BVH's node bounds and their importance at a shading point (Conty Estevez & Kulla,
// "Importance Sampling of Many Lights with Adaptive Tree Splitting", HPG 2018, in the form of
// pbrt-v4's LightBounds::Importance). A node bounds the positions (box), the emission directions
// (a cone of half-angle theta_o around `axis`, plus the spread theta_e beyond it) and the total
// power of the lights below it. The importance is an upper-bound-shaped estimate of what they
// deliver to a point p with normal n: power * cos(theta') / distance^2 * cos(theta_i'), 0 only
// where no light below the node can reach p's side. host/lights/light_tree.cpp builds the
// tree; shared/light_selection.glsl walks it.
#ifndef VKP_LIGHT_TREE_GLSL
#define VKP_LIGHT_TREE_GLSL
#include "compat.glsl"
#include "constants.glsl"
SHARED_BEGIN

// One node: 16 floats in the light-selection buffer (shared/light_selection.glsl).
struct GpuLightNode {
    vec3 boundsMin;
    float power;           // summed luminous power of the lights below (selection weight)
    vec3 boundsMax;
    float cosThetaO;       // cos of the emission-direction cone's half-angle (-1: all directions)
    vec3 axis;             // unit axis of that cone
    float cosThetaE;       // cos of the emission spread beyond the cone (0: a hemisphere)
    uint childOrLight;     // inner: index of the second child (the first follows the node); leaf: light
    uint flags;            // kLightNode*
    uint pad0;
    uint pad1;
};
STATIC_ASSERT_SIZE(GpuLightNode, 64)

const uint kLightNodeLeaf = 1u;
const uint kLightNodeTwoSided = 2u;  // emits on both sides of the cone (double-sided triangles)
const uint kLightNodeFloats = 16u;
const uint kLightTreeMaxDepth = 32u; // the light's path from the root fits a uint (bit d: second child at depth d)

// cos(a - b) from cos/sin, 1 where a < b (clamped at 0 angle).
INLINE float cosSubClamped(float sinA, float cosA, float sinB, float cosB) {
    if (cosA > cosB) return 1.0f;
    return cosA * cosB + sinA * sinB;
}

// sin(a - b) from cos/sin, 0 where a < b.
INLINE float sinSubClamped(float sinA, float cosA, float sinB, float cosB) {
    if (cosA > cosB) return 0.0f;
    return sinA * cosB - cosA * sinB;
}

// Importance of node `b` at point p; n: the surface normal there (either side), or zero for a point
// in a medium. Deterministic: sampling and the pdf of a given light evaluate it identically.
INLINE float lightNodeImportance(GpuLightNode b, vec3 p, vec3 n) {
    vec3 pc = 0.5f * (b.boundsMin + b.boundsMax);
    vec3 diag = b.boundsMax - b.boundsMin;
    vec3 toP = p - pc;
    float d2 = dot(toP, toP);
    float halfDiag = 0.5f * length(diag);
    d2 = max(d2, halfDiag);  // pbrt-v4's clamp: a point inside or beside the box stays finite
    float dist = sqrt(dot(toP, toP));
    vec3 wi = dist > 0.0f ? toP / dist : vec3(0.0f, 0.0f, 1.0f);

    float cosThetaW = dot(b.axis, wi);
    if ((b.flags & kLightNodeTwoSided) != 0u) cosThetaW = abs(cosThetaW);
    float sinThetaW = sqrt(max(0.0f, 1.0f - cosThetaW * cosThetaW));

    // Half-angle theta_b of the cone of directions from p that the box's bounding sphere subtends.
    float radius2 = halfDiag * halfDiag;
    float cosThetaB = -1.0f;
    if (dist * dist > radius2) cosThetaB = sqrt(max(0.0f, 1.0f - radius2 / (dist * dist)));
    float sinThetaB = sqrt(max(0.0f, 1.0f - cosThetaB * cosThetaB));

    // theta' = max(0, theta_w - theta_o - theta_b): the smallest angle between an emission
    // direction of the node and a direction towards p.
    float sinThetaO = sqrt(max(0.0f, 1.0f - b.cosThetaO * b.cosThetaO));
    float cosThetaX = cosSubClamped(sinThetaW, cosThetaW, sinThetaO, b.cosThetaO);
    float sinThetaX = sinSubClamped(sinThetaW, cosThetaW, sinThetaO, b.cosThetaO);
    float cosThetaP = cosSubClamped(sinThetaX, cosThetaX, sinThetaB, cosThetaB);
    if (cosThetaP <= b.cosThetaE) return 0.0f;

    float importance = b.power * cosThetaP / d2;
    if (dot(n, n) > 0.0f) {
        // theta_i' = max(0, theta_i - theta_b): the least angle of incidence at p.
        float cosThetaI = abs(dot(wi, n));
        float sinThetaI = sqrt(max(0.0f, 1.0f - cosThetaI * cosThetaI));
        importance *= cosSubClamped(sinThetaI, cosThetaI, sinThetaB, cosThetaB);
    }
    return max(importance, 0.0f);
}

SHARED_END
#endif
