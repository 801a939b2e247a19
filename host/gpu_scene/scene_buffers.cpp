#include "gpu_scene/scene_buffers.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <stdexcept>

#include "bvh/bvh.h"
#include "scene/environment_distribution.h"
#include "scene/textured_emission.h"
#include "shared/bsdf_tables.glsl"
#include "shared/constants.glsl"
#include "shared/light_selection.glsl"
#include "shared/photon.glsl"
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
    g.transmissionTexture = m.transmissionTexture;
    g.ior = m.ior;
    g.thickness = m.thickness;
    // Beer-Lambert: attenuationColor is the colour after attenuationDistance; sigma = -ln(c)/d.
    glm::vec3 sigma(0.0f);
    if (m.thickness > 0.0f && std::isfinite(m.attenuationDistance) && m.attenuationDistance > 0.0f)
        sigma = -glm::log(glm::max(m.attenuationColor, glm::vec3(1e-6f))) / m.attenuationDistance;
    g.attenuationCoeff = sigma;
    g.flags = (emitterDoubleSided ? gpu::kMaterialDoubleSided : 0u) |
              (m.transmission > 0.0f && m.thickness <= 0.0f ? gpu::kMaterialThinWalled : 0u) |
              (m.alphaMode == AlphaMode::Mask ? gpu::kMaterialAlphaMask : 0u) |
              (m.alphaMode == AlphaMode::Blend ? gpu::kMaterialAlphaBlend : 0u);
    g.baseColorTexture = m.baseColorTexture;
    g.metallicRoughnessTexture = m.metallicRoughnessTexture;
    g.emissiveTexture = m.emissiveTexture;
    g.normalTexture = m.normalTexture;
    g.normalScale = m.normalScale;
    g.alphaCutoff = m.alphaCutoff;
    g.specularColor = m.specularColor;
    g.specular = m.specular;
    g.sheenColor = m.sheenColor;
    g.sheenRoughness = m.sheenRoughness;
    g.clearcoat = m.clearcoat;
    g.clearcoatRoughness = m.clearcoatRoughness;
    g.specularTexture = m.specularTexture;
    g.specularColorTexture = m.specularColorTexture;
    g.sheenColorTexture = m.sheenColorTexture;
    g.sheenRoughnessTexture = m.sheenRoughnessTexture;
    g.clearcoatTexture = m.clearcoatTexture;
    g.clearcoatRoughnessTexture = m.clearcoatRoughnessTexture;
    g.clearcoatNormalTexture = m.clearcoatNormalTexture;
    g.clearcoatNormalScale = m.clearcoatNormalScale;
    g.anisotropy = m.anisotropy;
    g.anisotropyTexture = m.anisotropyTexture;
    g.anisotropyRotation = glm::vec2(std::cos(m.anisotropyRotation), std::sin(m.anisotropyRotation));
    g.iridescence = m.iridescence;
    g.iridescenceIor = m.iridescenceIor;
    g.iridescenceThicknessMin = m.iridescenceThicknessMin;
    g.iridescenceThicknessMax = m.iridescenceThicknessMax;
    g.iridescenceTexture = m.iridescenceTexture;
    g.iridescenceThicknessTexture = m.iridescenceThicknessTexture;
    g.dispersion = m.dispersion;
    return g;
}

// Normals, COLOR_0 and tangents of a triangle into GpuTriangleShading's packed fields.
void packVertexData(const Triangle& t, gpu::GpuTriangleShading& s) {
    s.n0 = gpu::encodeOctahedral(t.n[0]);
    s.n1 = gpu::encodeOctahedral(t.n[1]);
    s.n2 = gpu::encodeOctahedral(t.n[2]);
    s.color0 = glm::packUnorm4x8(t.color[0]);
    s.color1 = glm::packUnorm4x8(t.color[1]);
    s.color2 = glm::packUnorm4x8(t.color[2]);
    s.tangentSign = t.tangent[0].w == 0.0f ? gpu::kTangentNone
                    : t.tangent[0].w < 0.0f ? gpu::kTangentNegative
                                            : gpu::kTangentPositive;
    if (s.tangentSign == gpu::kTangentNone) return;
    s.tangent0 = gpu::encodeOctahedral(glm::vec3(t.tangent[0]));
    s.tangent1 = gpu::encodeOctahedral(glm::vec3(t.tangent[1]));
    s.tangent2 = gpu::encodeOctahedral(glm::vec3(t.tangent[2]));
}

}  // namespace

