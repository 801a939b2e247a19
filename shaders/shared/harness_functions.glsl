// The shared functions exercised by the shader unit harness, behind one dispatcher so that the
// GPU kernel (tests/shaders/shared_functions_test.comp) and the C++ reference run identical code.
// Results are returned as raw bits: integer results compare exactly, float results within a
// tolerance (GPU transcendental and division precision is not IEEE-exact).
#ifndef VKP_HARNESS_FUNCTIONS_GLSL
#define VKP_HARNESS_FUNCTIONS_GLSL
#include "compat.glsl"
#include "bsdf.glsl"
#include "halton.glsl"
#include "hash.glsl"
#include "sampling.glsl"
SHARED_BEGIN

struct HarnessInput {
    vec4 a;
    vec4 b;
    uvec4 u;
};
STATIC_ASSERT_SIZE(HarnessInput, 48)

const uint kHarnessPcgHash = 0u;
const uint kHarnessRadicalInverseDigits = 1u;
const uint kHarnessSamplerSequence = 2u;
const uint kHarnessCosineHemisphere = 3u;
const uint kHarnessGgxVisibleNormal = 4u;
const uint kHarnessEvalBsdf = 5u;
const uint kHarnessPdfBsdf = 6u;
const uint kHarnessFresnelDielectric = 7u;
const uint kHarnessOrthonormalBasis = 8u;
const uint kHarnessSampleBsdf = 9u;
const uint kHarnessRoughDielectric = 10u;
const uint kHarnessAnisotropicBsdf = 11u;
const uint kHarnessThinFilm = 12u;
const uint kHarnessRoughDielectricFilm = 13u;
const uint kHarnessFunctionCount = 14u;

INLINE uvec4 floatBits(vec4 v) {
    return uvec4(floatBitsToUint(v.x), floatBitsToUint(v.y), floatBitsToUint(v.z), floatBitsToUint(v.w));
}

INLINE BsdfParams harnessBsdfParams(HarnessInput in_) {
    BsdfParams p = makeBsdfParams(vec3(in_.b.x, in_.b.y, in_.b.z), in_.b.w, in_.a.w);
    p.ior = 1.0f + float(in_.u.y % 100u) * 0.01f;
    // KHR_materials_specular: weight 0, 0.25 .. 1 and an F0 colour up to 2 in green.
    p.specular = float((in_.u.y >> 8u) % 5u) * 0.25f;
    p.specularColor = vec3(1.0f, float((in_.u.y >> 12u) % 5u) * 0.5f, 1.0f);
    // KHR_materials_clearcoat: none, half or full, of roughness 0.3; a third of the coats have a
    // normal of their own, tilted 22 degrees off the shading normal.
    p.clearcoat = float((in_.u.y >> 16u) % 3u) * 0.5f;
    p.clearcoatRoughness = 0.3f;
    if ((in_.u.y >> 20u) % 3u == 0u) {
        p.clearcoatNormal = normalize(vec3(0.3f, -0.2f, 0.9f));
        p.flags |= kBsdfCoatNormal;
    }
    return p;
}

INLINE vec3 harnessDirection(vec2 u) {
    vec3 w = sampleCosineHemisphere(u);
    return normalize(vec3(w.x, w.y, max(w.z, 1.0e-3f)));
}

