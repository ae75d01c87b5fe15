// The hardware abstraction layer: what every backend (vulkan, gl with its EGL and OSMesa
// platforms, null) implements, and all that effects may use of a GPU.
//
// Conventions every backend keeps, so effects are written once:
// - Texel (x, y) of a texture is its y-th row in memory, on every API. In both Vulkan and GL,
//   normalised device y = -1 rasterises to row 0, so a projection matrix means the same
//   memory picture on every backend. Images the SDK writes to files put row 0 at the top.
// - Shaders address textures at integer texel coordinates (sfxTexel); a TextureBinding
//   selects the mip range a shader sees, and lod 0 in the shader is the binding's baseMip.
// - Commands are recorded in call order and run at flush(); reads of textures and buffers
//   flush first. With a host-provided Vulkan command buffer, flush() only ends recording.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sfx/handle.hpp"
#include "sfx/shader_program.hpp"
#include "sfx/status.hpp"

namespace sfx {

enum class BackendKind : uint32_t { Null, Vulkan, GLES, GL };
const char* toString(BackendKind kind);  // "null", "vulkan", "gles", "gl"

enum class Format : uint32_t {
    Undefined = 0,
    R8,     // unorm
    RGBA8,  // unorm
    R16F,
    RG16F,
    RGBA16F,
    R32F,
    RG32F,
    RGBA32F,
    R32UI,
    D16,    // depth, unorm
    D24S8,  // depth unorm 24 + stencil 8; bytes: one uint32 per texel, depth in the high 24 bits
    // (depth * 0xFFFFFF << 8), stencil in the low 8. Where the API cannot copy stencil
    // (Vulkan's depth-aspect copies, GL ES) stencil reads as 0 and is ignored on write.
    D32F,  // depth, float
    Count
};
const char* toString(Format format);
uint32_t bytesPerTexel(Format format);  // 0 for Undefined
bool isDepthFormat(Format format);
bool isIntegerFormat(Format format);
uint32_t channelCount(Format format);

enum TextureUsage : uint32_t {
    kTextureSampled = 1u << 0,       // read in shaders
    kTextureRenderTarget = 1u << 1,  // colour or depth attachment
    kTextureStorage = 1u << 2,       // image load/store (high tier)
};

struct TextureDesc {
    uint32_t width = 0;      // [1, caps.limits.maxTextureSize]
    uint32_t height = 0;     // [1, caps.limits.maxTextureSize]
    uint32_t mipLevels = 1;  // [1, 1 + floor(log2(max(width, height)))]
    Format format = Format::Undefined;
    uint32_t usage = kTextureSampled;
    const char* debugName = "";
};

enum BufferUsage : uint32_t {
    kBufferUniform = 1u << 0,
    kBufferStorage = 1u << 1,  // high tier only
    kBufferVertex = 1u << 2,
    kBufferIndex = 1u << 3,  // 32-bit indices
};

struct BufferDesc {
    uint64_t size = 0;  // bytes, [1, caps.limits.maxBufferSize]
    uint32_t usage = 0;
    const char* debugName = "";
};

enum class Filter : uint32_t { Nearest, Linear };
enum class AddressMode : uint32_t { ClampToEdge, Repeat, MirroredRepeat };
struct SamplerDesc {
    Filter minFilter = Filter::Nearest;
    Filter magFilter = Filter::Nearest;
    Filter mipFilter = Filter::Nearest;
    AddressMode address = AddressMode::ClampToEdge;
};

enum class VertexFormat : uint32_t { Float2, Float3, Float4 };
struct VertexAttribute {
    uint32_t location = 0;
    VertexFormat format = VertexFormat::Float3;
    uint32_t offset = 0;  // bytes from the start of the vertex
};
struct VertexLayout {
    uint32_t stride = 0;  // 0 and no attributes: the draw reads no vertex buffer (full-screen pass)
    std::vector<VertexAttribute> attributes;
};

enum class CompareOp : uint32_t { Never, Less, LessEqual, Greater, GreaterEqual, Equal, NotEqual, Always };
enum class BlendFactor : uint32_t { Zero, One, SrcAlpha, OneMinusSrcAlpha, DstAlpha, OneMinusDstAlpha };
enum class CullMode : uint32_t { None, Back, Front };

struct DepthState {
    bool test = false;
    bool write = false;
    CompareOp compare = CompareOp::Less;
};
struct BlendState {
    bool enable = false;
    BlendFactor src = BlendFactor::One;  // colour (and alpha, unless separateAlpha) factors, op add
    BlendFactor dst = BlendFactor::Zero;
    // Alpha with its own factors (weighted blended OIT: colour sums, alpha multiplies down).
    // One state for every attachment either way (GL ES 3.0 has no per-target blend state).
    bool separateAlpha = false;
    BlendFactor srcAlpha = BlendFactor::One;
    BlendFactor dstAlpha = BlendFactor::Zero;
};

// A specialisation constant of a pipeline's program: the shader declares
// `layout(constant_id = id) const int NAME = default;` and the pipeline fixes the value, so the
// driver compiles loop bounds and branches that depend on it as constants, once, when the
// pipeline is made (a uniform value there may make a driver recompile at draw time). Vulkan
// specialises the SPIR-V; GL compiles the program's text with the value in place. Ids a program
// does not declare are ignored.
struct SpecializationConstant {
    uint32_t id = 0;
    int32_t value = 0;
};

struct GraphicsPipelineDesc {
    ProgramHandle program;
    VertexLayout vertexLayout;
    DepthState depth;
    BlendState blend;
    CullMode cull = CullMode::None;    // front faces are counter-clockwise in framebuffer memory rows
    std::vector<Format> colorFormats;  // one per colour attachment, [0, caps.limits.maxColorAttachments]
    Format depthFormat = Format::Undefined;
    const char* debugName = "";
    std::vector<SpecializationConstant> constants;  // distinct ids
};

struct ComputePipelineDesc {
    ProgramHandle program;
    const char* debugName = "";
    std::vector<SpecializationConstant> constants;  // distinct ids
};

// Resources for one draw or dispatch, by the binding numbers the shader reflection reports
// (sfx::gen::<program>::<resource> constants generated by sfxc).
struct TextureBinding {
    uint32_t binding = 0;
    TextureHandle texture;
    uint32_t baseMip = 0;   // the shader's lod 0
    uint32_t mipCount = 1;  // mips visible to the shader
    SamplerHandle sampler;  // null: nearest, clamp to edge
};
struct BufferBinding {
    uint32_t binding = 0;
    BufferHandle buffer;
    uint64_t offset = 0;
    uint64_t size = 0;  // 0: to the end of the buffer
};
struct StorageImageBinding {
    uint32_t binding = 0;
    TextureHandle texture;
    uint32_t mip = 0;
};
struct BindingSet {
    std::vector<TextureBinding> textures;
    std::vector<BufferBinding> uniformBuffers;
    std::vector<BufferBinding> storageBuffers;
    std::vector<StorageImageBinding> storageImages;
};

enum class LoadOp : uint32_t { Clear, Load, DontCare };
struct ColorAttachment {
    TextureHandle texture;
    uint32_t mip = 0;
    LoadOp load = LoadOp::Clear;
    std::array<float, 4> clearColor{0, 0, 0, 0};  // integer formats take these values converted
};
struct DepthAttachment {
    TextureHandle texture;  // null: no depth attachment
    LoadOp load = LoadOp::Clear;
    float clearDepth = 1.0f;
};
struct RenderPassDesc {
    std::vector<ColorAttachment> colors;
    DepthAttachment depth;
    const char* debugName = "";
};

struct DrawDesc {
    PipelineHandle pipeline;
    BindingSet bindings;
    BufferHandle vertexBuffer;  // null for full-screen passes
    BufferHandle indexBuffer;   // null: non-indexed; else 32-bit indices
    uint32_t count = 3;         // vertices, or indices when indexed
    uint32_t instanceCount = 1;
};

struct DispatchDesc {
    PipelineHandle pipeline;
    BindingSet bindings;
    uint32_t groupsX = 1, groupsY = 1, groupsZ = 1;
};

enum class TimingSource : uint32_t {
    GpuTimestamps,         // GPU timestamp queries (Vulkan)
    WallClockAfterFinish,  // glFinish before and after, wall clock between (GL on llvmpipe)
};
const char* toString(TimingSource source);

struct TimerReading {
    double milliseconds = 0;
    TimingSource source = TimingSource::GpuTimestamps;
};

// Where clip-space depth lands and how rows are ordered: facts position reconstruction uses.
enum class ClipDepthRange : uint32_t { ZeroToOne, MinusOneToOne };
enum class FramebufferOrigin : uint32_t { UpperLeft, LowerLeft };

// A device opened under a ceiling behaves as the ceiling's class of hardware: the backend
// refuses what that class lacks and compiles the shader dialect it would use.
enum class CapabilityCeiling : uint32_t {
    None,
    GLES30,  // "behave as GL ES 3.0": ESSL 300 / GLSL 330, no compute, storage or atomics
};
const char* toString(CapabilityCeiling ceiling);

struct DeviceLimits {
    uint32_t maxTextureSize = 0;
    // The largest render target: the smaller of the framebuffer and viewport limits and
    // maxTextureSize (Vulkan maxFramebufferWidth/Height and maxViewportDimensions; GL
    // MAX_VIEWPORT_DIMS and MAX_RENDERBUFFER_SIZE). A texture with usage render-target beyond it is refused.
    uint32_t maxRenderTargetWidth = 0, maxRenderTargetHeight = 0;
    uint32_t maxColorAttachments = 0;
    // Bits of sub-pixel precision to which the rasteriser snaps vertex positions (Vulkan
    // subPixelPrecisionBits, GL SUBPIXEL_BITS; both specifications require at least 4): an edge
    // may move by up to 2^-bits / sqrt(2) pixels from where exact arithmetic puts it.
    uint32_t subPixelPrecisionBits = 0;
    uint64_t maxUniformBlockSize = 0;
    uint64_t maxStorageBufferSize = 0;  // 0 without storage buffers
    uint64_t maxBufferSize = 0;
    uint32_t maxComputeWorkGroupInvocations = 0;  // 0 without compute
    // Work groups one dispatch may launch along x, y and z (Vulkan maxComputeWorkGroupCount, GL
    // MAX_COMPUTE_WORK_GROUP_COUNT; both require at least 65535); 0 without compute.
    std::array<uint32_t, 3> maxComputeWorkGroupCount{};
    uint32_t maxTextureBindings = 0;
    // A uniform / storage BufferBinding's offset is a multiple of these (Vulkan
    // minUniformBufferOffsetAlignment / minStorageBufferOffsetAlignment, GL's
    // UNIFORM_BUFFER_OFFSET_ALIGNMENT / SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT); at least 1.
    uint64_t minUniformBufferOffsetAlignment = 1;
    uint64_t minStorageBufferOffsetAlignment = 1;
    // Samples per pixel, as a mask with bit k set for 2^k samples (bit 0: one sample), for colour
    // and depth attachments and for sampled colour and depth textures: Vulkan
    // framebufferColor/DepthSampleCounts and sampledImageColor/DepthSampleCounts; GL every power
    // of two up to MAX_SAMPLES (GL accepts any request up to it and may round it up) and, where
    // multisampled textures exist (desktop GL 3.2, GL ES 3.1), up to MAX_COLOR_TEXTURE_SAMPLES /
    // MAX_DEPTH_TEXTURE_SAMPLES, else one. Under the GL ES 3.0 ceiling sampled textures have one
    // sample, as GL ES 3.0 has no multisampled textures. Recorded for the host: the HAL makes
    // single-sampled textures only.
    uint32_t framebufferColorSampleCounts = 1, framebufferDepthSampleCounts = 1;
    uint32_t sampledImageColorSampleCounts = 1, sampledImageDepthSampleCounts = 1;
    // Texels one texel buffer may address: Vulkan maxTexelBufferElements, GL
    // MAX_TEXTURE_BUFFER_SIZE where the context has texture buffers (desktop GL 3.1, GL ES 3.2,
    // EXT_ or OES_texture_buffer); 0 without, and under the GL ES 3.0 ceiling, which has none.
    // Recorded for the host: the HAL makes no texel buffer.
    uint32_t maxTexelBufferElements = 0;
};

struct DeviceCaps {
    BackendKind backend = BackendKind::Null;
    std::string platform;  // "vulkan-loader", "egl", "osmesa", "null"
    std::string apiName;   // "Vulkan 1.3.239", "OpenGL ES 3.2 Mesa 22.3.6", ...
    uint32_t apiMajor = 0, apiMinor = 0;
    std::string deviceName;                        // "llvmpipe (LLVM 15.0.6, 256 bits)", "NVIDIA H100 ..."
    std::string deviceChoice;                      // why this device: "the only usable device of 1", "asked for by ..."
    ShaderDialect dialect = ShaderDialect::Spirv;  // what createProgram consumes
    CapabilityCeiling ceiling = CapabilityCeiling::None;

