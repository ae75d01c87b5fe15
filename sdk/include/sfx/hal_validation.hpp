// Checks of HAL descriptions shared by every backend, so a bad argument gets the same code and
// message on Vulkan, GL and the null device. Backends call these before touching their API.
#pragma once

#include "sfx/hal.hpp"

namespace sfx::validation {

Status textureDesc(const TextureDesc& desc, const DeviceCaps& caps);
Status bufferDesc(const BufferDesc& desc, const DeviceCaps& caps);
Status samplerDesc(const SamplerDesc& desc);
// Stage makeup, dialect present, storage/compute allowed by caps.
Status program(const CompiledProgram& program, const DeviceCaps& caps);
Status graphicsPipelineShape(const GraphicsPipelineDesc& desc, const DeviceCaps& caps);
Status mipRange(const TextureDesc& desc, uint32_t mip, const char* argument);
Status textureBytes(const TextureDesc& desc, uint32_t mip, size_t bytes, const char* argument);
Status bufferRange(const BufferDesc& desc, uint64_t offset, uint64_t bytes, const char* argument);
Status dispatchGroups(const DispatchDesc& dispatch, const DeviceCaps& caps);
// A draw may not sample a mip its pass renders to (a feedback loop: undefined on GL, a layout
// conflict on Vulkan). Handles are compared as values, so call after checking them.
Status noFeedbackLoop(const RenderPassDesc& pass, const DrawDesc& draw);

}  // namespace sfx::validation
