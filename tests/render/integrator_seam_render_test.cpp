// The integrator seam (docs/architecture.md, "Adding an integrator"): a toy integrator that
// renders a constant, written and registered here without touching host/render, renders through
// the driver and through the command line, with its own option and statistics.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/cli.h"
#include "support/gpu_test_support.h"
#include "image/exr.h"
#include "render/integrator_registry.h"
#include "render/renderer.h"
#include "support/test_scenes.h"
#include "util/errors.h"
#include "shaders/test_kernels.glsl"
#include "vk/kernel.h"

namespace vkp {
namespace {

// Radiance `value` in every pixel, one dispatch per batch.
class ConstantIntegrator : public Integrator {
public:
    ConstantIntegrator(const GpuScene& scene, float value) : m_scene(scene), m_value(value) {}

    std::string name() const override { return "constant"; }
    void prepare(const Frame& frame, const Film& film) override {
        m_kernel = std::make_unique<vk::Kernel<gpu::ConstantFilmKernel>>(m_scene.context());
        m_kernel->bind(gpu::kConstantFilmBinding, film.sums());
        m_pixels = frame.pixels();
    }
    uint32_t maxSamplesPerBatch() const override { return 1024; }
    void recordSamples(VkCommandBuffer cmd, uint32_t, uint32_t count) override {
        gpu::ConstantFilmParams push{};
        push.radiance = glm::vec4(m_value);
        push.pixels = uint32_t(m_pixels);
        push.sampleCount = count;
        m_kernel->record(cmd, m_pixels, push);
        vk::computeBarrier(cmd);
    }
    void report(Stats& stats) const override { stats.set("constant.value", m_value); }

private:
    const GpuScene& m_scene;
    float m_value;
    uint64_t m_pixels = 0;
    std::unique_ptr<vk::Kernel<gpu::ConstantFilmKernel>> m_kernel;
};

// Its settings and command-line option, as the registry asks.
class ConstantConfig : public IntegratorConfig {
public:
    void addOptions(IntegratorOptions& options) override {
        options.group("constant integrator", {"constant"})
            .add_option("--constant-value", m_value, "The radiance of every pixel")
            ->capture_default_str();
    }
    void check() const override {
        if (!(m_value >= 0.0f)) throw InputError("--constant-value must be a non-negative number");
    }
    std::unique_ptr<Integrator> create(const GpuScene& scene) const override {
        return std::make_unique<ConstantIntegrator>(scene, m_value);
    }

private:
    float m_value = 1.0f;
};

class IntegratorSeam : public test::GpuTest {};

TEST_F(IntegratorSeam, AToyIntegratorRendersThroughTheDriver) {
    const Scene scene = test::shippedScene("cornell-box");
    Renderer renderer(test::gpu(), scene);
    FrameSettings frame;
    frame.width = 13;  // not a multiple of the workgroup size
    frame.height = 7;
    frame.samplesPerPixel = 5;
    const RenderResult r = renderer.render<ConstantIntegrator>(frame, 0.375f);
    ASSERT_EQ(r.image.pixels.size(), 13u * 7u * 3u);
    for (float v : r.image.pixels) ASSERT_EQ(v, 0.375f);
    EXPECT_EQ(r.stats.get<std::string>("integrator"), "constant");
    EXPECT_EQ(r.stats.get<uint32_t>("counters.samplesPerPixel"), 5u);
    EXPECT_EQ(r.stats.get<double>("constant.value"), 0.375);
    EXPECT_FALSE(r.stats.get<bool>("partial"));
}

TEST_F(IntegratorSeam, ARegisteredIntegratorRendersFromTheCommandLine) {
    test::gpu();  // registers the test shaders (constant_film.comp) for the command line's own context
    registerIntegrator({"constant", "a constant radiance (a test)", [] { return std::make_unique<ConstantConfig>(); }});
    const auto dir = std::filesystem::temp_directory_path() / ("vkphoton-seam-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::string exr = (dir / "constant.exr").string();
    const std::string json = (dir / "constant.json").string();
    const std::string scene = std::string(VKPHOTON_SCENES) + "/cornell-box.gltf";
    const char* argv[] = {"vkphoton", "render", scene.c_str(), "--integrator", "constant", "--constant-value", "0.25",
                          "--width", "9", "--height", "4", "--spp", "3", "-o", exr.c_str(), "--stats-json",
                          json.c_str(), "--quiet", "--validate"};
    ASSERT_EQ(runCommandLine(int(std::size(argv)), argv), 0);
    const ImageRgb image = readExr(exr);
    ASSERT_EQ(image.pixels.size(), 9u * 4u * 3u);
    for (float v : image.pixels) EXPECT_EQ(v, 0.25f);
    std::ifstream in(json);
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_EQ(stats["integrator"], "constant");
    EXPECT_EQ(stats["constant"]["value"], 0.25);
    EXPECT_EQ(stats["counters"]["samplesPerPixel"], 3);

    // Its option is checked like any other: a bad value is exit code 2.
    const char* bad[] = {"vkphoton", "render", scene.c_str(), "--integrator", "constant", "--constant-value", "-1",
                         "-o", exr.c_str(), "--quiet"};
    EXPECT_EQ(runCommandLine(int(std::size(bad)), bad), 2);
    // It belongs to its integrator: another one refuses it (exit code 2).
    const char* other[] = {"vkphoton", "render", scene.c_str(), "--integrator", "path", "--constant-value", "0.5",
                           "-o", exr.c_str(), "--quiet"};
    EXPECT_EQ(runCommandLine(int(std::size(other)), other), 2);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vkp