    bool computeShaders = false;
    bool storageBuffers = false;
    bool atomics = false;  // atomic operations on storage buffers
    bool storageImages = false;
    // Storage buffer and storage image writes and atomics (atomicAdd on buffers,
    // imageAtomicExchange on R32UI storage images) from fragment shaders, so a render pass can
    // have side effects beyond its attachments (the A-buffer fill). A pass may then have no
    // colour attachment (depth only). Every render pass and dispatch is ordered after all
    // earlier commands' storage writes: a later pass sees what an earlier one wrote.
    bool fragmentStoresAndAtomics = false;
    bool floatRenderTargets = false;  // R32F, RG16F, RGBA16F colour-renderable
    TimingSource timing = TimingSource::WallClockAfterFinish;
    // Device::beginRecording / beginReplay work (Vulkan, unless DeviceOptions::reuseRecordings is
    // off); elsewhere they report UnsupportedFeature and effects record their commands each frame.
    bool reusableRecordings = false;

    ClipDepthRange clipDepth = ClipDepthRange::ZeroToOne;  // the API's default
    FramebufferOrigin origin = FramebufferOrigin::UpperLeft;

    DeviceLimits limits;
    // For each Format, what this device supports (Vulkan: the format's optimal-tiling features;
    // GL: the API version's and extensions' format tables). The checks refuse anything else:
    // sampledFormat / renderableFormat / storageFormat: TextureDesc.usage sampled / render-target /
    // storage; filterableFormat: a binding with a Linear filter in its sampler (GL ES 3.0 filters
    // 32-bit floats only with OES_texture_float_linear, and no depth or integer format);
    // blendableFormat: a colour format of a pipeline with blend.enable (32-bit floats need
    // EXT_float_blend on GL ES; integer formats never blend).
    std::array<bool, size_t(Format::Count)> sampledFormat{};
    std::array<bool, size_t(Format::Count)> renderableFormat{};
    std::array<bool, size_t(Format::Count)> filterableFormat{};
    std::array<bool, size_t(Format::Count)> blendableFormat{};
    std::array<bool, size_t(Format::Count)> storageFormat{};

