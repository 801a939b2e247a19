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

Bounds instanceBounds(const Scene& scene, const Instance& instance) {
    const Bounds& b = scene.meshes.at(instance.mesh).bounds;
    Bounds world;
    for (int corner = 0; corner < 8; ++corner)
        world.grow(glm::vec3(instance.transform * glm::vec4((corner & 1) ? b.max.x : b.min.x,
                                                            (corner & 2) ? b.max.y : b.min.y,
                                                            (corner & 4) ? b.max.z : b.min.z, 1.0f)));
    return world;
}

// A node's geometry: its flattened drawings (ranges of Scene::triangles) and its instances.
struct NodeGeometry {
    std::vector<const Drawing*> drawings;
    std::vector<uint32_t> instances;  // indices into Scene::instances
    Bounds bounds;                    // world space (instances by their boxes' corners)
};

// The node's triangles in world space (its instances transformed).
std::vector<Triangle> worldTriangles(const Scene& scene, const NodeGeometry& g) {
    std::vector<Triangle> out;
    for (const Drawing* d : g.drawings)
        out.insert(out.end(), scene.triangles.begin() + d->first, scene.triangles.begin() + d->first + d->count);
    for (uint32_t i : g.instances)
        appendInstanceTriangles(scene.meshes.at(scene.instances[i].mesh), scene.instances[i].transform, out);
    return out;
}

}  // namespace

