#include "render/aov.h"

#include <fmt/format.h>

#include "gpu_scene/gpu_scene.h"
#include "shared/kernels/aov.glsl"
#include "util/errors.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/kernel.h"

namespace vkp {

AovSettings parseAovList(const std::string& list) {
    AovSettings s;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t end = std::min(list.find(',', start), list.size());
        const std::string name = list.substr(start, end - start);
        if (name == "albedo") s.albedo = true;
        else if (name == "normal") s.normal = true;
        else if (name == "depth") s.depth = true;
        else throw InputError(fmt::format("--aov {}: '{}' is not one of albedo, normal, depth", list, name));
        start = end + 1;
    }
    return s;
}

AovImages renderAovs(const GpuScene& scene, const Frame& frame) {
    vk::Context& context = scene.context();
    const uint64_t pixels = frame.pixels();
    vk::Buffer albedo(context, "AOV albedo", pixels * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Buffer normal(context, "AOV normal and depth", pixels * sizeof(glm::vec4), vk::kStorageUsage);
    vk::Kernel<gpu::AovKernel> kernel(context);
    kernel.bind(scene.buffers().bindings());
    kernel.bind(gpu::kAovAlbedoBinding, albedo);
    kernel.bind(gpu::kAovNormalBinding, normal);
    gpu::AovParams params{};
    params.camera = frame.gpuCamera;
    params.width = frame.width;
    params.height = frame.height;
    params.seed = frame.seed;
    params.maxSpecularDepth = 8;
    context.submitAndWait([&](VkCommandBuffer cmd) { kernel.record(cmd, pixels, params); });

    const std::vector<glm::vec4> a = albedo.download<glm::vec4>();
    const std::vector<glm::vec4> n = normal.download<glm::vec4>();
    AovImages out;
    out.albedo = makeImage(frame.width, frame.height);
    out.normal = makeImage(frame.width, frame.height);
    out.depth.resize(pixels);
    for (uint64_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) {
            out.albedo.pixels[3 * i + c] = a[i][c];
            out.normal.pixels[3 * i + c] = n[i][c];
            out.depth[i] = n[i].w;
        }
    return out;
}

std::vector<ExrChannel> aovChannels(const AovImages& images, const AovSettings& settings) {
    std::vector<ExrChannel> channels;
    auto component = [](const ImageRgb& image, int c) {
        std::vector<float> v(image.pixels.size() / 3);
        for (size_t i = 0; i < v.size(); ++i) v[i] = image.pixels[3 * i + c];
        return v;
    };
    if (settings.albedo)
        for (int c = 0; c < 3; ++c) channels.push_back({std::string("Albedo.") + "RGB"[c], component(images.albedo, c)});
    if (settings.normal)
        for (int c = 0; c < 3; ++c) channels.push_back({std::string("N.") + "XYZ"[c], component(images.normal, c)});
    if (settings.depth) channels.push_back({"Z", images.depth});
    return channels;
}

}  // namespace vkp
