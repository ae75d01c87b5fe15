#include "renderer.hpp"

#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "scene.hpp"  // tools/scenes: the bunny scene's meshes and camera
#include "sfx/gl_device.hpp"

namespace engine_gl {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSpinPerFrame = 9.0 * kPi / 180.0;   // the bunny turns 9 degrees a frame
constexpr double kOrbitPerFrame = 0.6 * kPi / 180.0;  // the camera circles the bunny slowly

sfx::Status failed(const std::string& what) { return {sfx::StatusCode::DeviceError, "engine_gl: " + what}; }

void uniform(HostGl& gl, GLint location, const glm::dmat4& m) {
    const glm::mat4 f(m);
    gl.UniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(f));
}

}  // namespace

sfx::Result<std::unique_ptr<Renderer>> Renderer::create(EglContext& context, const RendererOptions& options) {
    if (options.width == 0 || options.height == 0)
        return sfx::invalidArgument("RendererOptions.width/height", std::to_string(options.width) + "x" + std::to_string(options.height),
                                    "both at least 1");
    std::unique_ptr<Renderer> r(new Renderer(context, options));
    if (std::string missing = r->gl_.load(&EglContext::getProcAddress); !missing.empty())
        return sfx::Status{sfx::StatusCode::BackendUnavailable, "engine_gl: the context lacks " + missing};
    SFX_TRY(r->createGlObjects());
    SFX_TRY(r->createMeshes());
    SFX_TRY(r->createSdk());
    return r;
}

Renderer::~Renderer() {
    // The effects and the device first (the SDK forgets the imported textures, deleting none),
    // then the host's own objects.
    ao_.reset();
    blur_.reset();
    device_.reset();
    for (Mesh& m : meshes_) {
        gl_.deleteVertexArray(m.vao);
        gl_.deleteBuffer(m.vertices);
        gl_.deleteBuffer(m.indices);
    }
    for (GLuint* fbo : {&gbufferFbo_, &litFbo_, &presentFbo_}) gl_.deleteFramebuffer(*fbo);
    for (Target* t : {&depth_, &normals_, &velocity_, &albedo_, &lit_, &aoOutput_, &blurred_, &presented_}) gl_.deleteTexture(t->texture);
    gl_.deleteSampler(sampler_);
    gl_.deleteVertexArray(emptyVao_);
    destroyPrograms(gl_, programs_);
}

GLuint Renderer::makeTarget(GLenum internalFormat) {
    GLuint t = gl_.genTexture();
    gl_.BindTexture(GL_TEXTURE_2D, t);
    gl_.texStorage2D(GL_TEXTURE_2D, 1, internalFormat, GLsizei(options_.width), GLsizei(options_.height));
    gl_.BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

sfx::Status Renderer::framebuffer(GLuint& fbo, std::initializer_list<GLuint> colours, GLuint depth, const char* what) {
    fbo = gl_.genFramebuffer();
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    std::vector<GLenum> buffers;
    for (GLuint c : colours) {
        const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(buffers.size());
        gl_.FramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, c, 0);
        buffers.push_back(attachment);
    }
    if (depth) gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    gl_.DrawBuffers(GLsizei(buffers.size()), buffers.data());
    const GLenum status = gl_.CheckFramebufferStatus(GL_FRAMEBUFFER);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) return failed(std::string(what) + " framebuffer is incomplete (" + std::to_string(status) + ")");
    return hostErrors(what);
}

sfx::Status Renderer::createGlObjects() {
    sfx::Result<HostPrograms> programs = buildPrograms(gl_, context_.api());
    if (!programs) return programs.status();
    programs_ = programs.value();
    const GLuint g = programs_.gbuffer;
    uniforms_ = {gl_.GetUniformLocation(g, "uModelView"),
                 gl_.GetUniformLocation(g, "uProjection"),
                 gl_.GetUniformLocation(g, "uPreviousClip"),
                 gl_.GetUniformLocation(g, "uNormalMatrix"),
                 gl_.GetUniformLocation(g, "uColour"),
                 gl_.GetUniformLocation(g, "uViewport"),
                 gl_.GetUniformLocation(programs_.composite, "uSunView")};
    depth_ = {makeTarget(GL_DEPTH_COMPONENT32F), GL_DEPTH_COMPONENT32F};
    normals_ = {makeTarget(GL_RGBA16F), GL_RGBA16F};
    velocity_ = {makeTarget(GL_RG16F), GL_RG16F};
    albedo_ = {makeTarget(GL_RGBA8), GL_RGBA8};
    lit_ = {makeTarget(GL_RGBA16F), GL_RGBA16F};
    aoOutput_ = {makeTarget(GL_R16F), GL_R16F};
    blurred_ = {makeTarget(GL_RGBA16F), GL_RGBA16F};
    presented_ = {makeTarget(GL_RGBA8), GL_RGBA8};
    SFX_TRY(framebuffer(gbufferFbo_, {normals_.texture, velocity_.texture, albedo_.texture}, depth_.texture, "G-buffer"));
    SFX_TRY(framebuffer(litFbo_, {lit_.texture}, 0, "composite"));
    SFX_TRY(framebuffer(presentFbo_, {presented_.texture}, 0, "present"));
    // The host samples through its own sampler (nearest: every pass reads texel for texel).
    sampler_ = gl_.genSampler();
    for (GLenum p : {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER}) gl_.SamplerParameteri(sampler_, p, GL_NEAREST);
    for (GLenum p : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T}) gl_.SamplerParameteri(sampler_, p, GL_CLAMP_TO_EDGE);
    emptyVao_ = gl_.genVertexArray();  // full-screen passes draw from gl_VertexID, but GL wants a VAO bound
    return hostErrors("creating the host's GL objects");
}

