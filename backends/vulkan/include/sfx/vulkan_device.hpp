// The Vulkan backend: a Device on an instance and device of its own, or on a host engine's
// Vulkan objects. Needs Vulkan 1.3 or VK_KHR_dynamic_rendering (render passes are dynamic).
#pragma once

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

#include "sfx/hal.hpp"

namespace sfx::vulkan {

// Opens the Vulkan loader at run time, creates an instance and a device on the best physical
// device (discrete first). BackendUnavailable with the reason when the loader, an ICD, a 1.3
// device or (with options.validation) VK_LAYER_KHRONOS_validation is missing.
Result<std::unique_ptr<Device>> createDevice(const DeviceOptions& options = {});

// One Vulkan physical device the loader sees (VK_ICD_FILENAMES / VK_DRIVER_FILES select drivers),
// in the loader's order: what DeviceOptions::physicalDevice picks among.
struct PhysicalDeviceInfo {
    uint32_t index = 0;
    std::string name;        // VkPhysicalDeviceProperties::deviceName
    std::string type;        // "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other"
    std::string apiVersion;  // "1.3.239"
    int typeRank = 0;        // what the default choice prefers: discrete 4, integrated 3, virtual 2, else 1
    bool usable = false;
    std::string unusableReason;  // when not usable: "no dynamic rendering", "no graphics+compute queue"
};
// BackendUnavailable when there is no loader or no driver.
Result<std::vector<PhysicalDeviceInfo>> listPhysicalDevices();

// A host engine's Vulkan objects. The SDK uses them but never destroys them; they must outlive
// the Device. The device must have been created with dynamic rendering enabled (Vulkan 1.3
// feature dynamicRendering, or VK_KHR_dynamic_rendering), and, for the high tier,
// fragmentStoresAndAtomics if effects use atomics in fragment shaders.
struct ExternalVulkan {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;  // the SDK submits here when it records into its own command buffers
    uint32_t queueFamily = 0;        // of `queue`; must support graphics and compute
    PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
    // Set when the host enabled VK_EXT_debug_utils on `instance`: then options.validation adds
    // a messenger whose warnings and errors takeValidationMessages() returns.
    bool debugUtilsEnabled = false;
    // Set when the host created `device` with synchronization2 (Vulkan 1.3 feature or
    // VK_KHR_synchronization2): the SDK then records one vkCmdPipelineBarrier2 per command
    // instead of one vkCmdPipelineBarrier per pair of stage masks, which costs less CPU.
    bool synchronization2Enabled = false;
};
Result<std::unique_ptr<Device>> wrapDevice(const ExternalVulkan& external, const DeviceOptions& options = {});

// Records the SDK's following commands into the host's command buffer, which the host has begun
// and will end and submit itself. flush() then only stops recording into it (the SDK goes back
// to its own command buffers); reads of textures and buffers refuse while it is set, since they
// need a submit. Pass VK_NULL_HANDLE to stop as well. Staging memory and descriptor sets used by
// a host command buffer are released at the next setCommandBuffer call, so the host must have
// finished executing the previous one by then. A host that attaches again before that — a
// second window in the same frame's command buffer, with a host pass between two effects —
// passes previousFinished = false: what the earlier windows used is then kept until a later
// call with true. InvalidArgument when `device` is not Vulkan.
Status setCommandBuffer(Device& device, VkCommandBuffer commandBuffer, bool previousFinished = true);

// ---- Host images in, SDK images out (docs/integration.md, "Host images and the state contract")

// A host VkImage the SDK may read or write as a texture: depth, normals, colour, velocity or an
// effect's output. The SDK's mip i is the host's mip baseMip + i of array layer `layer`.
struct ExternalImage {
    VkImage image = VK_NULL_HANDLE;
    // Its format: either as sfx::Format or as VkFormat (one of the VkFormats of the Formats:
    // R8_UNORM, R8G8B8A8_UNORM, R16_SFLOAT, R16G16_SFLOAT, R16G16B16A16_SFLOAT, R32_SFLOAT,
    // R32G32_SFLOAT, R32G32B32A32_SFLOAT, R32_UINT, D16_UNORM, D24_UNORM_S8_UINT, D32_SFLOAT);
    // when both are set they must name the same format.
    Format format = Format::Undefined;
    VkFormat vkFormat = VK_FORMAT_UNDEFINED;
    uint32_t width = 0, height = 0;  // of the host's mip baseMip
    uint32_t baseMip = 0;
    uint32_t mipLevels = 1;         // the SDK sees [baseMip, baseMip + mipLevels)
    uint32_t layer = 0;             // a 2D image or one layer of an array (must be < the image's layers)
    VkImageUsageFlags vkUsage = 0;  // what the image was created with
    // What the SDK may do with it (TextureUsage bits), each needing its Vulkan usage:
    // kTextureSampled SAMPLED, kTextureStorage STORAGE, kTextureRenderTarget COLOR_ATTACHMENT
    // or DEPTH_STENCIL_ATTACHMENT. readTexture / writeTexture need TRANSFER_SRC / TRANSFER_DST.
    uint32_t usage = kTextureSampled;
    // Optional: a 2D view of exactly the SDK's mips and layer, data aspect only (depth for depth
    // formats), which the SDK then samples through instead of making its own. Never destroyed.
    VkImageView view = VK_NULL_HANDLE;
    // The state contract: the layout the host leaves the image in whenever it hands the device
    // work (any SDK call) and gets back at every flush(). Not UNDEFINED or PREINITIALIZED; a
    // depth format takes a depth layout, a colour format a colour one (GENERAL, READ_ONLY_OPTIMAL,
    // ATTACHMENT_OPTIMAL, SHADER_READ_ONLY_OPTIMAL, TRANSFER_SRC/DST_OPTIMAL fit both).
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    const char* debugName = "";
};

// A texture of the device for the host's image. The SDK never destroys the image or the host's
// view: destroyTexture forgets them (the views the SDK made of it go at the next flush, so the
// host keeps the image alive until then). InvalidArgument naming the field and its allowed
// values for a null image, a format or layout outside the lists above, a usage the image lacks,
// a size the device cannot hold; InvalidArgument when `device` is not Vulkan.
Result<TextureHandle> importImage(Device& device, const ExternalImage& image);

// The Vulkan objects of a texture, imported or the SDK's own: the image, a 2D view of all its
// mips (data aspect), its format and layout. For an imported image `layout` is the contract's
// (ExternalImage.layout); for the SDK's own texture it is the layout of mip 0 after the commands
// recorded so far, and the host synchronises its own use of it after a flush().
struct NativeImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_UNDEFINED;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    uint32_t baseMip = 0, layer = 0;  // where the SDK's mip 0 is in `image`
};
Result<NativeImage> nativeImage(Device& device, TextureHandle texture);

}  // namespace sfx::vulkan