    std::string summary() const;  // one line for logs: backend, API, device, ceiling
};

// How bad a message the library hands the host is.
enum class LogSeverity : uint32_t { Info, Warning, Error };
// The library prints nothing: what it has to say beyond a Status goes to this callback. It is
// called on the thread making the SDK call (or destroying the device) that produced the
// message, never concurrently for one device; it must not call back into that device.
using LogCallback = std::function<void(LogSeverity severity, std::string_view message)>;

struct DeviceOptions {
    CapabilityCeiling ceiling = CapabilityCeiling::None;
    // API validation, only when the host asks: Vulkan enables VK_LAYER_KHRONOS_validation
    // with synchronization validation (own device) and the SDK's debug messenger; GL checks
    // glGetError after every call and turns on KHR_debug output. It multiplies the CPU cost of a dispatch (about 7.5x on
    // Vulkan), so it is off by default; the tests, the samples and `sfx --validate` turn it on.
    bool validation = false;
    // Where the library's own diagnostics go; empty: they are dropped. Validation messages
    // are also kept for Device::takeValidationMessages(); the ones still untaken when the
    // device is destroyed go here (LogSeverity::Error) so none is lost silently.
    LogCallback log;
    // Vulkan: effects record their passes once and replay them in frames that issue the same
    // commands (Device::beginRecording), which takes most of a dispatch's CPU cost away. Off:
    // every frame records every command, as capture tools that follow calls one by one may want.
    bool reuseRecordings = true;
    // Vulkan, own device: which physical device to open. Empty: the usable one of the best type
    // (discrete, integrated, virtual, CPU); otherwise its index in the loader's order or part of
    // its name ("SwiftShader", "llvmpipe"). Other backends have no choice to make and refuse a
    // non-empty value (InvalidArgument).
    std::string physicalDevice;
};

// How many objects of one kind exist now and how many were ever made.
struct ObjectCount {
    uint64_t live = 0;
    uint64_t created = 0;
    void add(uint64_t n = 1) {
        live += n;
        created += n;
    }
    void remove(uint64_t n = 1) { live -= n < live ? n : live; }
    bool operator==(const ObjectCount&) const = default;
};

// What a device has made, for a host's profiler and for the tests that check that a steady
// frame makes nothing: compare two readings taken a frame (or many) apart. The HAL kinds count
// what the Device calls made; the backend kinds count what the backend made behind them
// (0 where a backend has no such thing: GL has no descriptor sets, the null backend no memory).
struct DeviceStats {
    ObjectCount textures, buffers, samplers, programs, pipelines, timers;
    ObjectCount recordings;          // Device::endRecording (Vulkan: secondary command buffers)
    ObjectCount memoryAllocations;   // Vulkan: vkAllocateMemory; GL: texture and buffer storage
    ObjectCount stagingBuffers;      // Vulkan: blocks of the upload/readback ring; GL: readback copies
    ObjectCount descriptorSets;      // Vulkan: sets in the cache (made once per distinct binding set)
    ObjectCount descriptorPools;     // Vulkan
    ObjectCount imageViews;          // Vulkan: sampled, storage and attachment views
    ObjectCount framebuffers;        // GL: framebuffer objects (Vulkan renders without any)
    uint64_t deviceMemoryBytes = 0;  // bytes of GPU (or, null: host) memory the device holds now
    bool operator==(const DeviceStats&) const = default;
};
// The counts of a device's HandlePool (sfx/handle.hpp).
template <class Pool>
ObjectCount objectCount(const Pool& pool) {
    return {uint64_t(pool.aliveCount()), pool.createdCount()};
}
// The HAL kinds of DeviceStats from a backend's six pools; the backend adds its own kinds.
template <class Textures, class Buffers, class Samplers, class Programs, class Pipelines, class Timers>
DeviceStats halObjectStats(const Textures& textures, const Buffers& buffers, const Samplers& samplers, const Programs& programs,
                           const Pipelines& pipelines, const Timers& timers) {
    DeviceStats s;
    s.textures = objectCount(textures);
    s.buffers = objectCount(buffers);
    s.samplers = objectCount(samplers);
    s.programs = objectCount(programs);
    s.pipelines = objectCount(pipelines);
    s.timers = objectCount(timers);
    return s;
}

namespace validation {
class ObjectLookup;
struct PipelineInfo;
}  // namespace validation

// The one front end over every backend. Its public calls are defined once (hal_device.cpp): each
// runs the shared checks (sfx/hal_validation.hpp) in one fixed order (handles, then descriptions
// against the caps and limits, then what the handles' records say) and only then calls the
// backend's hook below, so a backend cannot skip or reorder a check and bad input gets the same
// code and message everywhere. Backends implement the private do* hooks and objects().
class Device {
public:
    virtual ~Device() = default;
    Device() = default;
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    virtual const DeviceCaps& caps() const = 0;