sfx::Status Renderer::createMeshes() {
    sfx::Result<sfx::tools::RasterScene> scene = sfx::tools::makeScene("bunny");
    if (!scene) return scene.status();
    eye_ = scene->eye;
    target_ = scene->target;
    sfx::Result<sfx::CameraProjection> camera = scene->projection(options_.width, options_.height, sfx::ClipDepthRange::MinusOneToOne);
    if (!camera) return camera.status();
    camera_ = camera.value();
    for (size_t i = 0; i < scene->meshes.size(); ++i) {
        const sfx::tools::Mesh& source = scene->meshes[i];
        Mesh m;
        m.model = source.model;
        m.spins = i > 0;  // the floor stays, the bunny turns
        m.colour = m.spins ? glm::vec3(0.85f, 0.62f, 0.45f) : glm::vec3(0.7f, 0.72f, 0.75f);
        m.indexCount = GLsizei(source.indices.size());
        m.vao = gl_.genVertexArray();
        gl_.BindVertexArray(m.vao);
        m.vertices = gl_.genBuffer();
        gl_.BindBuffer(GL_ARRAY_BUFFER, m.vertices);
        gl_.bufferData(GL_ARRAY_BUFFER, GLsizeiptr(source.vertices.size() * sizeof(sfx::tools::Vertex)), source.vertices.data(), GL_STATIC_DRAW);
        m.indices = gl_.genBuffer();
        gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, m.indices);
        gl_.bufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(source.indices.size() * sizeof(uint32_t)), source.indices.data(), GL_STATIC_DRAW);
        const GLsizei stride = sizeof(sfx::tools::Vertex);
        gl_.EnableVertexAttribArray(kAttribPosition);
        gl_.VertexAttribPointer(kAttribPosition, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
        gl_.EnableVertexAttribArray(kAttribNormal);
        gl_.VertexAttribPointer(kAttribNormal, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(sfx::tools::Vertex, normal)));
        gl_.BindVertexArray(0);
        gl_.BindBuffer(GL_ARRAY_BUFFER, 0);
        meshes_.push_back(m);
    }
    return hostErrors("uploading the meshes");
}

