// `vkphoton photons`: trace photon maps and write them as a PLY point cloud. The photon-path and
// deposition options are the photon integrators' own (photon/photon_path_options.h,
// photon/deposit_options.h); the view, environment and device options are render's.
#include <memory>

#include <CLI/CLI.hpp>

#include "app/cli_options.h"
#include "app/commands.h"
#include "app/subcommand.h"
#include "photon/photon_path_options.h"

namespace vkp {
namespace {

class PhotonsCommand : public Subcommand {
public:
    explicit PhotonsCommand(CLI::App& app) {
        PhotonsCommandOptions& photons = m_options;
        m_cmd = app.add_subcommand("photons", "Trace photons and write the photon maps as a PLY point cloud");
        m_cmd->add_option("scene", photons.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
        m_cmd->add_option("-o,--output", photons.output, "Output .ply [default: out/SCENE-photons.ply]");
        addPhotonPathOptions(*m_cmd, photons.photons, photons.maxDeposits, "Photon paths to emit");
        m_cmd->add_option("--seed", photons.seed, "Random seed")->capture_default_str();
        photons.deposit.addOptions(*m_cmd);
        m_cmd->add_option("--width", photons.width, "Width of the image the importons' camera looks at")
            ->capture_default_str();
        m_cmd->add_option("--height", photons.height, "Height of that image")->capture_default_str();
        m_cmd->add_option("--camera", photons.cameraIndex, "Scene camera index for the importons")
            ->check(CLI::NonNegativeNumber);
        addViewOptions(*m_cmd, photons.view);
        addEnvironmentOptions(*m_cmd, photons.environment);
        addDeviceOptions(*m_cmd, photons.device, photons.validate, photons.maxMemoryGiB, photons.textures);
        addSceneIndexOption(*m_cmd, photons.sceneIndex);
        m_cmd->add_flag("--quiet", photons.quiet, "No summary output");
    }
    const CLI::App& app() const override { return *m_cmd; }
    int run() override {
        requireNonEmpty(*m_cmd, "--output", m_options.output);
        m_options.check();
        return runPhotons(m_options);
    }

private:
    CLI::App* m_cmd = nullptr;
    PhotonsCommandOptions m_options;
};

}  // namespace

std::unique_ptr<Subcommand> addPhotonsCommand(CLI::App& app) { return std::make_unique<PhotonsCommand>(app); }

}  // namespace vkp
