#include "vk_host.hpp"

#include <cstring>

namespace sfx::engine {
namespace {

// clang-format off
#define ENGINE_VK(call)                                                                               \
    do {                                                                                              \
        const VkResult engine_vk_result_ = (call);                                                   \
        if (engine_vk_result_ != VK_SUCCESS)                                                          \
            return Status{StatusCode::DeviceError, std::string(#call) + " returned " + std::to_string(int(engine_vk_result_))}; \
    } while (0)
// clang-format on

VKAPI_ATTR VkBool32 VKAPI_CALL collect(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    static_cast<std::vector<std::string>*>(user)->push_back(data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

Status unavailable(const std::string& why) { return {StatusCode::BackendUnavailable, "engine_vulkan: " + why}; }

}  // namespace

bool VkHost::validationLayerInstalled() {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    bool found = false;
    for (const VkLayerProperties& l : layers) found |= std::strcmp(l.layerName, "VK_LAYER_KHRONOS_validation") == 0;
    return found;
}

Status VkHost::createInstance(bool validation) {
    const char* layer = "VK_LAYER_KHRONOS_validation";
    if (validation && !validationLayerInstalled()) return unavailable("VK_LAYER_KHRONOS_validation is not installed (validation was asked for)");
    const char* extensions[] = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME};
    const VkValidationFeatureEnableEXT sync = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &sync;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "engine_vulkan";
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    if (validation) {
        ci.pNext = &features;
        ci.enabledLayerCount = 1;
        ci.ppEnabledLayerNames = &layer;
        ci.enabledExtensionCount = 2;
        ci.ppEnabledExtensionNames = extensions;
    }
    if (vkCreateInstance(&ci, nullptr, &instance) != VK_SUCCESS) return unavailable("vkCreateInstance failed (no Vulkan driver?)");
    ++counts_.objectsCreated;
    if (!validation) return Status::ok();
    auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
    mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
    mi.pfnUserCallback = collect;
    mi.pUserData = &messages_;
    ENGINE_VK(createMessenger(instance, &mi, nullptr, &messenger_));
    ++counts_.objectsCreated;
    debugUtils = true;
    return Status::ok();
}

Status VkHost::createDevice(bool wantSynchronization2) {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> gpus(count);
    vkEnumeratePhysicalDevices(instance, &count, gpus.data());
    for (VkPhysicalDevice gpu : gpus) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(gpu, &p);
        if (p.apiVersion >= VK_API_VERSION_1_3) {
            physical = gpu;
            break;
        }
    }
    if (!physical) return unavailable("no Vulkan 1.3 device (dynamic rendering is needed)");
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, props.data());
    bool found = false;
    for (uint32_t i = 0; i < families && !found; ++i)
        if ((props[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (props[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
            family = i;
            found = true;
        }
    if (!found) return unavailable("no queue family with graphics and compute");
    // Dynamic rendering: the SDK's passes need it (ExternalVulkan), and the host's use it too.
    // synchronization2 where the device has it: the SDK then records fewer barrier commands.
    VkPhysicalDeviceVulkan13Features supported13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    supported.pNext = &supported13;
    vkGetPhysicalDeviceFeatures2(physical, &supported);
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    v13.dynamicRendering = VK_TRUE;
    synchronization2 = wantSynchronization2 && supported13.synchronization2 == VK_TRUE;
    v13.synchronization2 = synchronization2 ? VK_TRUE : VK_FALSE;
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = family;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &v13;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    if (vkCreateDevice(physical, &dci, nullptr, &device) != VK_SUCCESS) return unavailable("vkCreateDevice failed");
    ++counts_.objectsCreated;
    vkGetDeviceQueue(device, family, 0, &queue);
    return Status::ok();
}

Status VkHost::create(bool validation, bool wantSynchronization2) {
    SFX_TRY(createInstance(validation));
    return createDevice(wantSynchronization2);
}

VkHost::~VkHost() {
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger_) {
        auto destroyMessenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroyMessenger(instance, messenger_, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
}

std::vector<std::string> VkHost::takeMessages() {
    std::vector<std::string> out;
    out.swap(messages_);
    return out;
}

uint32_t VkHost::memoryType(uint32_t bits, VkMemoryPropertyFlags want) const {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(physical, &mp);
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
    return UINT32_MAX;
}

Status VkHost::allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags want, VkDeviceMemory* out) {
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = memoryType(req.memoryTypeBits, want);
    if (ai.memoryTypeIndex == UINT32_MAX) return {StatusCode::DeviceError, "engine_vulkan: no memory type fits"};
    ENGINE_VK(vkAllocateMemory(device, &ai, nullptr, out));
    ++counts_.memoryAllocations;
    return Status::ok();
}

Status VkHost::makeImage(VkFormat format, VkImageUsageFlags usage, uint32_t width, uint32_t height, HostImage* out) {
    out->format = format;
    out->usage = usage;
    out->width = width;
    out->height = height;
    out->aspect = format == VK_FORMAT_D32_SFLOAT ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    switch (format) {
        case VK_FORMAT_R16_SFLOAT: out->texelBytes = 2; break;
        case VK_FORMAT_R16G16_SFLOAT:
        case VK_FORMAT_R8G8B8A8_UNORM:
        case VK_FORMAT_D32_SFLOAT: out->texelBytes = 4; break;
        default: out->texelBytes = 8; break;  // R16G16B16A16_SFLOAT
    }
    VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = format;
    ici.extent = {width, height, 1};
    ici.mipLevels = 1;
    ici.arrayLayers = 1;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = usage;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    ENGINE_VK(vkCreateImage(device, &ici, nullptr, &out->image));
    ++counts_.objectsCreated;
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, out->image, &req);
    SFX_TRY(allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, &out->memory));
    ENGINE_VK(vkBindImageMemory(device, out->image, out->memory, 0));
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = out->image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = format;
    vci.subresourceRange = {out->aspect, 0, 1, 0, 1};
    ENGINE_VK(vkCreateImageView(device, &vci, nullptr, &out->view));
    ++counts_.objectsCreated;
    return Status::ok();
}

Status VkHost::makeBuffer(VkDeviceSize size, VkBufferUsageFlags usage, HostBuffer* out) {
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    bci.size = size;
    bci.usage = usage;
    ENGINE_VK(vkCreateBuffer(device, &bci, nullptr, &out->buffer));
    ++counts_.objectsCreated;
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, out->buffer, &req);
    SFX_TRY(allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, &out->memory));
    ENGINE_VK(vkBindBufferMemory(device, out->buffer, out->memory, 0));
    ENGINE_VK(vkMapMemory(device, out->memory, 0, VK_WHOLE_SIZE, 0, &out->mapped));
    out->size = size;
    return Status::ok();
}

Status VkHost::makeSetLayout(const std::vector<VkDescriptorSetLayoutBinding>& bindings, VkDescriptorSetLayout* out) {
    VkDescriptorSetLayoutCreateInfo ci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    ci.bindingCount = uint32_t(bindings.size());
    ci.pBindings = bindings.data();
    ENGINE_VK(vkCreateDescriptorSetLayout(device, &ci, nullptr, out));
    ++counts_.objectsCreated;
    return Status::ok();
}

Status VkHost::makePipeline(const PipelineDesc& desc, VkPipelineLayout* layout, VkPipeline* pipeline) {
    VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT, 0, desc.pushConstantBytes};
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &desc.setLayout;
    plci.pushConstantRangeCount = desc.pushConstantBytes ? 1 : 0;
    plci.pPushConstantRanges = &push;
    ENGINE_VK(vkCreatePipelineLayout(device, &plci, nullptr, layout));
    ++counts_.objectsCreated;

    VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
    const uint32_t* code[2] = {desc.vertexCode, desc.fragmentCode};
    const size_t words[2] = {desc.vertexWords, desc.fragmentWords};
    VkPipelineShaderStageCreateInfo stages[2] = {};
    for (int i = 0; i < 2; ++i) {
        VkShaderModuleCreateInfo mci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        mci.codeSize = words[i] * 4;
        mci.pCode = code[i];
        ENGINE_VK(vkCreateShaderModule(device, &mci, nullptr, &modules[i]));
        ++counts_.objectsCreated;
        stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
        stages[i].module = modules[i];
        stages[i].pName = "main";
    }
    const VkVertexInputBindingDescription binding{0, 24, VK_VERTEX_INPUT_RATE_VERTEX};
    const VkVertexInputAttributeDescription attributes[2] = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12}};
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (desc.meshVertices) {
        vi.vertexBindingDescriptionCount = 1;
        vi.pVertexBindingDescriptions = &binding;
        vi.vertexAttributeDescriptionCount = 2;
        vi.pVertexAttributeDescriptions = attributes;
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.cullMode = VK_CULL_MODE_NONE;  // the floor is one-sided geometry seen from above only; the bunny is closed
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = ds.depthWriteEnable = desc.depthFormat != VK_FORMAT_UNDEFINED;
    ds.depthCompareOp = VK_COMPARE_OP_LESS;
    std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colorFormats.size());
    for (auto& b : blends) b.colorWriteMask = 0xF;
    VkPipelineColorBlendStateCreateInfo cbs{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cbs.attachmentCount = uint32_t(blends.size());
    cbs.pAttachments = blends.data();
    const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dyn{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dyn.dynamicStateCount = 2;
    dyn.pDynamicStates = dynamics;
    VkPipelineRenderingCreateInfo rci{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rci.colorAttachmentCount = uint32_t(desc.colorFormats.size());
    rci.pColorAttachmentFormats = desc.colorFormats.data();
    rci.depthAttachmentFormat = desc.depthFormat;
    VkGraphicsPipelineCreateInfo gci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    gci.pNext = &rci;
    gci.stageCount = 2;
    gci.pStages = stages;
    gci.pVertexInputState = &vi;
    gci.pInputAssemblyState = &ia;
    gci.pViewportState = &vp;
    gci.pRasterizationState = &rs;
    gci.pMultisampleState = &ms;
    gci.pDepthStencilState = &ds;
    gci.pColorBlendState = &cbs;
    gci.pDynamicState = &dyn;
    gci.layout = *layout;
    const VkResult r = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &gci, nullptr, pipeline);
    for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
    ENGINE_VK(r);
    ++counts_.objectsCreated;
    return Status::ok();
}

Status VkHost::makeCommands(VkCommandPool* pool, VkCommandBuffer* cb, VkFence* fence) {
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = family;
    ENGINE_VK(vkCreateCommandPool(device, &pci, nullptr, pool));
    VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cai.commandPool = *pool;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = 1;
    ENGINE_VK(vkAllocateCommandBuffers(device, &cai, cb));
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    ENGINE_VK(vkCreateFence(device, &fci, nullptr, fence));
    counts_.objectsCreated += 3;
    return Status::ok();
}

Status VkHost::makeSampler(VkSampler* out) {
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    ENGINE_VK(vkCreateSampler(device, &sci, nullptr, out));
    ++counts_.objectsCreated;
    return Status::ok();
}

Status VkHost::makeDescriptorPool(uint32_t sets, uint32_t uniformBuffers, uint32_t samplers, VkDescriptorPool* out) {
    const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uniformBuffers},
                                           {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, samplers}};
    VkDescriptorPoolCreateInfo ci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    ci.maxSets = sets;
    ci.poolSizeCount = 2;
    ci.pPoolSizes = sizes;
    ENGINE_VK(vkCreateDescriptorPool(device, &ci, nullptr, out));
    ++counts_.objectsCreated;
    return Status::ok();
}

