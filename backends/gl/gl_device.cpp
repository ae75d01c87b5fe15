// The GL device itself: construction and teardown, which context is current, the commands' hooks
// (checked by Device's front end, then encoded), timers, and the factories of sfx/gl_device.hpp.
// The rest of GlDevice lives by concern in the files gl_driver.hpp lists.
#include <string_view>

#include "gl_driver.hpp"

#include "sfx/validation_errors.hpp"

namespace sfx::gl {
namespace {

// The platform whose context is current on this thread, as far as the SDK knows; devices
// re-make theirs current when another one (maybe of the other platform) was used last.
thread_local GlPlatform* gCurrentPlatform = nullptr;

}  // namespace

GlDevice::GlDevice(std::unique_ptr<GlPlatform> platform, Api api, const DeviceOptions& options)
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

GlDevice::~GlDevice() {
    if (!loaded_ || !makeCurrent()) return;
    textures_.forEachAlive([&](GlTexture& t) {
        if (!t.external) gl_.glDeleteTextures(1, &t.name);
    });
    buffers_.forEachAlive([&](GlBuffer& b) { gl_.glDeleteBuffers(1, &b.name); });
    samplers_.forEachAlive([&](GlSampler& s) { gl_.glDeleteSamplers(1, &s.name); });
    programs_.forEachAlive([&](GlProgram& p) { gl_.glDeleteProgram(p.name); });
    for (GLuint p : destroyedPrograms_) gl_.glDeleteProgram(p);
    pipelines_.forEachAlive([&](GlPipeline& p) {
        gl_.glDeleteVertexArrays(1, &p.vao);
        if (p.specialized) gl_.glDeleteProgram(p.specialized);
    });
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
    // Messages nobody took go to the host's log callback (DeviceOptions::log).
    for (const std::string& m : takeValidationMessages())
        if (options_.log) options_.log(LogSeverity::Error, "sfx gl: untaken validation message at teardown: " + m);
}

bool GlDevice::makeCurrent() {
    if (gCurrentPlatform == platform_.get()) return true;
    if (gCurrentPlatform) gCurrentPlatform->release();
    gCurrentPlatform = nullptr;
    if (!platform_->makeCurrent()) return false;
    gCurrentPlatform = platform_.get();
    return true;
}

Status GlDevice::enter() {
    if (!makeCurrent()) return {StatusCode::DeviceError, std::string("GL: cannot make the ") + platform_->name() + " context current"};
    pendingError_.clear();
    // Errors the host's own calls left pending are not this call's failure: clear them so
    // the per-call checks see only what the SDK did.
    if (options_.validation && hostContext())
        while (gl_.glGetError() != GL_NO_ERROR) {}
    // The host may have changed the pixel-store alignment since the last call: the SDK's uploads
    // and readbacks are tightly packed, and the state contract leaves both at 1.
    if (hostContext()) {
        gl_.glPixelStorei(GL_PACK_ALIGNMENT, 1);
        gl_.glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    }
    return Status::ok();
}

bool GlDevice::hostContext() const { return std::string_view(platform_->name()) == "host"; }

// ---- Timers ------------------------------------------------------------------------------

Result<TimerHandle> GlDevice::doCreateTimer() { return timers_.insert(GlTimer{}); }

Status GlDevice::doDestroyTimer(TimerHandle h) {
    timers_.remove(h);
    return Status::ok();
}

// GL timer queries on llvmpipe report far less than the work takes; wall clock between
// two glFinish calls is what the benchmarks can trust.
Status GlDevice::doBeginTimer(TimerHandle h) {
    SFX_TRY(enter());
    GL(glFinish);
    GlTimer& t = timers_.get(h);
    t.begun = true;
    t.ended = false;
    t.begin = Clock::now();
    return takeDeviceError(Status::ok());
}

Status GlDevice::doEndTimer(TimerHandle h) {
    if (!timers_.get(h).begun) return validation::fail(validation::Error::TimerNotBegun, {});
    SFX_TRY(enter());
    GL(glFinish);
    GlTimer& t = timers_.get(h);
    t.end = Clock::now();
    t.begun = false;
    t.ended = true;
    t.lastMs = std::chrono::duration<double, std::milli>(t.end - t.begin).count();
    return takeDeviceError(Status::ok());
}

Result<TimerReading> GlDevice::doReadTimer(TimerHandle h) {
    const GlTimer& t = timers_.get(h);
    if (t.lastMs < 0) return validation::fail(validation::Error::TimerNoMeasurement, {});
    return TimerReading{t.lastMs, caps_.timing};
}

// ---- Commands: checked by the front end before any GL work, then the encoding ------------

Status GlDevice::doRenderPass(const RenderPassDesc& pass, std::span<const DrawDesc> draws) {
    SFX_TRY(enter());
    passTargets(pass, passTargets_);
    return takeDeviceError(encodeRenderPass(pass, draws, passTargets_));
}

Status GlDevice::doDispatch(const DispatchDesc& d) {
    SFX_TRY(enter());
    encodeDispatch(programOf(pipelines_.get(d.pipeline)), d);
    return takeDeviceError(Status::ok());
}

Status GlDevice::doFlush() {
    SFX_TRY(enter());
    GL(glFinish);
    return takeDeviceError(Status::ok());
}

namespace {

Result<std::unique_ptr<Device>> finishDevice(Result<std::unique_ptr<GlPlatform>> platform, Api api, const DeviceOptions& options) {
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

std::unique_ptr<GlPlatform> hostPlatform(GetProcAddressFn getProcAddress) { return std::make_unique<HostPlatform>(getProcAddress); }

Result<std::unique_ptr<Device>> createDevice(Platform platform, Api api, const DeviceOptions& options) {
    // Whatever context the SDK left current goes first: opening makes the new one current.
    if (gCurrentPlatform) gCurrentPlatform->release();
    gCurrentPlatform = nullptr;
    if (platform == Platform::OSMesa) return finishDevice(openOsmesaPlatform(api), api, options);
    return finishDevice(openEglPlatform(api, options.validation), api, options);
}

Result<std::unique_ptr<Device>> wrapCurrentContext(GetProcAddressFn getProcAddress, Api api, const DeviceOptions& options) {
    using validation::Error;
    if (!getProcAddress) return validation::fail(Error::ExternalObjectNull, {"getProcAddress", "the host's GL loader"});
    // Without a current context every GL call would go nowhere (or crash): ask GL first.
    using GetString = const unsigned char* (*)(uint32_t);
    auto getString = reinterpret_cast<GetString>(getProcAddress("glGetString"));
    if (!getString) return validation::fail(Error::ExternalObjectNull, {"getProcAddress(\"glGetString\")", "the host's GL loader"});
    if (!getString(0x1F02 /* GL_VERSION */)) return validation::fail(Error::GlNoCurrentContext, {});
    // The host's context is current now; releasing an SDK context would unbind it.
    return finishDevice(hostPlatform(getProcAddress), api, options);
}

}  // namespace sfx::gl
