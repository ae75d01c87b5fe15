// The checks of every HAL call, shared by every backend, so a bad argument gets the same code and
// message on Vulkan, GL and the null device. Device's front end (hal_device.cpp) calls them, in
// one order, with the descriptions the backend keeps (the program's reflection, the pipeline's
// formats, the bound textures' and buffers' descriptions: ObjectLookup), before any backend work. Codes and messages come from the one table of
// sfx/validation_errors.hpp. Descriptions and reads/writes: hal_validation.cpp; render passes,
// draws, dispatches and bindings: hal_validation_commands.cpp.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sfx/hal.hpp"
#include "sfx/validation_errors.hpp"

namespace sfx::validation {

// What the validation knows of a program: kept by the backend from createProgram.
struct ProgramInfo {
    std::string name;
    bool compute = false;
    std::vector<ShaderResource> resources;
};
ProgramInfo programInfo(const CompiledProgram& program);

// What the validation knows of a pipeline: kept by the backend from pipeline creation, so draws
// are checked against the program's reflection and the formats the pipeline was made for.
struct PipelineInfo {
    bool compute = false;
    std::string programName;
    std::vector<ShaderResource> resources;
    std::vector<Format> colorFormats;
    Format depthFormat = Format::Undefined;
    VertexLayout vertexLayout;
};
// The program is of the pipeline's kind, then graphicsPipelineShape and graphicsPipelineState.
Result<PipelineInfo> graphicsPipeline(const GraphicsPipelineDesc& desc, const ProgramInfo& program, const DeviceCaps& caps);
// Compute: the program is a compute program and the desc's specialisation constants have distinct ids.
Result<PipelineInfo> computePipeline(const ComputePipelineDesc& desc, const ProgramInfo& program);

Status textureDesc(const TextureDesc& desc, const DeviceCaps& caps);
Status bufferDesc(const BufferDesc& desc, const DeviceCaps& caps);
Status samplerDesc(const SamplerDesc& desc);
// Stage makeup, dialect present, storage/compute allowed by caps.
Status program(const CompiledProgram& program, const DeviceCaps& caps);
// Attachment formats, and a vertex layout whose every attribute lies inside the stride at a
// location below kMaxVertexAttributes (64-bit sums, so a huge offset cannot wrap past the check).
Status graphicsPipelineShape(const GraphicsPipelineDesc& desc, const DeviceCaps& caps);

// Specialisation constants with distinct ids (SpecializationConstantIdTwice); `where` names the
// desc ("GraphicsPipelineDesc").
Status specializationConstants(const std::vector<SpecializationConstant>& constants, const char* where);

// Attribute locations every API offers (Vulkan maxVertexInputAttributes and GL_MAX_VERTEX_ATTRIBS
// are at least 16), and the smallest stride limit among them (maxVertexInputBindingStride and
// GL_MAX_VERTEX_ATTRIB_STRIDE are at least 2048).
constexpr uint32_t kMaxVertexAttributes = 16;
constexpr uint32_t kMaxVertexStride = 2048;
uint32_t vertexFormatBytes(VertexFormat format);  // 0 for an unknown format
// One past the last byte any attribute of the layout reads within a vertex; 0 without attributes.
uint64_t vertexAttributeEnd(const VertexLayout& layout);

// The fixed-function state: cull, depth compare, blend factors known enumerators, and no blending
// into an integer colour format. Every backend calls it at pipeline creation, so an unknown value
// is refused the same way everywhere instead of mapping to a default on one API.
Status graphicsPipelineState(const GraphicsPipelineDesc& desc, const DeviceCaps& caps);

Status mipRange(const TextureDesc& desc, uint32_t mip, std::string_view argument);
Status textureBytes(const TextureDesc& desc, uint32_t mip, size_t bytes, std::string_view argument);
Status bufferRange(const BufferDesc& desc, uint64_t offset, uint64_t bytes, std::string_view argument);
// A host pointer a read or write needs; `what` says what it points to ("the level's bytes").
Status pointer(const void* p, std::string_view argument, std::string_view what);
// The range a buffer binding covers: its size, or the rest of the buffer when size is 0.
uint64_t boundSize(const BufferBinding& binding, const BufferDesc& buffer);

// The backend's objects as the front end's checks read them (Device::objects()): each call
// checks the handle (null, foreign, unknown, destroyed) and gives the description the object was
// made with.
class ObjectLookup {
public:
    virtual ~ObjectLookup() = default;
    virtual Result<const TextureDesc*> texture(TextureHandle h, const std::string& argument) const = 0;
    virtual Result<const BufferDesc*> buffer(BufferHandle h, const std::string& argument) const = 0;
    virtual Result<const SamplerDesc*> sampler(SamplerHandle h, const std::string& argument) const = 0;
    virtual Result<const ProgramInfo*> program(ProgramHandle h, const std::string& argument) const = 0;
    virtual Result<const PipelineInfo*> pipeline(PipelineHandle h, const std::string& argument) const = 0;
    virtual Status timer(TimerHandle h, const std::string& argument) const = 0;
    // Only a device that keeps recordings has any: the front end asks after caps().reusableRecordings.
    virtual Status recording(RecordingHandle h, const std::string& argument) const = 0;
};

// The recordings of a device that keeps none: every handle is unknown to it.
struct NoRecordings {
    Status check(RecordingHandle, const std::string& argument) const {
        return {StatusCode::InvalidHandle, argument + ": this device keeps no recordings"};
    }
};

// An ObjectLookup over a backend's HandlePools, whose records hold `desc` (textures, buffers)
// and `info` (programs, pipelines). A backend keeps one next to its pools.
template <class Textures, class Buffers, class Samplers, class Programs, class Pipelines, class Timers, class Recordings = NoRecordings>
class PoolLookup final : public ObjectLookup {
public:
    PoolLookup(const Textures& t, const Buffers& b, const Samplers& s, const Programs& pr, const Pipelines& p, const Timers& ti,
               const Recordings& r = noRecordings_)
        : textures_(t), buffers_(b), samplers_(s), programs_(pr), pipelines_(p), timers_(ti), recordings_(r) {}
    Result<const TextureDesc*> texture(TextureHandle h, const std::string& argument) const override {
        SFX_TRY(textures_.check(h, argument));
        return &textures_.get(h).desc;
    }
    Result<const BufferDesc*> buffer(BufferHandle h, const std::string& argument) const override {
        SFX_TRY(buffers_.check(h, argument));
        return &buffers_.get(h).desc;
    }
    Result<const SamplerDesc*> sampler(SamplerHandle h, const std::string& argument) const override {
        SFX_TRY(samplers_.check(h, argument));
        return &samplers_.get(h).desc;
    }
    Result<const ProgramInfo*> program(ProgramHandle h, const std::string& argument) const override {
        SFX_TRY(programs_.check(h, argument));
        return &programs_.get(h).info;
    }
    Result<const PipelineInfo*> pipeline(PipelineHandle h, const std::string& argument) const override {
        SFX_TRY(pipelines_.check(h, argument));
        return &pipelines_.get(h).info;
    }
    Status timer(TimerHandle h, const std::string& argument) const override { return timers_.check(h, argument); }
    Status recording(RecordingHandle h, const std::string& argument) const override { return recordings_.check(h, argument); }

private:
    static constexpr NoRecordings noRecordings_{};
    const Textures& textures_;
    const Buffers& buffers_;
    const Samplers& samplers_;
    const Programs& programs_;
    const Pipelines& pipelines_;
    const Timers& timers_;
    const Recordings& recordings_;
};
// The PoolLookup of a backend's six pools (and its recordings, where it keeps them).
template <class Textures, class Buffers, class Samplers, class Programs, class Pipelines, class Timers>
PoolLookup<Textures, Buffers, Samplers, Programs, Pipelines, Timers> poolLookup(const Textures& t, const Buffers& b, const Samplers& s,
                                                                                const Programs& pr, const Pipelines& p, const Timers& ti) {
    return {t, b, s, pr, p, ti};
}
template <class Textures, class Buffers, class Samplers, class Programs, class Pipelines, class Timers, class Recordings>
PoolLookup<Textures, Buffers, Samplers, Programs, Pipelines, Timers, Recordings> poolLookup(const Textures& t, const Buffers& b, const Samplers& s,
                                                                                            const Programs& pr, const Pipelines& p, const Timers& ti,
                                                                                            const Recordings& r) {
    return {t, b, s, pr, p, ti, r};
}

// Every check of a render pass and its draws, before anything is recorded: the attachments (at
// least one, within maxColorAttachments, render targets of the right kind, known load ops, one
// size); each draw's pipeline (graphics, made for the pass's formats), its bindings against the
// program's reflection and the bound resources (see dispatch), no feedback loop, its vertex and
// index buffers; and no texture mip used two ways in the pass. What a draw reads from its buffers
// stays inside them. Non-indexed: the last vertex's attributes, (count - 1) * stride +
// vertexAttributeEnd, lie inside the vertex buffer. Indexed: the count 32-bit indices lie inside
// the index buffer (the vertices the index values name are the API's robustness's business:
// robustBufferAccess on Vulkan).
Status renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws, const ObjectLookup& objects, const DeviceCaps& caps);
// Every check of a dispatch: the device has compute, group counts, a compute pipeline, and its
// bindings: each given once, at a binding of the program's reflection, of the resource kind the
// program has there, every reflected resource given; textures with usage sampled (storage images:
// storage) and mips inside them; buffers with the usage of their kind, ranges inside them, offsets
// aligned to caps.limits, ranges within the limits and at least the reflected block's size.
Status dispatch(const DispatchDesc& dispatch, const ObjectLookup& objects, const DeviceCaps& caps);

}  // namespace sfx::validation
