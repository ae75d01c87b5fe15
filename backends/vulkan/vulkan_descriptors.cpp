// Descriptors: set and pipeline layouts from a program's reflection, a BindingSet resolved into
// descriptor writes (checked before by the shared validation), and the descriptor-set cache: a
// set is written once per distinct (set layout, descriptors) and reused by every later draw or
// dispatch that binds the same, so a steady frame allocates and updates none. A cached set is
// never written again, so command buffers still in flight may keep using it. The cache is
// cleared (its pools destroyed once the GPU is done) when a texture, buffer, sampler or pipeline
// it may name is destroyed, or when it grows past kMaxCachedSets.
#include <algorithm>

#include "sfx/hal_validation.hpp"
#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

namespace sfx::vulkan {

namespace {
constexpr size_t kMaxCachedSets = 4096;

// The pipeline stages that read or write `binding` of `kind`, from the program's reflection
// (the shared validation has matched every binding to a resource before).
VkPipelineStageFlags bindingStages(const VulkanPipeline& pl, uint32_t binding, ResourceKind kind) {
    for (const ShaderResource& r : pl.info.resources)
        if (r.binding == binding && r.kind == kind) return shaderStages(r.stages, pl.info.compute);
    return shaderStages(0, pl.info.compute);
}
}  // namespace

Status VulkanDevice::resolveBindings(const BindingSet& set, const VulkanPipeline& pl, Uses& uses, ResolvedBindings& out) {
    // Reserved up front: the writes point into images and buffers. `out` is the device's
    // scratch: cleared, its capacity kept.
    out.images.clear();
    out.buffers.clear();
    out.writes.clear();
    out.images.reserve(set.textures.size() + set.storageImages.size());
    out.buffers.reserve(set.uniformBuffers.size() + set.storageBuffers.size());
    auto write = [&](uint32_t binding, VkDescriptorType type) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstBinding = binding;
        w.descriptorCount = 1;
        w.descriptorType = type;
        out.writes.push_back(w);
        return &out.writes.back();
    };
    for (const TextureBinding& tb : set.textures) {
        VulkanTexture& t = textures_.get(tb.texture);
        const VkSampler sampler = tb.sampler.isNull() ? defaultSampler_ : samplers_.get(tb.sampler).sampler;
        Result<VkImageView> view = sampledView(t, tb.baseMip, tb.mipCount);
        if (!view) return view.status();
        out.images.push_back({sampler, view.value(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        write(tb.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)->pImageInfo = &out.images.back();
        uses.images.push_back({&t, tb.baseMip, tb.mipCount, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               bindingStages(pl, tb.binding, ResourceKind::SampledTexture), VK_ACCESS_SHADER_READ_BIT, false});
    }
    for (const StorageImageBinding& sb : set.storageImages) {
        VulkanTexture& t = textures_.get(sb.texture);
        Result<VkImageView> view = storageView(t, sb.mip);
        if (!view) return view.status();
        out.images.push_back({VK_NULL_HANDLE, view.value(), VK_IMAGE_LAYOUT_GENERAL});
        write(sb.binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)->pImageInfo = &out.images.back();
        uses.images.push_back({&t, sb.mip, 1, VK_IMAGE_LAYOUT_GENERAL, bindingStages(pl, sb.binding, ResourceKind::StorageImage),
                               VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, true});
    }
    auto buffers = [&](const std::vector<BufferBinding>& list, ResourceKind kind) {
        for (const BufferBinding& bb : list) {
            VulkanBuffer& b = buffers_.get(bb.buffer);
            out.buffers.push_back({b.buffer, bb.offset, validation::boundSize(bb, b.desc)});
            write(bb.binding, toVkDescriptor(kind))->pBufferInfo = &out.buffers.back();
            const bool storage = kind == ResourceKind::StorageBuffer;
            uses.buffers.push_back(
                {&b, bindingStages(pl, bb.binding, kind),
                 storage ? VkAccessFlags(VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT) : VkAccessFlags(VK_ACCESS_UNIFORM_READ_BIT),
                 storage});
        }
    };
    buffers(set.uniformBuffers, ResourceKind::UniformBuffer);
    buffers(set.storageBuffers, ResourceKind::StorageBuffer);
    return Status::ok();
}

Result<VkDescriptorSet> VulkanDevice::allocateSet(VkDescriptorSetLayout layout) {
    for (;;) {
        const bool fresh = currentPool_ == descriptorPools_.size();
        if (fresh) {
            const VkDescriptorPoolSize sizes[] = {
                {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kDescriptorPoolSets * 4},
                {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kDescriptorPoolSets * 8},
                {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kDescriptorPoolSets * 4},
                {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kDescriptorPoolSets * 2},
            };
            VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
            pci.maxSets = kDescriptorPoolSets;
            pci.poolSizeCount = 4;
            pci.pPoolSizes = sizes;
            VkDescriptorPool pool;
            SFX_VK(vk_.vkCreateDescriptorPool(device_, &pci, nullptr, &pool));
            descriptorPools_.push_back(pool);
            descriptorPoolCount_.add();
        }
        VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
        ai.descriptorPool = descriptorPools_[currentPool_];
        ai.descriptorSetCount = 1;
        ai.pSetLayouts = &layout;
        VkDescriptorSet set;
        VkResult r = vk_.vkAllocateDescriptorSets(device_, &ai, &set);
        if (r == VK_SUCCESS) {
            descriptorSetCount_.add();
            return set;
        }
        // A new pool that cannot hold one set never will: stop rather than loop.
        if (fresh || (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL)) return vkError("vkAllocateDescriptorSets", r);
        ++currentPool_;  // full: move on to the next (or a new) pool
    }
}

void VulkanDevice::clearSetCache() {
    changeObjects();  // recordings may have bound the sets
    Garbage& g = currentGarbage();
    g.descriptorPools.insert(g.descriptorPools.end(), descriptorPools_.begin(), descriptorPools_.end());
    g.descriptorSets += setCache_.size();
    descriptorPools_.clear();
    currentPool_ = 0;
    setCache_.clear();
}

Result<VkDescriptorSet> VulkanDevice::writeSet(const VulkanPipeline& pl, ResolvedBindings& resolved) {
    if (pl.info.resources.empty()) return VkDescriptorSet(VK_NULL_HANDLE);
    // The key: the set layout and every descriptor, in binding order of the writes.
    setKey_.clear();
    setKey_.push_back(uint64_t(pl.setLayout));
    for (const VkWriteDescriptorSet& w : resolved.writes) {
        setKey_.push_back((uint64_t(w.dstBinding) << 32) | uint64_t(w.descriptorType));
        if (w.pImageInfo) {
            setKey_.push_back(uint64_t(w.pImageInfo->sampler));
            setKey_.push_back(uint64_t(w.pImageInfo->imageView));
            setKey_.push_back(uint64_t(w.pImageInfo->imageLayout));
        } else {
            setKey_.push_back(uint64_t(w.pBufferInfo->buffer));
            setKey_.push_back(w.pBufferInfo->offset);
            setKey_.push_back(w.pBufferInfo->range);
        }
    }
    auto it = setCache_.find(setKey_);
    if (it != setCache_.end()) return it->second;
    if (setCache_.size() >= kMaxCachedSets) clearSetCache();
    Result<VkDescriptorSet> set = allocateSet(pl.setLayout);
    if (!set) return set.status();
    for (VkWriteDescriptorSet& w : resolved.writes) w.dstSet = set.value();
    vk_.vkUpdateDescriptorSets(device_, uint32_t(resolved.writes.size()), resolved.writes.data(), 0, nullptr);
    setCache_.emplace(setKey_, set.value());
    return set.value();
}

Status VulkanDevice::createLayouts(const std::vector<ShaderResource>& resources, bool compute, VulkanPipeline& out) {
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const ShaderResource& r : resources) {
        VkDescriptorSetLayoutBinding b{};
        b.binding = r.binding;
        b.descriptorType = toVkDescriptor(r.kind);
        b.descriptorCount = 1;
        b.stageFlags = toVkStages(r.stages);
        if (!b.stageFlags) b.stageFlags = compute ? VK_SHADER_STAGE_COMPUTE_BIT : VK_SHADER_STAGE_ALL_GRAPHICS;
        bindings.push_back(b);
    }
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = uint32_t(bindings.size());
    lci.pBindings = bindings.data();
    SFX_VK(vk_.vkCreateDescriptorSetLayout(device_, &lci, nullptr, &out.setLayout));
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &out.setLayout;
    SFX_VK(vk_.vkCreatePipelineLayout(device_, &plci, nullptr, &out.layout));
    return Status::ok();
}

}  // namespace sfx::vulkan
