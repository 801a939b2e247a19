#include "render/integrator_registry.h"

#include <algorithm>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {
namespace {

std::vector<IntegratorKind>& registry() {
    static std::vector<IntegratorKind> kinds;
    return kinds;
}

std::string integratorList(const std::vector<std::string>& names) {
    std::string text;
    for (size_t i = 0; i < names.size(); ++i)
        text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return text;
}

}  // namespace

CLI::App& IntegratorOptions::group(const std::string& title, std::vector<std::string> readers) {
    CLI::App* group = m_command.add_option_group(fmt::format("{} (--integrator {})", title, integratorList(readers)));
    m_groups.emplace_back(group, std::move(readers));
    return *group;
}

void IntegratorOptions::refuseUnread(const std::string& chosen) const {
    for (const auto& [group, readers] : m_groups) {
        if (std::find(readers.begin(), readers.end(), chosen) != readers.end()) continue;
        for (const CLI::Option* option : group->get_options())
            if (option->count() > 0)
                throw InputError(fmt::format("{} is an option of --integrator {}: --integrator {} does not read it",
                                             option->get_name(), integratorList(readers), chosen));
    }
}

std::unique_ptr<IntegratorConfig> configForKind(IntegratorConfig& family, const std::string& kind) {
    class KindConfig : public IntegratorConfig {
    public:
        KindConfig(IntegratorConfig& family, std::string kind) : m_family(family), m_kind(std::move(kind)) {}
        void check() const override {
            m_family.choose(m_kind);
            m_family.check();
        }
        std::string startMessage(const FrameSettings& frame) const override {
            m_family.choose(m_kind);
            return m_family.startMessage(frame);
        }
        std::unique_ptr<Integrator> create(const GpuScene& scene) const override {
            m_family.choose(m_kind);
            return m_family.create(scene);
        }

    private:
        IntegratorConfig& m_family;
        std::string m_kind;
    };
    return std::make_unique<KindConfig>(family, kind);
}

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
