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
// Attachment formats, and a vertex layout whose every attribute lies inside the stride at a
// location below kMaxVertexAttributes (64-bit sums, so a huge offset cannot wrap past the check).
Status graphicsPipelineShape(const GraphicsPipelineDesc& desc, const DeviceCaps& caps);

// Specialisation constants with distinct ids; `where` names the desc ("GraphicsPipelineDesc").
Status specializationConstants(const std::vector<SpecializationConstant>& constants, const char* where);

// Attribute locations every API offers (Vulkan maxVertexInputAttributes and GL_MAX_VERTEX_ATTRIBS
// are at least 16), and the smallest stride limit among them (maxVertexInputBindingStride and
// GL_MAX_VERTEX_ATTRIB_STRIDE are at least 2048).
constexpr uint32_t kMaxVertexAttributes = 16;
constexpr uint32_t kMaxVertexStride = 2048;
uint32_t vertexFormatBytes(VertexFormat format);  // 0 for an unknown format
// One past the last byte any attribute of the layout reads within a vertex; 0 without attributes.
uint64_t vertexAttributeEnd(const VertexLayout& layout);

// What a draw reads from its buffers stays inside them. Non-indexed: the last vertex's attributes,
// (count - 1) * stride + vertexAttributeEnd, lie inside vertexBuffer. Indexed: the count 32-bit
// indices lie inside indexBuffer (the vertices the index values name are the API's robustness's
// business: robustBufferAccess on Vulkan). Pass the descriptions of the draw's buffers, null where
// the draw has none; call after checking the handles.
Status drawRange(const DrawDesc& draw, const VertexLayout& layout, const BufferDesc* vertexBuffer,
                 const BufferDesc* indexBuffer);
// The fixed-function state: cull, depth compare, blend factors known enumerators, and no blending
// into an integer colour format. Every backend calls it at pipeline creation, so an unknown value
// is refused the same way everywhere instead of mapping to a default on one API.
Status graphicsPipelineState(const GraphicsPipelineDesc& desc, const DeviceCaps& caps);
// A texture binding's mips, baseMip and mipCount, make a non-empty range inside the texture's
// levels (checked without the 32-bit sum, which wraps), and the texture has kTextureSampled.
Status textureBinding(const TextureDesc& texture, const TextureBinding& binding);
Status mipRange(const TextureDesc& desc, uint32_t mip, const char* argument);
Status textureBytes(const TextureDesc& desc, uint32_t mip, size_t bytes, const char* argument);
Status bufferRange(const BufferDesc& desc, uint64_t offset, uint64_t bytes, const char* argument);
Status dispatchGroups(const DispatchDesc& dispatch, const DeviceCaps& caps);
// A draw may not sample a mip its pass renders to (a feedback loop: undefined on GL, a layout
// conflict on Vulkan). Handles are compared as values, so call after checking them.
Status noFeedbackLoop(const RenderPassDesc& pass, const DrawDesc& draw);

}  // namespace sfx::validation
