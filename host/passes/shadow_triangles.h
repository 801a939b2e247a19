// Edge adjacency for shadow volumes, built on the host: vertices welded by exact position, edges
// matched across triangles, components joined through manifold edges. A component is closed when
// every edge of it is shared by exactly two triangles that traverse it in opposite directions
// (a closed, consistently oriented 2-manifold): only its silhouette edges need extruding. Any other
// triangle (open boundary, edge of three or more triangles, flipped neighbour) falls back to a
// volume of its own (shaders/raster/shadow_volume_build.comp).
#pragma once

#include <vector>

#include "shared/gpu_types.glsl"
#include "shared/shadow_volume.glsl"

namespace vkp {

struct ShadowTriangles {
    std::vector<gpu::GpuShadowTriangle> triangles;  // same order as the input (BVH order)
    size_t closedTriangles = 0;
    size_t openTriangles = 0;
};

ShadowTriangles buildShadowTriangles(const std::vector<gpu::GpuTriangle>& triangles);

}  // namespace vkp
