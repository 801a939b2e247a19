#include "lights/backdrop.h"

#include <algorithm>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "bvh/scene_bvh.h"
#include "lights/surface_rays.h"
#include "scene/scene.h"

namespace vkp {
namespace {

// Whether a material can be a sky box's: glTF culls its back faces, it blocks light and gives none.
bool backdropMaterial(const Material& m) {
    return !m.doubleSided && m.alphaMode == AlphaMode::Opaque && m.transmission <= 0.0f &&
           !glm::any(glm::greaterThan(m.emissive, glm::vec3(0.0f)));
}

double area(const Triangle& t) {
    return 0.5 * glm::length(glm::cross(glm::dvec3(t.p[1] - t.p[0]), glm::dvec3(t.p[2] - t.p[0])));
}

// The side a triangle's front faces: its winding's normal, turned to agree with the vertex normals.
glm::dvec3 frontNormal(const Triangle& t) {
    glm::dvec3 n = glm::cross(glm::dvec3(t.p[1] - t.p[0]), glm::dvec3(t.p[2] - t.p[0]));
    if (glm::dot(n, glm::dvec3(t.n[0] + t.n[1] + t.n[2])) < 0.0) n = -n;
    return n;
}

}  // namespace

std::vector<BackdropCandidate> backdropCandidates(const Scene& scene, uint32_t rays) {
    // Each node's flattened triangles (several drawings for an EXT_mesh_gpu_instancing node).
    std::map<int, std::vector<const Drawing*>> byNode;
    for (const Drawing& d : scene.drawings) byNode[d.node].push_back(&d);
    std::vector<int> nodeOf(scene.triangles.size(), -1);
    std::map<int, Bounds> nodeBounds;  // each node's own
    for (const auto& [node, drawings] : byNode)
        for (const Drawing* d : drawings)
            for (uint32_t i = d->first; i < d->first + d->count && i < scene.triangles.size(); ++i) {
                nodeOf[i] = node;
                for (const glm::vec3& p : scene.triangles[i].p) nodeBounds[node].grow(p);
            }
    // Where the instances are: their world bounds' centres.
    std::vector<glm::vec3> instanceCentres;
    for (const Instance& instance : scene.instances)
        instanceCentres.push_back(glm::vec3(instance.transform * glm::vec4(scene.meshes.at(instance.mesh).bounds.center(), 1.0f)));

    std::vector<BackdropCandidate> candidates;
    for (const auto& [node, drawings] : byNode) {
        bool materials = true;
        double total = 0.0, inward = 0.0;
        const Bounds& own = nodeBounds[node];
        const glm::dvec3 centre(own.center());
        for (const Drawing* d : drawings)
            for (uint32_t i = d->first; i < d->first + d->count && materials; ++i) {
                const Triangle& t = scene.triangles[i];
                materials = t.material < scene.materials.size() && backdropMaterial(scene.materials[t.material]);
                const double a = area(t);
                total += a;
                const glm::dvec3 centroid = (glm::dvec3(t.p[0]) + glm::dvec3(t.p[1]) + glm::dvec3(t.p[2])) / 3.0;
                if (glm::dot(frontNormal(t), centre - centroid) > 0.0) inward += a;
            }
        if (!materials || !(total > 0.0)) continue;
        BackdropCandidate c;
        c.node = node;
        c.inwardArea = inward / total;
        const float slack = 0.01f * glm::length(own.extent());
        const auto inside = [&](const glm::vec3& p) {
            return glm::all(glm::greaterThanEqual(p, own.min - slack)) && glm::all(glm::lessThanEqual(p, own.max + slack));
        };
        candidates.push_back(c);
        // Only a shell around the scene's centre can enclose it.
        if (c.inwardArea < kBackdropMinInwardArea || !inside(scene.bounds.center())) continue;
        // Everything else inside: the other flattened triangles' area by centroid, and the
        // instances by their centres (an animated object may reach out of the box in its rest pose).
        double othersArea = 0.0, othersInside = 0.0;
        for (size_t i = 0; i < scene.triangles.size(); ++i) {
            if (nodeOf[i] == node) continue;
            const Triangle& t = scene.triangles[i];
            const double a = area(t);
            othersArea += a;
            if (inside((t.p[0] + t.p[1] + t.p[2]) / 3.0f)) othersInside += a;
        }
        const auto instancesInside = std::count_if(instanceCentres.begin(), instanceCentres.end(), inside);
        c.enclosesOthers = othersArea + double(instanceCentres.size()) > 0.0 &&
                           othersInside >= kBackdropMinInside * othersArea &&
                           double(instancesInside) >= kBackdropMinInside * double(instanceCentres.size());
        candidates.back() = c;
    }

    // Rays from the other surfaces, for the candidates whose shape says sky box.
    const auto shaped = [](const BackdropCandidate& c) { return c.enclosesOthers && c.inwardArea >= kBackdropMinInwardArea; };
    if (rays == 0 || std::none_of(candidates.begin(), candidates.end(), shaped)) return candidates;
    std::set<int> shells;
    for (const BackdropCandidate& c : candidates)
        if (shaped(c)) shells.insert(c.node);
    std::vector<uint32_t> sources;
    std::vector<double> areas;
    for (uint32_t i = 0; i < scene.triangles.size(); ++i) {
        const double a = area(scene.triangles[i]);
        if (shells.count(nodeOf[i]) || !(a > 0.0)) continue;
        sources.push_back(i);
        areas.push_back(a);
    }
    if (sources.empty()) return candidates;
    const SceneBvh bvh = buildSceneBvh(scene);
    const gpu::BvhArrays arrays = bvh.arrays();
    const float reach = rayOffsetScale(scene.bounds);
    std::mt19937 rng(11);
    std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
    std::map<int, uint32_t> endsOn;
    uint32_t escaping = 0;
    for (uint32_t r = 0; r < rays; ++r) {
        const Triangle& t = scene.triangles[sources[pick(rng)]];
        const SurfaceRay ray = frontRay(t, scene.materials[t.material].doubleSided, reach, rng);
        if (!ray.valid) continue;
        const RayHit hit = closestHit(arrays, ray.origin, ray.direction, std::numeric_limits<float>::infinity());
        if (!hit.hit) {
            ++escaping;
        } else if (hit.triangle < arrays.header.staticTriangles) {
            ++endsOn[nodeOf[bvh.staticOrder[hit.triangle]]];
        }
    }
    for (BackdropCandidate& c : candidates) {
        if (!shaped(c)) continue;
        c.raysOnIt = double(endsOn[c.node]) / double(rays);
        c.raysEscaping = double(escaping) / double(rays);
        c.backdrop = c.raysOnIt >= kBackdropMinRaysOnIt && c.raysEscaping <= kBackdropMaxEscaping;
    }
    return candidates;
}

std::vector<int> findBackdrops(const Scene& scene, uint32_t rays) {
    std::vector<int> nodes;
    for (const BackdropCandidate& c : backdropCandidates(scene, rays))
        if (c.backdrop) nodes.push_back(c.node);
    return nodes;
}

}  // namespace vkp
