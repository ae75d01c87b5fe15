// Programs (shader modules, their SPIR-V's structure checked first) and the graphics and compute
// pipelines made from them. Pipelines own their layouts, so a program may be destroyed first.
#include <cstddef>

#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

namespace sfx::vulkan {

// sfxc validated every embedded program with SPIRV-Tools at build time, so the runtime links no
// SPIR-V tooling; it still refuses a module whose structure a driver would walk off the end of:
// the header (magic number, five words) and every instruction's word count inside the module.
Status validateSpirv(const CompiledProgram& program, const StageCode& stage) {
    const std::vector<uint32_t>& words = stage.spirv;
    auto refuse = [&](const std::string& why) {
        return validation::fail(validation::Error::ShaderInvalidSpirv, {program.name, toString(stage.stage), "  " + why});
    };
    constexpr uint32_t kMagic = 0x07230203u;
    constexpr size_t kHeaderWords = 5;
    if (words.size() < kHeaderWords) return refuse(std::to_string(words.size()) + " words; a module has at least 5");
    if (words[0] != kMagic) return refuse("word 0 is not the SPIR-V magic number 0x07230203");
    for (size_t i = kHeaderWords; i < words.size();) {
        const uint32_t count = words[i] >> 16;
        if (count == 0 || count > words.size() - i)
            return refuse("instruction at word " + std::to_string(i) + " has word count " + std::to_string(count) + "; allowed 1.." +
                          std::to_string(words.size() - i));
        i += count;
    }
    return Status::ok();
}

Result<ProgramHandle> VulkanDevice::makeProgram(const CompiledProgram& program) {
    VulkanProgram p;
    p.info = validation::programInfo(program);
    auto cleanup = [&]() {
        for (auto& m : p.modules) vk_.vkDestroyShaderModule(device_, m.second, nullptr);
    };
    for (const StageCode& s : program.stages) {
        VkShaderModuleCreateInfo mci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        mci.codeSize = s.spirv.size() * sizeof(uint32_t);
        mci.pCode = s.spirv.data();
        VkShaderModule module;
        VkResult r = vk_.vkCreateShaderModule(device_, &mci, nullptr, &module);
        if (r != VK_SUCCESS) {
            cleanup();
            return Status{StatusCode::ShaderError, "program '" + program.name + "': vkCreateShaderModule failed: " + vkResultName(r)};
        }
        p.modules.emplace_back(s.stage, module);
    }
    return programs_.insert(std::move(p));
}

Status VulkanDevice::startPipeline(validation::PipelineInfo info, VulkanPipeline& p) {
    p.info = std::move(info);
    Status s = createLayouts(p.info.resources, p.info.compute, p);
    if (!s) retire(p);
    return s;
}

Result<PipelineHandle> VulkanDevice::finishPipeline(VulkanPipeline& p, VkResult r, const char* call, const char* debugName) {
    if (r != VK_SUCCESS) {
        const std::string program = p.info.programName;
        retire(p);
        return Status{StatusCode::ShaderError, "program '" + program + "': " + call + " failed: " + vkResultName(r)};
    }
    setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(p.pipeline), debugName);
    return pipelines_.insert(std::move(p));
}

namespace {

// The map of a pipeline's specialisation constants: one 32-bit int each, in the given order.
struct Specialization {
    std::vector<VkSpecializationMapEntry> entries;
    VkSpecializationInfo info{};
    explicit Specialization(const std::vector<SpecializationConstant>& constants) {
        for (size_t i = 0; i < constants.size(); ++i)
            entries.push_back(
                {constants[i].id, uint32_t(i * sizeof(SpecializationConstant) + offsetof(SpecializationConstant, value)), sizeof(int32_t)});
        info.mapEntryCount = uint32_t(entries.size());
        info.pMapEntries = entries.data();
        info.dataSize = constants.size() * sizeof(SpecializationConstant);
        info.pData = constants.data();
    }
    const VkSpecializationInfo* get() const { return entries.empty() ? nullptr : &info; }
};

}  // namespace

