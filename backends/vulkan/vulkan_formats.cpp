// Translations of HAL enums and formats into Vulkan's (declared in vulkan_formats.hpp).
#include "vulkan_formats.hpp"

#include <cstring>

namespace sfx::vulkan {

VkFormat toVkFormat(Format f) {
    switch (f) {
        case Format::R8: return VK_FORMAT_R8_UNORM;
        case Format::RGBA8: return VK_FORMAT_R8G8B8A8_UNORM;
        case Format::R16F: return VK_FORMAT_R16_SFLOAT;
        case Format::RG16F: return VK_FORMAT_R16G16_SFLOAT;
        case Format::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
        case Format::R32F: return VK_FORMAT_R32_SFLOAT;
        case Format::RG32F: return VK_FORMAT_R32G32_SFLOAT;
        case Format::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
        case Format::R32UI: return VK_FORMAT_R32_UINT;
        case Format::D16: return VK_FORMAT_D16_UNORM;
        case Format::D24S8: return VK_FORMAT_D24_UNORM_S8_UINT;
        case Format::D32F: return VK_FORMAT_D32_SFLOAT;
        default: return VK_FORMAT_UNDEFINED;
    }
}

VkImageAspectFlags fullAspect(Format f) {
    if (f == Format::D24S8) return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    if (isDepthFormat(f)) return VK_IMAGE_ASPECT_DEPTH_BIT;
    return VK_IMAGE_ASPECT_COLOR_BIT;
}
void d24s8ToVulkan(const void* hal, void* vk, size_t bytes) {
    for (size_t i = 0; i + 4 <= bytes; i += 4) {
        uint32_t v;
        std::memcpy(&v, static_cast<const uint8_t*>(hal) + i, 4);
        v >>= 8;
        std::memcpy(static_cast<uint8_t*>(vk) + i, &v, 4);
    }
}
void d24s8FromVulkan(const void* vk, void* hal, size_t bytes) {
    for (size_t i = 0; i + 4 <= bytes; i += 4) {
        uint32_t v;
        std::memcpy(&v, static_cast<const uint8_t*>(vk) + i, 4);
        v = (v & 0x00FFFFFFu) << 8;
        std::memcpy(static_cast<uint8_t*>(hal) + i, &v, 4);
    }
}

VkImageAspectFlags dataAspect(Format f) { return isDepthFormat(f) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT; }

VkCompareOp toVk(CompareOp op) {
    switch (op) {
        case CompareOp::Never: return VK_COMPARE_OP_NEVER;
        case CompareOp::Less: return VK_COMPARE_OP_LESS;
        case CompareOp::LessEqual: return VK_COMPARE_OP_LESS_OR_EQUAL;
        case CompareOp::Greater: return VK_COMPARE_OP_GREATER;
        case CompareOp::GreaterEqual: return VK_COMPARE_OP_GREATER_OR_EQUAL;
        case CompareOp::Equal: return VK_COMPARE_OP_EQUAL;
        case CompareOp::NotEqual: return VK_COMPARE_OP_NOT_EQUAL;
        case CompareOp::Always: return VK_COMPARE_OP_ALWAYS;
    }
    return VK_COMPARE_OP_ALWAYS;
}

VkBlendFactor toVk(BlendFactor f) {
    switch (f) {
        case BlendFactor::Zero: return VK_BLEND_FACTOR_ZERO;
        case BlendFactor::One: return VK_BLEND_FACTOR_ONE;
        case BlendFactor::SrcAlpha: return VK_BLEND_FACTOR_SRC_ALPHA;
        case BlendFactor::OneMinusSrcAlpha: return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        case BlendFactor::DstAlpha: return VK_BLEND_FACTOR_DST_ALPHA;
        case BlendFactor::OneMinusDstAlpha: return VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA;
    }
    return VK_BLEND_FACTOR_ONE;
}

VkShaderStageFlags toVkStages(uint32_t stageMask) {
    VkShaderStageFlags s = 0;
    if (stageMask & stageBit(ShaderStage::Vertex)) s |= VK_SHADER_STAGE_VERTEX_BIT;
    if (stageMask & stageBit(ShaderStage::Fragment)) s |= VK_SHADER_STAGE_FRAGMENT_BIT;
    if (stageMask & stageBit(ShaderStage::Compute)) s |= VK_SHADER_STAGE_COMPUTE_BIT;
    return s;
}

VkDescriptorType toVkDescriptor(ResourceKind k) {
    switch (k) {
        case ResourceKind::UniformBuffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        case ResourceKind::SampledTexture: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case ResourceKind::StorageBuffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        case ResourceKind::StorageImage: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    }
    return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
}

}  // namespace sfx::vulkan
