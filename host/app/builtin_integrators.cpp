#include "app/builtin_integrators.h"

#include "guiding/guided_integrator.h"
#include "photon/photon_integrator.h"
#include "render/path_integrator.h"

namespace vkp {

void registerBuiltinIntegrators() {
    static const bool registered = [] {
        registerIntegrator(pathIntegratorKind());
        registerIntegrator(photonIntegratorKind());
        registerIntegrator(sppmIntegratorKind());
        registerIntegrator(guidedIntegratorKind());
        return true;
    }();
    (void)registered;
}

}  // namespace vkp
