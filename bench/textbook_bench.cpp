// Error per sample of vkphoton's path tracer against a textbook one: a CPU path tracer
// on Embree 3 written the way the textbooks write it (pbrt's PathIntegrator for Lambertian
// surfaces: next-event estimation by power-proportional light choice and uniform area sampling,
// BSDF sampling by the cosine, both weighted by the power heuristic, Russian roulette on the
// throughput from the fourth vertex), independent uniform random numbers per sample and
// uniformly jittered pixel samples. Both render the scene's camera at the reference's size with
// the same spp; the table gives each one's relMSE against the reference (e.g. the Cycles renders
// in tests/data/cycles) averaged over seeds, and their ratio. Lambert scenes only (the Cornell
// "-lambert" files): other materials, textures and punctual lights are refused.
//   build/bench/textbook_bench SCENE.gltf REFERENCE.exr [--spp 4,16,64 --seeds 4 --threads T]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "embree_scene.h"
#include "gpu_scene/scene_buffers.h"
#include "image/exr.h"
#include "image/metrics.h"
#include "render/path_integrator.h"
#include "render/renderer.h"
#include "scene/gltf_loader.h"
#include "shared/gpu_types.glsl"
#include "shared/sampling.glsl"
#include "util/stopwatch.h"
#include "vk/context.h"

namespace {

using namespace vkp;

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// The emissive triangles, chosen in proportion to their power (area x luminance of the emission).
struct Lights {
    std::vector<uint32_t> triangles;
    std::vector<float> cdf;       // normalized, cdf.back() == 1
    std::vector<float> pick;      // per scene triangle: the probability of choosing it (0: not a light)
    std::vector<float> area;      // per scene triangle
};

Lights collectLights(const std::vector<Triangle>& triangles, const std::vector<Material>& materials) {
    Lights lights;
    lights.pick.assign(triangles.size(), 0.0f);
    lights.area.resize(triangles.size());
    double total = 0.0;
    std::vector<double> power;
    for (uint32_t i = 0; i < triangles.size(); ++i) {
        const Triangle& t = triangles[i];
        lights.area[i] = 0.5f * glm::length(glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]));
        const float le = luminance(materials[t.material].emissive);
        if (le <= 0.0f || lights.area[i] <= 0.0f) continue;
        lights.triangles.push_back(i);
        power.push_back(double(le) * lights.area[i]);
        total += power.back();
    }
    if (lights.triangles.empty()) throw std::runtime_error("the scene has no emissive triangles");
    double running = 0.0;
    for (size_t k = 0; k < power.size(); ++k) {
        running += power[k];
        lights.cdf.push_back(float(running / total));
        lights.pick[lights.triangles[k]] = float(power[k] / total);
    }
    lights.cdf.back() = 1.0f;
    return lights;
}

class TextbookPathTracer {
public:
    TextbookPathTracer(const Scene& scene, uint32_t width, uint32_t height)
        : m_triangles(flattenedTriangles(scene)), m_materials(scene.materials), m_embree(m_triangles),
          m_lights(collectLights(m_triangles, m_materials)), m_width(width), m_height(height) {
        if (scene.cameras.empty()) throw std::runtime_error("the scene has no camera");
        if (!scene.lights.empty()) throw std::runtime_error("punctual lights are not supported (Lambert + emitters only)");
        for (const Material& m : m_materials)  // a black emitter's specular layer is ignored (Cycles' mapping too)
            if (m.metallic > 0.0f || (m.specular > 0.0f && glm::vec3(m.baseColor) != glm::vec3(0.0f)) || m.transmission > 0.0f || m.baseColorTexture >= 0 ||
                m.emissiveTexture >= 0)
                throw std::runtime_error(fmt::format("material '{}' is not a plain Lambert surface (metallic 0, "
                                                     "specularFactor 0, no transmission, no textures)", m.name));
        m_camera = makeGpuCamera(scene.cameras[0], width, height);
    }

