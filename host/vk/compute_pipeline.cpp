#include "vk/compute_pipeline.h"

#include <fmt/format.h>

#include <algorithm>
#include <initializer_list>
#include <vector>

#include "shared/kernels/scene.glsl"
#include "shared/kernels/segmented.glsl"
#include "shared/kernels/terminations.glsl"
#include "vk/check.h"
#include "vk/context.h"
#include "vk/shader_reflection.h"
#include "vk/shader_registry.h"

namespace vkp::vk {

namespace {
VkDescriptorSetLayout createSetLayout(VkDevice device, const std::vector<VkDescriptorSetLayoutBinding>& bindings) {
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = static_cast<uint32_t>(bindings.size());
    info.pBindings = bindings.data();
    VkDescriptorSetLayout layout = VK_NULL_HANDLE;
    check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout), "creating a set layout");
    return layout;
}

// A set of two views of one descriptor type at bindings 0 and 1 (the scene's texture array, the
// BVH's texel buffers).
VkDescriptorSetLayout createTwoViewLayout(VkDevice device, VkDescriptorType type) {
    std::vector<VkDescriptorSetLayoutBinding> views(2);
    for (uint32_t i = 0; i < 2; ++i) views[i] = {i, type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    return createSetLayout(device, views);
}
}  // namespace

namespace {
// Whether SPIR-V decorates a specialization constant with one of `ids`.
bool declaresSpecId(std::span<const uint32_t> spirv, std::initializer_list<uint32_t> ids) {
    constexpr uint32_t kOpDecorate = 71;
    constexpr uint32_t kDecorationSpecId = 1;
    for (size_t i = 5; i < spirv.size();) {  // after the 5-word header: instructions (word count << 16 | opcode)
        const uint32_t words = spirv[i] >> 16u;
        if ((spirv[i] & 0xffffu) == kOpDecorate && words >= 4 && i + 3 < spirv.size() &&
            spirv[i + 2] == kDecorationSpecId && std::find(ids.begin(), ids.end(), spirv[i + 3]) != ids.end())
            return true;
        i += std::max(words, 1u);
    }
    return false;
}
}  // namespace

bool usesSceneSpecialization(std::span<const uint32_t> spirv) {
    return declaresSpecId(spirv, {gpu::kSceneHasInstancesId, gpu::kSceneHasAlphaTestId, gpu::kSceneHasTexturesId,
                                  gpu::kSceneLightSamplerId, gpu::kSceneBvhTexelsId});
}

bool usesSingleSegmentSpecialization(std::span<const uint32_t> spirv) {
    return declaresSpecId(spirv, {gpu::kSingleSegmentId});
}

ComputePipeline::ComputePipeline(const Context& context, const KernelInterface& interface, SceneSpecialization scene,
                                 bool singleSegment)
    : m_device(context.device()), m_name(interface.shader), m_scene(scene), m_singleSegment(singleSegment) {
    const std::string& name = interface.shader;
    const auto code = shaderCode(name);
    const ShaderInterface declared = checkKernelInterface(interface, code);
    VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    moduleInfo.codeSize = code.size_bytes();
    moduleInfo.pCode = code.data();
    check(vkCreateShaderModule(m_device, &moduleInfo, nullptr, &m_module),
          fmt::format("creating the shader module {}", name));

    std::vector<VkDescriptorSetLayoutBinding> buffers(interface.bindingCount);
    for (uint32_t i = 0; i < interface.bindingCount; ++i)
        buffers[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    m_setLayout = createSetLayout(m_device, buffers);
    std::vector<VkDescriptorSetLayout> setLayouts{m_setLayout};
    if (declared.terminationCounters) {  // set gpu::kTerminationSet == 1: the context's termination counters
        static_assert(gpu::kTerminationSet == 1 && gpu::kTerminationBinding == 0);
        m_terminationLayout =
            createSetLayout(m_device, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr}});
        setLayouts.push_back(m_terminationLayout);
    }
    // Sets a shader leaves out below one it declares get an empty layout.
    const auto padTo = [&](uint32_t set) {
        while (setLayouts.size() < set) {
            if (!m_emptyLayout) m_emptyLayout = createSetLayout(m_device, {});
            setLayouts.push_back(m_emptyLayout);
        }
    };
    if (declared.sceneTextures) {  // set gpu::kSceneTextureSet == 2: the scene's texture array (two views)
        static_assert(gpu::kSceneTextureSet == 2 && gpu::kSceneTextureUnormBinding == 0 &&
                      gpu::kSceneTextureSrgbBinding == 1);
        padTo(gpu::kSceneTextureSet);
        m_textureLayout = createTwoViewLayout(m_device, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
        setLayouts.push_back(m_textureLayout);
    }
    if (declared.sceneGeometry) {  // set gpu::kSceneGeometrySet == 3: the BVH's texel-buffer views
        static_assert(gpu::kSceneGeometrySet == 3 && gpu::kSceneNodeTexelsBinding == 0 &&
                      gpu::kSceneTriangleTexelsBinding == 1);
        padTo(gpu::kSceneGeometrySet);
        m_geometryLayout = createTwoViewLayout(m_device, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
        setLayouts.push_back(m_geometryLayout);
    }

    VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, interface.pushBytes};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.setLayoutCount = static_cast<uint32_t>(setLayouts.size());
    layoutInfo.pSetLayouts = setLayouts.data();
    layoutInfo.pushConstantRangeCount = interface.pushBytes ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    check(vkCreatePipelineLayout(m_device, &layoutInfo, nullptr, &m_pipelineLayout), "creating a pipeline layout");
}

