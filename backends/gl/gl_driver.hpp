// The GL driver's device class, shared by the files that implement it (internal to the GL
// backend). One class, its members defined by concern:
//   gl_device.cpp       construction, context switching, commands' validate-then-encode entry
//                       points, timers, and the factories
//   gl_caps.cpp         entry-point loading and the caps (init)
//   gl_errors.cpp       per-call GL error checks and KHR_debug output
//   gl_resources.cpp    textures, buffers, samplers
//   gl_programs.cpp     shader compile/link, name-based binding, pipelines
//   gl_checks.cpp       the checks only GL makes (the rest is the shared sfx::validation)
//   gl_commands.cpp     render passes, draws, dispatches: GL state and resource binding
//   gl_framebuffers.cpp the framebuffer object cache
//   gl_readback.cpp     texture and buffer readback, the GL ES depth copy
// GL runs commands as they are issued, so the HAL's call order is kept by calling GL in that
// order; flush() is glFinish.
#pragma once

#include <chrono>
#include <map>
#include <set>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gl_functions.hpp"
#include "gl_platform.hpp"
#include "sfx/gl_device.hpp"
#include "sfx/hal_validation.hpp"

namespace sfx::gl {

using Clock = std::chrono::steady_clock;

inline std::string str(uint64_t v) { return std::to_string(v); }

struct GlTexture {
    TextureDesc desc;
    GLuint name = 0;
    bool external = false;  // a host's texture (gl_external_textures.cpp): never deleted by the SDK
};
struct GlBuffer {
    BufferDesc desc;
    GLuint name = 0;
};
struct GlSampler {
    SamplerDesc desc;
    GLuint name = 0;
};
// Stage type and text, as compiled: kept so a pipeline with specialisation constants can
// compile its own copy with the values in place.
using GlSources = std::vector<std::pair<GLenum, std::string>>;
struct GlProgram {
    validation::ProgramInfo info;
    GLuint name = 0;
    GlSources sources;
};
struct GlPipeline {
    validation::PipelineInfo info;  // what the shared validation checks draws and dispatches against
    GLuint program = 0;             // the program's GL object, kept until its last pipeline goes
    GraphicsPipelineDesc desc;      // graphics state; program field unused
    GLuint vao = 0;
    GLuint specialized = 0;  // the program compiled with the pipeline's constants; 0: none
};
struct GlTimer {
    bool begun = false, ended = false;
    Clock::time_point begin{}, end{};
    double lastMs = -1;  // the last finished measurement
};

// A render pass's colour attachments (texture, mip) as the checks accepted them.
using ColorTargets = std::vector<std::pair<const GlTexture*, uint32_t>>;
// What a checked render pass renders to: its attachments and their one extent.
struct PassTargets {
    ColorTargets colors;
    const GlTexture* depth = nullptr;
    uint32_t width = 0, height = 0;
};

// Attachments of a framebuffer object: (texture name << 32 | mip) per colour, then depth.
using FboKey = std::vector<uint64_t>;

// A checked GL call inside GlDevice: glGetError after it when options.validation (see checked()).
#define GL(fn, ...) checked(#fn, __FILE__, __LINE__, gl_.fn __VA_OPT__(, ) __VA_ARGS__)

class GlDevice final : public Device {
public:
    GlDevice(std::unique_ptr<GlPlatform> platform, Api api, const DeviceOptions& options);
    ~GlDevice() override;

    // Loads entry points and fills the caps; the platform's context is current.
    Status init(CapabilityCeiling ceiling);

    const DeviceCaps& caps() const override { return caps_; }

    // gl_external_textures.cpp: host textures in, SDK textures out.
    Result<TextureHandle> importExternal(const ExternalTexture& texture);
    Result<NativeTexture> native(TextureHandle h) const;