    // Resources. Every create validates its description and names the bad field.
    Result<TextureHandle> createTexture(const TextureDesc& desc);
    Status destroyTexture(TextureHandle texture);
    Result<TextureDesc> textureDesc(TextureHandle texture) const;
    // Whole mip level, tightly packed rows, row 0 first. bytes must equal the level's size.
    // Depth formats in the layout their Format comment gives (D24S8: depth in the high 24 bits).
    Status writeTexture(TextureHandle texture, uint32_t mip, const void* data, size_t bytes);
    Status readTexture(TextureHandle texture, uint32_t mip, void* out, size_t bytes);

    Result<BufferHandle> createBuffer(const BufferDesc& desc);
    Status destroyBuffer(BufferHandle buffer);
    // Ordered with recorded commands: a pass recorded before sees the old contents.
    Status writeBuffer(BufferHandle buffer, uint64_t offset, const void* data, size_t bytes);
    Status readBuffer(BufferHandle buffer, uint64_t offset, void* out, size_t bytes);

    Result<SamplerHandle> createSampler(const SamplerDesc& desc);
    Status destroySampler(SamplerHandle sampler);

    // Takes the stage code for caps().dialect from the program; ShaderError when it fails
    // to compile or link, UnsupportedFeature for compute or storage under the ceiling.
    Result<ProgramHandle> createProgram(const CompiledProgram& program);
    Status destroyProgram(ProgramHandle program);

