// A small GL / GL ES renderer of its own (EGL context, textures, framebuffers, programs), with
// ScalableFX's AO and motion blur dropped in on its own textures. One frame:
//   1. G-buffer pass (host): hardware depth D32F, view-space normals RGBA16F, screen-space
//      velocity RG16F (from the previous frame's transforms) and albedo RGBA8;
//   2. sfx::AmbientObscurance on the host's depth and normals, into the host's R16F texture;
//   3. composite pass (host): lit colour RGBA16F = albedo x (ambient x AO + sun x n.l);
//   4. sfx::MotionBlur on the lit colour, depth and velocity, into the host's RGBA16F texture;
//   5. present pass (host): the blurred colour to an RGBA8 texture (what a swap chain would get).
// AO goes before the blur because the blur must move the final shaded colour: a moving
// object's occlusion smears with it. Nothing is created, uploaded or read back per frame.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "egl_context.hpp"
#include "host_gl.hpp"
#include "renderer_programs.hpp"
#include "sfx/ao.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/tiers.hpp"

namespace engine_gl {

struct RendererOptions {
    uint32_t width = 640, height = 360;
    // Development mode: the SDK's per-call GL error checks (DeviceOptions::validation) and the
    // host's own glGetError after each of its passes.
    bool debug = false;
    sfx::LogCallback log;
};

// The SDK calls inside a frame, for hooks that look at GL state around them.
enum class SdkCall { AmbientObscurance, MotionBlur, Flush };
struct FrameHooks {
    std::function<void(SdkCall)> before, after;
};

// The host textures the SDK sees, imported once (sfx::gl::importTexture): its inputs and the two
// the effects write (ao, blurred).
struct ImportedTextures {
    sfx::TextureHandle depth, normals, velocity, lit, ao, blurred;
};

class Renderer {
public:
    // With `context` current: the host's GL objects, the SDK device wrapping the context, the
    // imports and both effects.
    static sfx::Result<std::unique_ptr<Renderer>> create(EglContext& context, const RendererOptions& options);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Draws frame `index` (the scene animated to that frame; velocity from frame index - 1).
    sfx::Status renderFrame(uint32_t index);
    // The presented RGBA8 picture, row 0 = top: a host glReadPixels, never called by a frame.
    std::vector<uint8_t> readPresented();

    sfx::Device& device() { return *device_; }
    HostGl& gl() { return gl_; }
    const ImportedTextures& imported() const { return imported_; }
    const sfx::tiers::TierChoice& tier() const { return tier_; }
    const sfx::AoDesc& aoDesc() const { return ao_->desc(); }
    const sfx::MotionBlurDesc& motionBlurDesc() const { return blur_->desc(); }
    const sfx::MotionBlurSettings& motionBlurSettings() const { return blurSettings_; }
    const sfx::CameraProjection& camera() const { return camera_; }  // every frame's projection
    // CPU time of the last frame's two dispatch() calls (the SDK's per-frame overhead; on GL
    // they issue commands, the GPU work waits for the flush).
    double lastDispatchMs() const { return lastDispatchMs_; }
    uint32_t width() const { return options_.width; }
    uint32_t height() const { return options_.height; }
    FrameHooks hooks;

private:
    struct Mesh {
        GLuint vao = 0, vertices = 0, indices = 0;
        GLsizei indexCount = 0;
        glm::dmat4 model{1.0};
        glm::vec3 colour{1.0f};
        bool spins = false;
    };
    struct Target {
        GLuint texture = 0;
        GLenum internalFormat = 0;
    };

    Renderer(EglContext& context, const RendererOptions& options) : context_(context), options_(options) {}
    sfx::Status createGlObjects();
    sfx::Status createMeshes();
    sfx::Status createSdk();
    GLuint makeTarget(GLenum internalFormat);
    sfx::Status framebuffer(GLuint& fbo, std::initializer_list<GLuint> colours, GLuint depth, const char* what);
    glm::dmat4 view(uint32_t frame) const;
    glm::dmat4 model(const Mesh& mesh, uint32_t frame) const;
    void drawGBuffer(uint32_t frame);
    void bindFullScreen(GLuint fbo, GLuint program, std::initializer_list<std::pair<GLint, GLuint>> textures);
    sfx::Status hostErrors(const char* where);

    EglContext& context_;
    RendererOptions options_;
    HostGl gl_;
    HostPrograms programs_;
    struct Uniforms {  // looked up once: a frame only sets values
        GLint modelView = -1, projection = -1, previousClip = -1, normalMatrix = -1, colour = -1, viewport = -1, sun = -1;
    } uniforms_;
    GLuint sampler_ = 0, emptyVao_ = 0;
    Target depth_, normals_, velocity_, albedo_, lit_, aoOutput_, blurred_, presented_;
    GLuint gbufferFbo_ = 0, litFbo_ = 0, presentFbo_ = 0;
    std::vector<Mesh> meshes_;
    glm::dvec3 eye_{0.0}, target_{0.0};
    sfx::CameraProjection camera_;

    std::unique_ptr<sfx::Device> device_;
    sfx::tiers::TierChoice tier_;
    ImportedTextures imported_;
    std::unique_ptr<sfx::AmbientObscurance> ao_;
    std::unique_ptr<sfx::MotionBlur> blur_;
    sfx::MotionBlurSettings blurSettings_;
    double lastDispatchMs_ = 0;
};

}  // namespace engine_gl
