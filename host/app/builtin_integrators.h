// The integrators vkphoton ships: registered once, in the order --help lists them.
#pragma once

namespace vkp {

// Registers path, photon, sppm and guided (render/integrator_registry.h); safe to call again.
void registerBuiltinIntegrators();

}  // namespace vkp
