// The GL driver: one implementation of sfx::Device for GL ES 3.x and desktop GL core, over any
// GlPlatform. GL runs commands as they are issued, so the HAL's call order is kept by calling
// GL in that order; flush() is glFinish.
#include "gl_functions.hpp"
#include "gl_platform.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "sfx/half.hpp"
#include "sfx/gl_device.hpp"
#include "sfx/hal_validation.hpp"

namespace sfx::gl {
namespace {

using Clock = std::chrono::steady_clock;

// The platform whose context is current on this thread, as far as the SDK knows; devices
// re-make theirs current when another one (maybe of the other platform) was used last.
thread_local GlPlatform* gCurrentPlatform = nullptr;

struct GlFormat {
    GLenum internalFormat;
    GLenum format;  // for uploads and desktop depth reads
    GLenum type;
};

GlFormat glFormat(Format f) {
    switch (f) {
    case Format::R8: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
    case Format::RGBA8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
    case Format::R16F: return {GL_R16F, GL_RED, GL_HALF_FLOAT};
    case Format::RG16F: return {GL_RG16F, GL_RG, GL_HALF_FLOAT};
    case Format::RGBA16F: return {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT};
    case Format::R32F: return {GL_R32F, GL_RED, GL_FLOAT};
    case Format::RG32F: return {GL_RG32F, GL_RG, GL_FLOAT};
    case Format::RGBA32F: return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    case Format::R32UI: return {GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT};
    case Format::D16: return {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT};
    case Format::D24S8: return {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
    case Format::D32F: return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT};
    default: return {0, 0, 0};
    }
}

bool isHalfFormat(Format f) { return f == Format::R16F || f == Format::RG16F || f == Format::RGBA16F; }
bool isFloat32Format(Format f) { return f == Format::R32F || f == Format::RG32F || f == Format::RGBA32F; }


const char* glErrorName(GLenum e) {
    switch (e) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "GL error";
    }
}

GLenum compareFunc(CompareOp op) {
    switch (op) {
    case CompareOp::Never: return GL_NEVER;
    case CompareOp::Less: return GL_LESS;
    case CompareOp::LessEqual: return GL_LEQUAL;
    case CompareOp::Greater: return GL_GREATER;
    case CompareOp::GreaterEqual: return GL_GEQUAL;
    case CompareOp::Equal: return GL_EQUAL;
    case CompareOp::NotEqual: return GL_NOTEQUAL;
    case CompareOp::Always: return GL_ALWAYS;
    }
    return GL_LESS;
}

GLenum blendFactor(BlendFactor f) {
    switch (f) {
    case BlendFactor::Zero: return GL_ZERO;
    case BlendFactor::One: return GL_ONE;
    case BlendFactor::SrcAlpha: return GL_SRC_ALPHA;
    case BlendFactor::OneMinusSrcAlpha: return GL_ONE_MINUS_SRC_ALPHA;
    case BlendFactor::DstAlpha: return GL_DST_ALPHA;
    case BlendFactor::OneMinusDstAlpha: return GL_ONE_MINUS_DST_ALPHA;
    }
    return GL_ONE;
}

GLenum wrapMode(AddressMode a) {
    switch (a) {
    case AddressMode::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case AddressMode::Repeat: return GL_REPEAT;
    case AddressMode::MirroredRepeat: return GL_MIRRORED_REPEAT;
    }
    return GL_CLAMP_TO_EDGE;
}

std::string baseName(const char* path) {
    const char* slash = std::strrchr(path, '/');
    return slash ? slash + 1 : path;
}

std::string str(uint64_t v) { return std::to_string(v); }

// ESSL 300 pair for reading depth on GL ES, where glReadPixels cannot read depth: a full-screen
// pass copies the depth texture's base level into an R32F target that can be read back.
const char* kDepthCopyVertex =
    "#version 300 es\n"
    "void main() {\n"
    "    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));\n"
    "    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n"
    "}\n";
const char* kDepthCopyFragment =
    "#version 300 es\n"
    "precision highp float;\n"
    "uniform highp sampler2D uDepth;\n"
    "layout(location = 0) out vec4 outDepth;\n"
    "void main() { outDepth = vec4(texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).x, 0.0, 0.0, 1.0); }\n";

struct GlTexture {
    TextureDesc desc;
    GLuint name = 0;
};
struct GlBuffer {
    BufferDesc desc;
    GLuint name = 0;
};
struct GlSampler {
    SamplerDesc desc;
    GLuint name = 0;
};
struct GlProgram {
    std::string label;
    GLuint name = 0;
    bool compute = false;
    std::vector<ShaderResource> resources;
};
struct GlPipeline {
    bool compute = false;
    ProgramHandle program;
    GraphicsPipelineDesc desc;  // graphics state; program field unused
    GLuint vao = 0;
};
struct GlTimer {
    bool begun = false, ended = false;
    Clock::time_point begin{}, end{};
    double lastMs = -1;  // the last finished measurement
};

// A checked GL call inside GlDevice: glGetError after it when options.validation (see checked()).
#define GL(fn, ...) checked(#fn, __FILE__, __LINE__, gl_.fn __VA_OPT__(, ) __VA_ARGS__)

// Attachments of a framebuffer object: (texture name << 32 | mip) per colour, then depth.
using FboKey = std::vector<uint64_t>;

class GlDevice final : public Device {
public:
    GlDevice(std::unique_ptr<GlPlatform> platform, Api api, const DeviceOptions& options)
        : platform_(std::move(platform)),
          api_(api),
          options_(options),
          serial_(nextDeviceSerial()),
          textures_(serial_, "texture"),
          buffers_(serial_, "buffer"),
          samplers_(serial_, "sampler"),
          programs_(serial_, "program"),
          pipelines_(serial_, "pipeline"),
          timers_(serial_, "timer") {}

    ~GlDevice() override {
        if (!loaded_ || !makeCurrent()) return;
        textures_.forEachAlive([&](GlTexture& t) { gl_.glDeleteTextures(1, &t.name); });
        buffers_.forEachAlive([&](GlBuffer& b) { gl_.glDeleteBuffers(1, &b.name); });
        samplers_.forEachAlive([&](GlSampler& s) { gl_.glDeleteSamplers(1, &s.name); });
        programs_.forEachAlive([&](GlProgram& p) { gl_.glDeleteProgram(p.name); });
        pipelines_.forEachAlive([&](GlPipeline& p) { gl_.glDeleteVertexArrays(1, &p.vao); });
        for (auto& [key, fbo] : fbos_) gl_.glDeleteFramebuffers(1, &fbo);
        if (nearestSampler_) gl_.glDeleteSamplers(1, &nearestSampler_);
        if (emptyVao_) gl_.glDeleteVertexArrays(1, &emptyVao_);
        if (depthCopyProgram_) gl_.glDeleteProgram(depthCopyProgram_);
        if (debugOutput_) {
            gl_.glDisable(GL_DEBUG_OUTPUT);
            gl_.glDebugMessageCallback(nullptr, nullptr);
        }
        gl_.glFinish();
        platform_->release();
        if (gCurrentPlatform == platform_.get()) gCurrentPlatform = nullptr;
    }