std::vector<BackdropCandidate> backdropCandidates(const Scene& scene, uint32_t rays) {
    std::map<int, NodeGeometry> nodes;
    std::vector<int> nodeOf(scene.triangles.size(), -1);  // per flattened triangle
    for (const Drawing& d : scene.drawings) {
        NodeGeometry& g = nodes[d.node];
        g.drawings.push_back(&d);
        for (uint32_t i = d.first; i < d.first + d.count && i < scene.triangles.size(); ++i) {
            nodeOf[i] = d.node;
            for (const glm::vec3& p : scene.triangles[i].p) g.bounds.grow(p);
        }
    }
    std::vector<glm::vec3> instanceCentres;  // where the instances are: their boxes' centres
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Bounds b = instanceBounds(scene, scene.instances[i]);
        instanceCentres.push_back(b.center());
        NodeGeometry& g = nodes[scene.instances[i].node];
        g.instances.push_back(i);
        g.bounds.grow(b);
    }

    std::vector<BackdropCandidate> candidates;
    for (const auto& [node, geometry] : nodes) {
        if (node < 0) continue;  // instances without a node
        const Bounds& own = geometry.bounds;
        const float slack = 0.01f * glm::length(own.extent());
        const auto inside = [&](const glm::vec3& p) {
            return glm::all(glm::greaterThanEqual(p, own.min - slack)) && glm::all(glm::lessThanEqual(p, own.max + slack));
        };
        // Only a shell around the scene's centre can enclose it; only its materials qualify.
        if (own.empty() || !inside(scene.bounds.center())) continue;
        const auto qualifies = [&](uint32_t material) {
            return material < scene.materials.size() && backdropMaterial(scene.materials[material]);
        };
        bool materials = true;
        for (const Drawing* d : geometry.drawings)
            for (uint32_t i = d->first; i < d->first + d->count && materials; ++i)
                materials = qualifies(scene.triangles[i].material);
        for (uint32_t i : geometry.instances)
            for (const Triangle& t : scene.meshes.at(scene.instances[i].mesh).triangles)
                if (materials) materials = qualifies(t.material);
        if (!materials) continue;

        BackdropCandidate c;
        c.node = node;
        double total = 0.0, inward = 0.0;
        const glm::dvec3 centre(own.center());
        for (const Triangle& t : worldTriangles(scene, geometry)) {
            const double a = area(t);
            total += a;
            const glm::dvec3 centroid = (glm::dvec3(t.p[0]) + glm::dvec3(t.p[1]) + glm::dvec3(t.p[2])) / 3.0;
            if (glm::dot(frontNormal(t), centre - centroid) > 0.0) inward += a;
        }
        if (!(total > 0.0)) continue;
        c.inwardArea = inward / total;
        if (c.inwardArea >= kBackdropMinInwardArea) {
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
            size_t others = 0, othersCentred = 0;
            for (uint32_t i = 0; i < scene.instances.size(); ++i) {
                if (scene.instances[i].node == node) continue;
                ++others;
                othersCentred += inside(instanceCentres[i]);
            }
            c.enclosesOthers = othersArea + double(others) > 0.0 && othersInside >= kBackdropMinInside * othersArea &&
                               double(othersCentred) >= kBackdropMinInside * double(others);
        }
        candidates.push_back(c);
    }

    // Rays from the other surfaces, for the candidates whose shape says sky box.
    const auto shaped = [](const BackdropCandidate& c) { return c.enclosesOthers && c.inwardArea >= kBackdropMinInwardArea; };
    if (rays == 0 || std::none_of(candidates.begin(), candidates.end(), shaped)) return candidates;
    std::set<int> shells;
    for (const BackdropCandidate& c : candidates)
        if (shaped(c)) shells.insert(c.node);
    // The ray sources: every triangle of the other nodes, flattened (index < size) or an
    // instance's (index size + the instance's offset + its triangle), chosen by world area.
    std::vector<double> areas(scene.triangles.size(), 0.0);
    for (uint32_t i = 0; i < scene.triangles.size(); ++i)
        if (!shells.count(nodeOf[i])) areas[i] = area(scene.triangles[i]);
    std::vector<size_t> instanceOffset;
    for (const Instance& instance : scene.instances) {
        instanceOffset.push_back(areas.size());
        const bool shell = shells.count(instance.node) > 0;
        for (const Triangle& t : scene.meshes.at(instance.mesh).triangles) {
            glm::dvec3 p[3];
            for (int v = 0; v < 3; ++v) p[v] = glm::dvec3(instance.transform * glm::vec4(t.p[v], 1.0f));
            areas.push_back(shell ? 0.0 : 0.5 * glm::length(glm::cross(p[1] - p[0], p[2] - p[0])));
        }
    }
    if (std::none_of(areas.begin(), areas.end(), [](double a) { return a > 0.0; })) return candidates;
    const SceneBvh bvh = buildSceneBvh(scene);
    const gpu::BvhArrays arrays = bvh.arrays();
    const float reach = rayOffsetScale(scene.bounds);
    std::mt19937 rng(11);
    std::discrete_distribution<size_t> pick(areas.begin(), areas.end());
    std::map<int, uint32_t> endsOn;
    uint32_t escaping = 0;
    std::vector<Triangle> one;
    for (uint32_t r = 0; r < rays; ++r) {
        const size_t k = pick(rng);
        const Triangle* t = nullptr;
        if (k < scene.triangles.size()) {
            t = &scene.triangles[k];
        } else {
            const size_t instance = std::upper_bound(instanceOffset.begin(), instanceOffset.end(), k) - instanceOffset.begin() - 1;
            const Mesh& mesh = scene.meshes.at(scene.instances[instance].mesh);
            one.clear();
            appendInstanceTriangles(Mesh{mesh.name, {mesh.triangles[k - instanceOffset[instance]]}, mesh.bounds},
                                    scene.instances[instance].transform, one);
            t = &one.front();
        }
        const SurfaceRay ray = frontRay(*t, scene.materials[t->material].doubleSided, reach, rng);
        if (!ray.valid) continue;
        const RayHit hit = closestHit(arrays, ray.origin, ray.direction, std::numeric_limits<float>::infinity());
        if (!hit.hit) {
            ++escaping;
        } else if (hit.triangle < arrays.header.staticTriangles) {
            ++endsOn[nodeOf[bvh.staticOrder[hit.triangle]]];
        } else {
            const auto after = std::upper_bound(arrays.instances.begin(), arrays.instances.end(), hit.triangle,
                                                [](uint32_t id, const gpu::GpuInstance& g) { return id < g.firstId; });
            ++endsOn[scene.instances[size_t(after - arrays.instances.begin()) - 1].node];
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