    std::vector<std::string> takeValidationMessages() override;
    DeviceStats stats() const override;  // gl_resources.cpp

private:
    // ---- Device's hooks: arguments checked by the front end (hal_device.cpp) -----------------
    const validation::ObjectLookup& objects() const override { return lookup_; }
    // gl_resources.cpp, but for the reads (gl_readback.cpp)
    Result<TextureHandle> doCreateTexture(const TextureDesc& desc) override;
    Status doDestroyTexture(TextureHandle h) override;
    Status doWriteTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) override;
    Status doReadTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) override;
    Result<BufferHandle> doCreateBuffer(const BufferDesc& desc) override;
    Status doDestroyBuffer(BufferHandle h) override;
    Status doWriteBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) override;
    Status doReadBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) override;
    Result<SamplerHandle> doCreateSampler(const SamplerDesc& desc) override;
    Status doDestroySampler(SamplerHandle h) override;
    // gl_programs.cpp
    Result<ProgramHandle> doCreateProgram(const CompiledProgram& program) override;
    Status doDestroyProgram(ProgramHandle h) override;
    Result<PipelineHandle> doCreateGraphicsPipeline(const GraphicsPipelineDesc& desc, validation::PipelineInfo info) override;
    Result<PipelineHandle> doCreateComputePipeline(const ComputePipelineDesc& desc, validation::PipelineInfo info) override;
    Status doDestroyPipeline(PipelineHandle h) override;
    // gl_device.cpp
    Result<TimerHandle> doCreateTimer() override;
    Status doDestroyTimer(TimerHandle h) override;
    Status doBeginTimer(TimerHandle h) override;
    Status doEndTimer(TimerHandle h) override;
    Result<TimerReading> doReadTimer(TimerHandle h) override;
    Status doRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) override;
    Status doDispatch(const DispatchDesc& d) override;
    Status doFlush() override;

    // ---- Context (gl_device.cpp) ----------------------------------------------------------
    bool makeCurrent();
    Status enter();
    bool hostContext() const;

    // ---- Errors and debug output (gl_errors.cpp) ------------------------------------------
    // A call's result once GL has had its say: the first GL error caught since enter() wins.
    Status takeDeviceError(Status s);
    void checkError(const char* fn, const char* file, int line);
    template <class F, class... A>
    auto checked(const char* fn, const char* file, int line, F f, A&&... args) -> decltype(f(std::forward<A>(args)...)) {
        if constexpr (std::is_void_v<decltype(f(std::forward<A>(args)...))>) {
            f(std::forward<A>(args)...);
            checkError(fn, file, line);
        } else {
            auto r = f(std::forward<A>(args)...);
            checkError(fn, file, line);
            return r;
        }
    }
    void enableDebugOutput();
    static void APIENTRY debugCallback(GLenum source, GLenum type, GLuint, GLenum, GLsizei, const GLchar* message, const void* user);

    // ---- Resources (gl_resources.cpp) -----------------------------------------------------
    void setSamplerState(GLuint s, const SamplerDesc& d);

    // ---- Programs (gl_programs.cpp) -------------------------------------------------------
    // A GL pipeline draws with its program's GL object, while the HAL lets a program be destroyed
    // before its pipelines (as a Vulkan pipeline holds its own compiled state): the object is
    // deleted when the program and the last pipeline using it are both gone.
    void usePipelineProgram(GLuint program) { ++programUsers_[program]; }
    void releaseProgramObject(GLuint program, bool programDestroyed);
    // Compiles and links `program`'s text for the device's dialect and binds its resources by name.
    Result<GLuint> linkProgram(const CompiledProgram& program);
    static GlSources sourcesOf(const CompiledProgram& program, ShaderDialect dialect);
    Result<GLuint> linkSources(const std::string& programName, const GlSources& sources, const std::vector<ShaderResource>& resources);
    // The program of `pipeline` specialised with its constants (0 when it has none).
    Result<GLuint> specialize(const GlProgram& program, const std::vector<SpecializationConstant>& constants);
    GLuint programOf(const GlPipeline& pipeline) const { return pipeline.specialized ? pipeline.specialized : pipeline.program; }
    Result<GLuint> compileShader(const std::string& programName, GLenum type, const std::string& source);
    Result<GLuint> buildProgram(const std::string& programName, const std::vector<std::pair<GLenum, std::string>>& sources);
    void bindResourcesByName(GLuint program, const std::vector<ShaderResource>& resources);

    // ---- The checks only GL makes (gl_checks.cpp) -----------------------------------------
    Status checkTextureUnits(const CompiledProgram& program) const;

    // ---- Commands (gl_commands.cpp) -------------------------------------------------------
    // The attachments of a render pass the shared validation accepted, and their one extent.
    // Filled into `out` (cleared first: the device's passTargets_ keeps its capacity).
    void passTargets(const RenderPassDesc& pass, PassTargets& out) const;
    void bindResources(const BindingSet& b);
    void unbindResources(const BindingSet& b);
    Status encodeRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws, const PassTargets& targets);
    void encodeDraw(const DrawDesc& d);
    void encodeDispatch(GLuint program, const DispatchDesc& d);

    // ---- Framebuffer cache (gl_framebuffers.cpp) ------------------------------------------
    GLenum depthAttachmentPoint(Format f) const;
    Result<GLuint> framebuffer(const ColorTargets& colors, const GlTexture* depth, uint32_t depthMip);
    void forgetFbosOf(GLuint texture);

    // ---- Readback (gl_readback.cpp) -------------------------------------------------------
    Status readLevel(const GlTexture& t, uint32_t mip, void* out);
    Status copyDepthEs(const GlTexture& t, uint32_t mip, uint32_t w, uint32_t h, float* out);

    std::unique_ptr<GlPlatform> platform_;
    Api api_;
    DeviceOptions options_;
    GlFunctions gl_;
    bool loaded_ = false;
    DeviceCaps caps_;
    std::set<std::string> extensions_;
    bool debugOutput_ = false;
    std::vector<std::string> messages_;
    std::string pendingError_;  // the first GL error since the current call began

    uint16_t serial_;
    HandlePool<TextureTag, GlTexture> textures_;
    HandlePool<BufferTag, GlBuffer> buffers_;
    HandlePool<SamplerTag, GlSampler> samplers_;
    HandlePool<ProgramTag, GlProgram> programs_;
    HandlePool<PipelineTag, GlPipeline> pipelines_;
    HandlePool<TimerTag, GlTimer> timers_;
    const decltype(validation::poolLookup(textures_, buffers_, samplers_, programs_, pipelines_, timers_)) lookup_ = validation::poolLookup(
        textures_, buffers_, samplers_, programs_, pipelines_, timers_);

    std::map<GLuint, uint32_t> programUsers_;  // pipelines per GL program object
    std::set<GLuint> destroyedPrograms_;       // destroyed programs whose pipelines still draw
    std::map<FboKey, GLuint> fbos_;
    FboKey fboKey_;            // reused to build the key of each lookup
    PassTargets passTargets_;  // reused by every render pass
    // For stats(): texture and buffer storage (the textures readTexture copies depth through
    // included, and counted again as readback copies), framebuffer objects, and the bytes of
    // the HAL's textures and buffers alive.
    ObjectCount storage_, readbackCopies_, framebufferCount_;
    uint64_t bytesHeld_ = 0;
    GLuint nearestSampler_ = 0;
    GLuint emptyVao_ = 0;
    GLuint depthCopyProgram_ = 0;
};

}  // namespace sfx::gl
