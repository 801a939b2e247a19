// The integrators `--integrator` can name. Each kind brings a config that owns its settings,
// registers its command-line options and builds the integrator. Kinds of one family share one
// config (photon and sppm read the same photon-map settings); each option group says which kinds
// read it, so the command line refuses an option the chosen integrator would ignore. The built-in
// kinds are registered by the command line (app/builtin_integrators.h); a program or a test may
// add its own with registerIntegrator().
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "render/frame.h"
#include "render/integrator.h"

namespace CLI { class App; }

namespace vkp {

class GpuScene;

// The render command's integrator options, grouped by the kinds that read them.
class IntegratorOptions {
public:
    explicit IntegratorOptions(CLI::App& command) : m_command(command) {}
    // A group of options (titled `title` in --help) that only the kinds `readers` read.
    CLI::App& group(const std::string& title, std::vector<std::string> readers);
    // Throws InputError naming the first option given on the command line that the kind `chosen`
    // does not read, and the integrators that do.
    void refuseUnread(const std::string& chosen) const;

private:
    CLI::App& m_command;
    std::vector<std::pair<CLI::App*, std::vector<std::string>>> m_groups;
};

class IntegratorConfig {
public:
    virtual ~IntegratorConfig() = default;
    // Adds the family's options (write them into this config), each group naming its readers.
    virtual void addOptions(IntegratorOptions& options) { (void)options; }
    // The kind of this config's family the command line chose (before check and create).
    virtual void choose(const std::string& kind) { (void)kind; }
    // Throws InputError naming the flag of a setting out of range; called before the scene loads.
    virtual void check() const {}
    // A line printed before the render starts (e.g. how many photon paths it traces); empty: none.
    virtual std::string startMessage(const FrameSettings& frame) const {
        (void)frame;
        return {};
    }
    // Builds the integrator for a scene (settings already checked).
    virtual std::unique_ptr<Integrator> create(const GpuScene& scene) const = 0;
};

// One kind of a family's config, for a caller that builds several kinds from one parse (`vkphoton
// view` cycles through them): chooses `kind` on the family's config before it builds.
std::unique_ptr<IntegratorConfig> configForKind(IntegratorConfig& family, const std::string& kind);

struct IntegratorKind {
    std::string name;     // the value of --integrator
    std::string summary;  // what it is, for --help
    std::function<std::unique_ptr<IntegratorConfig>()> makeConfig;
    std::string family;   // kinds of one family share one config (made once); empty: the kind's name

    const std::string& familyName() const { return family.empty() ? name : family; }
};

// The default --integrator.
inline const std::string kDefaultIntegrator = "path";

// The registered kinds, in the order they were registered.
const std::vector<IntegratorKind>& integratorKinds();
// Adds (or, for a name already registered, replaces) a kind.
void registerIntegrator(IntegratorKind kind);
// The kind of that name, or null.
const IntegratorKind* findIntegrator(const std::string& name);

}  // namespace vkp
