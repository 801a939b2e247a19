#include "animation/frame_scene.h"

#include <cstring>
#include <vector>

#include "util/stopwatch.h"

namespace vkp {
namespace {

template <typename T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameBounds(const Bounds& a, const Bounds& b) { return a.min == b.min && a.max == b.max; }

// Whether anything that moves in place (instances, punctual lights) differs between the two.
bool somethingMoved(const Scene& current, const Scene& next) {
    for (size_t i = 0; i < current.instances.size(); ++i)
        if (current.instances[i].transform != next.instances[i].transform) return true;
    for (size_t i = 0; i < current.lights.size(); ++i)
        if (current.lights[i].position != next.lights[i].position ||
            current.lights[i].direction != next.lights[i].direction)
            return true;
    return false;
}

}  // namespace

FrameScene::FrameScene(vk::Context& context, LightSampling lightSampling, bool alwaysRebuild)
    : m_context(context), m_lightSampling(lightSampling), m_alwaysRebuild(alwaysRebuild) {}

FrameScene::~FrameScene() = default;

std::string FrameScene::whyNotInPlace(const Scene& current, const Scene& next) {
    // Scene::triangles are flattened (static) geometry: an animated emissive mesh stays flattened
    // (emissive meshes are never instanced, docs/bvh.md), so its motion changes them.
    if (!sameBytes(current.triangles, next.triangles)) return "static (flattened) triangles changed";
    if (current.meshes.size() != next.meshes.size()) return "the instanced meshes changed";
    for (size_t m = 0; m < current.meshes.size(); ++m)
        if (!sameBytes(current.meshes[m].triangles, next.meshes[m].triangles)) return "an instanced mesh changed";
    if (current.instances.size() != next.instances.size()) return "the number of instances changed";
    for (size_t i = 0; i < current.instances.size(); ++i)
        if (current.instances[i].mesh != next.instances[i].mesh) return "an instance's mesh changed";
    if (current.materials.size() != next.materials.size() || current.textures.size() != next.textures.size() ||
        current.textureViews.size() != next.textureViews.size())
        return "materials or textures changed";
    if (current.lights.size() != next.lights.size()) return "the number of punctual lights changed";
    if (!sameBounds(current.bounds, next.bounds)) return "the scene bounds changed";
    const Environment& a = current.environment;
    const Environment& b = next.environment;
    if (a.present != b.present || a.radiance != b.radiance || a.width != b.width || a.height != b.height ||
        a.rotation != b.rotation || a.importanceSampling != b.importanceSampling || !sameBytes(a.rgb, b.rgb))
        return "the environment changed";
    if (current.energyCompensation != next.energyCompensation) return "the energy compensation setting changed";
    return {};
}

FrameSceneChange FrameScene::set(Scene next) {
    FrameSceneChange change;
    m_retiredRenderer.reset();
    m_retiredScene.reset();
    if (m_renderer && !m_alwaysRebuild) {
        change.reason = whyNotInPlace(*m_scene, next);
        if (change.reason.empty()) {
            GpuScene& gpu = m_renderer->gpuScene();
            if (!gpu.updatePunctualLights(next)) {
                change.reason = "a punctual light changed more than its position and direction";
            } else {
                const bool moved = somethingMoved(*m_scene, next);
                std::vector<glm::mat4> transforms;
                transforms.reserve(next.instances.size());
                for (const Instance& instance : next.instances) transforms.push_back(instance.transform);
                gpu.updateInstanceTransforms(transforms);
                change.bvhSeconds = gpu.arrays().bvhBuildSeconds;
                change.uploadSeconds = gpu.uploadSeconds();
                // What GpuScene's Scene reference shows from now on (cameras for makeFrame,
                // lights and instance transforms for whoever reads the Scene).
                m_scene->instances = std::move(next.instances);
                m_scene->lights = std::move(next.lights);
                m_scene->cameras = std::move(next.cameras);
                // --light-sampler photon: the cells and the light reach follow the motion (the
                // cells' photons have their own fixed seed: the same scene gives the same cells).
                if (moved && m_lightSampling.sampler == LightSampler::Photon) {
                    const bool sameBuffer = m_renderer->refreshLightCells();
                    change.lightCellSeconds = m_renderer->lightCells()->seconds;
                    if (!sameBuffer) {  // a new light-selection buffer: integrators must bind it
                        change.rebuilt = true;
                        change.reason = "the photon light cells outgrew their buffer";
                        ++m_generation;
                    }
                }
                return change;
            }
        }
    } else {
        change.reason = m_renderer ? "rebuild every frame" : "first frame";
    }
    change.rebuilt = true;
    ++m_generation;
    // The old scene stays until the next call: the caller's integrator still refers to it.
    m_retiredRenderer = std::move(m_renderer);
    m_retiredScene = std::move(m_scene);
    m_scene = std::make_unique<Scene>(std::move(next));
    m_renderer = std::make_unique<Renderer>(m_context, *m_scene, m_lightSampling);
    change.bvhSeconds = m_renderer->gpuScene().arrays().bvhBuildSeconds;
    change.uploadSeconds = m_renderer->gpuScene().uploadSeconds();
    return change;
}

}  // namespace vkp
