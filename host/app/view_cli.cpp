// `vkphoton view` (host/view/, docs/viewer.md): the render options that apply to a window, every
// integrator's options (I cycles through the kinds, each with what was parsed), the event script
// and the selective update's budget.
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/builtin_integrators.h"
#include "app/cli_options.h"
#include "app/commands.h"
#include "app/subcommand.h"
#include "image/exposure.h"
#include "util/cli_choice.h"
#include "util/errors.h"
#include "view/view_command.h"

namespace vkp {
namespace {

class ViewCommand : public Subcommand {
public:
    explicit ViewCommand(CLI::App& app);
    const CLI::App& app() const override { return *m_cmd; }
    int run() override;

private:
    CLI::App* m_cmd = nullptr;
    ViewCommandOptions m_options;
    bool m_bsdfOnly = false;
    std::string m_integratorName = kDefaultIntegrator;
    std::string m_exposureText = "0";  // the window shows a fixed exposure
    std::unique_ptr<IntegratorOptions> m_integratorOptions;
    std::map<std::string, std::unique_ptr<IntegratorConfig>> m_families;
    std::vector<std::unique_ptr<IntegratorConfig>> m_kindConfigs;
};

ViewCommand::ViewCommand(CLI::App& app) {
    registerBuiltinIntegrators();
    RenderCommandOptions& render = m_options.render;
    m_cmd = app.add_subcommand(
        "view", "Open an interactive window that refines the image progressively (orbit, pan, dolly, select and move "
                "nodes; photon maps updated selectively); needs a display (DISPLAY)");
    m_cmd->add_option("scene", render.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
    addFrameOptions(*m_cmd, render.frame, m_bsdfOnly);
    addViewOptions(*m_cmd, render.frame.view);
    addEnvironmentOptions(*m_cmd, render.environment);
    addDeviceOptions(*m_cmd, render.device, render.validate, render.maxMemoryGiB, render.textures);
    addSceneIndexOption(*m_cmd, render.sceneIndex);
    std::string help = "The integrator to start with (I switches to the next):";
    std::string choices;
    for (const IntegratorKind& kind : integratorKinds()) {
        help += fmt::format(" {} ({});", kind.name, kind.summary);
        choices += (choices.empty() ? "" : "|") + kind.name;
    }
    m_cmd->add_option("--integrator", m_integratorName, help)
        ->check(CLI::IsMember(std::vector<std::string>(
            [] {
                std::vector<std::string> names;
                for (const IntegratorKind& kind : integratorKinds()) names.push_back(kind.name);
                return names;
            }())))
        ->option_text(fmt::format("{} [{}]", choices, m_integratorName));
    // Every family's options: the window switches between all kinds, so each option is read.
    m_integratorOptions = std::make_unique<IntegratorOptions>(*m_cmd);
    for (const IntegratorKind& kind : integratorKinds()) {
        std::unique_ptr<IntegratorConfig>& family = m_families[kind.familyName()];
        if (family) continue;
        family = kind.makeConfig();
        family->addOptions(*m_integratorOptions);
    }
    m_cmd->add_option("--events", m_options.events, "Replay an event script, one command a line (docs/viewer.md)");
    m_cmd->add_flag("--headless", m_options.headless,
                    "No window and no display needed: the --events script drives the view, each image is shown to an "
                    "offscreen image of the window's size (for benchmarks and machines without a display)");
    m_cmd->add_option("--stats-json", render.statsJson,
                      "Write the time to the first image and, per change, to its first image and its photon paths");
    m_cmd->add_option("--photon-budget", render.photonBudget,
                      "Photon paths traced per map and move, pilots included [default: paths / 8 + one pilot per group]")
        ->check(CLI::PositiveNumber);
    m_cmd->add_option("--photon-groups", render.photonGroups, "Selective update's photon groups")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    m_cmd->add_option("--animation", render.animation, "Space plays only glTF animation N [default: all]")
        ->check(CLI::NonNegativeNumber);
    const auto views = viewTransformChoices();
    m_cmd->add_option("--tonemap", render.display.view, "The window's and screenshots' view transform")
        ->transform(oneOf(views))
        ->option_text(choiceText(views, render.display.view));
    m_cmd->add_option("--exposure", m_exposureText,
                      "Exposure in stops of the window and the screenshots' PNG (auto: each screenshot's PNG metered "
                      "as render meters)")
        ->type_name("auto|EV")
        ->capture_default_str();
    m_cmd->add_flag("--quiet", render.quiet, "No messages but errors");
    m_cmd->add_flag("--sample-parts,!--no-sample-parts", m_options.sampleParts,
                    "Record a sample that takes longer than 0.1 s in parts of the pixels, so the window stays "
                    "responsive (the default; the same images), or whole (--no-sample-parts)");
    m_cmd->add_flag("--preview,!--no-preview", m_options.preview,
                    "Integrators with a preparation (photon maps, guides): one path-traced sample of a change first "
                    "(the default), or none (--no-preview)");
}

int ViewCommand::run() {
    RenderCommandOptions& render = m_options.render;
    requireNonEmpty(*m_cmd, "--stats-json", render.statsJson);
    requireNonEmpty(*m_cmd, "--events", m_options.events);
    if (m_options.headless && m_options.events.empty())
        throw InputError("--headless needs --events FILE: without a window only a script can drive the view (and end it "
                         "with quit)");
    render.frame.nextEventEstimation = !m_bsdfOnly;
    render.frame.check();
    render.display = parseExposure(m_exposureText, render.display);
    render.environment.check();
    render.lightSamplerAuto = true;
    // I cycles through the kinds from the chosen one; each builds from its family's parsed options.
    std::vector<std::pair<std::string, const IntegratorConfig*>> kinds;
    size_t first = 0;
    for (const IntegratorKind& kind : integratorKinds()) {
        if (kind.name == m_integratorName) first = kinds.size();
        m_kindConfigs.push_back(configForKind(*m_families.at(kind.familyName()), kind.name));
        kinds.emplace_back(kind.name, m_kindConfigs.back().get());
    }
    kinds[first].second->check();
    return runView(m_options, kinds, first);
}

}  // namespace

std::unique_ptr<Subcommand> addViewCommand(CLI::App& app) { return std::make_unique<ViewCommand>(app); }

}  // namespace vkp