    Result<PipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc);
    Result<PipelineHandle> createComputePipeline(const ComputePipelineDesc& desc);
    Status destroyPipeline(PipelineHandle pipeline);

    Result<TimerHandle> createTimer();
    Status destroyTimer(TimerHandle timer);

    // Commands, recorded in call order.
    Status renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws);
    Status dispatch(const DispatchDesc& dispatch);
    Status beginTimer(TimerHandle timer);
    Status endTimer(TimerHandle timer);
    // Runs what was recorded and waits for it (own device).
    Status flush();
    // The time between the timer's begin and end of the last flushed use.
    Result<TimerReading> readTimer(TimerHandle timer);

    // Reusable recordings (caps().reusableRecordings; elsewhere all five report UnsupportedFeature).
    // The commands between beginRecording and endRecording run where they were called, as
    // always, and are kept (Vulkan: a secondary command buffer, executed by endRecording). A later
    // beginReplay ... endReplay around the same calls with the same arguments runs the kept
    // commands instead of recording them again: renderPass and dispatch there are only compared
    // with the recorded calls, and endReplay runs the recording with the barriers the resources'
    // states at that point need. Resources are used by handle, so contents written before (a
    // changed uniform) are what the replay reads. endReplay reports StaleHandle and runs nothing
    // when the calls differ from the recorded ones, an object was created or destroyed since, a
    // resource it writes is not in the state it was recorded from, or the recording cannot be
    // reused (it wrote a resource it had used, or held a timer); beginReplay reports StaleHandle
    // for a destroyed recording. The caller then records the same calls again. Between begin and
    // end: flush, reads and another begin are refused (InvalidArgument).
    Status beginRecording();
    Result<RecordingHandle> endRecording();
    Status beginReplay(RecordingHandle recording);
    Status endReplay();
    Status destroyRecording(RecordingHandle recording);

    // Counts of what the device made (see DeviceStats); cheap, callable every frame.
    virtual DeviceStats stats() const = 0;

    // Messages from the API's validation since the last call: Vulkan validation-layer
    // messages, GL errors caught by the per-call checks and GL debug output. Tests fail on any.
    virtual std::vector<std::string> takeValidationMessages() { return {}; }