INLINE uvec4 evaluateHarnessFunction(uint function, HarnessInput in_) {
    if (function == kHarnessPcgHash) {
        return uvec4(pcgHash(in_.u.x), hashCombine(in_.u.x, in_.u.y), 0u, 0u);
    }
    if (function == kHarnessRadicalInverseDigits) {
        uint limit = 0u;
        uint base = haltonPrime(in_.u.z % kHaltonDimensions);
        uint digits = scrambledRadicalInverseDigits(base, in_.u.x, in_.u.y, limit);
        return uvec4(digits, limit, base, 0u);
    }
    if (function == kHarnessSamplerSequence) {
        Sampler s = makeSampler(in_.u.x, in_.u.y);
        s.dimension = in_.u.z % 40u;
        float x = nextSample(s);
        float y = nextSample(s);
        return floatBits(vec4(x, y, float(s.dimension), 0.0f));
    }
    if (function == kHarnessCosineHemisphere) {
        vec3 w = sampleCosineHemisphere(vec2(in_.a.x, in_.a.y));
        return floatBits(vec4(w, cosineHemispherePdf(w.z)));
    }
    if (function == kHarnessGgxVisibleNormal) {
        vec3 wo = harnessDirection(vec2(in_.a.x, in_.a.y));
        float alpha = max(in_.a.w * in_.a.w, kMinAlpha);
        vec3 h = sampleGgxVisibleNormal(wo, alpha, vec2(in_.a.z, in_.b.x));
        return floatBits(vec4(h, ggxD(h, alpha)));
    }
    if (function == kHarnessEvalBsdf || function == kHarnessPdfBsdf) {
        BsdfParams p = harnessBsdfParams(in_);
        vec3 wo = harnessDirection(vec2(in_.a.x, in_.a.y));
        vec3 wi = harnessDirection(vec2(in_.a.z, float(in_.u.x & 0xffffu) / 65536.0f));
        if (function == kHarnessEvalBsdf) return floatBits(vec4(evalBsdf(p, wo, wi), 0.0f));
        return floatBits(vec4(pdfBsdf(p, wo, wi), 0.0f, 0.0f, 0.0f));
    }
    if (function == kHarnessFresnelDielectric) {
        float eta = 0.5f + 1.5f * in_.a.y;
        return floatBits(vec4(fresnelDielectric(in_.a.x, eta), dielectricF0(1.0f + in_.a.z), 0.0f, 0.0f));
    }
    if (function == kHarnessOrthonormalBasis) {
        vec3 n = normalize(sampleUniformSphere(vec2(in_.a.x, in_.a.y)));
        vec3 t;
        vec3 b;
        orthonormalBasis(n, t, b);
        return floatBits(vec4(t.x, t.y, t.z, dot(cross(t, b), n)));
    }
    if (function == kHarnessSampleBsdf) {
        BsdfParams p = harnessBsdfParams(in_);
        vec3 wo = harnessDirection(vec2(in_.a.x, in_.a.y));
        BsdfSample s = sampleBsdf(p, wo, true, true, vec3(in_.a.z, in_.b.x, in_.b.y));
        return floatBits(vec4(s.wi.x, s.wi.y, s.wi.z, s.pdf));
    }
    if (function == kHarnessRoughDielectric) {
        // Rough glass (roughness 0.1 .. 1), solid or thin, entering or leaving: one sample of
        // sampleBsdf and the layer's eval and pdf at the sampled direction.
        BsdfParams p = harnessBsdfParams(in_);
        p.roughness = 0.1f + 0.9f * in_.a.w;
        p.transmission = 1.0f;
        p.thinWalled = in_.u.z & 1u;
        bool entering = (in_.u.z & 2u) == 0u;
        vec3 wo = harnessDirection(vec2(in_.a.x, in_.a.y));
        BsdfSample s = sampleBsdf(p, wo, entering, true, vec3(in_.b.w, in_.a.z, in_.b.x));
        return floatBits(vec4(s.wi.z, s.weight.x, evalDielectricLayer(p, wo, s.wi, entering, true).x,
                              pdfDielectricLayer(p, wo, s.wi, entering)));
    }
    if (function == kHarnessAnisotropicBsdf) {
        // KHR_materials_anisotropy: strength 0.25 .. 1 along one of 16 directions; eval and pdf at
        // a direction, and one sample of sampleBsdf.
        BsdfParams p = harnessBsdfParams(in_);
        p.anisotropy = float(((in_.u.y >> 24u) & 3u) + 1u) * 0.25f;
        float angle = float((in_.u.y >> 26u) & 15u) * (kTwoPi / 16.0f);
        p.anisotropyDirection = vec2(cos(angle), sin(angle));
        vec3 wo = harnessDirection(vec2(in_.a.x, in_.a.y));
        vec3 wi = harnessDirection(vec2(in_.a.z, float(in_.u.x & 0xffffu) / 65536.0f));
        BsdfSample s = sampleBsdf(p, wo, true, true, vec3(in_.b.w, in_.a.z, in_.b.x));
        return floatBits(vec4(evalBsdf(p, wo, wi).y, pdfBsdf(p, wo, wi), s.wi.x, s.pdf));
    }
    if (function == kHarnessThinFilm) {
        // KHR_materials_iridescence's film: ior 1 .. 2.5, thickness 0 .. 1200 nm, any angle and base.
        vec3 f = thinFilmFresnel(1.0f, 1.0f + 1.5f * in_.a.x, in_.a.y, 1200.0f * in_.a.z, vec3(in_.b.x, in_.b.y, in_.b.z));
        return floatBits(vec4(f, 0.0f));
    }
    if (function == kHarnessRoughDielectricFilm) {
        // Rough glass (roughness 0.1 .. 1, solid or thin) under KHR_materials_iridescence's film (factor
        // 0.25 .. 1, ior 1 .. 2.5, 100 .. 1100 nm), seen from outside: one sample of sampleBsdf (its
        // direction and blue weight) and the layer's eval (green) and pdf at the sampled direction.
        BsdfParams p = harnessBsdfParams(in_);
        p.roughness = 0.1f + 0.9f * in_.a.w;
        p.transmission = 1.0f;
        p.thinWalled = in_.u.z & 1u;
        p.iridescence = 0.25f + 0.75f * in_.b.z;
        p.iridescenceIor = 1.0f + 1.5f * in_.a.z;
        p.iridescenceThickness = 100.0f + 1000.0f * in_.b.y;
        vec3 wo = harnessDirection(vec2(in_.a.x, in_.a.y));
        BsdfSample s = sampleBsdf(p, wo, true, true, vec3(in_.b.w, in_.a.z, in_.b.x));
        return floatBits(vec4(s.wi.z, s.weight.z, evalDielectricLayer(p, wo, s.wi, true, true).y,
                              pdfDielectricLayer(p, wo, s.wi, true)));
    }
    return uvec4(0u);
}

SHARED_END
#endif
