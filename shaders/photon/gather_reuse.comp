// Final gathers shared between neighbouring pixels (docs/photon-mapping.md, "Gathers shared
// between pixels"). final_gather.comp left each ray of this camera sample in the gather-sample
// buffer: its direction wi_q and L_q / pdf_q, L_q the radiance it brought back to pixel q's visible
// point and pdf_q the density q drew it from. A pixel p whose BSDF is rough (gatherReusable) adds
//
//     (1 / n) sum over the n rays of the pixels q near p:  f_p(wi_q) cos_p(wi_q) L_q / pdf_q
//
// Each term estimates p's reflection integral with q's incident radiance over the part of p's
// hemisphere above q's horizon; divided by that part's cosine-weighted share, (1 + cos delta) / 2,
// it stands for the whole (exactly so for a Lambertian p under uniform light). q counts when its
// visible point lies on p's surface (within `radius` of p's pixel footprint, normals within
// kGatherReuseCos, off p's plane by at most a tenth of the radius): the error left is how much the
// incident light changes over that distance,
// and the host shrinks the radius with the sample index so that it vanishes as samples grow
// (photon_integrator.cpp, gatherReuseRadius). p's own rays always count: with radius 0 this is
// the plain final gather.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "shared/kernels/photon_estimates.glsl"
#include "render/scene_access.glsl"
#include "render/path_vertex.glsl"
#include "photon/visible_point_access.glsl"
#include "shared/photon_render.glsl"

layout(local_size_x = kPhotonEstimateGroupSize) in;

layout(std430, set = 0, binding = kGatherReuseFilmBinding) buffer Film { vec4 film[]; };
layout(std430, set = 0, binding = kGatherReusePointBinding) readonly buffer VisiblePoints { GpuVisiblePoint visiblePoints[]; };
layout(std430, set = 0, binding = kGatherReuseSampleBinding) readonly buffer GatherSamples { GatherSample gatherSamples[]; };

layout(push_constant) uniform Push { GatherReuseParams params; };

// The sum of f_p cos / pdf_q L_q over the rays of the pixels that share p's surface, and how many
// rays that is. `lambertian` (a constant at each call) gives the loop a copy without evalBsdf's
// other lobes (evalBsdfAs): lavapipe runs a loop's every branch under a mask, so the test inside
// evalBsdf alone saves little.
vec3 neighbourSum(uint pixel, GpuVisiblePoint vp, VisibleSurface s, const bool lambertian, out uint rays) {
    uint pixels = params.width * params.height;
    vec3 normal = decodeOctahedral(vp.geometricNormal);
    float radius = params.radius * vp.coneWidth * params.footprintScale;
    float planeTolerance = 0.1f * radius;
    int window = int(min(params.window, kMaxGatherReuseWindow));
    int x = int(pixel % params.width);
    int y = int(pixel / params.width);
    BsdfWoTerms woTerms = bsdfWoTerms(s.bsdf, s.wo);  // p's BSDF at many wi: its wo terms once
    vec3 sum = vec3(0.0f);
    rays = 0u;
    for (int dy = -window; dy <= window; ++dy) {
        for (int dx = -window; dx <= window; ++dx) {
            int qx = x + dx;
            int qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= int(params.width) || qy >= int(params.height)) continue;
            uint q = uint(qy) * params.width + uint(qx);
            GpuVisiblePoint vq = visiblePoints[q];
            if ((vq.flags & kVisiblePointValid) == 0u || ((vq.flags ^ vp.flags) & kVisiblePointFrontFace) != 0u) continue;
            vec3 offset = vq.position - vp.position;
            bool own = q == pixel;
            if (!own && (dot(offset, offset) > radius * radius || abs(dot(offset, normal)) > planeTolerance ||
                         dot(decodeOctahedral(vq.geometricNormal), normal) < kGatherReuseCos))
                continue;
            if (gatherSamples[q].radianceOverPdf.x < 0.0f) continue;  // q's BSDF keeps its rays
            // q's rays cover p's hemisphere only above q's horizon: (1 + cos delta) / 2 of its
            // cosine-weighted measure, divided out so that they stand for the whole of it.
            float coverage = own ? 1.0f : 0.5f + 0.5f * dot(decodeOctahedral(vq.shadingNormal), s.n);
            float scale = 1.0f / max(coverage, 0.5f);
            for (uint r = 0u; r < params.gatherRays; ++r) {
                GatherSample g = gatherSamples[r * pixels + q];
                ++rays;
                if (g.radianceOverPdf == vec3(0.0f)) continue;
                vec3 dir = decodeOctahedral(g.direction);
                vec3 wi = toLocal(dir, s.t, s.b, s.n);
                if (wi.z <= 0.0f || (!own && dot(dir, normal) <= 0.0f)) continue;  // below p's surface
                sum += evalBsdfAs(s.bsdf, woTerms, s.wo, wi, lambertian) * (wi.z * scale) * g.radianceOverPdf;
            }
        }
    }
    return sum;
}

void gatherReuse() {
    uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= params.width * params.height) return;
    GpuVisiblePoint vp = visiblePoints[pixel];
    if ((vp.flags & kVisiblePointValid) == 0u) return;
    if (gatherSamples[pixel].radianceOverPdf.x < 0.0f) return;  // not shared: final_gather.comp added its rays
    VisibleSurface s = visibleSurface(vp);
    uint rays;
    vec3 sum = bsdfIsLambertian(s.bsdf) ? neighbourSum(pixel, vp, s, true, rays) : neighbourSum(pixel, vp, s, false, rays);
    film[pixel] += vec4(finiteOrZero(vp.throughput * sum / float(max(rays, 1u))), 0.0f);
}

void main() {
    gatherReuse();
}
