#include "render/integrators/builtin.h"

#include "render/integrators/guided_integrator.h"
#include "render/integrators/path_integrator.h"
#include "render/integrators/photon_integrator.h"

namespace vkp {

// One line per integrator.
std::vector<IntegratorKind> builtinIntegrators() {
    return {pathIntegratorKind(), photonIntegratorKind(), guidedIntegratorKind()};
}

}  // namespace vkp
