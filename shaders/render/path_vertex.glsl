// GLSL-only: one vertex of any path the kernels trace — camera paths (path_tracer.glsl,
// visible_points.comp, raster_direct.comp), photon paths (photon_trace.comp), importon paths
// (importon_trace.comp) and final gather rays (final_gather.comp). Every kernel extends its paths
// the same way:
//
//   Ray ray = rayFrom(origin, dir);
//   PathVertex v;
//   if (!traceVertex(ray, v)) ...;          // escaped along ray.dir
//   throughput *= v.transmittance;          // absorption of the medium the ray crossed
//   ... emission, storing, next-event estimation at v ...
//   BsdfSample bs = sampleVertexBsdf(v, radiance, u);
//   spawnRay(v, bs, ray);                   // direction, offset origin, medium after the bounce
//
// so what the surface at a hit is lives here once: when alpha masking, normal mapping or a new
// BSDF arrive, traceVertex (skip masked hits, perturb the shading normal) and sampleVertexBsdf /
// the BsdfParams it reads change, and every kernel follows.
#ifndef VKP_PATH_VERTEX_GLSL
#define VKP_PATH_VERTEX_GLSL

#include "render/scene_access.glsl"
#include "shared/dispersion.glsl"

// A ray between two path vertices and the medium it travels through.
struct Ray {
    vec3 origin;
    vec3 dir;           // unit
    vec3 mediumSigma;   // Beer-Lambert absorption per unit length of the KHR_materials_volume
                        // solid the ray is inside (zero outside every solid)
    bool camera;        // a camera ray (primary visibility): skips culled back faces (traceClosest)
    float coneWidth;    // the ray cone (texture level of detail, sampleTexture): its width at the
    float coneSpread;   // origin and its growth per unit distance; both 0: textures at level 0
    float wavelength;   // nm, once the path met a dispersive surface (shared/dispersion.glsl); 0: white
};

// A ray that starts outside every solid (lights, reflections off a visible point).
Ray rayFrom(vec3 origin, vec3 dir) {
    Ray ray;
    ray.origin = origin;
    ray.dir = dir;
    ray.mediumSigma = vec3(0.0f);
    ray.camera = false;
    ray.coneWidth = 0.0f;
    ray.coneSpread = 0.0f;
    ray.wavelength = 0.0f;
    return ray;
}

// The ray from `cam` through film position `pixel` (0..width, 0..height, y down). What it meets
// first is what the image shows, so it skips the back faces of single-sided opaque triangles as
// glTF's back-face culling does (docs/scene-format.md "Back faces"); every other ray sees both
// faces. Its cone is one sample's share of the pixel (the pixel's angle, or an orthographic
// pixel's width, over sqrt(samples per pixel)): textures are filtered over what one sample
// stands for, so few samples see no aliasing and many converge to the supersampled texture.
Ray cameraRay(GpuCamera cam, uint width, uint height, vec2 pixel) {
    Ray ray = rayFrom(cameraRayOrigin(cam, width, height, pixel), cameraRayDirection(cam, width, height, pixel));
    ray.camera = true;
    float share = 1.0f / (float(height) * sqrt(float(max(cam.pixelSamples, 1u))));
    bool orthographic = cam.orthoHalfHeight > 0.0f;
    ray.coneWidth = orthographic ? 2.0f * cam.orthoHalfHeight * share : 0.0f;
    ray.coneSpread = orthographic ? 0.0f : 2.0f * cam.tanHalfFovY * share;
    return ray;
}

