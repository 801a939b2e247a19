// The environment light (docs/environment.md): the map's mapping (Blender's, in glTF axes) and
// rotation, its importance sampling against its pdf (chi-square), hostile maps, and renders with
// closed-form answers: a Lambert sphere under a uniform environment in every integrator, a plane
// lit by a sun-and-sky map to the irradiance summed from the map's pixels.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <stb/stb_image_write.h>

#include "lights/default_lighting.h"
#include "support/chi_square.h"
#include "support/gpu_test_support.h"
#include "image/exr.h"
#include "render/aov.h"
#include "guiding/guided_integrator.h"
#include "render/path_integrator.h"
#include "photon/photon_integrator.h"
#include "render/renderer.h"
#include "scene/environment.h"
#include "scene/environment_distribution.h"
#include "shared/environment.glsl"
#include "support/test_scenes.h"
#include "util/errors.h"
#include "support/small_frame.h"

namespace vkp {
namespace {

namespace fs = std::filesystem;
using gpu::EnvironmentMap;

constexpr double kPiD = 3.14159265358979323846;

fs::path tempDir() {
    const fs::path dir = fs::temp_directory_path() / ("vkphoton-env-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

// A sun-and-sky map: sky radiance rising towards the zenith (bluish), a dim ground, and a sun of
// 2x2 pixels at row sunRow (from the top) and column sunColumn.
Environment sunAndSky(uint32_t width, uint32_t height, uint32_t sunColumn, uint32_t sunRow, float sun) {
    Environment env;
    env.present = true;
    env.width = width;
    env.height = height;
    env.rgb.resize(size_t(width) * height * 3);
    for (uint32_t j = 0; j < height; ++j)
        for (uint32_t i = 0; i < width; ++i) {
            float* p = &env.rgb[3 * (size_t(j) * width + i)];
            const float t = (j + 0.5f) / height;
            const glm::vec3 c = t < 0.5f ? glm::vec3(0.4f, 0.6f, 1.0f) * (1.5f - t) : glm::vec3(0.1f, 0.08f, 0.05f);
            p[0] = c.x;
            p[1] = c.y;
            p[2] = c.z;
            if ((i == sunColumn || i == sunColumn + 1) && (j == sunRow || j == sunRow + 1)) {
                p[0] = sun;
                p[1] = sun * 0.95f;
                p[2] = sun * 0.85f;
            }
        }
    env.source = "sun-and-sky";
    return env;
}

EnvironmentMap mapOf(const Environment& env) {
    EnvironmentMap m;
    m.offset = 0;
    m.width = env.width;
    m.height = env.height;
    m.rotation = env.rotation;
    return m;
}

TEST(EnvironmentMapping, BlenderAxesInGltf) {
    // Centre column faces +X, u = 0.75 faces +Z, u = 0.25 faces -Z, the top row is +Y.
    const glm::vec2 x = gpu::environmentUv(glm::vec3(1, 0, 0));
    EXPECT_NEAR(x.x, 0.5f, 1e-6f);
    EXPECT_NEAR(x.y, 0.5f, 1e-6f);
    EXPECT_NEAR(gpu::environmentUv(glm::vec3(0, 0, 1)).x, 0.75f, 1e-6f);
    EXPECT_NEAR(gpu::environmentUv(glm::vec3(0, 0, -1)).x, 0.25f, 1e-6f);
    EXPECT_NEAR(gpu::environmentUv(glm::vec3(0, 1, 0)).y, 0.0f, 1e-6f);
    EXPECT_NEAR(gpu::environmentUv(glm::vec3(0, -1, 0)).y, 1.0f, 1e-6f);
    for (const glm::vec3 d : {glm::vec3(0.3f, 0.5f, -0.8f), glm::vec3(-0.9f, -0.1f, 0.2f)}) {
        const glm::vec3 back = gpu::environmentDirection(gpu::environmentUv(glm::normalize(d)));
        EXPECT_NEAR(glm::length(back - glm::normalize(d)), 0.0f, 1e-5f);
    }
}

TEST(EnvironmentMapping, RotationTurnsTheMapAboutY) {
    // A sun in the centre column at the horizon faces +X; turned by 90 degrees it faces -Z.
    Environment env = sunAndSky(64, 32, 31, 15, 10000.0f);
    const std::vector<float> data = environmentGpuData(env);
    EnvironmentMap map = mapOf(env);
    const float* envData = data.data();
    EXPECT_GT(gpu::environmentMapRadiance(envData, map, glm::normalize(glm::vec3(1, 0.01f, 0.01f))).x, 500.0f);
    map.rotation = 0.5f * float(kPiD);
    EXPECT_LT(gpu::environmentMapRadiance(envData, map, glm::normalize(glm::vec3(1, 0.01f, 0.01f))).x, 10.0f);
    EXPECT_GT(gpu::environmentMapRadiance(envData, map, glm::normalize(glm::vec3(-0.01f, 0.01f, -1))).x, 500.0f);
    // Samples follow: nearly all of them towards -Z.
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    int towardsSun = 0;
    for (int k = 0; k < 1000; ++k) {
        glm::vec3 radiance;
        float pdf;
        const glm::vec3 w = gpu::environmentMapSample(envData, map, glm::vec2(uniform(rng), uniform(rng)), radiance, pdf);
        if (w.z < -0.95f) ++towardsSun;  // the sun's 2x2 pixels span 11 degrees
    }
    EXPECT_GT(towardsSun, 950);  // the sun has 98.7 % of the map's luminance x sin(theta)
}

TEST(EnvironmentSampling, MapSamplingMatchesItsPdf) {
    // A map with smooth variation and a bright region, sampled by the code the GPU runs.
    Environment env;
    env.present = true;
    env.width = 16;
    env.height = 8;
    for (uint32_t j = 0; j < env.height; ++j)
        for (uint32_t i = 0; i < env.width; ++i) {
            const float v = 0.2f + float((i * 7 + j * 3) % 5) + (i == 3 && j == 2 ? 20.0f : 0.0f);
            env.rgb.insert(env.rgb.end(), {v, 0.5f * v, 0.25f * v});
        }
    env.rotation = 0.3f;
    const std::vector<float> data = environmentGpuData(env);
    const float* envData = data.data();
    const EnvironmentMap map = mapOf(env);
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const auto r = test::chiSquareSphere(
        [&](int, glm::vec3& w) {
            glm::vec3 radiance;
            float pdf;
            w = gpu::environmentMapSample(envData, map, glm::vec2(uniform(rng), uniform(rng)), radiance, pdf);
            // The returned pdf and radiance agree with the lookups of the same direction.
            if (std::abs(pdf - gpu::environmentMapPdf(envData, map, w)) > 1e-3f * pdf) return false;
            return pdf > 0.0f;
        },
        [&](const glm::vec3& w) { return double(gpu::environmentMapPdf(envData, map, w)); }, 200000, 16, 32, 24);
    EXPECT_GT(r.pValue, 0.001) << r.details;
}

TEST(EnvironmentSampling, ChiSquareCanFail) {
    // The uniform-sphere pdf claimed for the map's samples must be rejected.
    Environment env = sunAndSky(32, 16, 10, 4, 50.0f);
    const std::vector<float> data = environmentGpuData(env);
    const float* envData = data.data();
    const EnvironmentMap map = mapOf(env);
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const auto r = test::chiSquareSphere(
        [&](int, glm::vec3& w) {
            glm::vec3 radiance;
            float pdf;
            w = gpu::environmentMapSample(envData, map, glm::vec2(uniform(rng), uniform(rng)), radiance, pdf);
            return pdf > 0.0f;
        },
        [&](const glm::vec3&) { return 1.0 / (4.0 * kPiD); }, 50000);
    EXPECT_LT(r.pValue, 1e-6) << r.details;
}

TEST(EnvironmentSettings, Constants) {
    glm::vec3 c;
    ASSERT_TRUE(parseEnvironmentConstant("2", c));
    EXPECT_EQ(c, glm::vec3(2.0f));
    ASSERT_TRUE(parseEnvironmentConstant("1,0.9,0.8", c));
    EXPECT_EQ(c, glm::vec3(1.0f, 0.9f, 0.8f));
    EXPECT_FALSE(parseEnvironmentConstant("sky.hdr", c));
    EXPECT_FALSE(parseEnvironmentConstant("1,2", c));
    EXPECT_FALSE(parseEnvironmentConstant("1,,2", c));
}

TEST(EnvironmentSettings, DefaultSkyOnlyWithoutLights) {
    Scene lit = test::furnaceScene(0.5f, 0.5f);
    std::string note;
    applyEnvironment(lit, {}, note);
    EXPECT_FALSE(lit.environment.present);
    EXPECT_TRUE(note.empty());

    Scene dark = test::furnaceScene(0.5f, 0.0f);
    applyEnvironment(dark, {}, note);
    EXPECT_TRUE(dark.environment.present);
    EXPECT_EQ(dark.environment.radiance, glm::vec3(1.0f));
    EXPECT_NE(note.find("no lights"), std::string::npos);

    EnvironmentSettings none;
    none.value = "0";
    EXPECT_THROW(applyEnvironment(dark, none, note), InputError);
    EnvironmentSettings negative;
    negative.strength = -1.0f;
    EXPECT_THROW(applyEnvironment(dark, negative, note), InputError);
    EnvironmentSettings negativeConstant;
    negativeConstant.value = "-1";
    EXPECT_THROW(applyEnvironment(dark, negativeConstant, note), InputError);
}

void writeHdr(const fs::path& path, int width, int height, const std::vector<float>& rgb) {
    ASSERT_TRUE(stbi_write_hdr(path.c_str(), width, height, 3, rgb.data()));
}

void expectRefused(const fs::path& path, const std::string& substring, const EnvironmentLimits& limits = {}) {
    try {
        loadEnvironmentMap(path, limits);
        ADD_FAILURE() << path << ": loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(substring), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

TEST(EnvironmentMaps, ReadsHdrAndExr) {
    const fs::path dir = tempDir();
    std::vector<float> rgb(8 * 4 * 3);
    for (size_t k = 0; k < rgb.size(); ++k) rgb[k] = 0.25f * float(k % 7);
    writeHdr(dir / "map.hdr", 8, 4, rgb);
    const Environment hdr = loadEnvironmentMap(dir / "map.hdr");
    EXPECT_EQ(hdr.width, 8u);
    EXPECT_EQ(hdr.height, 4u);
    for (size_t k = 0; k < rgb.size(); ++k) EXPECT_NEAR(hdr.rgb[k], rgb[k], 0.02f * rgb[k] + 1e-6f);

    ImageRgb image = makeImage(8, 4);
    image.pixels = rgb;
    writeExr(dir / "map.exr", image);
    const Environment exr = loadEnvironmentMap(dir / "map.exr");
    EXPECT_EQ(exr.rgb, rgb);
}

TEST(EnvironmentMaps, HostileMapsAreRefused) {
    const fs::path dir = tempDir();
    expectRefused(dir / "missing.hdr", "no such file");
    {
        std::ofstream(dir / "corrupt.hdr") << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 4 +X 8\n\x01\x02";
        expectRefused(dir / "corrupt.hdr", "cannot decode");
        std::ofstream(dir / "garbage.hdr") << "this is not an image";
        expectRefused(dir / "garbage.hdr", "not a Radiance");
        std::ofstream(dir / "garbage.exr") << "this is not an image";
        expectRefused(dir / "garbage.exr", "cannot read EXR");
        std::ofstream(dir / "empty.exr");
        expectRefused(dir / "empty.exr", "cannot read EXR");
        std::ofstream(dir / "map.png") << "x";
        expectRefused(dir / "map.png", "unknown map format");
        // A header that claims 16384 x 8192 pixels: refused before any pixel is decoded.
        std::ofstream(dir / "huge.hdr") << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8192 +X 16384\n";
        expectRefused(dir / "huge.hdr", "larger than");
    }
    writeHdr(dir / "one.hdr", 1, 1, {1.0f, 1.0f, 1.0f});
    expectRefused(dir / "one.hdr", "too small");
    ImageRgb nan = makeImage(4, 2);
    nan.pixels[5] = std::nanf("");
    writeExr(dir / "nan.exr", nan);
    expectRefused(dir / "nan.exr", "finite");
    ImageRgb negative = makeImage(4, 2);
    negative.pixels[0] = -1.0f;
    writeExr(dir / "negative.exr", negative);
    expectRefused(dir / "negative.exr", "finite");
    // Memory: a map within the pixel limit but not within the memory allowed.
    writeHdr(dir / "small.hdr", 8, 4, std::vector<float>(8 * 4 * 3, 1.0f));
    writeHdr(dir / "black.hdr", 8, 4, std::vector<float>(8 * 4 * 3, 0.0f));
    expectRefused(dir / "black.hdr", "black");
    EnvironmentLimits tight;
    tight.maxMemoryBytes = 1000;
    expectRefused(dir / "small.hdr", "memory", tight);
}

// A UV sphere of radius 1 at the origin with flat (face) normals: convex, so under a uniform
// environment each point sees all of it above its tangent plane.
Scene lambertSphere(float albedo) {
    Scene scene;
    Material m;
    m.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.ior = 1.0f;  // no specular reflection: a Lambert surface
    scene.materials.push_back(m);
    const int rings = 48, sectors = 96;
    auto point = [&](int r, int s) {
        const double theta = kPiD * r / rings, phi = 2.0 * kPiD * s / sectors;
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    auto add = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        Triangle t;
        glm::vec3 n = glm::cross(b - a, c - a);
        if (glm::length(n) < 1e-9f) return;
        n = glm::normalize(n);
        if (glm::dot(n, a + b + c) < 0.0f) {
            std::swap(b, c);
            n = -n;
        }
        t.p[0] = a;
        t.p[1] = b;
        t.p[2] = c;
        for (int v = 0; v < 3; ++v) {
            t.n[v] = n;
            t.uv[v] = glm::vec2(0.0f);
            scene.bounds.grow(t.p[v]);
        }
        scene.triangles.push_back(t);
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < sectors; ++s) {
            add(point(r, s), point(r + 1, s), point(r + 1, s + 1));
            add(point(r, s), point(r + 1, s + 1), point(r, s + 1));
        }
    scene.cameras.push_back(test::lookAt(glm::vec3(0.3f, 0.4f, 6.0f), glm::vec3(0.0f), 0.2f));
    return scene;
}

double mean(const ImageRgb& image) {
    double sum = 0.0;
    for (float v : image.pixels) sum += v;
    return sum / double(image.pixels.size());
}

class EnvironmentRender : public test::GpuTest {};

FrameSettings frame(uint32_t size, uint32_t spp, uint32_t seed) {
    FrameSettings s = test::smallFrame(size, spp, seed);
    return s;
}

TEST_F(EnvironmentRender, LambertSphereReadsItsAlbedoInEveryIntegrator) {
    Scene scene = lambertSphere(0.5f);
    std::string note;
    EnvironmentSettings settings;
    settings.value = "1";
    applyEnvironment(scene, settings, note);
    ASSERT_TRUE(scene.environment.present);
    Renderer renderer(test::gpu(), scene);
    const double path = mean(renderer.render<PathIntegrator>(frame(24, 64, 1)).image);
    EXPECT_NEAR(path, 0.5, 0.01);
    FrameSettings noNee = frame(24, 64, 2);
    noNee.nextEventEstimation = false;
    EXPECT_NEAR(mean(renderer.render<PathIntegrator>(noNee).image), 0.5, 0.01);
    GuideSettings guide;
    guide.photons = 20000;
    EXPECT_NEAR(mean(renderer.render<GuidedIntegrator>(frame(24, 64, 3), guide).image), 0.5, 0.01);
    PhotonIntegratorSettings photon;
    photon.globalPaths = 20000;
    photon.causticPaths = 0;
    EXPECT_NEAR(mean(renderer.render<PhotonIntegrator>(frame(24, 64, 4), photon).image), 0.5, 0.01);
}

// A horizontal square facing +Y, Lambert, seen from above.
Scene lambertPlane(float albedo) {
    Scene scene = lambertSphere(albedo);
    scene.triangles.clear();
    scene.bounds = Bounds{};
    const glm::vec3 c[4] = {{-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}};
    for (int k = 0; k < 2; ++k) {
        Triangle t;
        const int idx[3] = {0, 1 + k, 2 + k};
        for (int v = 0; v < 3; ++v) {
            t.p[v] = c[idx[v]];
            t.n[v] = glm::vec3(0, 1, 0);
            t.uv[v] = glm::vec2(0.0f);
            scene.bounds.grow(t.p[v]);
        }
        scene.triangles.push_back(t);
    }
    scene.cameras = {test::lookAt(glm::vec3(0.01f, 3.0f, 0.0f), glm::vec3(0.0f), 0.3f)};
    return scene;
}

// Irradiance on a surface facing +Y from a map's upper half: each pixel's radiance times the
// integral of cos(theta) over its solid angle, (sin^2 theta1 - sin^2 theta0) / 2 x dphi.
double planeIrradiance(const Environment& env) {
    double e = 0.0;
    for (uint32_t j = 0; j < env.height / 2; ++j) {
        const double t0 = kPiD * j / env.height, t1 = kPiD * (j + 1) / env.height;
        const double w = 0.5 * (std::sin(t1) * std::sin(t1) - std::sin(t0) * std::sin(t0)) * 2.0 * kPiD / env.width;
        for (uint32_t i = 0; i < env.width; ++i) {
            const float* p = &env.rgb[3 * (size_t(j) * env.width + i)];
            e += w * (p[0] + p[1] + p[2]) / 3.0;
        }
    }
    return e;
}

// Relative standard deviation of the pixels' means over the three channels.
double relativeNoise(const ImageRgb& image) {
    double sum = 0.0, sum2 = 0.0;
    const size_t n = image.pixels.size() / 3;
    for (size_t k = 0; k < n; ++k) {
        const double v = (image.pixels[3 * k] + image.pixels[3 * k + 1] + image.pixels[3 * k + 2]) / 3.0;
        sum += v;
        sum2 += v * v;
    }
    const double m = sum / n;
    return std::sqrt(std::max(0.0, sum2 / n - m * m)) / m;
}

TEST_F(EnvironmentRender, SunAndSkyLightsAPlaneToTheMapsIrradiance) {
    Scene scene = lambertPlane(0.5f);
    scene.environment = sunAndSky(256, 128, 40, 30, 20000.0f);
    const double expected = 0.5 * planeIrradiance(scene.environment) / kPiD;
    Renderer renderer(test::gpu(), scene);
    const ImageRgb image = renderer.render<PathIntegrator>(frame(32, 16, 5)).image;
    EXPECT_NEAR(mean(image), expected, 0.02 * expected);
    EXPECT_LT(relativeNoise(image), 0.1);
}

TEST_F(EnvironmentRender, PhotonIntegratorAgreesWithThePathTracerUnderASunAndSky) {
    // Glass, chrome and clay spheres on a ground square lit only by a sun-and-sky map whose sun
    // (11 degrees across, so that the path tracer's caustic converges in a test's time) stands
    // behind them at azimuth 230 degrees, elevation 40: the photon integrator's environment
    // photons, the sun's caustic through the glass in front of it included, against the path tracer.
    Scene scene = test::shippedScene("spheres-outdoor");
    scene.environment = sunAndSky(64, 32, 8, 8, 200.0f);
    Renderer renderer(test::gpu(), scene);
    const ImageRgb reference = renderer.render<PathIntegrator>(frame(32, 1024, 1)).image;
    PhotonIntegratorSettings photon;
    const ImageRgb image = renderer.render<PhotonIntegrator>(frame(32, 64, 2), photon).image;
    EXPECT_NEAR(mean(image), mean(reference), 0.03 * mean(reference));
    // Region by region (8 x 8 pixel blocks): the sun's caustic and the ground's indirect light come
    // from environment photons; without them the shadowed blocks would be far darker. (64 camera
    // samples: the sun seen through the glass sphere is a small bright spot.)
    double worst = 0.0;
    std::string blocks;
    for (uint32_t by = 0; by < 4; ++by)
        for (uint32_t bx = 0; bx < 4; ++bx) {
            double a = 0.0, b = 0.0;
            for (uint32_t y = 8 * by; y < 8 * by + 8; ++y)
                for (uint32_t x = 8 * bx; x < 8 * bx + 8; ++x)
                    for (int c = 0; c < 3; ++c) {
                        a += image.at(x, y)[c];
                        b += reference.at(x, y)[c];
                    }
            worst = std::max(worst, std::abs(a - b) / b);
            blocks += fmt::format("{:6.3f}/{:6.3f}{}", a / 192.0, b / 192.0, bx == 3 ? "\n" : " ");
        }
    EXPECT_LT(worst, 0.1) << "photon/path per block:\n" << blocks;
}

TEST_F(EnvironmentRender, AovsOfAPlaneAreItsAlbedoNormalAndDistance) {
    Scene scene = lambertPlane(0.5f);
    scene.environment.present = true;
    scene.environment.radiance = glm::vec3(1.0f);
    Renderer renderer(test::gpu(), scene);
    FrameSettings s = frame(16, 1, 1);
    const AovImages aov = renderAovs(renderer.gpuScene(), makeFrame(scene, s));
    // The camera at height 3 looks straight down (0.3 rad field of view: every pixel sees the plane).
    for (size_t i = 0; i < aov.depth.size(); ++i) {
        EXPECT_NEAR(aov.depth[i], 3.0f, 3e-3f) << i;
        EXPECT_NEAR(aov.albedo.pixels[3 * i], 0.5f, 1e-5f);
        EXPECT_NEAR(aov.normal.pixels[3 * i + 1], 1.0f, 1e-5f);
    }
    AovSettings all = parseAovList("depth,albedo,normal");
    const std::vector<ExrChannel> channels = aovChannels(aov, all);
    std::vector<std::string> names;
    for (const ExrChannel& c : channels) names.push_back(c.name);
    EXPECT_EQ(names, (std::vector<std::string>{"Albedo.R", "Albedo.G", "Albedo.B", "N.X", "N.Y", "N.Z", "Z"}));
    EXPECT_THROW(parseAovList("albedo,colour"), InputError);
    EXPECT_THROW(parseAovList(""), InputError);
}

}  // namespace
}  // namespace vkp
