// Descriptors: set and pipeline layouts from a program's reflection, a BindingSet resolved into
// descriptor writes (its checks are in vulkan_checks.cpp), and the descriptor-set cache: a set is
// written once per distinct (set layout, descriptors) and reused by every later draw or dispatch
// that binds the same, so a steady frame allocates and updates none. A cached set is never
// written again, so command buffers still in flight may keep using it. The cache is cleared
// (its pools destroyed once the GPU is done) when a texture, buffer, sampler or pipeline it may
// name is destroyed, or when it grows past kMaxCachedSets.
#include <algorithm>

#include "sfx/hal_validation.hpp"
#include "vulkan_checks.hpp"
#include "vulkan_device_impl.hpp"
#include "vulkan_formats.hpp"

namespace sfx::vulkan {

namespace {
constexpr size_t kMaxCachedSets = 4096;
}

Status VulkanDevice::resolveBindings(const BindingSet& set, const VulkanPipeline& pl, const char* what,
                                     Uses& uses, ResolvedBindings& out) {
    out.images.reserve(set.textures.size() + set.storageImages.size());
    out.buffers.reserve(set.uniformBuffers.size() + set.storageBuffers.size());
    ReflectionMatch reflection(pl);
    auto write = [&](uint32_t binding, VkDescriptorType type) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstBinding = binding;
        w.descriptorCount = 1;
        w.descriptorType = type;
        out.writes.push_back(w);
        return &out.writes.back();
    };
    (void)what;

    for (const TextureBinding& tb : set.textures) {
        SFX_TRY(textures_.check(tb.texture, "TextureBinding.texture"));
        VulkanTexture& t = textures_.get(tb.texture);
        SFX_TRY(validation::textureBinding(t.desc, tb));
        VkSampler sampler = defaultSampler_;
        if (!tb.sampler.isNull()) {
            SFX_TRY(samplers_.check(tb.sampler, "TextureBinding.sampler"));
            sampler = samplers_.get(tb.sampler);
        }
        Result<const ShaderResource*> r = reflection.claim(tb.binding, ResourceKind::SampledTexture, "TextureBinding");
        if (!r) return r.status();
        Result<VkImageView> view = sampledView(t, tb.baseMip, tb.mipCount);
        if (!view) return view.status();
        out.images.push_back({sampler, view.value(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        write(tb.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER)->pImageInfo = &out.images.back();
        uses.images.push_back({&t, tb.baseMip, tb.mipCount, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                               shaderStages(r.value()->stages, pl.compute), VK_ACCESS_SHADER_READ_BIT, false});
    }
    for (const StorageImageBinding& sb : set.storageImages) {
        SFX_TRY(textures_.check(sb.texture, "StorageImageBinding.texture"));
        VulkanTexture& t = textures_.get(sb.texture);
        SFX_TRY(validation::mipRange(t.desc, sb.mip, "StorageImageBinding.mip"));
        Result<const ShaderResource*> r = reflection.claim(sb.binding, ResourceKind::StorageImage, "StorageImageBinding");
        if (!r) return r.status();
        SFX_TRY(checkStorageImageUsage(t.desc));
        Result<VkImageView> view = storageView(t, sb.mip);
        if (!view) return view.status();
        out.images.push_back({VK_NULL_HANDLE, view.value(), VK_IMAGE_LAYOUT_GENERAL});
        write(sb.binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE)->pImageInfo = &out.images.back();
        uses.images.push_back({&t, sb.mip, 1, VK_IMAGE_LAYOUT_GENERAL, shaderStages(r.value()->stages, pl.compute),
                               VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, true});
    }
    auto buffers = [&](const std::vector<BufferBinding>& list, ResourceKind kind, uint32_t usageBit,
                       uint64_t alignment, uint64_t maxRange) -> Status {
        for (const BufferBinding& bb : list) {
            SFX_TRY(buffers_.check(bb.buffer, "BufferBinding.buffer"));
            VulkanBuffer& b = buffers_.get(bb.buffer);
            Result<const ShaderResource*> r = reflection.claim(bb.binding, kind, "BufferBinding");
            if (!r) return r.status();
            Result<uint64_t> size = checkBufferBinding(b.desc, bb, kind, usageBit, *r.value(), alignment, maxRange);
            if (!size) return size.status();
            out.buffers.push_back({b.buffer, bb.offset, size.value()});
            write(bb.binding, toVkDescriptor(kind))->pBufferInfo = &out.buffers.back();
            const bool storage = kind == ResourceKind::StorageBuffer;
            uses.buffers.push_back({&b, shaderStages(r.value()->stages, pl.compute),
                                    storage ? VkAccessFlags(VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT)
                                            : VkAccessFlags(VK_ACCESS_UNIFORM_READ_BIT),
                                    storage});
        }
        return Status::ok();
    };
    SFX_TRY(buffers(set.uniformBuffers, ResourceKind::UniformBuffer, kBufferUniform,
                    props_.limits.minUniformBufferOffsetAlignment, props_.limits.maxUniformBufferRange));
    SFX_TRY(buffers(set.storageBuffers, ResourceKind::StorageBuffer, kBufferStorage,
                    props_.limits.minStorageBufferOffsetAlignment, props_.limits.maxStorageBufferRange));
    return reflection.allClaimed();
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
        if (fresh || (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL))
            return vkError("vkAllocateDescriptorSets", r);
        ++currentPool_;  // full: move on to the next (or a new) pool
    }
}

void VulkanDevice::clearSetCache() {
    Garbage& g = currentGarbage();
    g.descriptorPools.insert(g.descriptorPools.end(), descriptorPools_.begin(), descriptorPools_.end());
    g.descriptorSets += setCache_.size();
    descriptorPools_.clear();
    currentPool_ = 0;
    setCache_.clear();
}

Result<VkDescriptorSet> VulkanDevice::writeSet(const VulkanPipeline& pl, ResolvedBindings& resolved) {
    if (pl.resources.empty()) return VkDescriptorSet(VK_NULL_HANDLE);
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
