// `vkphoton guide-grid`: the guided path tracer's direction grid at one pixel, as a PNG. The
// guide's options are the guided integrator's own (guiding/path_guide.h); the view, environment
// and device options are render's.
#include <cstdint>
#include <memory>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli_options.h"
#include "app/commands.h"
#include "app/subcommand.h"

namespace vkp {
namespace {

class GuideGridCommand : public Subcommand {
public:
    explicit GuideGridCommand(CLI::App& app) {
        GuideGridCommandOptions& guide = m_options;
        m_cmd = app.add_subcommand("guide-grid", "Write the guided path tracer's direction grid at one pixel as a PNG");
        m_cmd->add_option("scene", guide.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
        m_cmd->add_option("--pixel", m_pixel, "Pixel X Y (from the top left)")->expected(2)->required();
        m_cmd->add_option("-o,--output", guide.output, "Output .png [default: out/SCENE-guide-X-Y.png]");
        m_cmd->add_option("--width", guide.width, "Image width the pixel belongs to")->capture_default_str();
        m_cmd->add_option("--height", guide.height, "Image height the pixel belongs to")->capture_default_str();
        m_cmd->add_option("--camera", guide.cameraIndex, "Scene camera index")->check(CLI::NonNegativeNumber);
        addViewOptions(*m_cmd, guide.view);
        addEnvironmentOptions(*m_cmd, guide.environment);
        m_cmd->add_option("--seed", guide.seed, "Random seed")->capture_default_str();
        guide.guide.addOptions(*m_cmd, false);
        addDeviceOptions(*m_cmd, guide.device, guide.validate, guide.maxMemoryGiB, guide.textures);
        addSceneIndexOption(*m_cmd, guide.sceneIndex);
        m_cmd->add_flag("--quiet", guide.quiet, "No output but the file");
    }
    const CLI::App& app() const override { return *m_cmd; }
    int run() override {
        requireNonEmpty(*m_cmd, "--output", m_options.output);
        m_options.x = m_pixel.at(0);
        m_options.y = m_pixel.at(1);
        m_options.check();
        return runGuideGrid(m_options);
    }

private:
    CLI::App* m_cmd = nullptr;
    GuideGridCommandOptions m_options;
    std::vector<uint32_t> m_pixel;
};

}  // namespace

std::unique_ptr<Subcommand> addGuideGridCommand(CLI::App& app) { return std::make_unique<GuideGridCommand>(app); }

}  // namespace vkp