protected:
    // Another device's objects, for a device that forwards to it (the tests' fault injection).
    static const validation::ObjectLookup& objectsOf(const Device& device) { return device.objects(); }

    // What the front end has open; the backend records into, or compares with, it.
    enum class RecordingState : uint8_t { None, Recording, Replaying };
    RecordingState recordingState() const { return recordingState_; }
    RecordingHandle replayedRecording() const { return replayed_; }
    // InvalidArgument while a recording or replay is open, naming the call that closes it.
    Status notWhileRecording(const char* call) const;

private:
    Status recordingsKept(const char* call) const;

    // ---- The backend's side ----------------------------------------------------------------
    // The backend's objects as the checks read them: each handle checked (null, foreign,
    // unknown, destroyed) and the description or reflection it was made with.
    virtual const validation::ObjectLookup& objects() const = 0;

    // Called only with arguments the front end checked: handles name live objects of this
    // device, descriptions are within the caps and limits, byte ranges and mips lie inside their
    // resource, pointers are not null. What a hook may still refuse is what only its API or its
    // own state can tell (a shader that does not compile, a read inside a recording).
    virtual Result<TextureHandle> doCreateTexture(const TextureDesc& desc) = 0;
    virtual Status doDestroyTexture(TextureHandle texture) = 0;
    virtual Status doWriteTexture(TextureHandle texture, uint32_t mip, const void* data, size_t bytes) = 0;
    virtual Status doReadTexture(TextureHandle texture, uint32_t mip, void* out, size_t bytes) = 0;

    virtual Result<BufferHandle> doCreateBuffer(const BufferDesc& desc) = 0;
    virtual Status doDestroyBuffer(BufferHandle buffer) = 0;
    virtual Status doWriteBuffer(BufferHandle buffer, uint64_t offset, const void* data, size_t bytes) = 0;
    virtual Status doReadBuffer(BufferHandle buffer, uint64_t offset, void* out, size_t bytes) = 0;

    virtual Result<SamplerHandle> doCreateSampler(const SamplerDesc& desc) = 0;
    virtual Status doDestroySampler(SamplerHandle sampler) = 0;

    virtual Result<ProgramHandle> doCreateProgram(const CompiledProgram& program) = 0;
    virtual Status doDestroyProgram(ProgramHandle program) = 0;

    // `info` is what the shared checks made of the desc and its program: the backend keeps it
    // for objects() to hand to the checks of later draws and dispatches.
    virtual Result<PipelineHandle> doCreateGraphicsPipeline(const GraphicsPipelineDesc& desc, validation::PipelineInfo info) = 0;
    virtual Result<PipelineHandle> doCreateComputePipeline(const ComputePipelineDesc& desc, validation::PipelineInfo info) = 0;
    virtual Status doDestroyPipeline(PipelineHandle pipeline) = 0;

    virtual Result<TimerHandle> doCreateTimer() = 0;
    virtual Status doDestroyTimer(TimerHandle timer) = 0;
    virtual Status doBeginTimer(TimerHandle timer) = 0;
    virtual Status doEndTimer(TimerHandle timer) = 0;
    virtual Result<TimerReading> doReadTimer(TimerHandle timer) = 0;

    // Called only where caps().reusableRecordings holds, with the open state checked: begin
    // with nothing open, end with its kind open (closed by the front end whatever the hook
    // reports), a live recording handle that is not being replayed for destroy.
    virtual Status doBeginRecording();
    virtual Result<RecordingHandle> doEndRecording();
    virtual Status doBeginReplay(RecordingHandle recording);
    virtual Status doEndReplay(RecordingHandle recording);
    virtual Status doDestroyRecording(RecordingHandle recording);
    // A renderPass or dispatch inside a replay: only compared with the recorded call, which was
    // checked when it was recorded (a refused call was not recorded, so it cannot match).
    virtual Status doReplayCall(const RenderPassDesc* pass, std::span<const DrawDesc> draws, const DispatchDesc* dispatch);
    virtual Status doRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) = 0;
    virtual Status doDispatch(const DispatchDesc& dispatch) = 0;
    virtual Status doFlush() = 0;

    RecordingState recordingState_ = RecordingState::None;
    RecordingHandle replayed_;
};

// Byte size of one mip level of a texture.
uint64_t mipLevelBytes(const TextureDesc& desc, uint32_t mip);
uint64_t textureBytes(const TextureDesc& desc);   // all its mip levels
uint32_t mipExtent(uint32_t base, uint32_t mip);  // max(1, base >> mip)
uint32_t maxMipLevels(uint32_t width, uint32_t height);

}  // namespace sfx
