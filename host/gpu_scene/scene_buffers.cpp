#include "gpu_scene/scene_buffers.h"

#include <chrono>
#include <cmath>

#include "bvh/bvh.h"
#include "shared/constants.glsl"
#include "shared/sampling.glsl"

namespace vkp {
namespace {

gpu::GpuMaterial toGpu(const Material& m, bool emitterDoubleSided) {
    gpu::GpuMaterial g{};
    g.baseColor = m.baseColor;
    g.emissive = m.emissive;
    g.metallic = m.metallic;
    g.roughness = m.roughness;
    g.transmission = m.transmission;
    g.ior = m.ior;
    g.thickness = m.thickness;
    // Beer-Lambert: attenuationColor is the colour after attenuationDistance; sigma = -ln(c)/d.
    glm::vec3 sigma(0.0f);
    if (m.thickness > 0.0f && std::isfinite(m.attenuationDistance) && m.attenuationDistance > 0.0f)
        sigma = -glm::log(glm::max(m.attenuationColor, glm::vec3(1e-6f))) / m.attenuationDistance;
    g.attenuationCoeff = sigma;
    g.flags = (emitterDoubleSided ? gpu::kMaterialDoubleSided : 0u) |
              (m.transmission > 0.0f && m.thickness <= 0.0f ? gpu::kMaterialThinWalled : 0u);
    g.baseColorTexture = m.baseColorTexture;
    g.metallicRoughnessTexture = m.metallicRoughnessTexture;
    g.emissiveTexture = m.emissiveTexture;
    return g;
}

glm::vec4 toVec4(const glm::vec3& v) { return glm::vec4(v, 0.0f); }

}  // namespace

SceneArrays buildSceneArrays(const Scene& scene, LightSampling sampling) {
    SceneArrays a;
    const auto start = std::chrono::steady_clock::now();
    const Bvh bvh = buildBvh(scene.triangles);
    a.bvhBuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    a.nodes = bvh.nodes;

    for (const Material& m : scene.materials) a.materials.push_back(toGpu(m, m.doubleSided));

    a.triangles = gpuTriangles(scene.triangles, bvh);
    a.shading.reserve(scene.triangles.size());
    std::vector<double> power;
    for (uint32_t i = 0; i < bvh.triangleOrder.size(); ++i) {
        const Triangle& t = scene.triangles[bvh.triangleOrder[i]];
        gpu::GpuTriangleShading s{};
        s.n0 = toVec4(t.n[0]);
        s.n1 = toVec4(t.n[1]);
        s.n2 = toVec4(t.n[2]);
        s.uv01 = glm::vec4(t.uv[0], t.uv[1]);
        s.uv2 = t.uv[2];
        s.material = t.material;
        s.emitterPdfArea = 0.0f;
        a.shading.push_back(s);

        const Material& m = scene.materials[t.material];
        const float le = gpu::luminance(m.emissive);
        if (le > 0.0f) {
            const float area = 0.5f * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
            if (area <= 0.0f) continue;
            gpu::GpuLight light{};
            light.type = gpu::kLightTriangle;
            light.triangle = i;
            a.lights.push_back(light);
            power.push_back(gpu::kPi * le * area * (m.doubleSided ? 2.0 : 1.0));
        }
    }

    const float sceneRadius = 0.5f * glm::length(scene.bounds.extent());
    for (const PunctualLight& l : scene.lights) {
        gpu::GpuLight light{};
        light.position = l.position;
        light.direction = glm::normalize(l.direction);
        light.intensity = l.intensity;
        const double lum = gpu::luminance(l.intensity);
        switch (l.type) {
        case LightType::Point:
            light.type = gpu::kLightPoint;
            power.push_back(4.0 * gpu::kPi * lum);
            break;
        case LightType::Spot: {
            light.type = gpu::kLightSpot;
            // glTF's smooth cone falloff: t = saturate(cos * scale + offset), attenuation t^2.
            const float cosOuter = std::cos(l.outerConeAngle);
            const float cosInner = std::cos(l.innerConeAngle);
            light.spotScale = 1.0f / std::max(0.001f, cosInner - cosOuter);
            light.spotOffset = -cosOuter * light.spotScale;
            power.push_back(2.0 * gpu::kPi * (1.0 - 0.5 * (cosInner + cosOuter)) * lum);
            break;
        }
        case LightType::Directional:
            light.type = gpu::kLightDirectional;
            power.push_back(lum * gpu::kPi * sceneRadius * sceneRadius);
            break;
        }
        a.lights.push_back(light);
    }

    double total = 0.0;
    for (double p : power) total += p;
    a.totalLightPower = total;
    double running = 0.0;
    for (size_t i = 0; i < a.lights.size(); ++i) {
        const double pdf = total > 0.0 ? power[i] / total : 1.0 / static_cast<double>(a.lights.size());
        a.lights[i].selectPdf = static_cast<float>(pdf);
        running += pdf;
        a.lightCdf.push_back(i + 1 == a.lights.size() ? 1.0f : static_cast<float>(running));
        if (a.lights[i].type == gpu::kLightTriangle) {
            const gpu::GpuTriangle& t = a.triangles[a.lights[i].triangle];
            const float area = 0.5f * glm::length(glm::cross(glm::vec3(t.v1 - t.v0), glm::vec3(t.v2 - t.v0)));
            a.shading[a.lights[i].triangle].emitterPdfArea = static_cast<float>(pdf) / area;
        }
    }
    for (gpu::GpuTriangle& t : a.triangles) t.v0.w = -1.0f;
    for (size_t i = 0; i < a.lights.size(); ++i)
        if (a.lights[i].type == gpu::kLightTriangle) a.triangles[a.lights[i].triangle].v0.w = static_cast<float>(i);
    a.lightSampling = sampling;
    a.lightTree = appendLightSelection(
        a.lightCdf, buildLightTree(a.lights, a.triangles, a.shading, a.materials, power),
        static_cast<uint32_t>(a.lights.size()), sampling);

    for (const Texture& tex : scene.textures) {
        gpu::GpuTexture g{};
        g.offset = static_cast<uint32_t>(a.texels.size());
        g.width = tex.width;
        g.height = tex.height;
        g.srgb = tex.srgb ? 1u : 0u;
        a.textures.push_back(g);
        a.texels.insert(a.texels.end(), tex.rgba8.begin(), tex.rgba8.end());
    }
    return a;
}

gpu::GpuCamera makeGpuCamera(const Camera& camera, uint32_t width, uint32_t height) {
    gpu::GpuCamera c{};
    c.position = camera.position;
    c.forward = glm::normalize(camera.forward);
    c.right = glm::normalize(glm::cross(c.forward, camera.up));
    c.up = glm::cross(c.right, c.forward);
    c.tanHalfFovY = std::tan(0.5f * camera.yfov);
    c.aspect = static_cast<float>(width) / static_cast<float>(height);
    return c;
}

SceneBuffers::SceneBuffers(vk::Context& context, const SceneArrays& a)
    : m_triangles(vk::makeStorageBuffer(context, "triangles", a.triangles)),
      m_nodes(vk::makeStorageBuffer(context, "BVH nodes", a.nodes)),
      m_shading(vk::makeStorageBuffer(context, "triangle shading", a.shading)),
      m_materials(vk::makeStorageBuffer(context, "materials", a.materials)),
      m_lights(vk::makeStorageBuffer(context, "lights", a.lights)),
      m_lightCdf(vk::makeStorageBuffer(context, "light CDF", a.lightCdf)),
      m_textures(vk::makeStorageBuffer(context, "textures", a.textures)),
      m_texels(vk::makeStorageBuffer(context, "texels", a.texels)),
      m_lightCount(static_cast<uint32_t>(a.lights.size())) {}

std::vector<const vk::Buffer*> SceneBuffers::bindings() const {
    std::vector<const vk::Buffer*> b(gpu::kSceneBindingCount);
    b[gpu::kSceneTrianglesBinding] = &m_triangles;
    b[gpu::kSceneBvhNodesBinding] = &m_nodes;
    b[gpu::kSceneShadingBinding] = &m_shading;
    b[gpu::kSceneMaterialsBinding] = &m_materials;
    b[gpu::kSceneLightsBinding] = &m_lights;
    b[gpu::kSceneLightCdfBinding] = &m_lightCdf;
    b[gpu::kSceneTexturesBinding] = &m_textures;
    b[gpu::kSceneTexelsBinding] = &m_texels;
    return b;
}

void SceneBuffers::replaceLightSelection(vk::Context& context, const std::vector<float>& data) {
    m_lightCdf = vk::makeStorageBuffer(context, "light CDF", data);
}

uint64_t SceneBuffers::bytes() const {
    uint64_t total = 0;
    for (const vk::Buffer* b : bindings()) total += b->size();
    return total;
}

}  // namespace vkp
