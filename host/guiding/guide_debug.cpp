#include "guiding/guide_debug.h"

#include <algorithm>

#include <fmt/format.h>

#include "bvh/scene_bvh.h"
#include "shared/bsdf.glsl"
#include "shared/guiding.glsl"
#include "shared/photon.glsl"
#include "util/errors.h"

namespace vkp {

GuideGridAtPixel guideGridAtPixel(const Scene& /*scene*/, const SceneArrays& arrays, const PathGuide& guide,
                                  const GuideSettings& settings, const Camera& camera, uint32_t width,
                                  uint32_t height, uint32_t x, uint32_t y) {
    if (x >= width || y >= height)
        throw InputError(fmt::format("--pixel {} {}: outside the {}x{} image", x, y, width, height));
    const gpu::GpuCamera cam = makeGpuCamera(camera, width, height);
    const glm::vec2 film(x + 0.5f, y + 0.5f);
    const glm::vec3 dir = gpu::cameraRayDirection(cam, width, height, film);
    const gpu::BvhArrays view = arrays.bvhArrays();
    const RayHit hit = closestHit(view, gpu::cameraRayOrigin(cam, width, height, film), dir, gpu::kInfinity, true);
    if (!hit.hit) throw InputError(fmt::format("--pixel {} {}: the camera ray meets no surface", x, y));
    const gpu::GpuTriangle t = worldTriangle(view, hit.triangle);
    const gpu::GpuMaterial& material = arrays.materials[arrays.shading[triangleOfHit(view, hit.triangle)].material];
    gpu::BsdfParams bsdf = gpu::makeBsdfParams(glm::vec3(material.baseColor), material.metallic, material.roughness);
    bsdf.transmission = material.transmission;
    bsdf.ior = material.ior;
    if (!gpu::storesPhotons(bsdf))
        throw InputError(fmt::format("--pixel {} {}: the camera ray meets a mirror-like surface: no guiding there", x, y));

    GuideGridAtPixel result;
    const glm::vec3 e1 = glm::vec3(t.v1 - t.v0), e2 = glm::vec3(t.v2 - t.v0);
    result.normal = glm::normalize(glm::cross(e1, e2));
    if (glm::dot(result.normal, dir) > 0.0f) result.normal = -result.normal;
    result.position = glm::vec3(t.v0) + hit.b1 * e1 + hit.b2 * e2;
    result.m = settings.gridU;
    result.n = settings.gridV;

    // The k nearest photons within the search radius that pass the normal test (brute force).
    std::vector<std::pair<float, size_t>> nearest;
    const auto photons = guide.map().downloadPhotons();
    const float r2 = guide.searchRadius() * guide.searchRadius();
    for (size_t i = 0; i < photons.size(); ++i) {
        const gpu::GpuPhoton& p = photons[i];
        const float d2 = glm::dot(p.position - result.position, p.position - result.position);
        if (d2 < r2 && glm::dot(gpu::decodeOctahedral(p.normal), result.normal) > gpu::kGatherNormalCosine)
            nearest.push_back({d2, i});
    }
    const size_t k = std::min<size_t>(settings.k, nearest.size());
    std::partial_sort(nearest.begin(), nearest.begin() + k, nearest.end());
    glm::vec3 tangent, bitangent;
    gpu::orthonormalBasis(result.normal, tangent, bitangent);
    float cdf[gpu::kMaxGuideCells] = {};
    for (size_t j = 0; j < k; ++j) {
        const gpu::GpuPhoton& p = photons[nearest[j].second];
        const glm::vec3 wi = gpu::toLocal(gpu::decodeOctahedral(p.direction), tangent, bitangent, result.normal);
        gpu::guideAdd(cdf, result.m, result.n, wi, gpu::luminance(gpu::photonRelativePower(p)));
    }
    gpu::guideFinalize(cdf, result.m, result.n);
    result.photons = static_cast<uint32_t>(k);
    const uint32_t cells = result.m * result.n;
    for (uint32_t c = 0; c < cells; ++c) result.density.push_back(gpu::guideCellProbability(cdf, c) * cells);
    return result;
}

ImageRgb guideGridImage(const GuideGridAtPixel& grid, uint32_t cellPixels) {
    ImageRgb image;
    image.width = grid.n * cellPixels;
    image.height = grid.m * cellPixels;
    image.pixels.assign(size_t(image.width) * image.height * 3, 0.0f);
    const float peak = std::max(1e-12f, *std::max_element(grid.density.begin(), grid.density.end()));
    for (uint32_t y = 0; y < image.height; ++y)
        for (uint32_t x = 0; x < image.width; ++x) {
            const float v = grid.density[(y / cellPixels) * grid.n + x / cellPixels] / peak;
            float* px = &image.pixels[3 * (size_t(y) * image.width + x)];
            px[0] = px[1] = px[2] = v;
        }
    return image;
}

}  // namespace vkp