sfx::Status Renderer::createSdk() {
    sfx::DeviceOptions options;
    options.validation = options_.debug;  // the SDK's per-call GL error checks
    options.log = options_.log;
    const sfx::gl::Api api = context_.api() == ContextApi::GLES ? sfx::gl::Api::GLES : sfx::gl::Api::DesktopGL;
    sfx::Result<std::unique_ptr<sfx::Device>> device = sfx::gl::wrapCurrentContext(&EglContext::getProcAddress, api, options);
    if (!device) return device.status();
    device_ = std::move(device.value());
    sfx::Result<sfx::tiers::TierChoice> tier = sfx::tiers::choose(device_->caps());
    if (!tier) return tier.status();
    tier_ = tier.value();

    auto import = [&](const Target& t, uint32_t usage, const char* name) -> sfx::Result<sfx::TextureHandle> {
        sfx::gl::ExternalTexture e;
        e.name = t.texture;
        e.internalFormat = t.internalFormat;
        e.width = options_.width;
        e.height = options_.height;
        e.usage = usage;
        e.debugName = name;
        return sfx::gl::importTexture(*device_, e);
    };
    const uint32_t sampled = sfx::kTextureSampled, target = sfx::kTextureSampled | sfx::kTextureRenderTarget;
    sfx::Result<sfx::TextureHandle> depth = import(depth_, sampled, "host depth");
    sfx::Result<sfx::TextureHandle> normals = import(normals_, sampled, "host normals");
    sfx::Result<sfx::TextureHandle> velocity = import(velocity_, sampled, "host velocity");
    sfx::Result<sfx::TextureHandle> lit = import(lit_, sampled, "host lit colour");
    sfx::Result<sfx::TextureHandle> ao = import(aoOutput_, target, "host ao");
    sfx::Result<sfx::TextureHandle> blurred = import(blurred_, target, "host blurred colour");
    for (const auto* r : {&depth, &normals, &velocity, &lit, &ao, &blurred})
        if (!*r) return r->status();
    imported_ = {depth.value(), normals.value(), velocity.value(), lit.value(), ao.value(), blurred.value()};

    sfx::AoSettings aoSettings;
    aoSettings.radius = 0.4f;
    aoSettings.normals = sfx::AoNormals::FromTexture;  // the G-buffer's normals, not derived ones
    sfx::Result<std::unique_ptr<sfx::AmbientObscurance>> effect = sfx::AmbientObscurance::create(
        *device_, {options_.width, options_.height, tier_.profile, aoSettings, sfx::DepthKind::Hardware});
    if (!effect) return effect.status();
    ao_ = std::move(effect.value());

    sfx::MotionBlurDesc blurDesc;
    blurDesc.width = options_.width;
    blurDesc.height = options_.height;
    blurDesc.profile = tier_.profile;
    blurDesc.colorFormat = sfx::Format::RGBA16F;
    blurDesc.depthInput = sfx::DepthKind::Hardware;
    sfx::Result<std::unique_ptr<sfx::MotionBlur>> blur = sfx::MotionBlur::create(*device_, blurDesc);
    if (!blur) return blur.status();
    blur_ = std::move(blur.value());
    blurSettings_.exposure = 1.0f;  // velocity is a whole frame's motion: a 360-degree shutter
    return sfx::Status::ok();
}

glm::dmat4 Renderer::view(uint32_t frame) const {
    const double a = kOrbitPerFrame * double(frame);
    const glm::dvec3 offset = eye_ - target_;
    const glm::dvec3 turned(offset.x * std::cos(a) + offset.z * std::sin(a), offset.y, -offset.x * std::sin(a) + offset.z * std::cos(a));
    return glm::lookAt(target_ + turned, target_, glm::dvec3(0, 1, 0));
}

glm::dmat4 Renderer::model(const Mesh& mesh, uint32_t frame) const {
    if (!mesh.spins) return mesh.model;
    return glm::rotate(glm::dmat4(1.0), kSpinPerFrame * double(frame), glm::dvec3(0, 1, 0)) * mesh.model;
}

