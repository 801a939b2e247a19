// The viewer's image on the device (shaders/render/display.comp): the film resolved (plus SPPM's
// estimate), kept as linear radiance for screenshots, and turned into the 8-bit pixels the
// swapchain copy takes (exposure, display transform, outline of the selected node), so no image
// crosses to the host per frame. The display transform is the PNG's (image/view_transform.h),
// sampled once into a lattice of 65^3 points over 24 stops (shared/kernels/display.glsl) and read
// by trilinear interpolation; screenshots and `render` keep the exact transform.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "image/view_transform.h"
#include "shared/kernels/display.glsl"
#include "vk/buffer.h"
#include "vk/kernel.h"

namespace vkp {

// The lattice display.comp reads: for every point (x fastest) the display-encoded (sRGB OETF) RGB
// of `view` at the radiance displayLatticeRadiance gives its axes.
std::vector<glm::vec4> displayLattice(ViewTransform view);

class DisplayPass {
public:
    // `lattice`: displayLattice() of the view transform to show.
    DisplayPass(vk::Context& context, uint32_t width, uint32_t height, const std::vector<glm::vec4>& lattice);

    // The selected node's pixels (width x height bytes, non-zero inside), or empty: no outline.
    void setMask(const std::vector<uint8_t>& mask);
    // Records the resolve of a film's sums (Film::sums(): radiance sums and sample count per
    // pixel; plus gpu::sppmRadiance of `progressive` after `passes` samples, when not null) and its
    // display pixels; ends with them visible to transfers.
    void record(VkCommandBuffer cmd, const vk::Buffer& filmSums, const vk::Buffer* progressive, uint32_t passes,
                float exposureScale, bool bgra);

    // R, G, B, A bytes per pixel (B, G, R, A when recorded with bgra), top row first.
    const vk::Buffer& pixels() const { return m_pixels; }
    // The linear image of the last recorded resolve (once its submission has completed).
    ImageRgb linearImage() const;

private:
    uint32_t m_width, m_height;
    vk::Buffer m_lattice;
    vk::Buffer m_mask;
    vk::Buffer m_noProgressive;  // bound when the integrator keeps no estimates
    vk::Buffer m_linear;
    vk::Buffer m_pixels;
    bool m_hasMask = false;
    vk::Kernel<gpu::DisplayKernel> m_kernel;
};

}  // namespace vkp
