// Translations of HAL enums and formats into Vulkan's, and the D24S8 texel layouts.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>

#include "sfx/hal.hpp"

namespace sfx::vulkan {

// VK_FORMAT_UNDEFINED for Format::Undefined and unknown values.
VkFormat toVkFormat(Format f);
// The aspects an image of the format has (barriers cover all of them).
VkImageAspectFlags fullAspect(Format f);
// What shaders sample, copies move and views see: depth only for depth formats.
VkImageAspectFlags dataAspect(Format f);
// D24S8 texels between the HAL layout (depth in the high 24 bits, stencil in the low 8; see
// hal.hpp) and what a copy of Vulkan's depth aspect moves (X8_D24: depth in the low 24 bits,
// the high 8 undefined). Stencil is not copied: it is dropped on upload and reads as 0.
void d24s8ToVulkan(const void* hal, void* vk, size_t bytes);
void d24s8FromVulkan(const void* vk, void* hal, size_t bytes);

VkCompareOp toVk(CompareOp op);
VkBlendFactor toVk(BlendFactor f);
VkShaderStageFlags toVkStages(uint32_t stageMask);
VkDescriptorType toVkDescriptor(ResourceKind k);

}  // namespace sfx::vulkan
