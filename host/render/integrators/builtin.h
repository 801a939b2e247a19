// The integrators vkphoton ships, in the order --help lists them (the first is the default).
#pragma once

#include <vector>

#include "render/integrator_registry.h"

namespace vkp {

std::vector<IntegratorKind> builtinIntegrators();

}  // namespace vkp
