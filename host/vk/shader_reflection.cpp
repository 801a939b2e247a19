#include "vk/shader_reflection.h"

#include <algorithm>
#include <memory>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spirv_cross_c.h>

#include "shared/kernels/scene.glsl"
#include "shared/kernels/terminations.glsl"
#include "util/errors.h"

namespace vkp::vk {
namespace {

using ContextPtr = std::unique_ptr<std::remove_pointer_t<spvc_context>, decltype(&spvc_context_destroy)>;

// The descriptor kinds a kernel's set layout cannot hold (it binds storage buffers only).
struct OtherResource {
    spvc_resource_type type;
    const char* what;
};
constexpr OtherResource kOtherResources[] = {
    {SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, "a uniform buffer"},
    {SPVC_RESOURCE_TYPE_STORAGE_IMAGE, "a storage image"},
    {SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, "a sampled image"},
    {SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, "an image"},
    {SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, "a sampler"},
    {SPVC_RESOURCE_TYPE_ATOMIC_COUNTER, "an atomic counter"},
    {SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE, "an acceleration structure"},
};

// "0..7, 9" for {0, 1, ..., 7, 9}; "none" for {}.
std::string describeBindings(const std::vector<uint32_t>& sorted) {
    if (sorted.empty()) return "none";
    std::string out;
    for (size_t i = 0; i < sorted.size();) {
        size_t j = i;
        while (j + 1 < sorted.size() && sorted[j + 1] == sorted[j] + 1) ++j;
        if (!out.empty()) out += ", ";
        out += j == i ? fmt::format("{}", sorted[i]) : fmt::format("{}..{}", sorted[i], sorted[j]);
        i = j + 1;
    }
    return out;
}

}  // namespace

ShaderInterface reflectComputeShader(std::string_view name, std::span<const uint32_t> spirv) {
    spvc_context raw = nullptr;
    if (spvc_context_create(&raw) != SPVC_SUCCESS) throw RuntimeError("SPIRV-Cross: cannot create a context");
    ContextPtr context(raw, &spvc_context_destroy);
    auto fail = [&](const char* what) {
        return RuntimeError(fmt::format("{}: reflecting its SPIR-V: {} ({})", name, what,
                                        spvc_context_get_last_error_string(context.get())));
    };
    spvc_parsed_ir ir = nullptr;
    if (spvc_context_parse_spirv(context.get(), spirv.data(), spirv.size(), &ir) != SPVC_SUCCESS)
        throw fail("parsing");
    spvc_compiler compiler = nullptr;
    if (spvc_context_create_compiler(context.get(), SPVC_BACKEND_NONE, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP,
                                     &compiler) != SPVC_SUCCESS)
        throw fail("creating a reflection compiler");
    if (spvc_compiler_get_execution_model(compiler) != SpvExecutionModelGLCompute)
        throw RuntimeError(fmt::format("{}: not a compute shader", name));
    spvc_resources resources = nullptr;
    if (spvc_compiler_create_shader_resources(compiler, &resources) != SPVC_SUCCESS) throw fail("listing resources");

    ShaderInterface out;
    // LocalSize, or LocalSizeId (glslang's choice for SPIR-V 1.6) with its constants evaluated.
    for (unsigned i = 0; i < 3; ++i)
        out.localSize[i] = spvc_compiler_get_execution_mode_argument_by_index(compiler, SpvExecutionModeLocalSize, i);

    const spvc_reflected_resource* list = nullptr;
    size_t count = 0;
    spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_STORAGE_BUFFER, &list, &count);
    for (size_t i = 0; i < count; ++i) {
        const unsigned set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
        const unsigned binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
        if (set == 0)
            out.storageBufferBindings.push_back(binding);
        else if (set == gpu::kTerminationSet && binding == gpu::kTerminationBinding)
            out.terminationCounters = true;
        else
            out.unbindable.push_back(fmt::format("a storage buffer '{}' in set {} (binding {})", list[i].name, set, binding));
    }
    std::sort(out.storageBufferBindings.begin(), out.storageBufferBindings.end());
    out.storageBufferBindings.erase(std::unique(out.storageBufferBindings.begin(), out.storageBufferBindings.end()),
                                    out.storageBufferBindings.end());
    for (const OtherResource& other : kOtherResources) {
        spvc_resources_get_resource_list_for_type(resources, other.type, &list, &count);
        for (size_t i = 0; i < count; ++i) {
            const unsigned set = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationDescriptorSet);
            const unsigned binding = spvc_compiler_get_decoration(compiler, list[i].id, SpvDecorationBinding);
            if (other.type == SPVC_RESOURCE_TYPE_SAMPLED_IMAGE && set == gpu::kSceneTextureSet &&
                (binding == gpu::kSceneTextureUnormBinding || binding == gpu::kSceneTextureSrgbBinding))
                out.sceneTextures = true;
            else if ((other.type == SPVC_RESOURCE_TYPE_SAMPLED_IMAGE ||  // SPIRV-Cross lists a samplerBuffer
                      other.type == SPVC_RESOURCE_TYPE_SEPARATE_IMAGE) &&    // as a separate image
                     set == gpu::kSceneGeometrySet &&
                     (binding == gpu::kSceneNodeTexelsBinding || binding == gpu::kSceneTriangleTexelsBinding))
                out.sceneGeometry = true;
            else
                out.unbindable.push_back(fmt::format("{} '{}' (binding {})", other.what, list[i].name, binding));
        }
    }

    spvc_resources_get_resource_list_for_type(resources, SPVC_RESOURCE_TYPE_PUSH_CONSTANT, &list, &count);
    for (size_t i = 0; i < count; ++i) {  // at most one block per entry point
        size_t bytes = 0;
        if (spvc_compiler_get_declared_struct_size(compiler, spvc_compiler_get_type_handle(compiler, list[i].base_type_id),
                                                   &bytes) != SPVC_SUCCESS)
            throw fail("sizing the push-constant block");
        out.pushConstantBytes = std::max(out.pushConstantBytes, static_cast<uint32_t>(bytes));
    }
    return out;
}

