// Opening a device: the GL entry points loaded through the platform, the context's version
// checked, and the caps filled from GL's queries under the capability ceiling.
#include <algorithm>
#include <cstring>

#include "gl_driver.hpp"
#include "gl_formats.hpp"

namespace sfx::gl {

Status GlDevice::init(CapabilityCeiling ceiling) {
    if (!makeCurrent()) return {StatusCode::BackendUnavailable, "GL: the context cannot be made current"};
// clang-format off
#define SFX_GL_LOAD(type, fn)                                                                            \
    gl_.fn = reinterpret_cast<type>(platform_->getProcAddress(#fn));                                     \
    if (!gl_.fn) return {StatusCode::BackendUnavailable, std::string("GL: entry point ") + #fn + " is missing"};
    // clang-format on
    SFX_GL_REQUIRED(SFX_GL_LOAD)
#undef SFX_GL_LOAD
    loaded_ = true;
    while (gl_.glGetError() != GL_NO_ERROR) {}
    const char* version = reinterpret_cast<const char*>(gl_.glGetString(GL_VERSION));
    const char* renderer = reinterpret_cast<const char*>(gl_.glGetString(GL_RENDERER));
    if (!version) return {StatusCode::BackendUnavailable, "GL: glGetString(GL_VERSION) returned NULL"};
    const bool es = std::strncmp(version, "OpenGL ES", 9) == 0;
    if (es != (api_ == Api::GLES))
        return {StatusCode::BackendUnavailable,
                std::string("GL: asked for ") + (api_ == Api::GLES ? "GL ES" : "desktop GL") + ", the context is '" + version + "'"};
    GLint major = 0, minor = 0;
    gl_.glGetIntegerv(GL_MAJOR_VERSION, &major);
    gl_.glGetIntegerv(GL_MINOR_VERSION, &minor);
    const int v = major * 10 + minor;
    if (es ? v < 30 : v < 33)
        return {StatusCode::BackendUnavailable, std::string("GL: '") + version + "' is older than " + (es ? "GL ES 3.0" : "desktop GL 3.3")};
    GLint extensionCount = 0;
    gl_.glGetIntegerv(GL_NUM_EXTENSIONS, &extensionCount);
    for (GLint i = 0; i < extensionCount; ++i)
        if (const GLubyte* e = gl_.glGetStringi(GL_EXTENSIONS, GLuint(i))) extensions_.insert(reinterpret_cast<const char*>(e));

    const bool modern = es ? v >= 31 : v >= 43;  // compute, storage buffers and images, atomics
    if (modern || extensions_.count("GL_KHR_debug")) {
#define SFX_GL_LOAD(type, fn) gl_.fn = reinterpret_cast<type>(platform_->getProcAddress(#fn));
        SFX_GL_OPTIONAL(SFX_GL_LOAD)
#undef SFX_GL_LOAD
    }
    // GL ES 3.0/3.1 name KHR_debug's entry points with a suffix.
    const bool coreDebug = es ? v >= 32 : v >= 43;
    if (!coreDebug && es && extensions_.count("GL_KHR_debug")) {
        gl_.glDebugMessageCallback = reinterpret_cast<PFNGLDEBUGMESSAGECALLBACKPROC>(platform_->getProcAddress("glDebugMessageCallbackKHR"));
        gl_.glDebugMessageControl = reinterpret_cast<PFNGLDEBUGMESSAGECONTROLPROC>(platform_->getProcAddress("glDebugMessageControlKHR"));
    }
    const bool haveDebug = (coreDebug || extensions_.count("GL_KHR_debug")) && gl_.glDebugMessageCallback && gl_.glDebugMessageControl;

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
    c.dialect = es ? (full ? ShaderDialect::Essl310 : ShaderDialect::Essl300) : (full ? ShaderDialect::Glsl450 : ShaderDialect::Glsl330);
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
    GLint viewport[2] = {0, 0};
    gl_.glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
    const uint32_t renderbuffer = geti(GL_MAX_RENDERBUFFER_SIZE);
    c.limits.maxRenderTargetWidth = std::min({uint32_t(std::max(viewport[0], 0)), renderbuffer, c.limits.maxTextureSize});
    c.limits.maxRenderTargetHeight = std::min({uint32_t(std::max(viewport[1], 0)), renderbuffer, c.limits.maxTextureSize});
    c.limits.maxColorAttachments = std::min(geti(GL_MAX_COLOR_ATTACHMENTS), geti(GL_MAX_DRAW_BUFFERS));
    c.limits.subPixelPrecisionBits = geti(GL_SUBPIXEL_BITS);
    c.limits.maxUniformBlockSize = get64(GL_MAX_UNIFORM_BLOCK_SIZE);
    c.limits.maxStorageBufferSize = full ? get64(GL_MAX_SHADER_STORAGE_BLOCK_SIZE) : 0;
    c.limits.maxBufferSize = uint64_t(1) << 30;  // GL has no query; generous for screen-space buffers
    c.limits.maxComputeWorkGroupInvocations = full ? geti(GL_MAX_COMPUTE_WORK_GROUP_INVOCATIONS) : 0;
    for (GLuint axis = 0; axis < 3; ++axis) {
        GLint groups = 0;
        if (full) gl_.glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis, &groups);
        c.limits.maxComputeWorkGroupCount[axis] = uint32_t(std::max(groups, 0));
    }
    c.limits.maxTextureBindings = geti(GL_MAX_TEXTURE_IMAGE_UNITS);
    c.limits.minUniformBufferOffsetAlignment = std::max<uint32_t>(1, geti(GL_UNIFORM_BUFFER_OFFSET_ALIGNMENT));
    c.limits.minStorageBufferOffsetAlignment = modern ? std::max<uint32_t>(1, geti(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT)) : 1;
    // Every power of two up to `most` samples, one at least (DeviceLimits' sample count masks).
    auto countsUpTo = [](uint32_t most) {
        uint32_t mask = 1;
        for (uint32_t k = 1; k < 31 && (1u << k) <= most; ++k) mask |= 1u << k;
        return mask;
    };
    c.limits.framebufferColorSampleCounts = c.limits.framebufferDepthSampleCounts = countsUpTo(geti(GL_MAX_SAMPLES));
    const bool uncapped = ceiling == CapabilityCeiling::None;
    if (uncapped && (!es || v >= 31)) {
        c.limits.sampledImageColorSampleCounts = countsUpTo(geti(GL_MAX_COLOR_TEXTURE_SAMPLES));
        c.limits.sampledImageDepthSampleCounts = countsUpTo(geti(GL_MAX_DEPTH_TEXTURE_SAMPLES));
    }
    const bool textureBuffers = !es || v >= 32 || extensions_.count("GL_EXT_texture_buffer") || extensions_.count("GL_OES_texture_buffer");
    c.limits.maxTexelBufferElements = uncapped && textureBuffers ? geti(GL_MAX_TEXTURE_BUFFER_SIZE) : 0;
    // GL ES 3.1 may offer storage to compute only (its minimum fragment counts are 0).
    c.fragmentStoresAndAtomics = full && geti(GL_MAX_FRAGMENT_SHADER_STORAGE_BLOCKS) > 0 && geti(GL_MAX_FRAGMENT_IMAGE_UNIFORMS) > 0;

    // Float colour targets are core in desktop GL and GL ES 3.2; GL ES 3.0/3.1 (and a
    // device under the ES 3.0 ceiling) have them only through EXT_color_buffer_float.
    const bool colorBufferFloat = !es || extensions_.count("GL_EXT_color_buffer_float") || (v >= 32 && ceiling == CapabilityCeiling::None);
    const bool colorBufferHalf = colorBufferFloat || extensions_.count("GL_EXT_color_buffer_half_float");
    const bool float32Filterable = !es || extensions_.count("GL_OES_texture_float_linear");
    // Desktop GL blends 32-bit float targets (core since 3.0); GL ES only with EXT_float_blend,
    // which a desktop context under the ES 3.0 ceiling does not list, as a phone might not.
    const bool float32Blendable = (!es && ceiling == CapabilityCeiling::None) || extensions_.count("GL_EXT_float_blend");
    for (size_t f = 1; f < size_t(Format::Count); ++f) {
        const Format format = Format(f);
        const bool colour = !isDepthFormat(format), integer = isIntegerFormat(format), float32 = isFloat32Format(format);
        c.sampledFormat[f] = true;
        c.renderableFormat[f] = isHalfFormat(format) ? colorBufferHalf : float32 ? colorBufferFloat : true;
        // Depth textures filter only through comparison samplers, which the HAL does not make.
        c.filterableFormat[f] = colour && !integer && (!float32 || float32Filterable);
        c.blendableFormat[f] = c.renderableFormat[f] && colour && !integer && (!float32 || float32Blendable);
        c.storageFormat[f] = c.storageImages && colour && (!es || isEs31ImageFormat(format));
    }
    c.floatRenderTargets = c.renderableFormat[size_t(Format::R32F)] && c.renderableFormat[size_t(Format::RG16F)] &&
        c.renderableFormat[size_t(Format::RGBA16F)];

    // Not on a host's context, which keeps its own callback (see enableDebugOutput).
    if (options_.validation && haveDebug && !hostContext()) enableDebugOutput();

    // The sampler of bindings without one: nearest within the binding's mips, clamped.
    GL(glGenSamplers, 1, &nearestSampler_);
    setSamplerState(nearestSampler_, SamplerDesc{});
    GL(glGenVertexArrays, 1, &emptyVao_);
    GL(glPixelStorei, GL_PACK_ALIGNMENT, 1);
    GL(glPixelStorei, GL_UNPACK_ALIGNMENT, 1);
    return takeDeviceError(Status::ok());
}

}  // namespace sfx::gl