// The surface a ray found, ready for shading: the hit, its material and BSDF, and the shading
// frame on the side the ray came from. Local directions (wo, BsdfSample.wi) are in that frame.
struct PathVertex {
    SurfaceHit hit;
    GpuMaterial material;
    BsdfParams bsdf;
    vec3 emitted;         // the material's emission at the hit (factor x texture), either side
    float distance;       // from the ray's origin (kInfinity when the ray escaped)
    vec3 transmittance;   // exp(-sigma * distance): what the ray's medium let through
    vec3 n;               // shading normal on the arrival side (+z of the frame), world space
    vec3 t;
    vec3 b;
    vec3 wo;              // local direction back along the ray, never below the horizon
    uint triangle;        // the hit triangle (BVH order) and its barycentrics (b1, b2)
    vec2 barycentrics;
    float coneWidth;      // the ray cone's width at the hit (Ray.coneWidth)
    float wavelength;     // the path's wavelength after this vertex (Ray.wavelength); 0: white
};

// The shading frame around n (world space) and the local outgoing direction woWorld in it. An
// interpolated shading normal can face away from a direction that is above the geometric surface
// (silhouettes): wo is then treated as grazing rather than as arriving from below.
void shadingFrame(vec3 n, vec3 woWorld, out vec3 t, out vec3 b, out vec3 wo) {
    orthonormalBasis(n, t, b);
    wo = toLocal(woWorld, t, b, n);
    if (wo.z <= 0.0f) wo.z = 1.0e-4f;
}

// The coat's own normal (SurfaceHit.coatNormal) into the BSDF, in the shading frame (t, b, n)
// built on the arrival side: the BSDF evaluates and samples its coat lobe around it.
void applyCoatNormal(inout BsdfParams p, SurfaceHit hit, vec3 t, vec3 b, vec3 n) {
    if (!hit.hasCoatNormal) return;
    vec3 coat = dot(n, hit.shadingNormal) < 0.0f ? -hit.coatNormal : hit.coatNormal;
    p.clearcoatNormal = normalize(toLocal(coat, t, b, n));
    p.flags |= kBsdfCoatNormal;
}

// KHR_materials_anisotropy's direction (SurfaceHit.anisotropyDirection) into the BSDF, in the
// shading frame (t, b, n): the specular lobe is stretched along it.
void applyAnisotropy(inout BsdfParams p, SurfaceHit hit, vec3 t, vec3 b) {
    if (!(p.anisotropy > 0.0f)) return;
    vec2 d = vec2(dot(hit.anisotropyDirection, t), dot(hit.anisotropyDirection, b));
    float len = length(d);
    p.anisotropyDirection = len > 1.0e-6f ? d / len : vec2(1.0f, 0.0f);
}

// KHR_materials_dispersion at a transmissive solid (thin walls bend no light): a white path takes one wavelength here, drawn
// uniformly from a hash of the ray (a new, deterministic random number), and its throughput the
// weight c(lambda) / pdf(lambda) through v.transmittance, which every kernel multiplies in right
// after traceVertex; a path that has a wavelength keeps it. The layer's index becomes the one at the
// path's wavelength. Non-dispersive surfaces leave paths as they are.
void applyDispersion(inout PathVertex v, Ray ray) {
    v.wavelength = ray.wavelength;
    if (!(v.material.dispersion > 0.0f) || !(v.bsdf.transmission > 0.0f) || v.bsdf.thinWalled != 0u) return;
    if (v.wavelength == 0.0f) {
        uint h = pcgHash(floatBitsToUint(ray.origin.x) ^ pcgHash(floatBitsToUint(ray.origin.y) ^
                 pcgHash(floatBitsToUint(ray.origin.z) ^ pcgHash(floatBitsToUint(ray.dir.x) ^
                 pcgHash(floatBitsToUint(ray.dir.y) ^ pcgHash(floatBitsToUint(ray.dir.z)))))));
        v.wavelength = sampleWavelength(float(h >> 8u) * (1.0f / 16777216.0f));
        v.transmittance *= spectralWeight(v.wavelength);
    }
    v.bsdf.ior = dispersiveIor(v.bsdf.ior, v.material.dispersion, v.wavelength);
}

