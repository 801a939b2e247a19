// The integrators `--integrator` can name. Each kind brings a config that owns its settings,
// registers its command-line options (one CLI11 option group) and builds the integrator. The
// built-in kinds are listed in render/integrators/builtin.cpp, one line each; a program or a test
// may add its own with registerIntegrator().
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/frame.h"
#include "render/integrator.h"

namespace CLI { class App; }

namespace vkp {

class GpuScene;

class IntegratorConfig {
public:
    virtual ~IntegratorConfig() = default;
    // Adds the integrator's own options to the render command (write them into this config).
    virtual void addOptions(CLI::App& command) { (void)command; }
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

struct IntegratorKind {
    std::string name;     // the value of --integrator
    std::string summary;  // what it is, for --help
    std::function<std::unique_ptr<IntegratorConfig>()> makeConfig;
};

// The registered kinds: the built-in ones first (the first is the default), then added ones.
const std::vector<IntegratorKind>& integratorKinds();
// Adds (or, for a name already registered, replaces) a kind.
void registerIntegrator(IntegratorKind kind);
// The kind of that name, or null.
const IntegratorKind* findIntegrator(const std::string& name);

}  // namespace vkp