VkPipeline ComputePipeline::pipeline() const {
    std::call_once(m_compiled, [&] {
        // Entries for constants a shader does not declare are ignored (shaders without a traversal).
        const uint32_t values[6] = {m_scene.instances ? VK_TRUE : VK_FALSE, m_scene.alphaTest ? VK_TRUE : VK_FALSE,
                                    m_scene.textures ? VK_TRUE : VK_FALSE, m_scene.lightSampler,
                                    m_scene.bvhTexels ? VK_TRUE : VK_FALSE, m_singleSegment ? VK_TRUE : VK_FALSE};
        const VkSpecializationMapEntry entries[6] = {{gpu::kSceneHasInstancesId, 0, sizeof(VkBool32)},
                                                     {gpu::kSceneHasAlphaTestId, 4, sizeof(VkBool32)},
                                                     {gpu::kSceneHasTexturesId, 8, sizeof(VkBool32)},
                                                     {gpu::kSceneLightSamplerId, 12, sizeof(uint32_t)},
                                                     {gpu::kSceneBvhTexelsId, 16, sizeof(VkBool32)},
                                                     {gpu::kSingleSegmentId, 20, sizeof(VkBool32)}};
        const VkSpecializationInfo specialization{6, entries, sizeof(values), values};
        VkComputePipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        pipelineInfo.stage.module = m_module;
        pipelineInfo.stage.pName = "main";
        pipelineInfo.stage.pSpecializationInfo = &specialization;
        pipelineInfo.layout = m_pipelineLayout;
        pipelineInfo.flags = VK_PIPELINE_CREATE_DISPATCH_BASE_BIT;  // windows of items (ItemRange)
        check(vkCreateComputePipelines(m_device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &m_pipeline),
              fmt::format("creating the compute pipeline {}", m_name));
    });
    return m_pipeline;
}

ComputePipeline::~ComputePipeline() {
    if (m_pipeline) vkDestroyPipeline(m_device, m_pipeline, nullptr);
    vkDestroyPipelineLayout(m_device, m_pipelineLayout, nullptr);
    for (VkDescriptorSetLayout layout : {m_setLayout, m_terminationLayout, m_emptyLayout, m_textureLayout, m_geometryLayout})
        if (layout) vkDestroyDescriptorSetLayout(m_device, layout, nullptr);
    vkDestroyShaderModule(m_device, m_module, nullptr);
}

const ComputePipeline& ComputePipelineCache::get(const Context& context, const KernelInterface& interface,
                                                 SceneSpecialization scene, bool singleSegment) {
    if (!usesSceneSpecialization(shaderCode(interface.shader))) scene = {};  // one pipeline for any scene
    if (!usesSingleSegmentSpecialization(shaderCode(interface.shader))) singleSegment = false;
    const std::string key = fmt::format("{}|{}|{}|{}|{}{}{}{}|{}|{}", interface.shader, interface.bindingCount,
                                        interface.pushBytes, interface.groupSize, int(scene.instances),
                                        int(scene.alphaTest), int(scene.textures), int(scene.bvhTexels),
                                        scene.lightSampler, int(singleSegment));
    std::lock_guard lock(m_mutex);
    auto& slot = m_pipelines[key];
    if (!slot) {
        try {
            slot = std::make_unique<ComputePipeline>(context, interface, scene, singleSegment);
        } catch (...) {
            m_pipelines.erase(key);
            throw;
        }
    }
    return *slot;
}

size_t ComputePipelineCache::size() const {
    std::lock_guard lock(m_mutex);
    return m_pipelines.size();
}

void ComputePipelineCache::clear() {
    std::lock_guard lock(m_mutex);
    m_pipelines.clear();
}

}  // namespace vkp::vk