std::vector<std::string> interfaceMismatches(const KernelInterface& host, const ShaderInterface& shader) {
    std::vector<std::string> out;
    std::vector<uint32_t> bound(host.bindingCount);
    for (uint32_t i = 0; i < host.bindingCount; ++i) bound[i] = i;
    if (shader.storageBufferBindings != bound)
        out.push_back(fmt::format("the shader declares storage buffers at bindings {}, the host binds {}",
                                  describeBindings(shader.storageBufferBindings), describeBindings(bound)));
    for (const std::string& resource : shader.unbindable)
        out.push_back(fmt::format("the shader declares {}, which a kernel cannot bind (storage buffers in set 0 only)",
                                  resource));
    if (shader.pushConstantBytes != host.pushBytes)
        out.push_back(fmt::format("the shader declares push constants of {} bytes, the host pushes {}",
                                  shader.pushConstantBytes, host.pushBytes));
    const auto& s = shader.localSize;
    if (s[0] != host.groupSize || s[1] != 1 || s[2] != 1)
        out.push_back(fmt::format("the shader's workgroup is {}x{}x{}, the host dispatches 1-D groups of {}", s[0], s[1],
                                  s[2], host.groupSize));
    return out;
}

ShaderInterface checkKernelInterface(const KernelInterface& host, std::span<const uint32_t> spirv) {
    ShaderInterface shader = reflectComputeShader(host.shader, spirv);
    const std::vector<std::string> mismatches = interfaceMismatches(host, shader);
    if (!mismatches.empty())
        throw RuntimeError(fmt::format("{}: {}", host.shader, fmt::join(mismatches, "; ")));
    return shader;
}

}  // namespace vkp::vk