Status VkHost::allocateSet(VkDescriptorPool pool, VkDescriptorSetLayout layout, VkDescriptorSet* out) {
    VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    ai.descriptorPool = pool;
    ai.descriptorSetCount = 1;
    ai.pSetLayouts = &layout;
    ENGINE_VK(vkAllocateDescriptorSets(device, &ai, out));
    ++counts_.objectsCreated;
    return Status::ok();
}

void VkHost::writeDescriptors(const std::vector<VkWriteDescriptorSet>& writes) {
    vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);
    ++counts_.descriptorWrites;
}

void VkHost::copyImageToBuffer(VkCommandBuffer cb, const HostImage& image, VkImageLayout layout, const HostBuffer& buffer) {
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect, 0, 0, 1};
    region.imageExtent = {image.width, image.height, 1};
    vkCmdCopyImageToBuffer(cb, image.image, layout, buffer.buffer, 1, &region);
    ++counts_.stagingCopies;
}

Status VkHost::submit(VkCommandBuffer cb, VkFence fence) {
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cb;
    ENGINE_VK(vkQueueSubmit(queue, 1, &si, fence));
    ++counts_.submits;
    return Status::ok();
}

void VkHost::destroy(HostImage& image) {
    if (image.view) vkDestroyImageView(device, image.view, nullptr);
    if (image.image) vkDestroyImage(device, image.image, nullptr);
    if (image.memory) vkFreeMemory(device, image.memory, nullptr);
    image = {};
}

void VkHost::destroy(HostBuffer& buffer) {
    if (buffer.buffer) vkDestroyBuffer(device, buffer.buffer, nullptr);
    if (buffer.memory) vkFreeMemory(device, buffer.memory, nullptr);
    buffer = {};
}

void imageBarrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess, uint32_t layer) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, layer, 1};
    vkCmdPipelineBarrier(cb, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

void imageBarrier(VkCommandBuffer cb, const HostImage& image, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    imageBarrier(cb, image.image, image.aspect, from, to, srcStage, srcAccess, dstStage, dstAccess);
}

}  // namespace sfx::engine
