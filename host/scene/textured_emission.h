// Light-selection weights of triangles with an emissive texture: the emission averaged over the
// texels the triangle can read, so triangles whose texels are all black are not lights and
// bright ones are chosen more often.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace vkp {

class TexturedEmission {
public:
    explicit TexturedEmission(const Scene& scene);

    // The mean emitted radiance (RGB, emissive factor included) over a superset of the texels
    // the triangle's emission reads: its UV bounding box under the view's transform, widened by
    // one texel for bilinear filtering and wrapped as the sampler wraps. Zero only if every one of
    // those texels is black, so next-event estimation that skips zero-weight triangles stays
    // unbiased. Without an emissive texture: the emissive factor.
    glm::dvec3 meanEmission(const Triangle& triangle) const;

private:
    // Linear RGB means of 2^L x 2^L texel blocks for L >= 1 (level 0 is decoded on demand).
    struct Pyramid {
        std::vector<uint32_t> widths, heights;
        std::vector<std::vector<glm::vec3>> levels;  // levels[L - 1]
    };
    glm::vec3 texel(int image, int level, int x, int y) const;
    const Scene& m_scene;
    std::vector<Pyramid> m_pyramids;  // per image; empty for images no emissive texture uses
};

}  // namespace vkp