SceneArrays buildSceneArrays(const Scene& scene, LightSampling sampling, const TextureLimits& textureLimits) {
    SceneArrays a;
    for (const Instance& instance : scene.instances)  // the light list holds static triangles only
        for (const Triangle& t : scene.meshes.at(instance.mesh).triangles)
            if (gpu::luminance(scene.materials.at(t.material).emissive) > 0.0f)
                throw std::invalid_argument("an instanced mesh has an emissive material (docs/bvh.md: emissive "
                                            "meshes are flattened)");
    const auto start = std::chrono::steady_clock::now();
    SceneBvh bvh = buildSceneBvh(scene);
    a.bvhBuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    a.nodes = std::move(bvh.nodes);
    a.triangles = std::move(bvh.triangles);
    a.topLevel = std::move(bvh.top);

    for (const Material& m : scene.materials) a.materials.push_back(toGpu(m, m.doubleSided));
    if (!scene.energyCompensation)
        for (gpu::GpuMaterial& g : a.materials) g.flags |= gpu::kMaterialNoEnergyCompensation;

    // The source triangle of each position in the triangle arrays: static ones, then meshes'.
    std::vector<const Triangle*> source;
    source.reserve(a.triangles.size());
    for (uint32_t index : bvh.staticOrder) source.push_back(&scene.triangles[index]);
    for (size_t m = 0; m < bvh.meshOrder.size(); ++m)
        for (uint32_t index : bvh.meshOrder[m]) source.push_back(&scene.meshes[m].triangles[index]);
    // Sky boxes' triangles (Scene::backdropNodes): flattened ones by the drawings of their nodes,
    // an instanced mesh's when every instance of it is a sky box's (its flags are shared).
    const auto isBackdrop = [&](int node) {
        return std::binary_search(scene.backdropNodes.begin(), scene.backdropNodes.end(), node);
    };
    std::vector<bool> backdrop(scene.triangles.size(), false);
    for (const Drawing& d : scene.drawings)
        if (isBackdrop(d.node) && d.first < backdrop.size())
            std::fill_n(backdrop.begin() + d.first, std::min<size_t>(d.count, backdrop.size() - d.first), true);
    std::vector<int> meshBackdrop(scene.meshes.size(), -1);  // -1: no instance yet, 1: all sky box, 0: not
    for (const Instance& instance : scene.instances) {
        int& state = meshBackdrop[instance.mesh];
        state = (state != 0 && isBackdrop(instance.node)) ? 1 : 0;
    }
    std::vector<bool> positionBackdrop;  // per position in the triangle arrays
    positionBackdrop.reserve(a.triangles.size());
    for (uint32_t index : bvh.staticOrder) positionBackdrop.push_back(backdrop[index]);
    for (size_t m = 0; m < bvh.meshOrder.size(); ++m)
        positionBackdrop.insert(positionBackdrop.end(), bvh.meshOrder[m].size(), meshBackdrop[m] == 1);
    for (uint32_t i = 0; i < a.triangles.size(); ++i) {  // the traversal's alpha test and culling (gpu_types.glsl)
        const Material& m = scene.materials[source[i]->material];
        if (m.alphaMode != AlphaMode::Opaque) a.triangles[i].v0.w = gpu::kTriangleAlphaTested;
        if (positionBackdrop[i]) a.triangles[i].v0.w = gpu::kTriangleBackdrop;
        // glTF culls the back faces of single-sided materials; camera rays do (docs/scene-format.md
        // "Back faces"), except on transmissive ones, whose back faces refracted rays see from inside.
        if (!m.doubleSided && m.transmission <= 0.0f) a.triangles[i].v2.w = 1.0f;
    }
    a.shading.reserve(a.triangles.size());
    const TexturedEmission emission(scene);
    std::vector<double> power;
    const uint32_t staticCount = a.topLevel.header.staticTriangles;
    for (uint32_t i = 0; i < source.size(); ++i) {
        const Triangle& t = *source[i];
        gpu::GpuTriangleShading s{};
        s.uv01 = glm::vec4(t.uv[0], t.uv[1]);
        s.uv2 = t.uv[2];
        s.material = t.material;
        s.emitterPdfArea = 0.0f;
        s.uvB01 = glm::vec4(t.uv1[0], t.uv1[1]);
        s.uvB2 = t.uv1[2];
        packVertexData(t, s);
        a.shading.push_back(s);
        if (i >= staticCount) continue;  // instanced triangles are never lights (checked above)

        const Material& m = scene.materials[t.material];
        // Emissive textures: the emission averaged over the texels the triangle reads; a
        // triangle whose texels are all black is no light (it emits nothing anywhere).
        const float le = gpu::luminance(glm::vec3(emission.meanEmission(t)));
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

    // The environment last (shaders/render/scene_access.glsl environmentLightIndex); its map's floats
    // follow the textures' texels (appended below).
    std::vector<float> environmentData = environmentGpuData(scene.environment);
    if (scene.environment.present) {
        gpu::GpuLight light{};
        light.type = gpu::kLightEnvironment;
        light.intensity = scene.environment.radiance;
        light.envWidth = scene.environment.width;
        light.envHeight = scene.environment.height;
        light.envRotation = scene.environment.rotation;
        light.envFlags = scene.environment.importanceSampling ? 0u : gpu::kEnvironmentSampleUniform;
        a.lights.push_back(light);
        power.push_back(environmentPower(scene.environment, std::max(sceneRadius, 1e-6f)));
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
    for (gpu::GpuTriangle& t : a.triangles) t.v1.w = -1.0f;
    for (size_t i = 0; i < a.lights.size(); ++i)
        if (a.lights[i].type == gpu::kLightTriangle) a.triangles[a.lights[i].triangle].v1.w = static_cast<float>(i);
    a.lightSampling = sampling;
    a.lightPower = power;
    a.lightTree = appendLightSelection(
        a.lightCdf, buildLightTree(a.lights, a.triangles, a.shading, a.materials, power),
        static_cast<uint32_t>(a.lights.size()), sampling);

    static_assert(uint32_t(TextureWrap::ClampToEdge) == gpu::kTextureWrapClamp &&
                  uint32_t(TextureWrap::MirroredRepeat) == gpu::kTextureWrapMirrored);
    static_assert(uint32_t(MipmapMode::Nearest) == gpu::kTextureMipmapNearest &&
                  uint32_t(MipmapMode::Linear) == gpu::kTextureMipmapLinear);
    std::vector<bool> mipmapped(scene.textures.size(), false);
    for (const TextureView& view : scene.textureViews)
        if (view.mipmaps != MipmapMode::None) mipmapped[view.image] = true;
    a.textureAtlas = buildTextureAtlas(scene.textures, textureLimits, mipmapped);
    for (const TextureView& view : scene.textureViews) {
        const Texture& tex = scene.textures[view.image];
        const TextureAtlasEntry& e = a.textureAtlas.entries[view.image];
        gpu::GpuTexture g{};
        g.origin = e.x | (e.y << 16);
        g.layer = e.layer;
        g.width = e.width;
        g.height = e.height;
        g.srgb = tex.srgb ? 1u : 0u;
        g.uvRow0 = glm::vec4(view.uvRow0, 0.0f);
        g.uvRow1 = glm::vec4(view.uvRow1, 0.0f);
        g.texCoord = static_cast<uint32_t>(view.texCoord);
        g.wrapS = static_cast<uint32_t>(view.wrapS);
        g.wrapT = static_cast<uint32_t>(view.wrapT);
        g.magFilter = view.nearest ? gpu::kTextureFilterNearest : gpu::kTextureFilterLinear;
        g.minFilter = view.minNearest ? gpu::kTextureFilterNearest : gpu::kTextureFilterLinear;
        g.mipmapMode = static_cast<uint32_t>(view.mipmaps);
        g.levels = view.mipmaps == MipmapMode::None ? 1u : e.levels;
        a.textures.push_back(g);
    }
    if (!environmentData.empty()) a.lights.back().envOffset = 0;
    a.environment = std::move(environmentData);
    return a;
}

std::vector<uint8_t> SceneArrays::instanceBytes() const {
    std::vector<uint8_t> bytes(sizeof(gpu::GpuInstanceHeader) + topLevel.instances.size() * sizeof(gpu::GpuInstance));
    std::memcpy(bytes.data(), &topLevel.header, sizeof(gpu::GpuInstanceHeader));
    if (!topLevel.instances.empty())
        std::memcpy(bytes.data() + sizeof(gpu::GpuInstanceHeader), topLevel.instances.data(),
                    topLevel.instances.size() * sizeof(gpu::GpuInstance));
    return bytes;
}

std::vector<gpu::GpuTriangle> worldTriangles(const SceneArrays& arrays) {
    const InstanceLevel& top = arrays.topLevel;
    if (top.instances.empty()) return arrays.triangles;
    std::vector<gpu::GpuTriangle> out(arrays.triangles.begin(), arrays.triangles.begin() + top.header.staticTriangles);
    for (size_t k = 0; k < top.instances.size(); ++k) {
        const gpu::GpuInstance& g = top.instances[k];
        const uint32_t count = top.meshTriangles[top.instanceMesh[k]];
        for (uint32_t j = 0; j < count; ++j) {
            gpu::GpuTriangle t = arrays.triangles[g.firstTriangle + j];
            for (glm::vec4* v : {&t.v0, &t.v1, &t.v2})
                *v = glm::vec4(gpu::transformPoint3x4(g.objectToWorld[0], g.objectToWorld[1], g.objectToWorld[2],
                                                      glm::vec3(*v)),
                               v->w);
            if ((g.flags & gpu::kInstanceMirrored) != 0u) {  // the winding the loader gives flattened copies
                const glm::vec3 p1(t.v1);                     // (positions only: w holds the flags)
                t.v1 = glm::vec4(glm::vec3(t.v2), t.v1.w);
                t.v2 = glm::vec4(p1, t.v2.w);
            }
            out.push_back(t);
        }
    }
    return out;
}

gpu::GpuCamera makeGpuCamera(const Camera& camera, uint32_t width, uint32_t height) {
    gpu::GpuCamera c{};
    c.position = camera.position;
    c.forward = glm::normalize(camera.forward);
    c.right = glm::normalize(glm::cross(c.forward, camera.up));
    c.up = glm::cross(c.right, c.forward);
    c.tanHalfFovY = std::tan(0.5f * camera.yfov);
    c.aspect = static_cast<float>(width) / static_cast<float>(height);
    c.orthoHalfHeight = camera.orthoHalfHeight;
    return c;
}

vk::Buffer makeBsdfTablesBuffer(vk::Context& context) {
    const std::vector<float> tables(std::begin(gpu::kBsdfTables), std::end(gpu::kBsdfTables));
    return vk::makeStorageBuffer(context, "BSDF tables", tables);
}

SceneBuffers::SceneBuffers(vk::Context& context, const SceneArrays& a)
    : m_triangles(vk::makeTexelReadBuffer(context, "triangles", a.triangles)),
      m_nodes(vk::makeTexelReadBuffer(context, "BVH nodes", a.nodes)),
      m_shading(vk::makeStorageBuffer(context, "triangle shading", a.shading)),
      m_materials(vk::makeStorageBuffer(context, "materials", a.materials)),
      m_lights(vk::makeStorageBuffer(context, "lights", a.lights)),
      m_lightCdf(vk::makeStorageBuffer(context, "light CDF", a.lightCdf)),
      m_textures(vk::makeStorageBuffer(context, "textures", a.textures)),
      m_texels(vk::makeStorageBuffer(context, "environment map", a.environment)),
      m_tables(makeBsdfTablesBuffer(context)),
      m_instances(vk::makeStorageBuffer(context, "instances", a.instanceBytes())),
      m_textureArray(std::make_unique<vk::TextureArray>(context, "texture atlas", a.textureAtlas.width,
                                                        a.textureAtlas.height, a.textureAtlas.layers,
                                                        a.textureAtlas.texels)),
      m_bvhTexels(context, m_nodes, a.nodes.size(), m_triangles, a.triangles.size()),
      m_lightCount(static_cast<uint32_t>(a.lights.size())), m_specialization(sceneSpecialization(a)) {
    m_specialization.bvhTexels = m_bvhTexels.covers();  // else the traversal reads the storage buffers
}

namespace {
// The mode word of light-selection data (shared/light_selection.glsl), kLightSamplerAny when there
// is none (no lights).
uint32_t lightSamplerOf(const std::vector<float>& selection, size_t lightCount) {
    if (lightCount == 0 || selection.size() <= lightCount) return gpu::kLightSamplerAny;
    uint32_t mode;
    std::memcpy(&mode, &selection[lightCount], sizeof mode);
    return mode;
}
}  // namespace

vk::SceneSpecialization sceneSpecialization(const SceneArrays& a) {
    vk::SceneSpecialization s;
    s.instances = a.topLevel.header.instanceCount > 0;
    s.alphaTest = std::any_of(a.triangles.begin(), a.triangles.end(),
                              [](const gpu::GpuTriangle& t) { return t.v0.w != 0.0f; });
    s.textures = !a.textures.empty();
    s.lightSampler = lightSamplerOf(a.lightCdf, a.lights.size());
    return s;
}

TextureLimits deviceTextureLimits(const vk::Context& context, uint32_t maxTextureSize) {
    const vk::TextureArrayLimits device = vk::textureArrayLimits(context);
    TextureLimits limits;
    limits.maxTextureSize = maxTextureSize;
    limits.maxLayerSize = device.maxSize;
    limits.maxLayers = device.maxLayers;
    limits.maxBytes = device.maxBytes;
    // Test hook: a smaller budget, so tests reach the automatic downscale without huge textures.
    if (const char* budget = std::getenv("VKPHOTON_TEXTURE_BUDGET_BYTES"))
        limits.maxBytes = std::min<uint64_t>(limits.maxBytes, std::strtoull(budget, nullptr, 10));
    return limits;
}

vk::KernelBindings SceneBuffers::bindings() const {
    std::vector<const vk::Buffer*> b(gpu::kSceneBindingCount);
    b[gpu::kSceneTrianglesBinding] = &m_triangles;
    b[gpu::kSceneBvhNodesBinding] = &m_nodes;
    b[gpu::kSceneShadingBinding] = &m_shading;
    b[gpu::kSceneMaterialsBinding] = &m_materials;
    b[gpu::kSceneLightsBinding] = &m_lights;
    b[gpu::kSceneLightCdfBinding] = &m_lightCdf;
    b[gpu::kSceneTexturesBinding] = &m_textures;
    b[gpu::kSceneTexelsBinding] = &m_texels;
    b[gpu::kSceneTablesBinding] = &m_tables;
    b[gpu::kSceneInstancesBinding] = &m_instances;
    return {b, m_textureArray.get(), m_specialization, &m_bvhTexels.views()};
}

void SceneBuffers::updateInstances(const SceneArrays& a) {
    if ((a.topLevel.header.instanceCount > 0) != m_specialization.instances)  // kernels are specialized for it
        throw std::logic_error("SceneBuffers::updateInstances: a scene cannot gain or lose its instances");
    const std::vector<uint8_t> bytes = a.instanceBytes();
    m_instances.upload(bytes.data(), bytes.size());
    const uint32_t first = a.topLevel.header.tlasRoot;
    if (a.topLevel.instances.empty() || first >= a.nodes.size()) return;
    m_nodes.upload(a.nodes.data() + first, (a.nodes.size() - first) * sizeof(gpu::GpuBvhNode),
                   first * sizeof(gpu::GpuBvhNode));
}

void SceneBuffers::updateLights(const SceneArrays& a) {
    const auto padded = [](size_t bytes) { return std::max<VkDeviceSize>(16, bytes); };  // makeStorageBuffer's size
    if (padded(a.lights.size() * sizeof(gpu::GpuLight)) != m_lights.size() ||
        a.lightCdf.size() * sizeof(float) > m_lightCdf.size())
        throw std::logic_error("SceneBuffers::updateLights: the lights changed size or their selection data outgrew its buffer");
    checkLightSampler(a.lightCdf);
    m_lights.upload(a.lights);
    m_lightCdf.upload(a.lightCdf);
}

void SceneBuffers::checkLightSampler(const std::vector<float>& selection) const {
    // Kernels bound to this scene are compiled for its light sampler (sceneSpecialization).
    if (m_specialization.lightSampler != gpu::kLightSamplerAny &&
        lightSamplerOf(selection, m_lightCount) != m_specialization.lightSampler)
        throw std::logic_error("SceneBuffers: new light-selection data names another light sampler than the scene's");
}

bool SceneBuffers::replaceLightSelection(vk::Context& context, const std::vector<float>& data) {
    const VkDeviceSize bytes = data.size() * sizeof(float);
    checkLightSampler(data);
    if (bytes <= m_lightCdf.size()) {
        if (!data.empty()) m_lightCdf.upload(data);
        return true;
    }
    // Headroom: per-frame photon light cells (render --frames) vary in size from frame to frame.
    m_lightCdf = vk::Buffer(context, "light CDF", 2 * bytes, vk::kStorageUsage);
    m_lightCdf.upload(data);
    return false;
}

uint64_t SceneBuffers::bytes() const {
    uint64_t total = 0;
    for (const vk::Buffer* b : bindings().buffers) total += b->size();
    total += m_textureArray->bytes();
    return total;
}

}  // namespace vkp
