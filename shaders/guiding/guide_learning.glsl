// The learning path tracer's side of learning the guiding cache (guided_learning_pathtrace.comp,
// shared/kernels/guide_learn.glsl): a path notes each of its first kGuideLearnVertices guided
// vertices (the grid's direction cell the sample went to, the throughput after it) and, when it
// ends, adds the radiance that arrived there along the sampled direction to that cell. Only light
// that a further bounce brought counts: the emission the sampled ray finds is direct light, which
// next-event estimation samples and the guiding photons leave out too. The includer defines
// GUIDE_LEARN_SUMS_BINDING and has prepared the vertex's guide (prepareGuide).
// A sample adds at most kGuideLearnCap times its grid's irradiance from the photons (at least
// kGuideLearnMinIrradiance times pi times the scene's mean radiance): the rare path that finds a
// bright spot through a long chain of bounces would otherwise make a spike of one cell for
// iterations. The cap only shapes the guide; the image's samples keep their whole weight.
#ifndef VKP_GUIDE_LEARNING_GLSL
#define VKP_GUIDE_LEARNING_GLSL

#include "shared/kernels/guide_learn.glsl"

layout(std430, set = 0, binding = GUIDE_LEARN_SUMS_BINDING) buffer GuideLearnSums { vec4 learnHeader; uvec2 learned[]; };

struct GuideLearnRecord {
    uint slot;    // the sum the sample adds to: grid * kGuideLearnStride + direction cell
    vec3 base;    // the path's radiance before the light the sampled direction brought
    vec3 weight;  // per channel: cos / (pdf * throughput after the vertex), 0 where that is 0
    float cap;    // the most the sample adds, in the sums' units
};
const float kGuideLearnCap = 8.0f;
const float kGuideLearnMinIrradiance = 0.05f;
// The path's records, newest first, in variables rather than an array: lavapipe keeps an array
// indexed by a variable in memory, per lane, and its reads and writes cost more than the shifts.
GuideLearnRecord learnRecord0;
GuideLearnRecord learnRecord1;
GuideLearnRecord learnRecord2;
GuideLearnRecord learnRecord3;
uint learnRecordCount;
bool learnBasePending;  // the last record's base waits for the next vertex's emission

void learnBeginPath() {
    learnRecordCount = 0u;
    learnBasePending = false;
}

// Notes the direction `bs` sampled at the guided vertex v; `throughput`: the path's after it.
void learnNoteVertex(PathVertex v, BsdfSample bs, vec3 throughput, vec3 radiance) {
    if (!vertexGuide.guided || learnRecordCount >= kGuideLearnVertices || (bs.lobe & kLobeDelta) != 0u || !(bs.pdf > 0.0f))
        return;
    vec3 wiGrid = toLocal(toWorld(bs.wi, v.t, v.b, v.n), vertexGuide.t, vertexGuide.b, vertexGuide.normal);
    if (wiGrid.z <= 0.0f) return;  // outside the grid's hemisphere: no cell learns it
    uint m = guide.gridSize & 0xffu;
    uint n = (guide.gridSize >> 8u) & 0xffu;
    uint cell = guideDirectionCell(wiGrid, m, n);
    GuideLearnRecord r;
    r.slot = (vertexGuide.cdfBase / kMaxGuideCells) * kGuideLearnStride + cell;
    r.base = radiance;
    vec3 inverse = vec3(throughput.r > 0.0f ? 1.0f / throughput.r : 0.0f, throughput.g > 0.0f ? 1.0f / throughput.g : 0.0f,
                        throughput.b > 0.0f ? 1.0f / throughput.b : 0.0f);
    r.weight = inverse * (bs.wi.z / bs.pdf);
    r.cap = kGuideLearnCap * max(luminance(vertexGuide.irradiance.rgb) * learnHeader.x,
                                 kPi * kGuideLearnMinIrradiance * kGuideLearnFixedPoint);
    learnRecord3 = learnRecord2;
    learnRecord2 = learnRecord1;
    learnRecord1 = learnRecord0;
    learnRecord0 = r;
    learnRecordCount += 1u;
    learnBasePending = true;
}

// At the next vertex, after its emission (or the environment's) was added: what arrives later is
// the light the sampled direction brought from further bounces.
void learnSetBase(vec3 radiance) {
    if (!learnBasePending) return;
    learnRecord0.base = radiance;
    learnBasePending = false;
}

// Adds `value` to a 64-bit sum of two words, carrying into the high word.
void learnAdd(uint slot, uint value) {
    if (value == 0u) return;
    uint old = atomicAdd(learned[slot].x, value);
    if (old + value < old) atomicAdd(learned[slot].y, 1u);
}

// Adds what arrived along record r's direction, the path having ended with `radiance`.
void learnSplat(GuideLearnRecord r, vec3 radiance, bool finite) {
    float value = luminance(max(radiance - r.base, vec3(0.0f)) * r.weight) * learnHeader.x;
    if (finite && value > 0.0f) learnAdd(r.slot, uint(min(min(value, r.cap), kGuideLearnMaxSample - 1.0f) + 0.5f));
    uint grid = r.slot / kGuideLearnStride;
    learnAdd(grid * kGuideLearnStride + kGuideLearnCountSlot, 1u);
}

// The path has ended with `radiance`: each noted vertex adds what arrived along its direction.
void learnEndPath(vec3 radiance) {
    bool finite = !any(isnan(radiance)) && !any(isinf(radiance));
    if (learnRecordCount > 0u) learnSplat(learnRecord0, radiance, finite);
    if (learnRecordCount > 1u) learnSplat(learnRecord1, radiance, finite);
    if (learnRecordCount > 2u) learnSplat(learnRecord2, radiance, finite);
    if (learnRecordCount > 3u) learnSplat(learnRecord3, radiance, finite);
    learnBeginPath();
}

#endif