    ImageRgb render(uint32_t spp, uint32_t seed, unsigned threads) const {
        ImageRgb image;
        image.width = m_width;
        image.height = m_height;
        image.pixels.assign(size_t(m_width) * m_height * 3, 0.0f);
        std::atomic<uint32_t> nextRow{0};
        std::vector<std::thread> pool;
        for (unsigned t = 0; t < threads; ++t)
            pool.emplace_back([&] {
                for (uint32_t y; (y = nextRow.fetch_add(1)) < m_height;)
                    for (uint32_t x = 0; x < m_width; ++x) {
                        std::mt19937_64 rng((uint64_t(seed) << 40) ^ (uint64_t(y) << 20) ^ x ^ 0x9e3779b97f4a7c15ull);
                        glm::dvec3 sum(0.0);
                        for (uint32_t s = 0; s < spp; ++s) sum += glm::dvec3(radiance(x, y, rng));
                        for (int c = 0; c < 3; ++c) image.pixels[3 * (size_t(y) * m_width + x) + c] = float(sum[c] / spp);
                    }
            });
        for (auto& thread : pool) thread.join();
        return image;
    }

private:
    static float uniform(std::mt19937_64& rng) {
        return std::min(float((rng() >> 11) * 0x1.0p-53), 0x1.fffffep-1f);
    }

    // Emission leaving triangle `tri` towards -dir (front face only unless double-sided).
    glm::vec3 emission(uint32_t tri, const glm::vec3& geometricNormal, const glm::vec3& dir) const {
        const Material& m = m_materials[m_triangles[tri].material];
        const float facing = -glm::dot(geometricNormal, dir);
        return (facing > 0.0f || m.doubleSided) ? m.emissive : glm::vec3(0.0f);
    }

    // Solid-angle pdf of next-event estimation choosing the point at distance t on light `tri`.
    float lightPdf(uint32_t tri, const glm::vec3& lightNormal, const glm::vec3& dir, float t) const {
        const float cosLight = std::abs(glm::dot(lightNormal, dir));
        if (cosLight <= 0.0f) return 0.0f;
        return m_lights.pick[tri] / m_lights.area[tri] * t * t / cosLight;
    }

    glm::vec3 radiance(uint32_t px, uint32_t py, std::mt19937_64& rng) const {
        const glm::vec2 pixel(px + uniform(rng), py + uniform(rng));
        glm::vec3 origin = gpu::cameraRayOrigin(m_camera, m_width, m_height, pixel);
        glm::vec3 dir = gpu::cameraRayDirection(m_camera, m_width, m_height, pixel);
        glm::vec3 throughput(1.0f), result(0.0f);
        float previousBsdfPdf = 0.0f;  // 0: the camera vertex (emission counts in full)
        for (int depth = 0; depth < 64; ++depth) {
            float t;
            glm::vec3 ng;
            uint32_t tri;
            if (!m_embree.intersect(origin, dir, 1e-4f, t, ng, &tri)) break;
            const glm::vec3 x = origin + t * dir;
            const glm::vec3 le = emission(tri, ng, dir);
            if (le != glm::vec3(0.0f)) {
                float weight = 1.0f;
                if (previousBsdfPdf > 0.0f) {
                    const float pl = lightPdf(tri, ng, dir, t);
                    weight = previousBsdfPdf * previousBsdfPdf / (previousBsdfPdf * previousBsdfPdf + pl * pl);
                }
                result += throughput * le * weight;
            }
            const glm::vec3 n = glm::dot(ng, dir) < 0.0f ? ng : -ng;  // faced towards the incoming ray
            const glm::vec3 albedo(m_materials[m_triangles[tri].material].baseColor);

            // Next-event estimation: a light by power, a uniform point on it.
            const float u = uniform(rng);
            const size_t k = std::min(size_t(std::lower_bound(m_lights.cdf.begin(), m_lights.cdf.end(), u) -
                                             m_lights.cdf.begin()),
                                      m_lights.cdf.size() - 1);
            const uint32_t light = m_lights.triangles[k];
            const Triangle& lt = m_triangles[light];
            const glm::vec2 b = gpu::sampleTriangleBarycentrics(glm::vec2(uniform(rng), uniform(rng)));
            const glm::vec3 y = lt.p[0] + b.x * (lt.p[1] - lt.p[0]) + b.y * (lt.p[2] - lt.p[0]);
            const glm::vec3 toLight = y - x;
            const float dist = glm::length(toLight);
            const glm::vec3 wi = toLight / dist;
            const glm::vec3 nl = glm::normalize(glm::cross(lt.p[1] - lt.p[0], lt.p[2] - lt.p[0]));
            const float cosSurface = glm::dot(n, wi);
            const glm::vec3 lightLe = emission(light, nl, wi);
            if (cosSurface > 0.0f && lightLe != glm::vec3(0.0f) && dist > 2e-4f &&
                !m_embree.occluded(x, wi, 1e-4f, dist * (1.0f - 1e-4f))) {
                const float pl = lightPdf(light, nl, wi, dist);
                const float pb = cosSurface * gpu::kInvPi;
                if (pl > 0.0f) {
                    const float weight = pl * pl / (pl * pl + pb * pb);
                    result += throughput * albedo * gpu::kInvPi * cosSurface * lightLe * (weight / pl);
                }
            }

            // BSDF sampling: cosine-weighted, so the throughput gains the albedo.
            glm::vec3 tangent, bitangent;
            gpu::orthonormalBasis(n, tangent, bitangent);
            const glm::vec3 local = gpu::sampleCosineHemisphere(glm::vec2(uniform(rng), uniform(rng)));
            dir = glm::normalize(gpu::toWorld(local, tangent, bitangent, n));
            previousBsdfPdf = gpu::cosineHemispherePdf(local.z);
            if (previousBsdfPdf <= 0.0f) break;
            throughput *= albedo;
            origin = x;
            if (depth >= 3) {  // Russian roulette from the fourth vertex on
                const float q = std::min(0.95f, std::max({throughput.x, throughput.y, throughput.z}));
                if (uniform(rng) >= q) break;
                throughput /= q;
            }
        }
        return result;
    }