// Follows the ray to the closest surface and sets up the vertex there. Returns false when the
// ray leaves the scene: v.distance is then kInfinity and the escape direction is ray.dir, where
// light from an environment will be looked up.
bool traceVertex(Ray ray, out PathVertex v) {
    float b1;
    float b2;
    uint tri;
    if (!traceClosest(ray.origin, ray.dir, kInfinity, ray.camera, v.distance, tri, b1, b2)) {
        v.distance = kInfinity;
        return false;
    }
    v.transmittance = exp(-ray.mediumSigma * v.distance);
    // Every texture of the hit's material in one loop (normal map, BSDF, emission): one inlined
    // texture lookup instead of one per texture slot.
    MaterialTexels texels;
    v.coneWidth = ray.coneWidth + ray.coneSpread * v.distance;
    v.hit = surfaceTexelsAt(tri, b1, b2, ray.dir, v.coneWidth, ~0u, texels);
    v.triangle = tri;
    v.barycentrics = vec2(b1, b2);
    v.material = materials[v.hit.material];
    v.bsdf = bsdfParamsOf(v.material, texels);
    v.bsdf.baseColor *= v.hit.color.rgb;
    v.emitted = emittedRadianceOf(v.material, texels);
    v.n = v.hit.frontFace ? v.hit.shadingNormal : -v.hit.shadingNormal;
    shadingFrame(v.n, -ray.dir, v.t, v.b, v.wo);
    applyCoatNormal(v.bsdf, v.hit, v.t, v.b, v.n);
    applyAnisotropy(v.bsdf, v.hit, v.t, v.b);
    applyDispersion(v, ray);
    return true;
}

// The sample, or none (kLobeNone) where its direction leaves on the geometric side its lobe does
// not: a direction the shading normal allows but the geometry does not (see sampleVertexBsdf).
BsdfSample keepOnSurfaceSide(PathVertex v, BsdfSample bs) {
    vec3 side = v.hit.frontFace ? v.hit.geometricNormal : -v.hit.geometricNormal;
    bool reflects = (bs.lobe & kLobeTransmission) == 0u;
    if (bs.lobe != kLobeNone && (dot(toWorld(bs.wi, v.t, v.b, v.n), side) > 0.0f) != reflects) bs.lobe = kLobeNone;
    return bs;
}

// Samples the vertex's BSDF for the next direction (local). `radiance`: camera-path and gather
// throughput (refraction scales it by eta^2), not photons and importons (shared/bsdf.glsl).
// A direction the shading normal (interpolated or normal-mapped) allows but the geometry does not
// (a reflection below the surface, a transmission that stays on the arrival side) is dropped
// (kLobeNone), so shading normals never carry camera paths, photons or importons through a surface.
BsdfSample sampleVertexBsdf(PathVertex v, bool radiance, vec3 u) {
    return keepOnSurfaceSide(v, sampleBsdf(v.bsdf, v.wo, v.hit.frontFace, radiance, u));
}

// The vertex's BSDF (f, without the cosine) towards local wi.
vec3 evalVertexBsdf(PathVertex v, vec3 wi) {
    return evalBsdf(v.bsdf, v.wo, wi);
}

// Solid-angle pdf with which sampleVertexBsdf produces local wi through its non-delta lobes.
float pdfVertexBsdf(PathVertex v, vec3 wi) {
    return pdfBsdf(v.bsdf, v.wo, wi);
}

// The rough dielectric layer (KHR_materials_transmission with roughness >= kDeltaRoughness,
// shared/bsdf.glsl) towards local wi on either side, times its share `transmission`, for radiance,
// and the density with which sampleVertexBsdf produces wi through it. The layer is not in
// evalBsdf/pdfBsdf (photon estimates leave it out); the camera-path integrators add it for
// next-event estimation (evalVertexDirect) and weigh its samples (kLobeLayer) against that with
// the power heuristic over pdfVertexMis, as for every other lobe.
bool hasRoughLayer(PathVertex v) {
    return v.bsdf.transmission > 0.0f && !dielectricIsDelta(v.bsdf);
}

vec3 evalVertexLayer(PathVertex v, vec3 wi) {
    if (!hasRoughLayer(v)) return vec3(0.0f);
    return v.bsdf.transmission * evalDielectricLayer(v.bsdf, v.wo, wi, v.hit.frontFace, true);
}

