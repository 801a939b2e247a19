// The commands that render nothing: `info` (what a glTF file holds), `devices`, `merge` (the
// parts of a render joined) and `compare` (two EXRs, bit for bit).
#include <memory>

#include <CLI/CLI.hpp>

#include "app/cli_options.h"
#include "app/commands.h"
#include "app/compare_command.h"
#include "app/info_command.h"
#include "app/merge_command.h"
#include "app/subcommand.h"

namespace vkp {
namespace {

class InfoCommand : public Subcommand {
public:
    explicit InfoCommand(CLI::App& app) {
        m_cmd = app.add_subcommand(
            "info", "Describe a glTF scene: geometry, materials, lights, cameras, animations, extensions, textures");
        m_cmd->add_option("scene", m_options.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
        m_cmd->add_flag("--json", m_options.json, "Print the report as JSON");
        addSceneIndexOption(*m_cmd, m_options.sceneIndex);
    }
    const CLI::App& app() const override { return *m_cmd; }
    int run() override { return runInfo(m_options); }

private:
    CLI::App* m_cmd = nullptr;
    InfoCommandOptions m_options;
};

class DevicesCommand : public Subcommand {
public:
    explicit DevicesCommand(CLI::App& app) { m_cmd = app.add_subcommand("devices", "List the Vulkan devices"); }
    const CLI::App& app() const override { return *m_cmd; }
    int run() override { return runDevices(); }

private:
    CLI::App* m_cmd = nullptr;
};

class MergeCommand : public Subcommand {
public:
    explicit MergeCommand(CLI::App& app) {
        m_cmd = app.add_subcommand(
            "merge", "Join the parts of one render (render --tile or --crop) into the full EXR and PNG, bit for bit");
        m_cmd->add_option("parts", m_options.parts, "The parts' EXR files")->required();
        m_cmd->add_option("-o,--output", m_options.output, "Output EXR path; a PNG is written beside it")->required();
        m_cmd->add_flag("--quiet", m_options.quiet, "No summary output");
    }
    const CLI::App& app() const override { return *m_cmd; }
    int run() override {
        requireNonEmpty(*m_cmd, "--output", m_options.output);
        return runMerge(m_options);
    }

private:
    CLI::App* m_cmd = nullptr;
    MergeCommandOptions m_options;
};

class CompareCommand : public Subcommand {
public:
    explicit CompareCommand(CLI::App& app) {
        m_cmd = app.add_subcommand(
            "compare", "Are two EXRs' pixels identical, bit for bit (every channel)? Exit 0 if so, 3 if not");
        m_cmd->add_option("a", m_options.a, "First EXR")->required();
        m_cmd->add_option("b", m_options.b, "Second EXR")->required();
        m_cmd->add_flag("--quiet", m_options.quiet, "No output, only the exit code");
    }
    const CLI::App& app() const override { return *m_cmd; }
    int run() override { return runCompare(m_options); }

private:
    CLI::App* m_cmd = nullptr;
    CompareCommandOptions m_options;
};

}  // namespace

std::unique_ptr<Subcommand> addInfoCommand(CLI::App& app) { return std::make_unique<InfoCommand>(app); }
std::unique_ptr<Subcommand> addDevicesCommand(CLI::App& app) { return std::make_unique<DevicesCommand>(app); }
std::unique_ptr<Subcommand> addMergeCommand(CLI::App& app) { return std::make_unique<MergeCommand>(app); }
std::unique_ptr<Subcommand> addCompareCommand(CLI::App& app) { return std::make_unique<CompareCommand>(app); }

}  // namespace vkp
