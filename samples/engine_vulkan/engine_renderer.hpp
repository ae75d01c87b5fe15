// The engine sample's renderer: the bunny scene (glmark2-data) drawn on raw Vulkan into the
// host's own G-buffer images, the SDK's AO and motion blur recorded into the host's command
// buffer between its own passes, and a composite. samples/engine_vulkan/main.cpp runs it and
// writes a PNG; tests/engine/test_engine_vulkan.cpp runs the same code and checks it.
//
// One frame, in one host command buffer (docs/integration.md, "Walkthrough: AO in an existing
// Vulkan renderer"):
//   1. host G-buffer pass: depth (D32F), view-space normals (RGBA16F), velocity (RG16F, pixels
//      from the previous frame's camera and bunny transform to this frame's), albedo (RGBA8);
//   2. SDK: AO of depth + normals into the host's AO image (R16F);
//   3. host lighting pass: albedo x (ambient x AO + sun) into the host's lit image (RGBA16F);
//   4. SDK: motion blur of the lit image along the velocity, into the host's blurred image;
//   5. host present pass: the blurred colour, gamma-encoded, into the host's RGBA8 image.
// AO comes before motion blur because it is part of the shading that moves with the surface.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sfx/ao.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/tier.hpp"
#include "vk_host.hpp"

namespace sfx::engine {

struct EngineOptions {
    uint32_t width = 640, height = 360;
    Tier tier = Tier::High;
    // The Khronos validation layer with synchronization validation on the host's instance, and
    // DeviceOptions::validation on the SDK's device.
    bool validation = false;
};

// The host images the renderer can read back (outside the frame loop).
enum class HostImageKind { Depth, Normals, Velocity, Albedo, Ao, Lit, Blurred, Final };

class EngineRenderer {
public:
    // BackendUnavailable (no Vulkan 1.3, no validation layer when asked) or FileError (no
    // glmark2-data bunny) say why the sample cannot run here.
    static Result<std::unique_ptr<EngineRenderer>> create(const EngineOptions& options);
    ~EngineRenderer();
    EngineRenderer(const EngineRenderer&) = delete;
    EngineRenderer& operator=(const EngineRenderer&) = delete;

    // Waits for the previous frame, animates, records the whole frame and submits it. Creates,
    // allocates, uploads and reads back nothing.
    Status renderFrame();
    // Waits for the last frame submitted.
    Status finish();

    // Copies a host image into the host's readback buffer (made at create()) and returns its
    // texels, tightly packed, row 0 first. Waits for the GPU: not for the frame loop.
    Result<std::vector<uint8_t>> readImage(HostImageKind kind);

    Device& sfxDevice() { return *sfx_; }
    const AmbientObscurance& ao() const { return *ao_; }
    const MotionBlur& motionBlur() const { return *mb_; }
    const MotionBlurSettings& motionBlurSettings() const { return mbSettings_; }
    const CameraProjection& camera() const { return camera_; }
    uint32_t width() const { return options_.width; }
    uint32_t height() const { return options_.height; }
    uint32_t frames() const { return frame_; }
    const HostCounts& hostCounts() const { return host_.counts(); }
    // The host layer's messages, then the SDK's (both empty without validation).
    std::vector<std::string> takeValidationMessages();

private:
    EngineRenderer() = default;
    Status init(const EngineOptions& options);
    Status loadScene();
    Status createTargets();
    Status createPipelines();
    Status connectSdk();
    Status writeDescriptorSets();
    void animate();
    Status recordFrame(VkCommandBuffer cb);
    void gbufferPass(VkCommandBuffer cb);
    void fullscreenPass(VkCommandBuffer cb, const HostImage& target, VkPipeline pipeline, VkPipelineLayout layout, VkDescriptorSet set);
    const HostImage& image(HostImageKind kind) const;
    VkImageLayout contractLayout(HostImageKind kind) const;

    EngineOptions options_;
    VkHost host_;
    // Meshes: one vertex and one index buffer (host-visible, written once at create), drawn
    // per mesh with its model transform.
    struct DrawMesh {
        uint32_t firstIndex = 0, indexCount = 0;
        int32_t vertexOffset = 0;
        glm::dmat4 model{1.0}, previousModel{1.0};
    };
    std::vector<DrawMesh> meshes_;
    size_t bunny_ = 0;  // index of the animated mesh
    glm::dmat4 baseBunnyModel_{1.0};
    glm::dvec3 target_{0.0};
    double orbitRadius_ = 1, orbitHeight_ = 1, orbitAngle_ = 0;
    glm::dmat4 view_{1.0}, previousView_{1.0};
    CameraProjection camera_;
    HostBuffer vertices_, indices_, sceneUniforms_, readback_;
    HostImage depth_, normals_, velocity_, albedo_, aoImage_, lit_, blurred_, final_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout gbufferSetLayout_ = VK_NULL_HANDLE, lightingSetLayout_ = VK_NULL_HANDLE, presentSetLayout_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptorPool_ = VK_NULL_HANDLE;
    VkDescriptorSet gbufferSet_ = VK_NULL_HANDLE, lightingSet_ = VK_NULL_HANDLE, presentSet_ = VK_NULL_HANDLE;
    VkPipelineLayout gbufferLayout_ = VK_NULL_HANDLE, lightingLayout_ = VK_NULL_HANDLE, presentLayout_ = VK_NULL_HANDLE;
    VkPipeline gbufferPipeline_ = VK_NULL_HANDLE, lightingPipeline_ = VK_NULL_HANDLE, presentPipeline_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cb_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    bool inFlight_ = false;
    uint32_t frame_ = 0;

    // The SDK on the host's device, and the host's images as SDK textures.
    std::unique_ptr<Device> sfx_;
    TextureHandle depthTex_, normalTex_, velocityTex_, aoTex_, litTex_, blurredTex_;
    std::unique_ptr<AmbientObscurance> ao_;
    std::unique_ptr<MotionBlur> mb_;
    MotionBlurSettings mbSettings_;
};

}  // namespace sfx::engine