float pdfVertexLayer(PathVertex v, vec3 wi) {
    if (!hasRoughLayer(v)) return 0.0f;
    return v.bsdf.transmission * pdfDielectricLayer(v.bsdf, v.wo, wi, v.hit.frontFace);
}

// The density the MIS weights use for BSDF sampling at v towards local wi: the opaque lobes' and
// the rough layer's (both sides of the power heuristic use this one function).
float pdfVertexMis(PathVertex v, vec3 wi) {
    return pdfVertexBsdf(v, wi) + pdfVertexLayer(v, wi);
}

// That density for a sample sampleVertexBsdf (or the guide) took: its own pdf plus the layer's;
// a layer sample's is the whole mixture's. Equal to bs.pdf where there is no rough layer.
float misPdfOfSample(PathVertex v, BsdfSample bs) {
    if ((bs.lobe & kLobeLayer) != 0u) return pdfVertexMis(v, bs.wi);
    return bs.pdf + pdfVertexLayer(v, bs.wi);
}

// The sample is a Dirac for MIS: emission found through it counts in full (smooth mirrors and
// glass; not the rough layer, which has a density).
bool isDeltaForMis(BsdfSample bs) {
    return (bs.lobe & kLobeDelta) != 0u && (bs.lobe & kLobeLayer) == 0u;
}

// f of the vertex towards a light sample (local wi), for next-event estimation: the evaluated
// lobes for light on the arrival side, and the rough dielectric layer on either side (reflection,
// or transmission from a light behind the surface). Zero where the shading and geometric normals
// disagree about the side. A light inside an absorbing solid (the shadow ray runs behind the
// geometric normal of a KHR_materials_volume surface) is attenuated by Beer-Lambert.
vec3 evalVertexDirect(PathVertex v, LightSample ls, vec3 wi) {
    vec3 sideNormal = v.hit.frontFace ? v.hit.geometricNormal : -v.hit.geometricNormal;
    bool above = dot(ls.wi, sideNormal) > 0.0f;
    if ((wi.z > 0.0f) != above) return vec3(0.0f);
    vec3 f = above ? evalVertexBsdf(v, wi) : vec3(0.0f);
    f += evalVertexLayer(v, wi);
    vec3 sigma = v.material.attenuationCoeff;
    if (dot(ls.wi, v.hit.geometricNormal) < 0.0f && maxComponent(sigma) > 0.0f &&
        (v.material.flags & kMaterialThinWalled) == 0u)
        f *= exp(-sigma * ls.distance);
    return f;
}

// Continues the ray from the vertex along the sampled direction: the origin leaves the surface on
// that side (offsetRayOrigin), and a transmission into or out of a solid with
// KHR_materials_volume absorption changes the medium (thin-walled surfaces have no inside).
void spawnRay(PathVertex v, BsdfSample bs, inout Ray ray) {
    ray.dir = normalize(toWorld(bs.wi, v.t, v.b, v.n));
    ray.camera = false;
    // A mirror or a smooth pane passes the cone on (as a flat surface would: the reflected or
    // seen-through texture is filtered like a directly seen one at the same distance); any
    // other lobe spreads the ray over far more than its cone, so later hits read level 0.
    bool delta = (bs.lobe & (kLobeDelta | kLobeLayer)) == kLobeDelta;
    ray.coneWidth = delta ? v.coneWidth : 0.0f;
    ray.coneSpread = delta ? ray.coneSpread : 0.0f;
    ray.origin = offsetRayOrigin(v.hit.position, v.hit.geometricNormal, ray.dir);
    if ((bs.lobe & kLobeTransmission) != 0u && (v.material.flags & kMaterialThinWalled) == 0u)
        ray.mediumSigma = v.hit.frontFace ? v.material.attenuationCoeff : vec3(0.0f);
    ray.wavelength = v.wavelength;
}

#endif
