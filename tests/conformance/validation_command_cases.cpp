// The invalid calls of the validation parity test for pipelines, reads and writes, timers, render
// passes, draws, dispatches and bindings, and the checks only one API makes.
#include <catch2/catch.hpp>

#include "sfx_shaders.hpp"
#include "sfx_test_shaders.hpp"
#include "validation_cases.hpp"

namespace sfx::test {
namespace {

using validation::Error;
using Caps = DeviceCaps;

bool compute(const Caps& c) { return c.computeShaders && c.storageBuffers && c.storageImages; }
bool noCompute(const Caps& c) { return !c.computeShaders; }
bool isVulkan(const Caps& c) { return c.backend == BackendKind::Vulkan; }
bool isGl(const Caps& c) { return c.backend == BackendKind::GL || c.backend == BackendKind::GLES; }

// A pass into one 8x8 RGBA8 target with one draw.
Status drawOnce(Objects& o, const DrawDesc& draw) {
    RenderPassDesc pass;
    pass.colors = {{o.texture(8, 8, Format::RGBA8, kRenderable), 0}};
    return o.dev.renderPass(pass, {&draw, 1});
}
DrawDesc copyDraw(Objects& o) {
    DrawDesc d;
    d.pipeline = o.graphics("copy", {Format::RGBA8});
    d.bindings.textures = {{gen::copy::uSource, o.texture(8, 8, Format::RGBA8, kTextureSampled)}};
    return d;
}
Status tryPipeline(Objects& o, GraphicsPipelineDesc d, const char* program = "hal_test_pattern") {
    d.program = o.program(program, Tier::Current);
    Result<PipelineHandle> p = o.dev.createGraphicsPipeline(d);
    if (p.isOk()) (void)o.dev.destroyPipeline(p.value());
    return p.status();
}
Status tryMesh(Objects& o, VertexLayout layout) {
    GraphicsPipelineDesc d;
    d.colorFormats = {Format::RGBA8};
    d.vertexLayout = std::move(layout);
    return tryPipeline(o, d, "hal_test_mesh");
}
GraphicsPipelineDesc withState(auto change) {
    GraphicsPipelineDesc d;
    d.colorFormats = {Format::RGBA8};
    change(d);
    return d;
}
Status drawMesh(Objects& o, uint32_t count, uint64_t vertexBytes, uint64_t indexBytes = 0) {
    DrawDesc d;
    d.pipeline = o.graphics("hal_test_mesh", {Format::RGBA8}, Format::Undefined, meshLayout());
    d.vertexBuffer = o.buffer(vertexBytes, kBufferVertex);
    if (indexBytes) d.indexBuffer = o.buffer(indexBytes, kBufferIndex);
    d.count = count;
    return drawOnce(o, d);
}
Status drawUniform(Objects& o, uint64_t bufferBytes, uint32_t usage, uint64_t offset, uint64_t size) {
    DrawDesc d;
    d.pipeline = o.graphics("hal_test_uniform", {Format::RGBA8});
    d.bindings.uniformBuffers = {{gen::hal_test_uniform::ColorParams, o.buffer(bufferBytes, usage), offset, size}};
    return drawOnce(o, d);
}
Status passOf(Objects& o, RenderPassDesc pass) { return o.dev.renderPass(pass, {}); }
VertexLayout meshWith(auto change) {
    VertexLayout l = meshLayout();
    change(l);
    return l;
}
// hal_test_storage_image with a sampled texture added to its reflection: the shader does not read
// it, but the validation refuses the command before anything runs.
CompiledProgram storageAndSampled() {
    CompiledProgram p = shaderProgram("hal_test_storage_image", Tier::High);
    p.resources.push_back({"uExtra", "uExtra", ResourceKind::SampledTexture, 1, stageBit(ShaderStage::Compute), 0});
    return p;
}

}  // namespace

std::vector<ValidationCase> pipelineAndCommandCases() {
    std::vector<ValidationCase> v;
    auto add = [&](const char* what, Error rule, std::function<bool(const Caps&)> applies, std::function<std::string(const Caps&)> expected,
                   std::function<Status(Objects&)> call, bool (*onlyOn)(const Caps&) = nullptr) {
        v.push_back({what, rule, std::move(applies), std::move(expected), std::move(call), onlyOn});
    };
    auto fixed = [](std::string s) { return [s](const Caps&) { return s; }; };
    const std::string attr = "GraphicsPipelineDesc.vertexLayout.attributes";

    // ---- Pipelines -------------------------------------------------------------------------
    add("graphics pipeline of a compute program", Error::PipelineProgramCompute, compute,
        fixed("GraphicsPipelineDesc.program is compute program 'hal_atomic_count'; allowed a program with vertex and fragment stages"),
        [](Objects& o) {
            GraphicsPipelineDesc d;
            d.program = o.program("hal_atomic_count", Tier::High);
            d.colorFormats = {Format::RGBA8};
            return o.dev.createGraphicsPipeline(d).status();
        });
    add("compute pipeline of a graphics program", Error::PipelineProgramGraphics, {},
        fixed("ComputePipelineDesc.program is graphics program 'copy'; allowed a compute program"),
        [](Objects& o) { return o.dev.createComputePipeline({o.program("copy", Tier::Current)}).status(); });
    add(
        "too many colour formats", Error::PipelineColorCount, {},
        [](const Caps& c) {
            return "GraphicsPipelineDesc.colorFormats has " + str(c.limits.maxColorAttachments + 1) + " formats; allowed [0, " +
                str(c.limits.maxColorAttachments) + "]";
        },
        [](Objects& o) {
            return tryPipeline(o, withState([&](auto& d) { d.colorFormats.assign(o.dev.caps().limits.maxColorAttachments + 1, Format::RGBA8); }));
        });
    add(
        "depth format as colour", Error::PipelineColorFormat, {},
        [](const Caps& c) {
            return "GraphicsPipelineDesc.colorFormats[0] is D32F; allowed a colour format this device renders to: " +
                formatList([&](Format f) { return !isDepthFormat(f) && c.renderableFormat[size_t(f)]; });
        },
        [](Objects& o) { return tryPipeline(o, withState([](auto& d) { d.colorFormats = {Format::D32F}; })); });
    add("colour format as depth", Error::PipelineDepthFormat, {},
        fixed("GraphicsPipelineDesc.depthFormat is RGBA8; allowed Undefined, D16, D24S8 or D32F"),
        [](Objects& o) { return tryPipeline(o, withState([](auto& d) { d.depthFormat = Format::RGBA8; })); });
    add("no attachment formats", Error::PipelineNoAttachments, {},
        fixed("GraphicsPipelineDesc has no colour format and no depth format; allowed at least one of them"),
        [](Objects& o) { return tryPipeline(o, withState([](auto& d) { d.colorFormats.clear(); })); });
    add("attributes without a stride", Error::VertexStrideAttributes, {},
        fixed("GraphicsPipelineDesc.vertexLayout.stride is 0 with 2 attributes; allowed a stride above 0 exactly when attributes are given"),
        [](Objects& o) { return tryMesh(o, meshWith([](auto& l) { l.stride = 0; })); });
    add("stride over the limit", Error::VertexStrideMax, {}, fixed("GraphicsPipelineDesc.vertexLayout.stride is 4096; allowed [0, 2048]"),
        [](Objects& o) { return tryMesh(o, meshWith([](auto& l) { l.stride = 4096; })); });
    add("unknown attribute format", Error::VertexAttributeFormat, {}, fixed(attr + "[0].format is 7; allowed Float2, Float3 or Float4"),
        [](Objects& o) { return tryMesh(o, meshWith([](auto& l) { l.attributes[0].format = VertexFormat(7); })); });
    add("attribute location over the limit", Error::VertexAttributeLocation, {}, fixed(attr + "[0].location is 16; allowed [0, 15]"),
        [](Objects& o) { return tryMesh(o, meshWith([](auto& l) { l.attributes[0].location = 16; })); });
    add("attribute location twice", Error::VertexAttributeLocationTwice, {},
        fixed(attr + "[1].location is 0, which attributes[0] also has; allowed a location no other attribute uses"),
        [](Objects& o) { return tryMesh(o, meshWith([](auto& l) { l.attributes[1].location = 0; })); });
    add("attribute past the stride", Error::VertexAttributeOffset, {},
        fixed(attr + "[1].offset is 13; allowed [0, 12], so that its 16 bytes end within the stride of 28"),
        [](Objects& o) { return tryMesh(o, meshWith([](auto& l) { l.attributes[1].offset = 13; })); });
    add("offset that wraps in 32 bits", Error::VertexAttributeOffset, {},
        fixed(attr + "[1].offset is 4294967292; allowed [0, 12], so that its 16 bytes end within the stride of 28"),
        [](Objects& o) { return tryMesh(o, meshWith([](auto& l) { l.attributes[1].offset = 0xFFFFFFFCu; })); });
    add("unknown cull mode", Error::PipelineCull, {}, fixed("GraphicsPipelineDesc.cull is 3; allowed None, Back or Front"),
        [](Objects& o) { return tryPipeline(o, withState([](auto& d) { d.cull = CullMode(3); })); });
    add("unknown depth compare", Error::PipelineDepthCompare, {},
        fixed("GraphicsPipelineDesc.depth.compare is 99; allowed Never, Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual or Always"),
        [](Objects& o) { return tryPipeline(o, withState([](auto& d) { d.depth.compare = CompareOp(99); })); });
    add("unknown blend factor", Error::PipelineBlendFactor, {},
        fixed("GraphicsPipelineDesc.blend.dst is 2147483648; allowed Zero, One, SrcAlpha, OneMinusSrcAlpha, DstAlpha or OneMinusDstAlpha"),
        [](Objects& o) {
            return tryPipeline(o, withState([](auto& d) { d.blend = {true, BlendFactor::One, BlendFactor(0x80000000u)}; }));
        });
    add(
        "blending an integer target", Error::PipelineBlendInteger, [](const Caps& c) { return c.renderableFormat[size_t(Format::R32UI)]; },
        fixed("GraphicsPipelineDesc.blend.enable is true with the integer format R32UI in colorFormats[0]; allowed false, as integer "
              "targets do not blend"),
        [](Objects& o) {
            return tryPipeline(o, withState([](auto& d) {
                                   d.colorFormats = {Format::R32UI};
                                   d.blend = {true, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha};
                               }));
        });
    add(
        "blending a target the device cannot blend", Error::PipelineBlendFormat,
        [](const Caps& c) { return firstNonBlendableTarget(c) != Format::Undefined; },
        [](const Caps& c) {
            return std::string("GraphicsPipelineDesc.blend.enable is true with colorFormats[0] = ") + toString(firstNonBlendableTarget(c)) +
                ", which this device cannot blend; allowed blend.enable false, or a blendable format: " +
                formatList([&](Format f) { return c.blendableFormat[size_t(f)]; });
        },
        [](Objects& o) {
            return tryPipeline(o, withState([&](auto& d) {
                                   d.colorFormats = {firstNonBlendableTarget(o.dev.caps())};
                                   d.blend = {true, BlendFactor::One, BlendFactor::One};
                               }));
        });
    add("specialisation constant id twice", Error::SpecializationConstantIdTwice, {},
        fixed("GraphicsPipelineDesc.constants[2].id is 3, which constants[0] also has; allowed an id no other constant uses"), [](Objects& o) {
            return tryPipeline(o, withState([](auto& d) { d.constants = {{3, 1}, {4, 2}, {3, 5}}; }));
        });
    add("compute specialisation constant id twice", Error::SpecializationConstantIdTwice, compute,
        fixed("ComputePipelineDesc.constants[1].id is 0, which constants[0] also has; allowed an id no other constant uses"), [](Objects& o) {
            ComputePipelineDesc d;
            d.program = o.program("hal_atomic_count", Tier::High);
            d.constants = {{0, 1}, {0, 2}};
            return o.dev.createComputePipeline(d).status();
        });

    // ---- Reads, writes and timers ------------------------------------------------------------
    add("mip past the texture", Error::MipOutOfRange, {}, fixed("mip is 5; allowed [0, 1], the mips of the texture"), [](Objects& o) {
        std::vector<uint8_t> bytes(256);
        return o.dev.readTexture(o.texture(8, 8, Format::RGBA8, kRenderable, 2), 5, bytes.data(), bytes.size());
    });
    add("wrong level size", Error::TextureBytes, {}, fixed("bytes is 255; allowed 256, the size of mip 0 of a 8x8 RGBA8 texture"), [](Objects& o) {
        std::vector<uint8_t> bytes(256);
        return o.dev.writeTexture(o.texture(8, 8, Format::RGBA8, kTextureSampled), 0, bytes.data(), 255);
    });
    add("write past the buffer", Error::BufferRange, {},
        fixed("writeBuffer(offset, bytes) covers offset 8 + 9 bytes; allowed a non-empty range inside the buffer's 16 bytes"), [](Objects& o) {
            std::vector<uint8_t> bytes(16);
            return o.dev.writeBuffer(o.buffer(16, kBufferUniform), 8, bytes.data(), 9);
        });
    add("null data", Error::NullPointer, {}, fixed("data is null; allowed a pointer to the level's bytes"),
        [](Objects& o) { return o.dev.writeTexture(o.texture(8, 8, Format::RGBA8, kTextureSampled), 0, nullptr, 256); });
    add("null out", Error::NullPointer, {}, fixed("out is null; allowed a pointer to room for the bytes read"),
        [](Objects& o) { return o.dev.readBuffer(o.buffer(16, kBufferUniform), 0, nullptr, 16); });
    add("timer ended before it began", Error::TimerNotBegun, {}, fixed("endTimer: the timer was not begun; allowed after beginTimer"),
        [](Objects& o) {
            TimerHandle t = o.dev.createTimer().value();
            Status s = o.dev.endTimer(t);
            (void)o.dev.destroyTimer(t);
            return s;
        });
    add("timer read before a measurement", Error::TimerNoMeasurement, {},
        fixed("readTimer: the timer has no finished measurement; allowed after beginTimer, endTimer and flush"), [](Objects& o) {
            TimerHandle t = o.dev.createTimer().value();
            Status s = o.dev.readTimer(t).status();
            (void)o.dev.destroyTimer(t);
            return s;
        });

    // ---- Render passes -----------------------------------------------------------------------
    add("pass without attachments", Error::PassNoAttachments, {},
        fixed("RenderPassDesc has no attachments; allowed at least one colour or depth attachment"),
        [](Objects& o) { return o.dev.renderPass({}, {}); });
    add(
        "too many colour attachments", Error::PassColorCount, {},
        [](const Caps& c) {
            return "RenderPassDesc.colors has " + str(c.limits.maxColorAttachments + 1) + " attachments; allowed [0, " +
                str(c.limits.maxColorAttachments) + "]";
        },
        [](Objects& o) {
            RenderPassDesc pass;
            pass.colors.assign(o.dev.caps().limits.maxColorAttachments + 1, {o.texture(8, 8, Format::RGBA8, kRenderable), 0});
            return passOf(o, pass);
        });
    add("colour target without render-target", Error::PassColorTarget, {},
        fixed("RenderPassDesc.colors[0].texture is a RGBA8 texture with usage sampled; allowed a colour texture with usage render-target"),
        [](Objects& o) {
            RenderPassDesc pass;
            pass.colors = {{o.texture(8, 8, Format::RGBA8, kTextureSampled), 0}};
            return passOf(o, pass);
        });
    add("colour texture as depth", Error::PassDepthTarget, {},
        fixed("RenderPassDesc.depth.texture is a RGBA8 texture with usage render-target; allowed a depth texture with usage render-target"),
        [](Objects& o) {
            RenderPassDesc pass;
            pass.depth.texture = o.texture(8, 8, Format::RGBA8, kTextureRenderTarget);
            return passOf(o, pass);
        });
    add("unknown load op", Error::PassLoadOp, {}, fixed("RenderPassDesc.colors[0].load is 7; allowed Clear, Load or DontCare"), [](Objects& o) {
        RenderPassDesc pass;
        pass.colors = {{o.texture(8, 8, Format::RGBA8, kRenderable), 0, LoadOp(7)}};
        return passOf(o, pass);
    });
    add("attachments of two sizes", Error::PassSize, {},
        fixed("RenderPassDesc.colors[1].texture is 4x4 at mip 0; allowed 8x8, the size of the pass's first attachment"), [](Objects& o) {
            RenderPassDesc pass;
            pass.colors = {{o.texture(8, 8, Format::RGBA8, kRenderable), 0}, {o.texture(4, 4, Format::RGBA8, kRenderable), 0}};
            return passOf(o, pass);
        });

    // ---- Draws and dispatches ----------------------------------------------------------------
    add("draw with a compute pipeline", Error::DrawPipelineCompute, compute,
        fixed("DrawDesc.pipeline is a compute pipeline (program 'hal_atomic_count'); allowed a graphics pipeline"), [](Objects& o) {
            DrawDesc d;
            d.pipeline = o.compute("hal_atomic_count");
            return drawOnce(o, d);
        });
    add("dispatch of a graphics pipeline", Error::DispatchPipelineGraphics, compute,
        fixed("DispatchDesc.pipeline is a graphics pipeline (program 'copy'); allowed a compute pipeline"), [](Objects& o) {
            DispatchDesc d;
            d.pipeline = o.graphics("copy", {Format::RGBA8});
            return o.dev.dispatch(d);
        });
    add("pipeline for other formats", Error::DrawPipelineFormats, {},
        fixed("DrawDesc.pipeline was made for colour formats [RGBA8] and depth format Undefined; allowed a pipeline made for the pass's "
              "colour formats [RGBA8, RGBA8] and depth format Undefined"),
        [](Objects& o) {
            DrawDesc d = copyDraw(o);
            RenderPassDesc pass;
            pass.colors = {{o.texture(8, 8, Format::RGBA8, kRenderable), 0}, {o.texture(8, 8, Format::RGBA8, kRenderable), 0}};
            return o.dev.renderPass(pass, {&d, 1});
        });
    add("no instances", Error::DrawInstanceCount, {}, fixed("DrawDesc.instanceCount is 0; allowed [1, 4294967295]"), [](Objects& o) {
        DrawDesc d = copyDraw(o);
        d.instanceCount = 0;
        return drawOnce(o, d);
    });
    add("mesh without vertices", Error::DrawVertexBufferMissing, {},
        fixed("DrawDesc.vertexBuffer is null; allowed a buffer with usage vertex, as the pipeline has vertex attributes"), [](Objects& o) {
            DrawDesc d;
            d.pipeline = o.graphics("hal_test_mesh", {Format::RGBA8}, Format::Undefined, meshLayout());
            return drawOnce(o, d);
        });
    add("vertices for a full-screen pass", Error::DrawVertexBufferUnused, {},
        fixed("DrawDesc.vertexBuffer is set; allowed null, as the pipeline has no vertex attributes"), [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.vertexBuffer = o.buffer(84, kBufferVertex);
            return drawOnce(o, d);
        });
    add("indices past the index buffer", Error::DrawIndexCount, {},
        fixed("DrawDesc.count is 4; allowed [0, 3], the 32-bit indices in its index buffer of 12 bytes"),
        [](Objects& o) { return drawMesh(o, 4, 84, 12); });
    add("vertices past the vertex buffer", Error::DrawVertexCount, {},
        fixed("DrawDesc.count is 4; allowed [0, 3], the vertices of stride 28 in its vertex buffer of 84 bytes"),
        [](Objects& o) { return drawMesh(o, 4, 84); });
    add("count whose vertex bytes overflow 32 bits", Error::DrawVertexCount, {},
        fixed("DrawDesc.count is 4294967295; allowed [0, 3], the vertices of stride 28 in its vertex buffer of 84 bytes"),
        [](Objects& o) { return drawMesh(o, 0xFFFFFFFFu, 84); });
    add(
        "dispatch without compute", Error::DispatchUnsupported, noCompute,
        [](const Caps& c) { return "dispatch: this device has no compute shaders" + ceiling(c); }, [](Objects& o) { return o.dev.dispatch({}); });
    add(
        "no groups", Error::DispatchGroups, compute,
        [](const Caps& c) {
            return "DispatchDesc.groupsY is 0; allowed [1, " + str(c.limits.maxComputeWorkGroupCount[1]) +
                "] (the device's maxComputeWorkGroupCount)";
        },
        [](Objects& o) {
            DispatchDesc d;
            d.groupsY = 0;
            return o.dev.dispatch(d);
        });
    add(
        "more groups than the device launches", Error::DispatchGroups,
        [](const Caps& c) { return compute(c) && c.limits.maxComputeWorkGroupCount[0] < 0xFFFFFFFFu; },
        [](const Caps& c) {
            return "DispatchDesc.groupsX is " + str(c.limits.maxComputeWorkGroupCount[0] + 1) + "; allowed [1, " +
                str(c.limits.maxComputeWorkGroupCount[0]) + "] (the device's maxComputeWorkGroupCount)";
        },
        [](Objects& o) {
            DispatchDesc d;
            d.groupsX = o.dev.caps().limits.maxComputeWorkGroupCount[0] + 1;
            return o.dev.dispatch(d);
        });

    // ---- Bindings ----------------------------------------------------------------------------
    add("binding given twice", Error::BindingTwice, {},
        fixed("DrawDesc.bindings.textures[1]: binding 0 is given again (DrawDesc.bindings.textures[0] has it); allowed each binding once"),
        [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.bindings.textures.push_back(d.bindings.textures[0]);
            return drawOnce(o, d);
        });
    add("binding the program lacks", Error::BindingUnknown, {},
        fixed("DrawDesc.bindings.textures[1]: binding 7 does not exist in program 'copy'; its bindings are 0 (uSource)"), [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.bindings.textures.push_back({7, d.bindings.textures[0].texture});
            return drawOnce(o, d);
        });
    add("binding of the wrong kind", Error::BindingKind, {},
        fixed("DrawDesc.bindings.uniformBuffers[0]: binding 0 of program 'copy' is sampled texture 'uSource'; allowed it in "
              "BindingSet.textures"),
        [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.bindings.textures.clear();
            d.bindings.uniformBuffers = {{0, o.buffer(16, kBufferUniform)}};
            return drawOnce(o, d);
        });
    add("resource left unbound", Error::BindingMissing, {},
        fixed("DrawDesc.bindings.textures has nothing at binding 0; program 'copy' needs sampled texture 'uSource' there"), [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.bindings.textures.clear();
            return drawOnce(o, d);
        });
    add("mips that wrap in 32 bits", Error::BindingMips, {},
        fixed("DrawDesc.bindings.textures[0]: baseMip+mipCount is 1+4294967295; allowed a non-empty range inside the texture's 2 mips"),
        [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.bindings.textures = {{gen::copy::uSource, o.texture(8, 8, Format::RGBA8, kTextureSampled, 2), 1, 0xFFFFFFFFu}};
            return drawOnce(o, d);
        });
    // Integer formats filter nowhere: the rule applies on every device.
    add(
        "linear sampler on an integer texture", Error::BindingNotFilterable, {},
        [](const Caps& c) {
            return "DrawDesc.bindings.textures[0]: a sampler with a Linear filter on the texture's format R32UI, which this device cannot "
                   "filter; allowed a Nearest sampler, or a filterable format: " +
                formatList([&](Format f) { return c.filterableFormat[size_t(f)]; });
        },
        [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.bindings.textures[0].texture = o.texture(8, 8, Format::R32UI, kTextureSampled);
            d.bindings.textures[0].sampler = o.sampler({Filter::Nearest, Filter::Nearest, Filter::Linear});
            return drawOnce(o, d);
        });
    add("texture without sampled", Error::ResourceUsage, {},
        fixed("DrawDesc.bindings.textures[0].texture has usage render-target; allowed a texture with usage sampled"), [](Objects& o) {
            DrawDesc d = copyDraw(o);
            d.bindings.textures[0].texture = o.texture(8, 8, Format::RGBA8, kTextureRenderTarget);
            return drawOnce(o, d);
        });
    add("index buffer as vertices", Error::ResourceUsage, {}, fixed("DrawDesc.vertexBuffer has usage index; allowed a buffer with usage vertex"),
        [](Objects& o) {
            DrawDesc d;
            d.pipeline = o.graphics("hal_test_mesh", {Format::RGBA8}, Format::Undefined, meshLayout());
            d.vertexBuffer = o.buffer(84, kBufferIndex);
            return drawOnce(o, d);
        });
    add("vertex buffer as uniforms", Error::ResourceUsage, {},
        fixed("DrawDesc.bindings.uniformBuffers[0].buffer has usage vertex; allowed a buffer with usage uniform"),
        [](Objects& o) { return drawUniform(o, 64, kBufferVertex, 0, 0); });
    add("uniform range past the buffer", Error::BufferRange, {},
        fixed("DrawDesc.bindings.uniformBuffers[0] covers offset 0 + 64 bytes; allowed a non-empty range inside the buffer's 32 bytes"),
        [](Objects& o) { return drawUniform(o, 32, kBufferUniform, 0, 64); });
    add(
        "misaligned uniform offset", Error::BufferBindingAlignment, [](const Caps& c) { return c.limits.minUniformBufferOffsetAlignment > 1; },
        [](const Caps& c) {
            const uint64_t a = c.limits.minUniformBufferOffsetAlignment;
            return "DrawDesc.bindings.uniformBuffers[0].offset is " + str(a / 2) + "; allowed a multiple of " + str(a) +
                ", this device's caps.limits.minUniformBufferOffsetAlignment";
        },
        [](Objects& o) {
            const uint64_t a = o.dev.caps().limits.minUniformBufferOffsetAlignment;
            return drawUniform(o, 2 * a, kBufferUniform, a / 2, 16);
        });
    add(
        "storage range over the limit", Error::BufferBindingMaxRange,
        [](const Caps& c) {
            return compute(c) && c.limits.maxStorageBufferSize + 16 <= c.limits.maxBufferSize && c.limits.maxStorageBufferSize <= (1u << 28);
        },
        [](const Caps& c) {
            return "DispatchDesc.bindings.storageBuffers[0] binds " + str(c.limits.maxStorageBufferSize + 16) + " bytes; allowed at most " +
                str(c.limits.maxStorageBufferSize) + ", this device's caps.limits.maxStorageBufferSize";
        },
        [](Objects& o) {
            DispatchDesc d;
            d.pipeline = o.compute("hal_atomic_count");
            d.bindings.storageBuffers = {{0, o.buffer(o.dev.caps().limits.maxStorageBufferSize + 16, kBufferStorage)}};
            return o.dev.dispatch(d);
        });
    add("uniform range smaller than the block", Error::BufferBindingBlockSize, {},
        fixed("DrawDesc.bindings.uniformBuffers[0] binds 8 bytes; allowed at least the 16 bytes of block 'ColorParams'"),
        [](Objects& o) { return drawUniform(o, 32, kBufferUniform, 0, 8); });
    add("sampling the mip the pass renders to", Error::FeedbackLoop, {},
        fixed("DrawDesc.bindings.textures[0]: mips 0+2 include mip 0, which the pass renders to (RenderPassDesc.colors[0]); allowed a "
              "range without it"),
        [](Objects& o) {
            DrawDesc d = copyDraw(o);
            TextureHandle t = o.texture(8, 8, Format::RGBA8, kRenderable, 2);
            d.bindings.textures[0] = {gen::copy::uSource, t, 0, 2};
            RenderPassDesc pass;
            pass.colors = {{t, 0}};
            return o.dev.renderPass(pass, {&d, 1});
        });
    add("one mip sampled and stored", Error::MipUsedTwoWays, compute,
        fixed("DispatchDesc.bindings.storageImages[0] uses mip 0 of a texture that DispatchDesc.bindings.textures[0] also uses as a "
              "sampled texture; allowed one use per mip in one command"),
        [](Objects& o) {
            DispatchDesc d;
            d.pipeline = o.computeFrom(storageAndSampled());
            TextureHandle t = o.texture(8, 8, Format::R32F, kTextureSampled | kTextureStorage);
            d.bindings.textures = {{1, t}};
            d.bindings.storageImages = {{0, t, 0}};
            return o.dev.dispatch(d);
        });

    // ---- Checks only one API makes (the call succeeds on the others) --------------------------
    add(
        "SPIR-V whose structure is broken", Error::ShaderInvalidSpirv, {}, fixed(""),
        [](Objects& o) {
            CompiledProgram p = shaderProgram("copy", Tier::Current);
            for (size_t i = 5; i < p.stages[0].spirv.size(); ++i) p.stages[0].spirv[i] = 0xdeadbeefu;
            return tryProgram(o, p);
        },
        isVulkan);
    add(
        "GLSL that does not compile", Error::ShaderCompile, {}, fixed(""),
        [](Objects& o) {
            CompiledProgram p = shaderProgram("copy", Tier::Current);
            for (std::string& g : p.stages[1].glsl)
                if (!g.empty()) g = g.substr(0, g.find('\n') + 1) + "void main() { this is not glsl; }\n";
            return tryProgram(o, p);
        },
        isGl);
    add(
        "stages that do not link", Error::ShaderLink, {}, fixed(""),
        [](Objects& o) {
            CompiledProgram p = shaderProgram("copy", Tier::Current);
            for (std::string& g : p.stages[1].glsl)
                if (!g.empty())
                    g = g.substr(0, g.find('\n') + 1) +
                        "precision highp float;\nout vec4 sfxOut;\nvoid notMain() { sfxOut = vec4(1.0); }\n";  // no main: links nowhere
            return tryProgram(o, p);
        },
        isGl);
    add(
        "texture binding past the texture units", Error::ProgramTextureUnit, {},
        [](const Caps& c) {
            return "program 'copy' samples 'uSource' at binding " + str(c.limits.maxTextureBindings) + "; allowed bindings [0, " +
                str(c.limits.maxTextureBindings - 1) + "], the texture units of this device";
        },
        [](Objects& o) {
            CompiledProgram p = shaderProgram("copy", Tier::Current);
            p.resources[0].binding = o.dev.caps().limits.maxTextureBindings;
            return tryProgram(o, p);
        },
        isGl);
    add(
        "more timers than the query pool holds", Error::TimerPoolFull, {},
        fixed("createTimer: all 256 timers of the device are in use; allowed after destroying one"),
        [](Objects& o) {
            std::vector<TimerHandle> timers;
            Status s;
            for (int i = 0; i < 257 && s.isOk(); ++i) {
                Result<TimerHandle> t = o.dev.createTimer();
                if (t.isOk()) timers.push_back(t.value());
                s = t.status();
            }
            for (TimerHandle t : timers) (void)o.dev.destroyTimer(t);
            return s;
        },
        isVulkan);
    return v;
}

}  // namespace sfx::test
