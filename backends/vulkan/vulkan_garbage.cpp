// Deferred destruction: destroyed objects wait in a Garbage list until the GPU is done with the
// commands recorded with them (pending_: the next submit; hostPending_: the next
// setCommandBuffer, when the host has finished its command buffer), and teardown.
#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {

void VulkanDevice::retire(VulkanTexture& t) {
    Garbage& g = currentGarbage();
    for (auto& v : t.views) g.views.push_back(v.second);
    for (VkImageView v : t.attachmentViews)
        if (v) g.views.push_back(v);
    if (!t.external) {  // a host's image and its view are the host's to destroy
        g.images.push_back(t.image);
        g.memories.push_back(t.memory);
        g.memoryBytes += t.memoryBytes;
    }
    t = VulkanTexture{};
}

void VulkanDevice::retire(VulkanBuffer& b, Garbage& g) {
    g.buffers.push_back(b.buffer);
    g.memories.push_back(b.alloc.memory);  // freeing unmaps
    g.memoryBytes += b.alloc.size;
    b = VulkanBuffer{};
}

void VulkanDevice::releaseGarbage(Garbage& g) {
    for (VkPipeline p : g.pipelines) vk_.vkDestroyPipeline(device_, p, nullptr);
    for (VkPipelineLayout p : g.pipelineLayouts) vk_.vkDestroyPipelineLayout(device_, p, nullptr);
    for (VkDescriptorSetLayout s : g.setLayouts) vk_.vkDestroyDescriptorSetLayout(device_, s, nullptr);
    for (VkShaderModule m : g.modules) vk_.vkDestroyShaderModule(device_, m, nullptr);
    for (VkImageView v : g.views) vk_.vkDestroyImageView(device_, v, nullptr);
    imageViewCount_.remove(g.views.size());
    for (VkImage i : g.images) vk_.vkDestroyImage(device_, i, nullptr);
    for (VkBuffer b : g.buffers) vk_.vkDestroyBuffer(device_, b, nullptr);
    for (VkDeviceMemory m : g.memories) vk_.vkFreeMemory(device_, m, nullptr);
    memoryCount_.remove(g.memories.size());
    memoryBytes_ -= g.memoryBytes;
    for (VkSampler s : g.samplers) vk_.vkDestroySampler(device_, s, nullptr);
    for (VkDescriptorPool p : g.descriptorPools) vk_.vkDestroyDescriptorPool(device_, p, nullptr);
    descriptorPoolCount_.remove(g.descriptorPools.size());
    descriptorSetCount_.remove(g.descriptorSets);
    // No command buffer that executed them is pending any more: they can be begun again.
    freeSecondaries_.insert(freeSecondaries_.end(), g.secondaries.begin(), g.secondaries.end());
    g = Garbage{};
}

void VulkanDevice::retire(VulkanPipeline& p) {
    Garbage& g = currentGarbage();
    if (p.pipeline) g.pipelines.push_back(p.pipeline);
    if (p.layout) g.pipelineLayouts.push_back(p.layout);
    if (p.setLayout) g.setLayouts.push_back(p.setLayout);
    p = VulkanPipeline{};
}

// Destroyed objects wait in pending_ until the commands recorded with them have run; with
// nothing recording (and no host command buffer) that is now.
void VulkanDevice::releaseIdleGarbage() {
    if (!recording_ && !hostCommandBuffer_) releaseGarbage(pending_);
}

void VulkanDevice::shutdown() {
    if (device_) {
        hostCommandBuffer_ = VK_NULL_HANDLE;
        // The host owns its queue's other work; waiting on our queue is enough for our objects.
        if (recording_) {
            vk_.vkEndCommandBuffer(commandBuffer_);
            recording_ = false;
        }
        if (ownsDevice_)
            vk_.vkDeviceWaitIdle(device_);
        else
            vk_.vkQueueWaitIdle(queue_);
        releaseGarbage(pending_);
        releaseGarbage(hostPending_);
        destroyStaging();
        clearSetCache();
        textures_.forEachAlive([&](VulkanTexture& t) { retire(t); });
        buffers_.forEachAlive([&](VulkanBuffer& b) { retire(b, pending_); });
        samplers_.forEachAlive([&](VulkanSampler& s) { pending_.samplers.push_back(s.sampler); });
        pipelines_.forEachAlive([&](VulkanPipeline& p) { retire(p); });
        programs_.forEachAlive([&](VulkanProgram& p) {
            for (auto& m : p.modules) pending_.modules.push_back(m.second);
        });
        releaseGarbage(pending_);
        if (queryPool_) vk_.vkDestroyQueryPool(device_, queryPool_, nullptr);
        if (defaultSampler_) vk_.vkDestroySampler(device_, defaultSampler_, nullptr);
        if (fence_) vk_.vkDestroyFence(device_, fence_, nullptr);
        if (commandPool_) vk_.vkDestroyCommandPool(device_, commandPool_, nullptr);
        if (ownsDevice_) vk_.vkDestroyDevice(device_, nullptr);
        device_ = VK_NULL_HANDLE;
    }
    if (messenger_ && vk_.vkDestroyDebugUtilsMessengerEXT) vk_.vkDestroyDebugUtilsMessengerEXT(setup_.instance, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
    if (setup_.ownsInstance && setup_.instance) vk_.vkDestroyInstance(setup_.instance, nullptr);
    setup_.instance = VK_NULL_HANDLE;
    closeLoader(setup_.loaderLibrary);
}

}  // namespace sfx::vulkan
