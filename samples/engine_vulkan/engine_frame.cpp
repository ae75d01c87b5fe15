// The engine sample's frame: the host's passes and the SDK's effects in one host command
// buffer, and the host's barriers between them. Nothing here creates, allocates, uploads or
// reads back anything (readImage, at the end, is for after the frame loop).
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>

#include "engine_renderer.hpp"
#include "sfx/vulkan_device.hpp"

namespace sfx::engine {
namespace {

constexpr double kOrbitPerFrame = 0.02;  // radians the camera moves around the bunny per frame
constexpr double kSpinPerFrame = 0.12;   // radians the bunny turns per frame

// clang-format off
#define ENGINE_VK(call)                                                                              \
    do {                                                                                             \
        const VkResult engine_vk_result_ = (call);                                                  \
        if (engine_vk_result_ != VK_SUCCESS)                                                         \
            return Status{StatusCode::DeviceError, std::string(#call) + " returned " + std::to_string(int(engine_vk_result_))}; \
    } while (0)
// clang-format on

void storeMatrix(float* dst, const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) dst[c * 4 + r] = float(m[c][r]);
}

VkRenderingAttachmentInfo colorAttachment(const HostImage& image) {
    VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    a.imageView = image.view;
    a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // a = 0 everywhere: "nothing drawn"
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    return a;
}

void setViewport(VkCommandBuffer cb, uint32_t w, uint32_t h) {
    const VkViewport viewport{0, 0, float(w), float(h), 0, 1};
    const VkRect2D scissor{{0, 0}, {w, h}};
    vkCmdSetViewport(cb, 0, 1, &viewport);
    vkCmdSetScissor(cb, 0, 1, &scissor);
}

}  // namespace

// Camera orbit and bunny spin; the previous frame's transforms stay for the velocity.
void EngineRenderer::animate() {
    const bool first = frame_ == 0;
    const double angle = orbitAngle_ + kOrbitPerFrame * frame_;
    const glm::dvec3 eye = target_ + glm::dvec3(orbitRadius_ * std::cos(angle), orbitHeight_, orbitRadius_ * std::sin(angle));
    previousView_ = view_;
    view_ = glm::lookAt(eye, target_, glm::dvec3(0, 1, 0));
    for (DrawMesh& m : meshes_) m.previousModel = m.model;
    meshes_[bunny_].model = glm::rotate(baseBunnyModel_, kSpinPerFrame * frame_, glm::dvec3(0, 1, 0));
    if (first) {  // no previous frame: no motion
        previousView_ = view_;
        for (DrawMesh& m : meshes_) m.previousModel = m.model;
    }
}

Status EngineRenderer::renderFrame() {
    // One frame in flight: setCommandBuffer reuses what the SDK used in the previous frame's
    // command buffer, so that one must have finished.
    SFX_TRY(finish());
    animate();
    ENGINE_VK(vkResetCommandBuffer(cb_, 0));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    ENGINE_VK(vkBeginCommandBuffer(cb_, &bi));
    SFX_TRY(recordFrame(cb_));
    ENGINE_VK(vkEndCommandBuffer(cb_));
    ENGINE_VK(vkResetFences(host_.device, 1, &fence_));
    SFX_TRY(host_.submit(cb_, fence_));
    inFlight_ = true;
    ++frame_;
    return Status::ok();
}

Status EngineRenderer::finish() {
    if (!inFlight_) return Status::ok();
    ENGINE_VK(vkWaitForFences(host_.device, 1, &fence_, VK_TRUE, UINT64_MAX));
    inFlight_ = false;
    return Status::ok();
}

Status EngineRenderer::recordFrame(VkCommandBuffer cb) {
    constexpr VkImageLayout kRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    constexpr VkImageLayout kColor = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    constexpr VkImageLayout kDepth = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    constexpr VkPipelineStageFlags kFragment = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    constexpr VkPipelineStageFlags kColorOut = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    constexpr VkPipelineStageFlags kDepthTests = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

    // 1. G-buffer. Last frame's contents are not needed (old layout UNDEFINED); the writes wait
    //    for last frame's reads (the SDK's and the lighting pass's, all fragment shaders).
    for (const HostImage* img : {&normals_, &velocity_, &albedo_})
        imageBarrier(cb, *img, VK_IMAGE_LAYOUT_UNDEFINED, kColor, kFragment, 0, kColorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    imageBarrier(cb, depth_, VK_IMAGE_LAYOUT_UNDEFINED, kDepth, kFragment | kDepthTests, 0, kDepthTests,
                 VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    gbufferPass(cb);
    // Normals and velocity go to their contract layout for the SDK, albedo for the lighting
    // pass. Depth stays as the pass left it: that is its contract layout, and the SDK's first
    // use of it waits for the depth writes itself.
    for (const HostImage* img : {&normals_, &velocity_, &albedo_})
        imageBarrier(cb, *img, kColor, kRead, kColorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, kFragment, VK_ACCESS_SHADER_READ_BIT);

    // 2. The SDK's AO, into the host's AO image. flush() ends the SDK's recording and returns
    //    every imported image it used to its contract layout, visible to the host's next pass.
    SFX_TRY(vulkan::setCommandBuffer(*sfx_, cb));
    AoInputs ao;
    ao.depth = DepthSource{depthTex_, DepthKind::Hardware, camera_};
    ao.normals = normalTex_;
    ao.output = aoTex_;
    SFX_TRY(ao_->dispatch(ao));
    SFX_TRY(sfx_->flush());

    // 3. Lighting: albedo x (ambient x AO + sun) into the lit image, then its contract layout.
    imageBarrier(cb, lit_, VK_IMAGE_LAYOUT_UNDEFINED, kColor, kFragment, 0, kColorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    fullscreenPass(cb, lit_, lightingPipeline_, lightingLayout_, lightingSet_);
    imageBarrier(cb, lit_, kColor, kRead, kColorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, kFragment, VK_ACCESS_SHADER_READ_BIT);

    // 4. The SDK's motion blur of the lit image. A second window in the same command buffer:
    //    the first one's staging must stay until the frame has executed (previousFinished false).
    SFX_TRY(vulkan::setCommandBuffer(*sfx_, cb, false));
    MotionBlurInputs mb;
    mb.color = litTex_;
    mb.depth = DepthSource{depthTex_, DepthKind::Hardware, camera_};
    mb.velocity = velocityTex_;
    mb.output = blurredTex_;
    SFX_TRY(mb_->dispatch(mb, mbSettings_));
    SFX_TRY(sfx_->flush());

    // 5. Present from the host's blurred image: flush() left it in its contract layout
    //    (SHADER_READ_ONLY_OPTIMAL), visible to every later stage, so no barrier against the SDK.
    imageBarrier(cb, final_, kColor, kColor, kColorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, kColorOut, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    fullscreenPass(cb, final_, presentPipeline_, presentLayout_, presentSet_);
    return Status::ok();
}

void EngineRenderer::gbufferPass(VkCommandBuffer cb) {
    const uint32_t w = options_.width, h = options_.height;
    VkRenderingAttachmentInfo colors[3] = {colorAttachment(normals_), colorAttachment(velocity_), colorAttachment(albedo_)};
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = depth_.view;
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {w, h}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 3;
    ri.pColorAttachments = colors;
    ri.pDepthAttachment = &depth;
    vkCmdBeginRendering(cb, &ri);
    setViewport(cb, w, h);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, gbufferPipeline_);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, gbufferLayout_, 0, 1, &gbufferSet_, 0, nullptr);
    const VkDeviceSize offset = 0;
    vkCmdBindVertexBuffers(cb, 0, 1, &vertices_.buffer, &offset);
    vkCmdBindIndexBuffer(cb, indices_.buffer, 0, VK_INDEX_TYPE_UINT32);
    for (uint32_t k = 0; k < meshes_.size(); ++k) {
        const DrawMesh& m = meshes_[k];
        float push[32];
        storeMatrix(push, view_ * m.model);
        storeMatrix(push + 16, previousView_ * m.previousModel);
        vkCmdPushConstants(cb, gbufferLayout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(push), push);
        // firstInstance = mesh index: the shaders pick the mesh's colour by gl_InstanceIndex.
        vkCmdDrawIndexed(cb, m.indexCount, 1, m.firstIndex, m.vertexOffset, k);
    }
    vkCmdEndRendering(cb);
}

void EngineRenderer::fullscreenPass(VkCommandBuffer cb, const HostImage& target, VkPipeline pipeline, VkPipelineLayout layout, VkDescriptorSet set) {
    VkRenderingAttachmentInfo color = colorAttachment(target);
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;  // every pixel is written
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {target.width, target.height}};
    ri.layerCount = 1;
    ri.colorAttachmentCount = 1;
    ri.pColorAttachments = &color;
    vkCmdBeginRendering(cb, &ri);
    setViewport(cb, target.width, target.height);
    vkCmdBindPipeline(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(cb, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, nullptr);
    vkCmdDraw(cb, 3, 1, 0, 0);
    vkCmdEndRendering(cb);
}

Result<std::vector<uint8_t>> EngineRenderer::readImage(HostImageKind kind) {
    SFX_TRY(finish());
    const HostImage& img = image(kind);
    const VkImageLayout layout = contractLayout(kind);
    ENGINE_VK(vkResetCommandBuffer(cb_, 0));
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    ENGINE_VK(vkBeginCommandBuffer(cb_, &bi));
    // Outside the frame: wait for whatever wrote it last, and hand it back to every stage.
    imageBarrier(cb_, img, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    host_.copyImageToBuffer(cb_, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_);
    imageBarrier(cb_, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                 VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cb_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
    ENGINE_VK(vkEndCommandBuffer(cb_));
    ENGINE_VK(vkResetFences(host_.device, 1, &fence_));
    SFX_TRY(host_.submit(cb_, fence_));
    inFlight_ = true;
    SFX_TRY(finish());
    const size_t bytes = size_t(img.width) * img.height * img.texelBytes;
    std::vector<uint8_t> out(bytes);
    std::memcpy(out.data(), readback_.mapped, bytes);
    return out;
}

}  // namespace sfx::engine
