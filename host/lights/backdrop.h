// Sky boxes (docs/environment.md "Sky boxes"): a scene made for a viewer's image-based light often
// wraps itself in a textured box or dome that faces inward: a rasteriser lights it and everything
// in it with the environment whatever encloses them, and shows the box as the background. A path
// tracer that lets the box block light sees a closed, dark box. When the scene is lit by an
// environment alone, such a drawing is a backdrop: camera rays see it, no other ray does (a
// GpuTriangle flag, shared/bvh_traverse.glsl), so the environment lights the scene through it.
#pragma once

#include <cstdint>
#include <vector>

namespace vkp {

struct Scene;

// What decides whether a node's drawing is a sky box, for the note and the tests.
struct BackdropCandidate {
    int node = -1;
    double inwardArea = 0.0;   // share of its area whose front faces the centre of its bounds
    bool enclosesOthers = false;  // its bounds hold the rest of the scene (kBackdropMinInside)
    double raysOnIt = 0.0;     // share of the rays leaving the other surfaces that end on it
    double raysEscaping = 0.0; // share that leave the scene (reach the environment)
    bool backdrop = false;
};

// A node is a sky box when all of these hold:
//  - its materials are single-sided, opaque, not transmissive, not emissive;
constexpr double kBackdropMinInwardArea = 0.9;  // - this share of its area faces inward;
constexpr double kBackdropMinInside = 0.99;     // - its bounds (and 1 % of its diagonal) hold
                                                //   this share of the other flattened triangles'
                                                //   area (by centroid) and of the instances (by
                                                //   the centres of their bounds);
constexpr double kBackdropMinRaysOnIt = 0.25;   // - this share of the rays leaving the other
constexpr double kBackdropMaxEscaping = 0.05;   //   surfaces end on it, and at most this share
                                                //   reaches the environment: it hides the sky.
// Rays: `rays` cosine-distributed ones from points uniform over the area of the other nodes'
// triangles, flattened or instanced (their fronts; either side if double-sided), through the
// shaders' traversal on the host; a fixed seed. A node's geometry is its flattened drawings and
// its instances (`view` draws every node as an instance).
std::vector<BackdropCandidate> backdropCandidates(const Scene& scene, uint32_t rays = 4096);
// The nodes of the candidates that are backdrops, ascending.
std::vector<int> findBackdrops(const Scene& scene, uint32_t rays = 4096);

}  // namespace vkp