    // Loads entry points and fills the caps; the platform's context is current.
    Status init(CapabilityCeiling ceiling) {
        if (!makeCurrent()) return {StatusCode::BackendUnavailable, "GL: the context cannot be made current"};
#define SFX_GL_LOAD(type, fn)                                                                            \
    gl_.fn = reinterpret_cast<type>(platform_->getProcAddress(#fn));                                     \
    if (!gl_.fn) return {StatusCode::BackendUnavailable, std::string("GL: entry point ") + #fn + " is missing"};
        SFX_GL_REQUIRED(SFX_GL_LOAD)
#undef SFX_GL_LOAD
        loaded_ = true;
        while (gl_.glGetError() != GL_NO_ERROR) {
        }
        const char* version = reinterpret_cast<const char*>(gl_.glGetString(GL_VERSION));
        const char* renderer = reinterpret_cast<const char*>(gl_.glGetString(GL_RENDERER));
        if (!version) return {StatusCode::BackendUnavailable, "GL: glGetString(GL_VERSION) returned NULL"};
        const bool es = std::strncmp(version, "OpenGL ES", 9) == 0;
        if (es != (api_ == Api::GLES))
            return {StatusCode::BackendUnavailable, std::string("GL: asked for ") + (api_ == Api::GLES ? "GL ES" : "desktop GL") +
                                                        ", the context is '" + version + "'"};
        GLint major = 0, minor = 0;
        gl_.glGetIntegerv(GL_MAJOR_VERSION, &major);
        gl_.glGetIntegerv(GL_MINOR_VERSION, &minor);
        const int v = major * 10 + minor;
        if (es ? v < 30 : v < 33)
            return {StatusCode::BackendUnavailable, std::string("GL: '") + version + "' is older than " +
                                                        (es ? "GL ES 3.0" : "desktop GL 3.3")};
        GLint extensionCount = 0;
        gl_.glGetIntegerv(GL_NUM_EXTENSIONS, &extensionCount);
        for (GLint i = 0; i < extensionCount; ++i)
            if (const GLubyte* e = gl_.glGetStringi(GL_EXTENSIONS, GLuint(i)))
                extensions_.insert(reinterpret_cast<const char*>(e));

        const bool modern = es ? v >= 31 : v >= 43;  // compute, storage buffers and images, atomics
        if (modern || extensions_.count("GL_KHR_debug")) {
#define SFX_GL_LOAD(type, fn) gl_.fn = reinterpret_cast<type>(platform_->getProcAddress(#fn));
            SFX_GL_OPTIONAL(SFX_GL_LOAD)
#undef SFX_GL_LOAD
        }
        // GL ES 3.0/3.1 name KHR_debug's entry points with a suffix.
        const bool coreDebug = es ? v >= 32 : v >= 43;
        if (!coreDebug && es && extensions_.count("GL_KHR_debug")) {
            gl_.glDebugMessageCallback =
                reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKPROC>(platform_->getProcAddress("glDebugMessageCallbackKHR"));
            gl_.glDebugMessageControl =
                reinterpret_cast<PFNGLDEBUGMESSAGECONTROLPROC>(platform_->getProcAddress("glDebugMessageControlKHR"));
        }
        const bool haveDebug = (coreDebug || extensions_.count("GL_KHR_debug")) && gl_.glDebugMessageCallback &&
                               gl_.glDebugMessageControl;

        DeviceCaps& c = caps_;
        c.backend = es ? BackendKind::GLES : BackendKind::GL;
        c.platform = platform_->name();
        // Desktop GL_VERSION starts with the number ("4.5 (Core Profile) Mesa ..."); name the API.
        c.apiName = es ? std::string(version) : "OpenGL " + std::string(version);
        c.apiMajor = uint32_t(major);
        c.apiMinor = uint32_t(minor);
        c.deviceName = renderer ? renderer : "unknown";
        c.ceiling = ceiling;
        const bool full = modern && ceiling == CapabilityCeiling::None;
        c.dialect = es ? (full ? ShaderDialect::Essl310 : ShaderDialect::Essl300)
                       : (full ? ShaderDialect::Glsl450 : ShaderDialect::Glsl330);
        c.computeShaders = full;
        c.storageBuffers = full;
        c.atomics = full;
        c.storageImages = full;
        c.clipDepth = ClipDepthRange::MinusOneToOne;
        c.origin = FramebufferOrigin::LowerLeft;
        c.timing = TimingSource::WallClockAfterFinish;

        auto geti = [&](GLenum e) {
            GLint x = 0;
            gl_.glGetIntegerv(e, &x);
            return uint32_t(std::max(x, 0));
        };
        auto get64 = [&](GLenum e) {
            GLint64 x = 0;
            gl_.glGetInteger64v(e, &x);
            return uint64_t(std::max<GLint64>(x, 0));
        };
        c.limits.maxTextureSize = geti(GL_MAX_TEXTURE_SIZE);
        c.limits.maxColorAttachments = std::min(geti(GL_MAX_COLOR_ATTACHMENTS), geti(GL_MAX_DRAW_BUFFERS));
        c.limits.maxUniformBlockSize = get64(GL_MAX_UNIFORM_BLOCK_SIZE);
        c.limits.maxStorageBufferSize = full ? get64(GL_MAX_SHADER_STORAGE_BLOCK_SIZE) : 0;
        c.limits.maxBufferSize = uint64_t(1) << 30;  // GL has no query; generous for screen-space buffers
        c.limits.maxComputeWorkGroupInvocations = full ? geti(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS) : 0;
        c.limits.maxTextureBindings = geti(GL_MAX_TEXTURE_IMAGE_UNITS);
        uniformOffsetAlignment_ = std::max<uint32_t>(1, geti(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT));
        storageOffsetAlignment_ = modern ? std::max<uint32_t>(1, geti(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT)) : 1;

        // Float colour targets are core in desktop GL and GL ES 3.2; GL ES 3.0/3.1 (and a
        // device under the ES 3.0 ceiling) have them only through EXT_color_buffer_float.
        const bool colorBufferFloat = !es || extensions_.count("GL_EXT_color_buffer_float") ||
                                      (v >= 32 && ceiling == CapabilityCeiling::None);
        const bool colorBufferHalf = colorBufferFloat || extensions_.count("GL_EXT_color_buffer_half_float");
        float32Filterable_ = !es || extensions_.count("GL_OES_texture_float_linear");
        for (size_t f = 1; f < size_t(Format::Count); ++f) {
            const Format format = Format(f);
            c.sampledFormat[f] = true;
            c.renderableFormat[f] = isHalfFormat(format) ? colorBufferHalf
                                    : isFloat32Format(format) ? colorBufferFloat
                                                              : true;
        }
        c.floatRenderTargets = c.renderableFormat[size_t(Format::R32F)] && c.renderableFormat[size_t(Format::RG16F)] &&
                               c.renderableFormat[size_t(Format::RGBA16F)];
        c.float32Filterable = float32Filterable_;

        // A host's context keeps its own debug callback: the SDK does not replace it (nor
        // disable debug output when it goes away); it relies on its per-call checks there.
        if (options_.validation && haveDebug && !hostContext()) {
            gl_.glEnable(GL_DEBUG_OUTPUT);
            gl_.glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
            gl_.glDebugMessageCallback(&GlDevice::debugCallback, this);
            gl_.glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
            debugOutput_ = true;
        }

        // The sampler for unfiltered formats (integer, depth, unfilterable float) and for
        // bindings without one: nearest within the binding's mips, clamped.
        GL(glGenSamplers, 1, &nearestSampler_);
        setSamplerState(nearestSampler_, SamplerDesc{});
        GL(glGenVertexArrays, 1, &emptyVao_);
        GL(glPixelStorei, GL_PACK_ALIGNMENT, 1);
        GL(glPixelStorei, GL_UNPACK_ALIGNMENT, 1);
        return takeDeviceError(Status::ok());
    }

    const DeviceCaps& caps() const override { return caps_; }

    // ---- Textures -------------------------------------------------------------------------

    Result<TextureHandle> createTexture(const TextureDesc& desc) override {
        SFX_TRY(validation::textureDesc(desc, caps_));
        SFX_TRY(enter());
        const GlFormat f = glFormat(desc.format);
        GlTexture t{desc, 0};
        GL(glGenTextures, 1, &t.name);
        GL(glBindTexture, GL_TEXTURE_2D, t.name);
        GL(glTexStorage2D, GL_TEXTURE_2D, GLsizei(desc.mipLevels), f.internalFormat, GLsizei(desc.width),
           GLsizei(desc.height));
        // Depth is read as a value in shaders (texelFetch), never compared.
        if (isDepthFormat(desc.format)) GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
        GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        GL(glBindTexture, GL_TEXTURE_2D, 0);
        Status s = takeDeviceError(Status::ok());
        if (!s) {
            gl_.glDeleteTextures(1, &t.name);
            return s;
        }
        return textures_.insert(t);
    }

    Status destroyTexture(TextureHandle h) override {
        SFX_TRY(textures_.check(h, "texture"));
        SFX_TRY(enter());
        GlTexture t = textures_.remove(h);
        forgetFbosOf(t.name);
        GL(glDeleteTextures, 1, &t.name);
        return takeDeviceError(Status::ok());
    }

    Result<TextureDesc> textureDesc(TextureHandle h) const override {
        SFX_TRY(textures_.check(h, "texture"));
        return textures_.get(h).desc;
    }

    Status writeTexture(TextureHandle h, uint32_t mip, const void* data, size_t bytes) override {
        SFX_TRY(textures_.check(h, "texture"));
        const GlTexture& t = textures_.get(h);
        SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
        if (!data) return invalidArgument("data", "null", "a pointer to the level's bytes");
        SFX_TRY(enter());
        const GlFormat f = glFormat(t.desc.format);
        GL(glBindBuffer, GL_PIXEL_UNPACK_BUFFER, 0);
        GL(glActiveTexture, GL_TEXTURE0);
        GL(glBindTexture, GL_TEXTURE_2D, t.name);
        GL(glTexSubImage2D, GL_TEXTURE_2D, GLint(mip), 0, 0, GLsizei(mipExtent(t.desc.width, mip)),
           GLsizei(mipExtent(t.desc.height, mip)), f.format, f.type, data);
        GL(glBindTexture, GL_TEXTURE_2D, 0);
        return takeDeviceError(Status::ok());
    }

    Status readTexture(TextureHandle h, uint32_t mip, void* out, size_t bytes) override {
        SFX_TRY(textures_.check(h, "texture"));
        const GlTexture t = textures_.get(h);
        SFX_TRY(validation::textureBytes(t.desc, mip, bytes, "bytes"));
        if (!out) return invalidArgument("out", "null", "a pointer to the level's bytes");
        SFX_TRY(enter());
        return takeDeviceError(readLevel(t, mip, out));
    }

    // ---- Buffers and samplers -------------------------------------------------------------

    Result<BufferHandle> createBuffer(const BufferDesc& desc) override {
        SFX_TRY(validation::bufferDesc(desc, caps_));
        SFX_TRY(enter());
        GlBuffer b{desc, 0};
        GL(glGenBuffers, 1, &b.name);
        GL(glBindBuffer, GL_COPY_WRITE_BUFFER, b.name);
        // Zero-filled like every backend's new buffer, from a small block rather than a host
        // copy of the whole buffer (which may be up to maxBufferSize).
        GL(glBufferData, GL_COPY_WRITE_BUFFER, GLsizeiptr(desc.size), nullptr, GL_DYNAMIC_DRAW);
        static const std::vector<uint8_t> kZeros(64 * 1024, 0);
        for (uint64_t offset = 0; offset < desc.size; offset += kZeros.size())
            GL(glBufferSubData, GL_COPY_WRITE_BUFFER, GLintptr(offset),
               GLsizeiptr(std::min<uint64_t>(kZeros.size(), desc.size - offset)), kZeros.data());
        GL(glBindBuffer, GL_COPY_WRITE_BUFFER, 0);
        Status s = takeDeviceError(Status::ok());
        if (!s) {
            gl_.glDeleteBuffers(1, &b.name);
            return s;
        }
        return buffers_.insert(b);
    }

    Status destroyBuffer(BufferHandle h) override {
        SFX_TRY(buffers_.check(h, "buffer"));
        SFX_TRY(enter());
        GlBuffer b = buffers_.remove(h);
        GL(glDeleteBuffers, 1, &b.name);
        return takeDeviceError(Status::ok());
    }

    Status writeBuffer(BufferHandle h, uint64_t offset, const void* data, size_t bytes) override {
        SFX_TRY(buffers_.check(h, "buffer"));
        const GlBuffer& b = buffers_.get(h);
        SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "writeBuffer range"));
        if (!data) return invalidArgument("data", "null", "a pointer to the bytes to write");
        SFX_TRY(enter());
        GL(glBindBuffer, GL_COPY_WRITE_BUFFER, b.name);
        GL(glBufferSubData, GL_COPY_WRITE_BUFFER, GLintptr(offset), GLsizeiptr(bytes), data);
        GL(glBindBuffer, GL_COPY_WRITE_BUFFER, 0);
        return takeDeviceError(Status::ok());
    }

    Status readBuffer(BufferHandle h, uint64_t offset, void* out, size_t bytes) override {
        SFX_TRY(buffers_.check(h, "buffer"));
        const GlBuffer& b = buffers_.get(h);
        SFX_TRY(validation::bufferRange(b.desc, offset, bytes, "readBuffer range"));
        if (!out) return invalidArgument("out", "null", "a pointer for the bytes read");
        SFX_TRY(enter());
        // GL ES has no glGetBufferSubData; mapping for reading works on both APIs.
        GL(glBindBuffer, GL_COPY_READ_BUFFER, b.name);
        const void* mapped = GL(glMapBufferRange, GL_COPY_READ_BUFFER, GLintptr(offset), GLsizeiptr(bytes), GL_MAP_READ_BIT);
        if (mapped) {
            std::memcpy(out, mapped, bytes);
            GL(glUnmapBuffer, GL_COPY_READ_BUFFER);
        }
        GL(glBindBuffer, GL_COPY_READ_BUFFER, 0);
        Status s = takeDeviceError(Status::ok());
        if (s && !mapped) return {StatusCode::DeviceError, "readBuffer: glMapBufferRange returned NULL"};
        return s;
    }

    Result<SamplerHandle> createSampler(const SamplerDesc& desc) override {
        SFX_TRY(validation::samplerDesc(desc));
        SFX_TRY(enter());
        GlSampler s{desc, 0};
        GL(glGenSamplers, 1, &s.name);
        setSamplerState(s.name, desc);
        Status st = takeDeviceError(Status::ok());
        if (!st) return st;
        return samplers_.insert(s);
    }

    Status destroySampler(SamplerHandle h) override {
        SFX_TRY(samplers_.check(h, "sampler"));
        SFX_TRY(enter());
        GlSampler s = samplers_.remove(h);
        GL(glDeleteSamplers, 1, &s.name);
        return takeDeviceError(Status::ok());
    }

    // ---- Programs and pipelines -----------------------------------------------------------

    Result<ProgramHandle> createProgram(const CompiledProgram& program) override {
        // The shared check names what the device lacks before looking for the dialect's text.
        SFX_TRY(validation::program(program, caps_));
        SFX_TRY(enter());
        std::vector<std::pair<GLenum, std::string>> sources;
        for (const StageCode& s : program.stages) {
            const GLenum type = s.stage == ShaderStage::Vertex     ? GL_VERTEX_SHADER
                                : s.stage == ShaderStage::Fragment ? GL_FRAGMENT_SHADER
                                                                   : GL_COMPUTE_SHADER;
            sources.push_back({type, s.glsl[size_t(caps_.dialect)]});
        }
        Result<GLuint> linked = buildProgram(program.name, sources);
        if (!linked) return takeDeviceError(linked.status());
        const GLuint name = linked.value();
        bindResourcesByName(name, program.resources);
        Status s = takeDeviceError(Status::ok());
        if (!s) {
            gl_.glDeleteProgram(name);
            return s;
        }
        return programs_.insert(GlProgram{program.name, name, program.isCompute(), program.resources});
    }

    Status destroyProgram(ProgramHandle h) override {
        SFX_TRY(programs_.check(h, "program"));
        SFX_TRY(enter());
        GlProgram p = programs_.remove(h);
        GL(glDeleteProgram, p.name);
        return takeDeviceError(Status::ok());
    }

    Result<PipelineHandle> createGraphicsPipeline(const GraphicsPipelineDesc& desc) override {
        SFX_TRY(programs_.check(desc.program, "GraphicsPipelineDesc.program"));
        if (programs_.get(desc.program).compute)
            return Status{StatusCode::InvalidArgument, "GraphicsPipelineDesc.program is a compute program"};
        SFX_TRY(validation::graphicsPipelineShape(desc, caps_));
        SFX_TRY(validation::graphicsPipelineState(desc, caps_));
        SFX_TRY(enter());
        GlPipeline p;
        p.program = desc.program;
        p.desc = desc;
        p.desc.debugName = "";
        // The VAO holds which attributes are enabled; the buffer is attached per draw.
        GL(glGenVertexArrays, 1, &p.vao);
        GL(glBindVertexArray, p.vao);
        for (const VertexAttribute& a : desc.vertexLayout.attributes) GL(glEnableVertexAttribArray, a.location);
        GL(glBindVertexArray, 0);
        Status s = takeDeviceError(Status::ok());
        if (!s) {
            gl_.glDeleteVertexArrays(1, &p.vao);
            return s;
        }
        return pipelines_.insert(std::move(p));
    }

    Result<PipelineHandle> createComputePipeline(const ComputePipelineDesc& desc) override {
        SFX_TRY(programs_.check(desc.program, "ComputePipelineDesc.program"));
        if (!programs_.get(desc.program).compute)
            return Status{StatusCode::InvalidArgument, "ComputePipelineDesc.program is not a compute program"};
        GlPipeline p;
        p.compute = true;
        p.program = desc.program;
        return pipelines_.insert(std::move(p));
    }

    Status destroyPipeline(PipelineHandle h) override {
        SFX_TRY(pipelines_.check(h, "pipeline"));
        SFX_TRY(enter());
        GlPipeline p = pipelines_.remove(h);
        if (p.vao) GL(glDeleteVertexArrays, 1, &p.vao);
        return takeDeviceError(Status::ok());
    }

    // ---- Timers ---------------------------------------------------------------------------

    Result<TimerHandle> createTimer() override { return timers_.insert(GlTimer{}); }
    Status destroyTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        timers_.remove(h);
        return Status::ok();
    }
    // GL timer queries on llvmpipe report far less than the work takes; wall clock between
    // two glFinish calls is what the benchmarks can trust.
    Status beginTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        SFX_TRY(enter());
        GL(glFinish);
        GlTimer& t = timers_.get(h);
        t.begun = true;
        t.ended = false;
        t.begin = Clock::now();
        return takeDeviceError(Status::ok());
    }
    Status endTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        if (!timers_.get(h).begun) return {StatusCode::InvalidArgument, "endTimer: timer was not begun"};
        SFX_TRY(enter());
        GL(glFinish);
        GlTimer& t = timers_.get(h);
        t.end = Clock::now();
        t.begun = false;
        t.ended = true;
        t.lastMs = std::chrono::duration<double, std::milli>(t.end - t.begin).count();
        return takeDeviceError(Status::ok());
    }
    Result<TimerReading> readTimer(TimerHandle h) override {
        SFX_TRY(timers_.check(h, "timer"));
        const GlTimer& t = timers_.get(h);
        if (t.lastMs < 0) return Status{StatusCode::InvalidArgument, "readTimer: timer has no finished measurement"};
        return TimerReading{t.lastMs, caps_.timing};
    }

    // ---- Commands -------------------------------------------------------------------------

    Status renderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) override {
        SFX_TRY(enter());
        return takeDeviceError(renderPassImpl(pass, draws));
    }

    Status dispatch(const DispatchDesc& d) override {
        SFX_TRY(validation::dispatchGroups(d, caps_));
        SFX_TRY(pipelines_.check(d.pipeline, "DispatchDesc.pipeline"));
        const GlPipeline& p = pipelines_.get(d.pipeline);
        if (!p.compute) return {StatusCode::InvalidArgument, "DispatchDesc.pipeline is a graphics pipeline"};
        SFX_TRY(programs_.check(p.program, "DispatchDesc.pipeline's program"));
        const GlProgram& program = programs_.get(p.program);
        SFX_TRY(checkBindingsMatch(program, d.bindings, "DispatchDesc.bindings"));
        SFX_TRY(checkResources(d.bindings, &program));
        SFX_TRY(enter());
        GL(glUseProgram, program.name);
        bindResources(d.bindings);
        // Earlier passes' writes visible to the dispatch, and its writes to what follows.
        GL(glMemoryBarrier, GL_ALL_BARRIER_BITS);
        GL(glDispatchCompute, d.groupsX, d.groupsY, d.groupsZ);
        GL(glMemoryBarrier, GL_ALL_BARRIER_BITS);
        unbindResources(d.bindings);
        GL(glUseProgram, 0);
        return takeDeviceError(Status::ok());
    }

    Status flush() override {
        SFX_TRY(enter());
        GL(glFinish);
        return takeDeviceError(Status::ok());
    }

    std::vector<std::string> takeValidationMessages() override {
        std::vector<std::string> m;
        m.swap(messages_);
        return m;
    }