Result<PipelineHandle> VulkanDevice::makeGraphicsPipeline(const GraphicsPipelineDesc& desc, const VulkanProgram& prog,
                                                          validation::PipelineInfo info) {
    VulkanPipeline p;
    SFX_TRY(startPipeline(std::move(info), p));

    const Specialization specialization(desc.constants);
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const auto& [stage, module] : prog.modules) {
        VkPipelineShaderStageCreateInfo si{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        si.stage = stage == ShaderStage::Vertex ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
        si.module = module;
        si.pName = "main";
        si.pSpecializationInfo = specialization.get();
        stages.push_back(si);
    }
    VkVertexInputBindingDescription vb{0, desc.vertexLayout.stride, VK_VERTEX_INPUT_RATE_VERTEX};
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (const VertexAttribute& a : desc.vertexLayout.attributes) {
        const VkFormat f = a.format == VertexFormat::Float2 ? VK_FORMAT_R32G32_SFLOAT
            : a.format == VertexFormat::Float3              ? VK_FORMAT_R32G32B32_SFLOAT
                                                            : VK_FORMAT_R32G32B32A32_SFLOAT;
        attributes.push_back({a.location, 0, f, a.offset});
    }
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (p.usesVertexBuffer()) {
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &vb;
        vi.vertexAttributeDescriptionCount = uint32_t(attributes.size());
        vi.pVertexAttributeDescriptions = attributes.data();
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = desc.cull == CullMode::Back ? VK_CULL_MODE_BACK_BIT : desc.cull == CullMode::Front ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_NONE;
    // The HAL's front faces wind counter-clockwise with rows counted upwards (GL's window
    // convention). Vulkan measures winding with framebuffer y pointing down the rows, so the same
    // memory picture winds clockwise here.
    rs.frontFace = VK_FRONT_FACE_CLOCKWISE;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = desc.depth.test;
    ds.depthWriteEnable = desc.depth.write;
    ds.depthCompareOp = desc.depth.test ? toVk(desc.depth.compare) : VK_COMPARE_OP_ALWAYS;
    std::vector<VkPipelineColorBlendAttachmentState> blends;
    for (size_t i = 0; i < desc.colorFormats.size(); ++i) {
        VkPipelineColorBlendAttachmentState b{};
        b.blendEnable = desc.blend.enable;
        b.srcColorBlendFactor = toVk(desc.blend.src);
        b.dstColorBlendFactor = toVk(desc.blend.dst);
        b.srcAlphaBlendFactor = toVk(desc.blend.separateAlpha ? desc.blend.srcAlpha : desc.blend.src);
        b.dstAlphaBlendFactor = toVk(desc.blend.separateAlpha ? desc.blend.dstAlpha : desc.blend.dst);
        b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
        b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        blends.push_back(b);
    }
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = uint32_t(blends.size());
    cb.pAttachments = blends.data();
    const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dyn{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dyn.dynamicStateCount = 2;
    dyn.pDynamicStates = dynamics;
    std::vector<VkFormat> colorFormats;
    for (Format f : desc.colorFormats) colorFormats.push_back(toVkFormat(f));
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = uint32_t(colorFormats.size());
    rendering.pColorAttachmentFormats = colorFormats.data();
    rendering.depthAttachmentFormat = toVkFormat(desc.depthFormat);

    VkGraphicsPipelineCreateInfo pci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    pci.pNext = &rendering;
    pci.stageCount = uint32_t(stages.size());
    pci.pStages = stages.data();
    pci.pVertexInputState = &vi;
    pci.pInputAssemblyState = &ia;
    pci.pViewportState = &vp;
    pci.pRasterizationState = &rs;
    pci.pMultisampleState = &ms;
    pci.pDepthStencilState = &ds;
    pci.pColorBlendState = &cb;
    pci.pDynamicState = &dyn;
    pci.layout = p.layout;
    const VkResult r = vk_.vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &pci, nullptr, &p.pipeline);
    return finishPipeline(p, r, "vkCreateGraphicsPipelines", desc.debugName);
}

Result<PipelineHandle> VulkanDevice::makeComputePipeline(const ComputePipelineDesc& desc, const VulkanProgram& prog, validation::PipelineInfo info) {
    VulkanPipeline p;
    SFX_TRY(startPipeline(std::move(info), p));
    VkComputePipelineCreateInfo pci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    pci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    pci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pci.stage.module = prog.modules[0].second;
    pci.stage.pName = "main";
    const Specialization specialization(desc.constants);
    pci.stage.pSpecializationInfo = specialization.get();
    pci.layout = p.layout;
    const VkResult r = vk_.vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &pci, nullptr, &p.pipeline);
    return finishPipeline(p, r, "vkCreateComputePipelines", desc.debugName);
}

}  // namespace sfx::vulkan