void Renderer::drawGBuffer(uint32_t frame) {
    const uint32_t previous = frame == 0 ? 0 : frame - 1;
    gl_.BindFramebuffer(GL_FRAMEBUFFER, gbufferFbo_);
    gl_.Viewport(0, 0, GLsizei(options_.width), GLsizei(options_.height));
    gl_.Disable(GL_BLEND);
    gl_.Disable(GL_SCISSOR_TEST);
    gl_.Disable(GL_CULL_FACE);  // the floor is one-sided and the projection flips the winding
    gl_.Enable(GL_DEPTH_TEST);
    gl_.DepthFunc(GL_LESS);
    gl_.DepthMask(GL_TRUE);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const GLfloat zero[4] = {0, 0, 0, 0}, far[1] = {1.0f};
    for (GLint i : {GLint(kGBufferNormals), GLint(kGBufferVelocity), GLint(kGBufferAlbedo)}) gl_.ClearBufferfv(GL_COLOR, i, zero);
    gl_.ClearBufferfv(GL_DEPTH, 0, far);
    gl_.UseProgram(programs_.gbuffer);
    gl_.Uniform2f(uniforms_.viewport, GLfloat(options_.width), GLfloat(options_.height));
    const glm::dmat4 v = view(frame), vPrevious = view(previous);
    for (const Mesh& m : meshes_) {
        const glm::dmat4 modelView = v * model(m, frame);
        uniform(gl_, uniforms_.modelView, modelView);
        uniform(gl_, uniforms_.projection, camera_.projection);
        uniform(gl_, uniforms_.previousClip, camera_.projection * vPrevious * model(m, previous));
        const glm::mat3 normalMatrix(glm::transpose(glm::inverse(glm::dmat3(modelView))));
        gl_.UniformMatrix3fv(uniforms_.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
        gl_.Uniform3f(uniforms_.colour, m.colour.r, m.colour.g, m.colour.b);
        gl_.BindVertexArray(m.vao);
        gl_.DrawElements(GL_TRIANGLES, m.indexCount, GL_UNSIGNED_INT, nullptr);
    }
}

// The state of a full-screen pass into `fbo` with `textures` (unit, name) through the host's
// sampler; the caller sets its uniforms and draws the triangle.
void Renderer::bindFullScreen(GLuint fbo, GLuint program, std::initializer_list<std::pair<GLint, GLuint>> textures) {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl_.Viewport(0, 0, GLsizei(options_.width), GLsizei(options_.height));
    gl_.Disable(GL_DEPTH_TEST);
    gl_.Disable(GL_BLEND);
    gl_.Disable(GL_CULL_FACE);
    gl_.Disable(GL_SCISSOR_TEST);
    gl_.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl_.UseProgram(program);
    for (const auto& [unit, name] : textures) {
        gl_.ActiveTexture(GL_TEXTURE0 + GLenum(unit));
        gl_.BindTexture(GL_TEXTURE_2D, name);
        gl_.BindSampler(GLuint(unit), sampler_);
    }
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindVertexArray(emptyVao_);
}

sfx::Status Renderer::hostErrors(const char* where) {
    if (!options_.debug) return sfx::Status::ok();
    gl_.checkErrors(where);
    if (std::string errors = gl_.takeErrors(); !errors.empty()) return failed(errors);
    return sfx::Status::ok();
}

sfx::Status Renderer::renderFrame(uint32_t index) {
    drawGBuffer(index);
    SFX_TRY(hostErrors("G-buffer pass"));  // before the SDK, which clears errors left pending

    // The SDK reads the host's depth and normals and writes the host's AO texture. The host's
    // bindings are the SDK's to change; the host sets its own again in the next pass.
    if (hooks.before) hooks.before(SdkCall::AmbientObscurance);
    sfx::AoInputs aoIn;
    aoIn.depth = sfx::DepthSource{imported_.depth, sfx::DepthKind::Hardware, camera_};
    aoIn.normals = imported_.normals;
    aoIn.output = imported_.ao;
    using Clock = std::chrono::steady_clock;
    const Clock::time_point aoStart = Clock::now();
    SFX_TRY(ao_->dispatch(aoIn));
    const Clock::duration aoTime = Clock::now() - aoStart;
    if (hooks.after) hooks.after(SdkCall::AmbientObscurance);

    bindFullScreen(litFbo_, programs_.composite, {{kUnitAlbedo, albedo_.texture}, {kUnitNormals, normals_.texture}, {kUnitAo, aoOutput_.texture}});
    const glm::dvec3 sunWorld = glm::normalize(glm::dvec3(0.4, 0.9, 0.35));
    const glm::vec3 sun(glm::normalize(glm::dmat3(view(index)) * sunWorld));
    gl_.Uniform3f(uniforms_.sun, sun.x, sun.y, sun.z);
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
    SFX_TRY(hostErrors("composite pass"));

    if (hooks.before) hooks.before(SdkCall::MotionBlur);
    sfx::MotionBlurInputs blurIn;
    blurIn.color = imported_.lit;
    blurIn.depth = aoIn.depth;
    blurIn.velocity = imported_.velocity;
    blurIn.output = imported_.blurred;  // into the host's texture: the present pass samples it
    const Clock::time_point blurStart = Clock::now();
    SFX_TRY(blur_->dispatch(blurIn, blurSettings_));
    lastDispatchMs_ = std::chrono::duration<double, std::milli>(aoTime + (Clock::now() - blurStart)).count();
    if (hooks.after) hooks.after(SdkCall::MotionBlur);

    bindFullScreen(presentFbo_, programs_.present, {{kUnitBlurred, blurred_.texture}});
    gl_.DrawArrays(GL_TRIANGLES, 0, 3);
    gl_.BindFramebuffer(GL_FRAMEBUFFER, 0);
    SFX_TRY(hostErrors("present pass"));
    // The frame's end: the SDK's flush (glFinish on GL) stands in for the swap.
    if (hooks.before) hooks.before(SdkCall::Flush);
    SFX_TRY(device_->flush());
    if (hooks.after) hooks.after(SdkCall::Flush);
    return sfx::Status::ok();
}

std::vector<uint8_t> Renderer::readPresented() {
    std::vector<uint8_t> rgba(size_t(options_.width) * options_.height * 4);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, presentFbo_);
    gl_.ReadBuffer(GL_COLOR_ATTACHMENT0);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl_.readPixels(0, 0, GLsizei(options_.width), GLsizei(options_.height), GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return rgba;
}

}  // namespace engine_gl