private:
    // ---- Context and error checking -------------------------------------------------------

    bool makeCurrent() {
        if (gCurrentPlatform == platform_.get()) return true;
        if (gCurrentPlatform) gCurrentPlatform->release();
        gCurrentPlatform = nullptr;
        if (!platform_->makeCurrent()) return false;
        gCurrentPlatform = platform_.get();
        return true;
    }

    Status enter() {
        if (!makeCurrent())
            return {StatusCode::DeviceError, std::string("GL: cannot make the ") + platform_->name() + " context current"};
        pendingError_.clear();
        // Errors the host's own calls left pending are not this call's failure: clear them so
        // the per-call checks see only what the SDK did.
        if (options_.validation && hostContext())
            while (gl_.glGetError() != GL_NO_ERROR) {
            }
        return Status::ok();
    }

    bool hostContext() const { return std::string_view(platform_->name()) == "host"; }

    // A call's result once GL has had its say: the first GL error caught since enter() wins.
    Status takeDeviceError(Status s) {
        if (pendingError_.empty()) return s;
        std::string e;
        e.swap(pendingError_);
        if (!s) return s;
        return {StatusCode::DeviceError, e};
    }

    void checkError(const char* fn, const char* file, int line) {
        if (!options_.validation) return;
        for (GLenum e; (e = gl_.glGetError()) != GL_NO_ERROR;) {
            std::string m = std::string(fn) + ": " + glErrorName(e) + " at " + baseName(file) + ":" + str(uint64_t(line));
            messages_.push_back(m);
            if (pendingError_.empty()) pendingError_ = m;
        }
    }

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

    static void APIENTRY debugCallback(GLenum source, GLenum type, GLuint, GLenum, GLsizei, const GLchar* message,
                                         const void* user) {
        // Compile and link failures reach the caller as ShaderError with the info log.
        if (type != GL_DEBUG_TYPE_ERROR || source == GL_DEBUG_SOURCE_SHADER_COMPILER) return;
        auto* self = static_cast<GlDevice*>(const_cast<void*>(user));
        self->messages_.push_back(std::string("GL debug: ") + (message ? message : ""));
    }

    // ---- Helpers --------------------------------------------------------------------------

    void setSamplerState(GLuint s, const SamplerDesc& d) {
        // Always a mipmapped min filter, so lods past the binding's base are reachable.
        GLenum minFilter;
        if (d.minFilter == Filter::Nearest)
            minFilter = d.mipFilter == Filter::Nearest ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_LINEAR;
        else
            minFilter = d.mipFilter == Filter::Nearest ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR;
        GL(glSamplerParameteri, s, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
        GL(glSamplerParameteri, s, GL_TEXTURE_MAG_FILTER, d.magFilter == Filter::Nearest ? GL_NEAREST : GL_LINEAR);
        GL(glSamplerParameteri, s, GL_TEXTURE_WRAP_S, GLint(wrapMode(d.address)));
        GL(glSamplerParameteri, s, GL_TEXTURE_WRAP_T, GLint(wrapMode(d.address)));
        GL(glSamplerParameteri, s, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    }

    bool filterable(Format f) const {
        if (isIntegerFormat(f) || isDepthFormat(f)) return false;
        return !isFloat32Format(f) || float32Filterable_;
    }

    Result<GLuint> compileShader(const std::string& programName, GLenum type, const std::string& source) {
        const GLuint shader = GL(glCreateShader, type);
        const char* text = source.c_str();
        GL(glShaderSource, shader, 1, &text, nullptr);
        GL(glCompileShader, shader);
        GLint ok = 0;
        GL(glGetShaderiv, shader, GL_COMPILE_STATUS, &ok);
        if (ok) return shader;
        GLint length = 0;
        GL(glGetShaderiv, shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        GL(glGetShaderInfoLog, shader, GLsizei(log.size()), nullptr, log.data());
        GL(glDeleteShader, shader);
        const char* stage = type == GL_VERTEX_SHADER ? "vertex" : type == GL_FRAGMENT_SHADER ? "fragment" : "compute";
        return Status{StatusCode::ShaderError, "program '" + programName + "' " + stage + " stage failed to compile (" +
                                                   toString(caps_.dialect) + "): " + log.c_str()};
    }

    Result<GLuint> buildProgram(const std::string& programName, const std::vector<std::pair<GLenum, std::string>>& sources) {
        std::vector<GLuint> shaders;
        auto deleteShaders = [&] {
            for (GLuint s : shaders) GL(glDeleteShader, s);
        };
        for (const auto& [type, text] : sources) {
            Result<GLuint> s = compileShader(programName, type, text);
            if (!s) {
                deleteShaders();
                return s.status();
            }
            shaders.push_back(s.value());
        }
        const GLuint program = GL(glCreateProgram);
        for (GLuint s : shaders) GL(glAttachShader, program, s);
        GL(glLinkProgram, program);
        deleteShaders();  // flagged; they go with the program
        GLint ok = 0;
        GL(glGetProgramiv, program, GL_LINK_STATUS, &ok);
        if (ok) return program;
        GLint length = 0;
        GL(glGetProgramiv, program, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        GL(glGetProgramInfoLog, program, GLsizei(log.size()), nullptr, log.data());
        GL(glDeleteProgram, program);
        return Status{StatusCode::ShaderError, "program '" + programName + "' failed to link (" +
                                                   toString(caps_.dialect) + "): " + log.c_str()};
    }

    // SPIR-V to ESSL 300 / GLSL 330 drops binding qualifiers, so bind by the reflected GL name
    // (harmless where the qualifier survived). Texture unit = uniform block binding = the
    // reflected binding number.
    void bindResourcesByName(GLuint program, const std::vector<ShaderResource>& resources) {
        GL(glUseProgram, program);
        for (const ShaderResource& r : resources) {
            switch (r.kind) {
            case ResourceKind::SampledTexture: {
                const GLint loc = GL(glGetUniformLocation, program, r.glName.c_str());
                if (loc >= 0) GL(glUniform1i, loc, GLint(r.binding));
                break;
            }
            case ResourceKind::UniformBuffer: {
                const GLuint index = GL(glGetUniformBlockIndex, program, r.glName.c_str());
                if (index != GL_INVALID_INDEX) GL(glUniformBlockBinding, program, index, r.binding);
                break;
            }
            case ResourceKind::StorageBuffer:
                // GL ES has no glShaderStorageBlockBinding; ESSL 310 keeps binding= instead.
                if (api_ == Api::DesktopGL && gl_.glShaderStorageBlockBinding && gl_.glGetProgramResourceIndex) {
                    const GLuint index = GL(glGetProgramResourceIndex, program, GL_SHADER_STORAGE_BLOCK, r.glName.c_str());
                    if (index != GL_INVALID_INDEX) GL(glShaderStorageBlockBinding, program, index, r.binding);
                }
                break;
            case ResourceKind::StorageImage:
                // Image units cannot be reassigned on GL ES; high-tier dialects keep binding=.
                if (api_ == Api::DesktopGL) {
                    const GLint loc = GL(glGetUniformLocation, program, r.glName.c_str());
                    if (loc >= 0) GL(glUniform1i, loc, GLint(r.binding));
                }
                break;
            }
        }
        GL(glUseProgram, 0);
    }

    // Every reflected resource bound, and nothing bound the program lacks, by kind and number.
    Status checkBindingsMatch(const GlProgram& program, const BindingSet& b, const char* where) {
        auto has = [&](ResourceKind kind, uint32_t binding) {
            switch (kind) {
            case ResourceKind::SampledTexture:
                return std::any_of(b.textures.begin(), b.textures.end(), [&](const auto& x) { return x.binding == binding; });
            case ResourceKind::UniformBuffer:
                return std::any_of(b.uniformBuffers.begin(), b.uniformBuffers.end(),
                                   [&](const auto& x) { return x.binding == binding; });
            case ResourceKind::StorageBuffer:
                return std::any_of(b.storageBuffers.begin(), b.storageBuffers.end(),
                                   [&](const auto& x) { return x.binding == binding; });
            case ResourceKind::StorageImage:
                return std::any_of(b.storageImages.begin(), b.storageImages.end(),
                                   [&](const auto& x) { return x.binding == binding; });
            }
            return false;
        };
        for (const ShaderResource& r : program.resources)
            if (!has(r.kind, r.binding))
                return {StatusCode::InvalidArgument, std::string(where) + " lacks " + toString(r.kind) + " '" + r.name +
                                                         "' (binding " + str(r.binding) + ") of program '" + program.label + "'"};
        auto uses = [&](ResourceKind kind, uint32_t binding) {
            return std::any_of(program.resources.begin(), program.resources.end(),
                               [&](const ShaderResource& r) { return r.kind == kind && r.binding == binding; });
        };
        auto refuse = [&](ResourceKind kind, uint32_t binding) {
            return Status{StatusCode::InvalidArgument, std::string(where) + " binds a " + toString(kind) + " at binding " +
                                                           str(binding) + ", which program '" + program.label +
                                                           "' does not use"};
        };
        for (const auto& x : b.textures)
            if (!uses(ResourceKind::SampledTexture, x.binding)) return refuse(ResourceKind::SampledTexture, x.binding);
        for (const auto& x : b.uniformBuffers)
            if (!uses(ResourceKind::UniformBuffer, x.binding)) return refuse(ResourceKind::UniformBuffer, x.binding);
        for (const auto& x : b.storageBuffers)
            if (!uses(ResourceKind::StorageBuffer, x.binding)) return refuse(ResourceKind::StorageBuffer, x.binding);
        for (const auto& x : b.storageImages)
            if (!uses(ResourceKind::StorageImage, x.binding)) return refuse(ResourceKind::StorageImage, x.binding);
        return Status::ok();
    }

    // The range a buffer binding covers: its size, or the rest of the buffer when size is 0.
    static uint64_t boundSize(const BufferBinding& bb, const BufferDesc& d) {
        return bb.size ? bb.size : (bb.offset < d.size ? d.size - bb.offset : 0);
    }

    Status checkBufferRange(GLenum target, const BufferBinding& bb, uint32_t alignment, uint32_t minSize,
                            const ShaderResource* resource) {
        SFX_TRY(buffers_.check(bb.buffer, "BufferBinding.buffer"));
        const GlBuffer& buf = buffers_.get(bb.buffer);
        const uint64_t size = boundSize(bb, buf.desc);
        SFX_TRY(validation::bufferRange(buf.desc, bb.offset, size, "BufferBinding range"));
        if (bb.offset % alignment)
            return invalidArgument("BufferBinding.offset", str(bb.offset), "a multiple of " + str(alignment));
        const uint32_t needUsage = target == GL_UNIFORM_BUFFER ? kBufferUniform : kBufferStorage;
        if (!(buf.desc.usage & needUsage))
            return invalidArgument("BufferBinding.buffer usage", str(buf.desc.usage),
                                   target == GL_UNIFORM_BUFFER ? "with kBufferUniform" : "with kBufferStorage");
        if (size < minSize)
            return invalidArgument("BufferBinding size", str(size),
                                   ">= " + str(minSize) + " bytes of block '" + (resource ? resource->name : "") + "'");
        return Status::ok();
    }

    const ShaderResource* findResource(const GlProgram* program, ResourceKind kind, uint32_t binding) {
        if (!program) return nullptr;
        for (const ShaderResource& r : program->resources)
            if (r.kind == kind && r.binding == binding) return &r;
        return nullptr;
    }

    // Every check of a draw's or dispatch's resources, made before the command does any GL work,
    // so a refused command leaves the targets (and the GL state) as they were.
    Status checkResources(const BindingSet& b, const GlProgram* program) {
        for (const TextureBinding& tb : b.textures) {
            SFX_TRY(textures_.check(tb.texture, "TextureBinding.texture"));
            SFX_TRY(validation::textureBinding(textures_.get(tb.texture).desc, tb));
            if (tb.binding >= caps_.limits.maxTextureBindings)
                return invalidArgument("TextureBinding.binding", str(tb.binding),
                                       "[0, " + str(caps_.limits.maxTextureBindings - 1) + "]");
            if (!tb.sampler.isNull()) SFX_TRY(samplers_.check(tb.sampler, "TextureBinding.sampler"));
        }
        for (const BufferBinding& bb : b.uniformBuffers) {
            const ShaderResource* r = findResource(program, ResourceKind::UniformBuffer, bb.binding);
            SFX_TRY(checkBufferRange(GL_UNIFORM_BUFFER, bb, uniformOffsetAlignment_, r ? r->blockSize : 0, r));
        }
        for (const BufferBinding& bb : b.storageBuffers) {
            if (!caps_.storageBuffers)
                return {StatusCode::UnsupportedFeature, "BindingSet.storageBuffers: the device has no storage buffers"};
            const ShaderResource* r = findResource(program, ResourceKind::StorageBuffer, bb.binding);
            SFX_TRY(checkBufferRange(GL_SHADER_STORAGE_BUFFER, bb, storageOffsetAlignment_, r ? r->blockSize : 0, r));
        }
        for (const StorageImageBinding& ib : b.storageImages) {
            if (!caps_.storageImages)
                return {StatusCode::UnsupportedFeature, "BindingSet.storageImages: the device has no storage images"};
            SFX_TRY(textures_.check(ib.texture, "StorageImageBinding.texture"));
            const GlTexture& t = textures_.get(ib.texture);
            SFX_TRY(validation::mipRange(t.desc, ib.mip, "StorageImageBinding.mip"));
            if (!(t.desc.usage & kTextureStorage))
                return invalidArgument("StorageImageBinding.texture usage", str(t.desc.usage), "with kTextureStorage");
        }
        return Status::ok();
    }

    // Leaves no SDK sampler or texture bound on the units a draw used: a sampler object left
    // bound would silently override the filtering of whatever the host binds there next.
    void unbindResources(const BindingSet& b) {
        for (const TextureBinding& tb : b.textures) {
            GL(glBindSampler, tb.binding, 0);
            GL(glActiveTexture, GL_TEXTURE0 + tb.binding);
            GL(glBindTexture, GL_TEXTURE_2D, 0);
        }
        GL(glActiveTexture, GL_TEXTURE0);
    }

    // Binds resources checkResources accepted. Textures show the shader only the binding's mips
    // (BASE_LEVEL/MAX_LEVEL), which also makes rendering into a mip outside them legal.
    void bindResources(const BindingSet& b) {
        for (const TextureBinding& tb : b.textures) {
            const GlTexture& t = textures_.get(tb.texture);
            GLuint sampler = nearestSampler_;
            // Unfilterable formats would make the texture incomplete under a linear sampler.
            if (!tb.sampler.isNull() && filterable(t.desc.format)) sampler = samplers_.get(tb.sampler).name;
            GL(glActiveTexture, GL_TEXTURE0 + tb.binding);
            GL(glBindTexture, GL_TEXTURE_2D, t.name);
            GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, GLint(tb.baseMip));
            GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(tb.baseMip + tb.mipCount - 1));
            GL(glBindSampler, tb.binding, sampler);
        }
        GL(glActiveTexture, GL_TEXTURE0);
        auto bindRange = [&](GLenum target, const BufferBinding& bb) {
            const GlBuffer& buf = buffers_.get(bb.buffer);
            GL(glBindBufferRange, target, bb.binding, buf.name, GLintptr(bb.offset), GLsizeiptr(boundSize(bb, buf.desc)));
        };
        for (const BufferBinding& bb : b.uniformBuffers) bindRange(GL_UNIFORM_BUFFER, bb);
        for (const BufferBinding& bb : b.storageBuffers) bindRange(GL_SHADER_STORAGE_BUFFER, bb);
        for (const StorageImageBinding& ib : b.storageImages) {
            const GlTexture& t = textures_.get(ib.texture);
            GL(glBindImageTexture, ib.binding, t.name, GLint(ib.mip), GL_FALSE, 0, GL_READ_WRITE,
               glFormat(t.desc.format).internalFormat);
        }
    }

    GLenum depthAttachmentPoint(Format f) const {
        return f == Format::D24S8 ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT;
    }

    // A framebuffer object per attachment set, made once and kept until a texture goes.
    Result<GLuint> framebuffer(const std::vector<std::pair<const GlTexture*, uint32_t>>& colors, const GlTexture* depth,
                               uint32_t depthMip) {
        FboKey key;
        for (const auto& [t, mip] : colors) key.push_back((uint64_t(t->name) << 32) | mip);
        key.push_back(depth ? (uint64_t(depth->name) << 32) | depthMip : ~uint64_t(0));
        auto it = fbos_.find(key);
        if (it != fbos_.end()) {
            GL(glBindFramebuffer, GL_FRAMEBUFFER, it->second);
            return it->second;
        }
        GLuint fbo = 0;
        GL(glGenFramebuffers, 1, &fbo);
        GL(glBindFramebuffer, GL_FRAMEBUFFER, fbo);
        std::vector<GLenum> drawBuffers;
        for (size_t i = 0; i < colors.size(); ++i) {
            GL(glFramebufferTexture2D, GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, colors[i].first->name,
               GLint(colors[i].second));
            drawBuffers.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
        }
        if (depth)
            GL(glFramebufferTexture2D, GL_FRAMEBUFFER, depthAttachmentPoint(depth->desc.format), GL_TEXTURE_2D, depth->name,
               GLint(depthMip));
        if (drawBuffers.empty()) {
            const GLenum none = GL_NONE;
            GL(glDrawBuffers, 1, &none);
            GL(glReadBuffer, GL_NONE);
        } else {
            GL(glDrawBuffers, GLsizei(drawBuffers.size()), drawBuffers.data());
            GL(glReadBuffer, GL_COLOR_ATTACHMENT0);
        }
        const GLenum status = GL(glCheckFramebufferStatus, GL_FRAMEBUFFER);
        if (status != GL_FRAMEBUFFER_COMPLETE) {
            GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
            GL(glDeleteFramebuffers, 1, &fbo);
            char hex[16];
            std::snprintf(hex, sizeof(hex), "0x%04x", unsigned(status));
            return Status{StatusCode::UnsupportedFormat,
                          std::string("the attachments make an incomplete framebuffer (status ") + hex + ")"};
        }
        fbos_[key] = fbo;
        return fbo;
    }

    void forgetFbosOf(GLuint texture) {
        for (auto it = fbos_.begin(); it != fbos_.end();) {
            const bool uses = std::any_of(it->first.begin(), it->first.end(), [&](uint64_t k) {
                return k != ~uint64_t(0) && GLuint(k >> 32) == texture;
            });
            if (uses) {
                GL(glDeleteFramebuffers, 1, &it->second);
                it = fbos_.erase(it);
            } else {
                ++it;
            }
        }
    }

    Status renderPassImpl(const RenderPassDesc& pass, std::span<const DrawDesc> draws) {
        if (pass.colors.empty() && pass.depth.texture.isNull())
            return invalidArgument("RenderPassDesc", "without attachments", "at least one colour or depth attachment");
        if (pass.colors.size() > caps_.limits.maxColorAttachments)
            return invalidArgument("RenderPassDesc.colors.size()", str(pass.colors.size()),
                                   "[0, " + str(caps_.limits.maxColorAttachments) + "]");
        std::vector<std::pair<const GlTexture*, uint32_t>> colors;
        uint32_t width = 0, height = 0;
        auto extentMatches = [&](const TextureDesc& d, uint32_t mip, const char* what) -> Status {
            const uint32_t w = mipExtent(d.width, mip), h = mipExtent(d.height, mip);
            if (width == 0) {
                width = w;
                height = h;
            } else if (w != width || h != height) {
                return invalidArgument(what, str(w) + "x" + str(h), "the pass's extent " + str(width) + "x" + str(height));
            }
            return Status::ok();
        };
        for (const ColorAttachment& ca : pass.colors) {
            SFX_TRY(textures_.check(ca.texture, "RenderPassDesc.colors[].texture"));
            const GlTexture& t = textures_.get(ca.texture);
            SFX_TRY(validation::mipRange(t.desc, ca.mip, "RenderPassDesc.colors[].mip"));
            if (!(t.desc.usage & kTextureRenderTarget) || isDepthFormat(t.desc.format))
                return invalidArgument("RenderPassDesc.colors[].texture", toString(t.desc.format),
                                       "a colour texture with kTextureRenderTarget");
            SFX_TRY(extentMatches(t.desc, ca.mip, "RenderPassDesc.colors[] extent"));
            colors.push_back({&t, ca.mip});
        }
        const GlTexture* depth = nullptr;
        if (!pass.depth.texture.isNull()) {
            SFX_TRY(textures_.check(pass.depth.texture, "RenderPassDesc.depth.texture"));
            depth = &textures_.get(pass.depth.texture);
            if (!(depth->desc.usage & kTextureRenderTarget) || !isDepthFormat(depth->desc.format))
                return invalidArgument("RenderPassDesc.depth.texture", toString(depth->desc.format),
                                       "a depth texture with kTextureRenderTarget");
            SFX_TRY(extentMatches(depth->desc, 0, "RenderPassDesc.depth extent"));
        }
        // Check every draw before any GL work, so a bad draw leaves the targets untouched.
        for (const DrawDesc& d : draws) {
            SFX_TRY(checkDraw(d, colors, depth));
            SFX_TRY(validation::noFeedbackLoop(pass, d));
        }

        Result<GLuint> fbo = framebuffer(colors, depth, 0);
        if (!fbo) return fbo.status();
        GL(glViewport, 0, 0, GLsizei(width), GLsizei(height));
        GL(glDisable, GL_SCISSOR_TEST);
        GL(glDisable, GL_BLEND);
        GL(glColorMask, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        for (size_t i = 0; i < pass.colors.size(); ++i) {
            const ColorAttachment& ca = pass.colors[i];
            if (ca.load != LoadOp::Clear) continue;
            if (isIntegerFormat(colors[i].first->desc.format)) {
                GLuint v[4];
                for (int c = 0; c < 4; ++c) v[c] = GLuint(std::max(0.0f, ca.clearColor[size_t(c)]));
                GL(glClearBufferuiv, GL_COLOR, GLint(i), v);
            } else {
                GL(glClearBufferfv, GL_COLOR, GLint(i), ca.clearColor.data());
            }
        }
        if (depth && pass.depth.load == LoadOp::Clear) {
            GL(glDepthMask, GL_TRUE);
            if (depth->desc.format == Format::D24S8)
                GL(glClearBufferfi, GL_DEPTH_STENCIL, 0, pass.depth.clearDepth, 0);
            else
                GL(glClearBufferfv, GL_DEPTH, 0, &pass.depth.clearDepth);
        }
        for (const DrawDesc& d : draws) SFX_TRY(draw(d));
        GL(glBindVertexArray, 0);
        GL(glUseProgram, 0);
        GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
        return Status::ok();
    }

    Status checkDraw(const DrawDesc& d, const std::vector<std::pair<const GlTexture*, uint32_t>>& colors,
                     const GlTexture* depth) {
        SFX_TRY(pipelines_.check(d.pipeline, "DrawDesc.pipeline"));
        const GlPipeline& p = pipelines_.get(d.pipeline);
        if (p.compute) return {StatusCode::InvalidArgument, "DrawDesc.pipeline is a compute pipeline"};
        SFX_TRY(programs_.check(p.program, "DrawDesc.pipeline's program"));
        const GraphicsPipelineDesc& pd = p.desc;
        if (pd.colorFormats.size() != colors.size())
            return invalidArgument("DrawDesc.pipeline colour formats", str(pd.colorFormats.size()),
                                   str(colors.size()) + ", the pass's colour attachments");
        for (size_t i = 0; i < colors.size(); ++i)
            if (pd.colorFormats[i] != colors[i].first->desc.format)
                return invalidArgument("DrawDesc.pipeline colorFormats[" + str(i) + "]", toString(pd.colorFormats[i]),
                                       std::string(toString(colors[i].first->desc.format)) + ", the pass's attachment");
        const Format passDepth = depth ? depth->desc.format : Format::Undefined;
        if (pd.depthFormat != passDepth)
            return invalidArgument("DrawDesc.pipeline depthFormat", toString(pd.depthFormat),
                                   std::string(toString(passDepth)) + ", the pass's depth attachment");
        SFX_TRY(checkBindingsMatch(programs_.get(p.program), d.bindings, "DrawDesc.bindings"));
        SFX_TRY(checkResources(d.bindings, &programs_.get(p.program)));
        const BufferDesc* vertexBuffer = nullptr;
        const BufferDesc* indexBuffer = nullptr;
        if (!pd.vertexLayout.attributes.empty()) {
            SFX_TRY(buffers_.check(d.vertexBuffer, "DrawDesc.vertexBuffer"));
            vertexBuffer = &buffers_.get(d.vertexBuffer).desc;
        } else if (!d.vertexBuffer.isNull()) {
            return invalidArgument("DrawDesc.vertexBuffer", "set", "null for a pipeline without vertex attributes");
        }
        if (!d.indexBuffer.isNull()) {
            SFX_TRY(buffers_.check(d.indexBuffer, "DrawDesc.indexBuffer"));
            indexBuffer = &buffers_.get(d.indexBuffer).desc;
        }
        return validation::drawRange(d, pd.vertexLayout, vertexBuffer, indexBuffer);
    }

    Status draw(const DrawDesc& d) {
        const GlPipeline& p = pipelines_.get(d.pipeline);
        const GlProgram& program = programs_.get(p.program);
        const GraphicsPipelineDesc& pd = p.desc;
        GL(glUseProgram, program.name);
        bindResources(d.bindings);

        if (pd.depth.test || pd.depth.write) {
            // GL skips depth writes with the test off; ALWAYS keeps a write-only pipeline writing.
            GL(glEnable, GL_DEPTH_TEST);
            GL(glDepthFunc, pd.depth.test ? compareFunc(pd.depth.compare) : GL_ALWAYS);
        } else {
            GL(glDisable, GL_DEPTH_TEST);
        }
        GL(glDepthMask, pd.depth.write ? GL_TRUE : GL_FALSE);
        if (pd.blend.enable) {
            GL(glEnable, GL_BLEND);
            GL(glBlendFunc, blendFactor(pd.blend.src), blendFactor(pd.blend.dst));
        } else {
            GL(glDisable, GL_BLEND);
        }
        // NDC y = -1 is memory row 0 and GL's window y grows with the row, so GL's own CCW is
        // counter-clockwise in memory rows.
        GL(glFrontFace, GL_CCW);
        if (pd.cull == CullMode::None) {
            GL(glDisable, GL_CULL_FACE);
        } else {
            GL(glEnable, GL_CULL_FACE);
            GL(glCullFace, pd.cull == CullMode::Back ? GL_BACK : GL_FRONT);
        }

        GL(glBindVertexArray, p.vao);
        if (!pd.vertexLayout.attributes.empty()) {
            GL(glBindBuffer, GL_ARRAY_BUFFER, buffers_.get(d.vertexBuffer).name);
            for (const VertexAttribute& a : pd.vertexLayout.attributes) {
                const GLint size = a.format == VertexFormat::Float2 ? 2 : a.format == VertexFormat::Float3 ? 3 : 4;
                GL(glVertexAttribPointer, a.location, size, GL_FLOAT, GL_FALSE, GLsizei(pd.vertexLayout.stride),
                   reinterpret_cast<const void*>(uintptr_t(a.offset)));
            }
            GL(glBindBuffer, GL_ARRAY_BUFFER, 0);
        }
        if (!d.indexBuffer.isNull()) {
            GL(glBindBuffer, GL_ELEMENT_ARRAY_BUFFER, buffers_.get(d.indexBuffer).name);
            GL(glDrawElementsInstanced, GL_TRIANGLES, GLsizei(d.count), GL_UNSIGNED_INT, nullptr, GLsizei(d.instanceCount));
            GL(glBindBuffer, GL_ELEMENT_ARRAY_BUFFER, 0);
        } else {
            GL(glDrawArraysInstanced, GL_TRIANGLES, 0, GLsizei(d.count), GLsizei(d.instanceCount));
        }
        unbindResources(d.bindings);
        return Status::ok();
    }

    // ---- Readback -------------------------------------------------------------------------

    Status readLevel(const GlTexture& t, uint32_t mip, void* out) {
        const uint32_t w = mipExtent(t.desc.width, mip), h = mipExtent(t.desc.height, mip);
        const size_t texels = size_t(w) * h;
        const Format f = t.desc.format;
        GL(glBindBuffer, GL_PIXEL_PACK_BUFFER, 0);
        if (isDepthFormat(f)) {
            if (api_ == Api::DesktopGL) {
                // Desktop GL reads depth directly, already in the texture's layout.
                Result<GLuint> fbo = framebuffer({}, &t, mip);
                if (!fbo) return fbo.status();
                const GlFormat gf = glFormat(f);
                GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), gf.format, gf.type, out);
                GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
                return Status::ok();
            }
            std::vector<float> depth(texels);
            SFX_TRY(copyDepthEs(t, mip, w, h, depth.data()));
            for (size_t i = 0; i < texels; ++i) {
                const double d = std::clamp(double(depth[i]), 0.0, 1.0);
                if (f == Format::D16) {
                    const uint16_t v = uint16_t(std::lround(d * 65535.0));
                    std::memcpy(static_cast<uint8_t*>(out) + i * 2, &v, 2);
                } else if (f == Format::D24S8) {
                    // Depth in the high 24 bits as GL's UNSIGNED_INT_24_8; stencil reads as 0 on GL ES.
                    const uint32_t v = uint32_t(std::lround(d * 16777215.0)) << 8;
                    std::memcpy(static_cast<uint8_t*>(out) + i * 4, &v, 4);
                } else {
                    std::memcpy(static_cast<uint8_t*>(out) + i * 4, &depth[i], 4);
                }
            }
            return Status::ok();
        }

        // GL ES guarantees RGBA with UNSIGNED_BYTE, FLOAT or UNSIGNED_INT per target class: read
        // that on both APIs and narrow to the texture's layout here.
        Result<GLuint> fbo = framebuffer({{&t, mip}}, nullptr, 0);
        if (!fbo) return fbo.status();
        const uint32_t channels = channelCount(f);
        if (f == Format::R8 || f == Format::RGBA8) {
            std::vector<uint8_t> rgba(texels * 4);
            GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
            auto* o = static_cast<uint8_t*>(out);
            for (size_t i = 0; i < texels; ++i)
                for (uint32_t c = 0; c < channels; ++c) o[i * channels + c] = rgba[i * 4 + c];
        } else if (f == Format::R32UI) {
            std::vector<uint32_t> rgba(texels * 4);
            GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA_INTEGER, GL_UNSIGNED_INT, rgba.data());
            auto* o = static_cast<uint32_t*>(out);
            for (size_t i = 0; i < texels; ++i) o[i] = rgba[i * 4];
        } else {
            std::vector<float> rgba(texels * 4);
            GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA, GL_FLOAT, rgba.data());
            if (isHalfFormat(f)) {
                auto* o = static_cast<uint16_t*>(out);
                for (size_t i = 0; i < texels; ++i)
                    for (uint32_t c = 0; c < channels; ++c) o[i * channels + c] = floatToHalf(rgba[i * 4 + c]);
            } else {
                auto* o = static_cast<float*>(out);
                for (size_t i = 0; i < texels; ++i)
                    for (uint32_t c = 0; c < channels; ++c) o[i * channels + c] = rgba[i * 4 + c];
            }
        }
        GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
        return Status::ok();
    }

    // GL ES cannot glReadPixels depth: draw the level into a temporary R32F target and read that.
    Status copyDepthEs(const GlTexture& t, uint32_t mip, uint32_t w, uint32_t h, float* out) {
        if (!extensions_.count("GL_EXT_color_buffer_float") && !(caps_.apiMajor * 10 + caps_.apiMinor >= 32))
            return {StatusCode::UnsupportedFeature, "readTexture of depth on GL ES needs R32F render targets"};
        if (!depthCopyProgram_) {
            Result<GLuint> p = buildProgram("gl_depth_copy", {{GL_VERTEX_SHADER, kDepthCopyVertex},
                                                              {GL_FRAGMENT_SHADER, kDepthCopyFragment}});
            if (!p) return p.status();
            depthCopyProgram_ = p.value();
            GL(glUseProgram, depthCopyProgram_);
            const GLint loc = GL(glGetUniformLocation, depthCopyProgram_, "uDepth");
            if (loc >= 0) GL(glUniform1i, loc, 0);
        }
        GlTexture target;
        target.desc = TextureDesc{w, h, 1, Format::R32F, kTextureRenderTarget, "gl_depth_copy"};
        GL(glGenTextures, 1, &target.name);
        GL(glBindTexture, GL_TEXTURE_2D, target.name);
        GL(glTexStorage2D, GL_TEXTURE_2D, 1, GL_R32F, GLsizei(w), GLsizei(h));
        GL(glBindTexture, GL_TEXTURE_2D, 0);
        Status s = [&]() -> Status {
            Result<GLuint> fbo = framebuffer({{&target, 0}}, nullptr, 0);
            if (!fbo) return fbo.status();
            GL(glViewport, 0, 0, GLsizei(w), GLsizei(h));
            GL(glDisable, GL_DEPTH_TEST);
            GL(glDisable, GL_BLEND);
            GL(glDisable, GL_CULL_FACE);
            GL(glDisable, GL_SCISSOR_TEST);
            GL(glColorMask, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            GL(glUseProgram, depthCopyProgram_);
            GL(glActiveTexture, GL_TEXTURE0);
            GL(glBindTexture, GL_TEXTURE_2D, t.name);
            GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, GLint(mip));
            GL(glTexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(mip));
            GL(glBindSampler, 0, nearestSampler_);
            GL(glBindVertexArray, emptyVao_);
            GL(glDrawArraysInstanced, GL_TRIANGLES, 0, 3, 1);
            GL(glBindSampler, 0, 0);
            GL(glBindTexture, GL_TEXTURE_2D, 0);
            GL(glBindVertexArray, 0);
            GL(glUseProgram, 0);
            std::vector<float> rgba(size_t(w) * h * 4);
            GL(glReadPixels, 0, 0, GLsizei(w), GLsizei(h), GL_RGBA, GL_FLOAT, rgba.data());
            for (size_t i = 0; i < size_t(w) * h; ++i) out[i] = rgba[i * 4];
            GL(glBindFramebuffer, GL_FRAMEBUFFER, 0);
            return Status::ok();
        }();
        forgetFbosOf(target.name);
        GL(glDeleteTextures, 1, &target.name);
        return s;
    }

