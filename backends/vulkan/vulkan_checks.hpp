// The checks the Vulkan backend makes on its own rather than through sfx::validation (see the
// list at the top of vulkan_checks.cpp). They are kept together so that they can move into the
// shared validation as one piece.
#pragma once

#include <cstdint>
#include <vector>

#include "sfx/handle.hpp"
#include "vulkan_objects.hpp"

namespace sfx::vulkan {

// Binding versus reflection: each binding of a BindingSet is given once, names a resource the
// pipeline's program reflects, of the kind the binding is; every reflected resource is given.
class ReflectionMatch {
public:
    explicit ReflectionMatch(const VulkanPipeline& pipeline) : pipeline_(pipeline) {}
    // The reflected resource at `binding`, of `kind`; InvalidArgument names what is wrong.
    Result<const ShaderResource*> claim(uint32_t binding, ResourceKind kind, const char* arg);
    // InvalidArgument naming the first reflected resource no binding claimed.
    Status allClaimed() const;

private:
    const VulkanPipeline& pipeline_;
    std::vector<uint32_t> given_;
};

// A storage image binding's texture has kTextureStorage.
Status checkStorageImageUsage(const TextureDesc& desc);

// A uniform or storage buffer binding against the buffer and the reflected block: usage, range,
// offset alignment, the API's largest range, and at least the block's size. Returns the bound size.
Result<uint64_t> checkBufferBinding(const BufferDesc& buffer, const BufferBinding& binding, ResourceKind kind,
                                    uint32_t usageBit, const ShaderResource& block, uint64_t alignment,
                                    uint64_t maxRange);

// Attachments of a render pass: at least one, no more than the caps allow, render targets of
// the right kind, known load ops, one size. Fills `out` with their formats and layouts.
Status checkAttachments(const RenderPassDesc& pass, HandlePool<TextureTag, VulkanTexture>& textures,
                        const DeviceCaps& caps, PassTargets& out);
// A draw's pipeline was made for the pass's attachment formats.
Status checkPipelineAttachments(const VulkanPipeline& pipeline, const PassTargets& targets);

// Two uses of one mip in different layouts within a command cannot both hold.
Status checkLayoutConflicts(const std::vector<ImageUse>& uses);

}  // namespace sfx::vulkan