    std::vector<Triangle> m_triangles;
    std::vector<Material> m_materials;
    bench::EmbreeScene m_embree;
    Lights m_lights;
    uint32_t m_width, m_height;
    gpu::GpuCamera m_camera{};
};

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Error per sample: vkphoton's path tracer against a textbook NEE+MIS path tracer (Embree, CPU)"};
    std::string scenePath, referencePath, device;
    std::vector<uint32_t> spps{4, 16, 64};
    uint32_t seeds = 4;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());
    app.add_option("scene", scenePath, "Lambert glTF scene (e.g. tests/data/cycles/cornell-box-lambert.gltf)")->required();
    app.add_option("reference", referencePath, "converged reference EXR of its first camera")->required();
    app.add_option("--spp", spps, "samples per pixel to compare")->delimiter(',')->capture_default_str();
    app.add_option("--seeds", seeds, "renders per spp (relMSE is their mean)")->capture_default_str();
    app.add_option("--threads", threads, "CPU threads of the textbook tracer")->capture_default_str();
    app.add_option("--device", device, "Vulkan device for vkphoton");
    CLI11_PARSE(app, argc, argv);
    try {
        const Scene scene = loadGltf(scenePath);
        const ImageRgb reference = readExr(referencePath);
        const TextbookPathTracer textbook(scene, reference.width, reference.height);
        vk::Context context({false, device});
        Renderer renderer(context, scene);
        fmt::print("{} against {} ({}x{}), {} seeds, vkphoton on {}, textbook on {} CPU threads\n\n", scenePath,
                   referencePath, reference.width, reference.height, seeds, context.deviceName(), threads);
        fmt::print("| spp | textbook relMSE | vkphoton relMSE | vkphoton / textbook | textbook mean / reference | "
                   "vkphoton mean / reference | textbook s | vkphoton s |\n");
        fmt::print("|---|---|---|---|---|---|---|---|\n");
        const double referenceMean = meanLuminance(reference);
        for (uint32_t spp : spps) {
            double errTextbook = 0, errVkp = 0, secTextbook = 0, secVkp = 0, meanTextbook = 0, meanVkp = 0;
            for (uint32_t seed = 0; seed < seeds; ++seed) {
                auto start = Clock::now();
                const ImageRgb mine = textbook.render(spp, seed, threads);
                errTextbook += relativeMse(mine, reference);
                meanTextbook += meanLuminance(mine) / referenceMean;
                secTextbook += secondsSince(start);
                FrameSettings settings;
                settings.width = reference.width;
                settings.height = reference.height;
                settings.samplesPerPixel = spp;
                settings.seed = seed;
                start = Clock::now();
                const ImageRgb theirs = renderer.render<PathIntegrator>(settings).image;
                errVkp += relativeMse(theirs, reference);
                meanVkp += meanLuminance(theirs) / referenceMean;
                secVkp += secondsSince(start);
            }
            fmt::print("| {} | {:.4g} | {:.4g} | {:.3f} | {:.4f} | {:.4f} | {:.2f} | {:.2f} |\n", spp,
                       errTextbook / seeds, errVkp / seeds, errVkp / errTextbook, meanTextbook / seeds, meanVkp / seeds,
                       secTextbook / seeds, secVkp / seeds);
            std::fflush(stdout);
        }
    } catch (const std::exception& e) {
        fmt::print(stderr, "textbook_bench: {}\n", e.what());
        return 1;
    }
    return 0;
}
