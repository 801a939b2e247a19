#include "render/integrator_registry.h"

#include "render/integrators/builtin.h"

namespace vkp {
namespace {

std::vector<IntegratorKind>& registry() {
    static std::vector<IntegratorKind> kinds = builtinIntegrators();
    return kinds;
}

}  // namespace

const std::vector<IntegratorKind>& integratorKinds() { return registry(); }

void registerIntegrator(IntegratorKind kind) {
    for (IntegratorKind& existing : registry())
        if (existing.name == kind.name) {
            existing = std::move(kind);
            return;
        }
    registry().push_back(std::move(kind));
}

const IntegratorKind* findIntegrator(const std::string& name) {
    for (const IntegratorKind& kind : registry())
        if (kind.name == name) return &kind;
    return nullptr;
}

}  // namespace vkp