#undef GL

    std::unique_ptr<GlPlatform> platform_;
    Api api_;
    DeviceOptions options_;
    GlFunctions gl_;
    bool loaded_ = false;
    DeviceCaps caps_;
    std::set<std::string> extensions_;
    bool float32Filterable_ = false;
    bool debugOutput_ = false;
    uint32_t uniformOffsetAlignment_ = 1, storageOffsetAlignment_ = 1;
    std::vector<std::string> messages_;
    std::string pendingError_;  // the first GL error since the current call began

    uint16_t serial_;
    HandlePool<TextureTag, GlTexture> textures_;
    HandlePool<BufferTag, GlBuffer> buffers_;
    HandlePool<SamplerTag, GlSampler> samplers_;
    HandlePool<ProgramTag, GlProgram> programs_;
    HandlePool<PipelineTag, GlPipeline> pipelines_;
    HandlePool<TimerTag, GlTimer> timers_;

    std::map<FboKey, GLuint> fbos_;
    GLuint nearestSampler_ = 0;
    GLuint emptyVao_ = 0;
    GLuint depthCopyProgram_ = 0;
};

Result<std::unique_ptr<Device>> finishDevice(Result<std::unique_ptr<GlPlatform>> platform, Api api,
                                             const DeviceOptions& options) {
    if (!platform) return platform.status();
    gCurrentPlatform = platform.value().get();  // opening made it current
    auto device = std::make_unique<GlDevice>(std::move(platform.value()), api, options);
    SFX_TRY(device->init(options.ceiling));
    return std::unique_ptr<Device>(std::move(device));
}

