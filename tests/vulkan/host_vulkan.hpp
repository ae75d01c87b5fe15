// A host engine's Vulkan objects for the tests on host devices (tests/vulkan/test_vulkan_import.cpp,
// test_vulkan_external.cpp): the engine sample's instance and device, a command buffer, and the
// images, buffers, barriers, uploads and readbacks a host makes itself, without the SDK.
#pragma once

#include <catch2/catch.hpp>

#include <vulkan/vulkan.h>

#include <cstring>
#include <string>
#include <vector>

#include "sfx/vulkan_device.hpp"
#include "vk_host.hpp"

namespace sfx::hostvk {

// A host engine: the engine sample's raw Vulkan layer (tools/vk_host/vk_host.hpp: an
// instance with the validation layer and synchronization validation, a 1.3 device with dynamic
// rendering, one queue), plus a command buffer. It leaves synchronization2 off (the engine
// sample turns it on), so these tests keep the SDK's barriers without it, one
// vkCmdPipelineBarrier per pair of stage masks, under synchronization validation.
// The instance, physical device, device, queue and family are VkHost's own members.
struct Host : engine::VkHost {
    VkCommandPool pool = VK_NULL_HANDLE;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    bool validation = false;  // the layer is on (always, when create() required it)
    std::string skipReason;

    // requireValidation false: without the layer installed the host runs without it.
    bool create(bool requireValidation = true) {
        validation = engine::VkHost::validationLayerInstalled();
        if (!validation && requireValidation) {
            skipReason = "VK_LAYER_KHRONOS_validation is not installed (these tests need synchronization validation)";
            return false;
        }
        if (Status s = VkHost::create(validation, /*wantSynchronization2=*/false); !s) {
            skipReason = s.toString();
            return false;
        }
        VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
        pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        pci.queueFamilyIndex = family;
        vkCreateCommandPool(device, &pci, nullptr, &pool);
        VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        cai.commandPool = pool;
        cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cai.commandBufferCount = 1;
        vkAllocateCommandBuffers(device, &cai, &cb);
        return true;
    }

    vulkan::ExternalVulkan external() const { return {instance, physical, device, queue, family, vkGetInstanceProcAddr, validation}; }

    uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags want) const {
        VkPhysicalDeviceMemoryProperties mp;
        vkGetPhysicalDeviceMemoryProperties(physical, &mp);
        for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
            if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
        return 0;
    }

    void begin() {
        VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        REQUIRE(vkBeginCommandBuffer(cb, &bi) == VK_SUCCESS);
    }
    void submitAndWait() {
        REQUIRE(vkEndCommandBuffer(cb) == VK_SUCCESS);
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO};
        si.commandBufferCount = 1;
        si.pCommandBuffers = &cb;
        REQUIRE(vkQueueSubmit(queue, 1, &si, VK_NULL_HANDLE) == VK_SUCCESS);
        REQUIRE(vkQueueWaitIdle(queue) == VK_SUCCESS);
    }

    ~Host() {  // ~VkHost then destroys the device, the messenger and the instance
        if (device) {
            vkDeviceWaitIdle(device);
            if (pool) vkDestroyCommandPool(device, pool, nullptr);
        }
    }
};

// The SDK on the host's device, with validation (the tests ask for it; the default is off).
inline std::unique_ptr<Device> wrapValidated(Host& host) {
    DeviceOptions options;
    options.validation = true;
    Result<std::unique_ptr<Device>> wrapped = vulkan::wrapDevice(host.external(), options);
    INFO(wrapped.status().toString());
    REQUIRE(wrapped.isOk());
    return std::move(wrapped.value());
}

// No message from the SDK's validation nor from the host's messenger (taken, so the next check
// sees only what came after this one).
inline void checkNoMessages(Device& d, Host& host) {
    const std::vector<std::string> messages = d.takeValidationMessages();
    const std::vector<std::string> hostErrors = host.takeMessages();
    for (const std::string& m : messages) UNSCOPED_INFO("validation: " << m);
    for (const std::string& m : hostErrors) UNSCOPED_INFO("host validation: " << m);
    CHECK(messages.empty());
    CHECK(hostErrors.empty());
}

// A host-visible buffer for the host's uploads and readbacks.
struct HostBuffer {
    const Host& host;
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    void* mapped = nullptr;
    HostBuffer(const Host& h, VkDeviceSize size) : host(h) {
        VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
        bci.size = size;
        bci.usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        REQUIRE(vkCreateBuffer(h.device, &bci, nullptr, &buffer) == VK_SUCCESS);
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(h.device, buffer, &req);
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = h.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
        REQUIRE(vkAllocateMemory(h.device, &ai, nullptr, &memory) == VK_SUCCESS);
        vkBindBufferMemory(h.device, buffer, memory, 0);
        vkMapMemory(h.device, memory, 0, VK_WHOLE_SIZE, 0, &mapped);
    }
    ~HostBuffer() {
        vkDestroyBuffer(host.device, buffer, nullptr);
        vkFreeMemory(host.device, memory, nullptr);
    }
};

