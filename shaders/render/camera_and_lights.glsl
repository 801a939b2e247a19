// GLSL-only helpers shared by the camera-path integrators (pathtrace.comp, visible_points.comp):
// next-event estimation and the MIS weight of emission found by BSDF sampling. Include after
// scene_access.glsl and shared/halton.glsl.
#ifndef VKP_CAMERA_AND_LIGHTS_GLSL
#define VKP_CAMERA_AND_LIGHTS_GLSL

#include "render/path_vertex.glsl"

// The density with which the including integrator samples directions at a vertex, for next-event
// estimation's MIS weight: the BSDF's (pdfVertexMis), unless the includer defines
// CAMERA_PATH_DIRECTION_PDF as a function (PathVertex, local wi) declared before this file (the
// guided path tracer: its mixture of guiding grid and BSDF). Both sides of the power heuristic
// must use the density the samples really have, or their weights do not sum to one.
#ifndef CAMERA_PATH_DIRECTION_PDF
#define CAMERA_PATH_DIRECTION_PDF pdfVertexMis
#endif

// Next-event estimation at a non-delta path vertex: one light chosen by the light sampler
// (selectLight, shared/light_selection.glsl) at the vertex's position and shading normal, one
// sample on it, a shadow ray. With `mis` the contribution of area lights is weighted by the power heuristic
// against BSDF sampling (the caller then MIS-weights emission found by BSDF rays); without it the
// estimate stands alone. Lights whose type bit (1 << type) is set in skipTypes contribute nothing:
// another pass (the raster direct light) adds their full expectation, so dropping them keeps the
// sum unbiased without changing the light selection. Always draws 3 sample dimensions.
vec3 directLight(PathVertex v, uint lightCount, bool mis, uint skipTypes, inout Sampler rng) {
    float uPick = nextSample(rng);
    vec2 uLight = nextSample2(rng);
    if (lightCount == 0u) return vec3(0.0f);
    LightChoice choice = selectLight(lightCount, v.hit.position, v.n, uPick);
    if (choice.pdf <= 0.0f) return vec3(0.0f);
    uint index = choice.index;
    if ((skipTypes & (1u << lights[index].type)) != 0u) return vec3(0.0f);
    LightSample ls = sampleLight(index, choice.pdf, triangleSolidAngleSampling(lightCount), v.hit.position, uLight);
    if (ls.pdf <= 0.0f) return vec3(0.0f);
    vec3 wi = toLocal(ls.wi, v.t, v.b, v.n);
    vec3 f = evalVertexDirect(v, ls, wi);  // zero for a light behind the surface, but through rough glass
    if (f.r + f.g + f.b <= 0.0f) return vec3(0.0f);
    if (!lightVisible(v.hit.position, v.hit.geometricNormal, ls)) return vec3(0.0f);
    float weight = ls.delta || !mis ? 1.0f : powerHeuristic(ls.pdf, CAMERA_PATH_DIRECTION_PDF(v, wi));
    return f * abs(wi.z) * ls.radiance * (weight / ls.pdf);
}

// MIS weight (power heuristic) of emission that a BSDF-sampled ray with solid-angle pdf `bsdfPdf`
// found at vertex v, against next-event estimation of that point from the vertex the ray left
// (its position `from` and shading normal `fromNormal`, as directLight saw them there): the
// light's selection pdf there times the pdf of its sample (solid angle or area).
float emissionMisWeight(PathVertex v, float bsdfPdf, uint lightCount, vec3 from, vec3 fromNormal) {
    float lightIndex = lightIndexOfHit(v.hit.triangle);
    if (lightIndex < 0.0f) return 1.0f;  // not in the light list: only BSDF sampling finds it
    float selectPdf = selectLightPdf(lightCount, from, fromNormal, uint(lightIndex));
    GpuTriangle t = triangles[v.hit.triangle];
    float lightPdf = selectPdf * triangleLightPdf(t.v0.xyz, t.v1.xyz, t.v2.xyz, from, v.hit.position,
                                                  triangleSolidAngleSampling(lightCount));
    return powerHeuristic(bsdfPdf, lightPdf);
}

// Environment light arriving along a camera-path ray that left the scene along dir: in full
// behind the camera and delta bounces (`mis` false), else weighted by the power heuristic against
// next-event estimation of the environment (bsdfPdf: the solid-angle pdf of the escaping ray;
// from, fromNormal: the vertex it left and its shading normal, as emissionMisWeight takes them).
vec3 escapedRadiance(uint lightCount, vec3 dir, bool mis, float bsdfPdf, vec3 from, vec3 fromNormal) {
    int index = environmentLightIndex(lightCount);
    if (index < 0) return vec3(0.0f);
    vec3 le = environmentRadiance(lights[index], dir);
    return mis ? le * environmentMisWeight(lightCount, dir, bsdfPdf, from, fromNormal) : le;
}

#endif
