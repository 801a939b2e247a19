// The guiding distribution at one pixel, for inspection (`vkphoton guide-grid`): the grid the
// guided path tracer's per-vertex mode (--guide-cache off, Jensen 1995) builds where the pixel's
// camera ray first meets a surface, from the k nearest photons of the guiding map, weighted by
// flux (the diffuse case of the paper's f_r-weighted grid).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "guiding/path_guide.h"

namespace vkp {

struct GuideGridAtPixel {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    uint32_t photons = 0;           // photons that filled the grid
    uint32_t m = 0, n = 0;          // theta bands x phi sectors
    std::vector<float> density;     // per cell (row = theta band): P(cell) * cells, 1 = cosine sampling
};

// Throws InputError when the pixel is outside the image, sees no surface, or sees a mirror-like
// surface (no guiding there).
GuideGridAtPixel guideGridAtPixel(const Scene& scene, const SceneArrays& arrays, const PathGuide& guide,
                                  const GuideSettings& settings, const Camera& camera, uint32_t width,
                                  uint32_t height, uint32_t x, uint32_t y);

// The grid as an image, `cellPixels` per cell, density scaled so the densest cell is 1.
ImageRgb guideGridImage(const GuideGridAtPixel& grid, uint32_t cellPixels = 24);

}  // namespace vkp