// A host image of one mip with `layers` layers, and a 2D view of layer `viewLayer`.
struct HostImage {
    const Host& host;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format;
    VkImageAspectFlags aspect;
    uint32_t width, height;
    HostImage(const Host& h, VkFormat f, VkImageUsageFlags usage, uint32_t w, uint32_t hgt, uint32_t layers = 1, uint32_t viewLayer = 0)
        : host(h), format(f), width(w), height(hgt) {
        aspect = (f == VK_FORMAT_D32_SFLOAT || f == VK_FORMAT_D16_UNORM) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
        VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        ici.imageType = VK_IMAGE_TYPE_2D;
        ici.format = f;
        ici.extent = {w, hgt, 1};
        ici.mipLevels = 1;
        ici.arrayLayers = layers;
        ici.samples = VK_SAMPLE_COUNT_1_BIT;
        ici.tiling = VK_IMAGE_TILING_OPTIMAL;
        ici.usage = usage;
        ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        REQUIRE(vkCreateImage(h.device, &ici, nullptr, &image) == VK_SUCCESS);
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(h.device, image, &req);
        VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        ai.allocationSize = req.size;
        ai.memoryTypeIndex = h.memoryType(req.memoryTypeBits, 0);
        REQUIRE(vkAllocateMemory(h.device, &ai, nullptr, &memory) == VK_SUCCESS);
        vkBindImageMemory(h.device, image, memory, 0);
        VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        vci.image = image;
        vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
        vci.format = f;
        vci.subresourceRange = {aspect, 0, 1, viewLayer, 1};
        REQUIRE(vkCreateImageView(h.device, &vci, nullptr, &view) == VK_SUCCESS);
    }
    ~HostImage() {
        vkDestroyImageView(host.device, view, nullptr);
        vkDestroyImage(host.device, image, nullptr);
        vkFreeMemory(host.device, memory, nullptr);
    }
};

// What the SDK is told of a host image (its layer 0): the Vulkan usage it was made with, what
// the SDK may do with it, the layout the host keeps it in, and the host's view unless
// `withView` is false (the SDK then makes its own).
inline vulkan::ExternalImage externalImage(const HostImage& img, VkImageUsageFlags vkUsage, uint32_t usage, VkImageLayout layout,
                                           bool withView = true) {
    vulkan::ExternalImage e;
    e.image = img.image;
    e.vkFormat = img.format;
    e.width = img.width;
    e.height = img.height;
    e.vkUsage = vkUsage;
    e.usage = usage;
    e.view = withView ? img.view : VK_NULL_HANDLE;
    e.layout = layout;
    return e;
}

inline void imageBarrier(VkCommandBuffer cb, const HostImage& img, uint32_t layer, VkImageLayout from, VkImageLayout to,
                         VkPipelineStageFlags srcStage, VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    engine::imageBarrier(cb, img.image, img.aspect, from, to, srcStage, srcAccess, dstStage, dstAccess, layer);
}

// The host fills layer `layer` of `img` and leaves it in `layout`, everything made visible.
inline void hostUpload(Host& host, const HostImage& img, uint32_t layer, const void* data, size_t bytes, VkImageLayout layout) {
    HostBuffer staging(host, bytes);
    std::memcpy(staging.mapped, data, bytes);
    host.begin();
    imageBarrier(host.cb, img, layer, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {img.aspect, 0, layer, 1};
    region.imageExtent = {img.width, img.height, 1};
    vkCmdCopyBufferToImage(host.cb, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    imageBarrier(host.cb, img, layer, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layout, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                 VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
    host.submitAndWait();
}

// The host copies its image (in `layout`) out, and leaves it in `layout`.
inline std::vector<uint8_t> hostDownload(Host& host, const HostImage& img, VkImageLayout layout, size_t bytes) {
    HostBuffer readback(host, bytes);
    host.begin();
    imageBarrier(host.cb, img, 0, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {img.aspect, 0, 0, 1};
    region.imageExtent = {img.width, img.height, 1};
    vkCmdCopyImageToBuffer(host.cb, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
    imageBarrier(host.cb, img, 0, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                 VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(host.cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
    host.submitAndWait();
    std::vector<uint8_t> out(bytes);
    std::memcpy(out.data(), readback.mapped, bytes);
    return out;
}

}  // namespace sfx::hostvk
