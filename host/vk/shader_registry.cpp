#include "vk/shader_registry.h"

#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp::embedded {
extern const vk::ShaderEntry* const vkphoton_shaders_table[];
}

namespace vkp::vk {
namespace {

std::mutex g_mutex;

std::vector<const ShaderEntry* const*>& tables() {
    static std::vector<const ShaderEntry* const*> list{embedded::vkphoton_shaders_table};
    return list;
}

}  // namespace

void registerShaderTable(const ShaderEntry* const* table) {
    std::lock_guard lock(g_mutex);
    tables().push_back(table);
}

std::span<const uint32_t> shaderCode(std::string_view name) {
    std::lock_guard lock(g_mutex);
    for (const ShaderEntry* const* table : tables())
        for (const ShaderEntry* const* e = table; *e != nullptr; ++e)
            if ((*e)->first == name) return (*e)->second;
    throw RuntimeError(fmt::format("shader '{}' was not built into this binary", name));
}

}  // namespace vkp::vk