class HostPlatform final : public GlPlatform {
public:
    explicit HostPlatform(GetProcAddressFn fn) : fn_(fn) {}
    bool makeCurrent() override { return true; }  // the host keeps its context current
    void release() override {}
    void* getProcAddress(const char* name) override { return fn_(name); }
    const char* name() const override { return "host"; }

private:
    GetProcAddressFn fn_;
};

}  // namespace

std::unique_ptr<GlPlatform> hostPlatform(GetProcAddressFn getProcAddress) {
    return std::make_unique<HostPlatform>(getProcAddress);
}

Result<std::unique_ptr<Device>> createDevice(Platform platform, Api api, const DeviceOptions& options) {
    // Whatever context the SDK left current goes first: opening makes the new one current.
    if (gCurrentPlatform) gCurrentPlatform->release();
    gCurrentPlatform = nullptr;
    if (platform == Platform::OSMesa) return finishDevice(openOsmesaPlatform(api), api, options);
    return finishDevice(openEglPlatform(api, options.validation), api, options);
}

Result<std::unique_ptr<Device>> wrapCurrentContext(GetProcAddressFn getProcAddress, Api api, const DeviceOptions& options) {
    if (!getProcAddress) return invalidArgument("getProcAddress", "null", "the host's GL loader");
    // The host's context is current now; releasing an SDK context would unbind it.
    return finishDevice(hostPlatform(getProcAddress), api, options);
}

}  // namespace sfx::gl
