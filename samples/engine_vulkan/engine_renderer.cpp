// Set-up and teardown of the engine sample: the host's scene buffers, G-buffer images and
// pipelines, then the SDK on the host's device with the host's images imported. The frame loop
// is in engine_frame.cpp.
#include "engine_renderer.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>

#include "fullscreen_vert.hpp"
#include "gbuffer_frag.hpp"
#include "gbuffer_vert.hpp"
#include "lighting_frag.hpp"
#include "present_frag.hpp"
#include "scene.hpp"
#include "sfx/tiers.hpp"
#include "sfx/vulkan_device.hpp"

namespace sfx::engine {
namespace {

// The gbuffer shaders' uniform block (std140), written once at create().
struct SceneUniforms {
    float projection[16];
    float viewport[4];
    float colours[8][4];
};

void store(float (&dst)[16], const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) dst[c * 4 + r] = float(m[c][r]);
}

constexpr VkImageUsageFlags kGBufferUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

}  // namespace

Result<std::unique_ptr<EngineRenderer>> EngineRenderer::create(const EngineOptions& options) {
    std::unique_ptr<EngineRenderer> r(new EngineRenderer());
    Status s = r->init(options);
    if (!s) return s;
    return r;
}

Status EngineRenderer::init(const EngineOptions& options) {
    if (options.width == 0 || options.height == 0)
        return invalidArgument("EngineOptions.width/height", std::to_string(options.width) + "x" + std::to_string(options.height), "both at least 1");
    options_ = options;
    SFX_TRY(host_.create(options.validation));
    SFX_TRY(loadScene());
    SFX_TRY(createTargets());
    SFX_TRY(createPipelines());
    SFX_TRY(connectSdk());
    return writeDescriptorSets();
}

// The bunny scene of tools/scenes (glmark2's bunny on a floor), copied into one vertex and
// one index buffer of the host's; its camera orbits the bunny, which turns on the spot.
Status EngineRenderer::loadScene() {
    Result<tools::RasterScene> scene = tools::makeScene("bunny");
    if (!scene) return scene.status();
    Result<CameraProjection> camera = scene->projection(options_.width, options_.height, ClipDepthRange::ZeroToOne);
    if (!camera) return camera.status();
    camera_ = camera.value();
    size_t vertexCount = 0, indexCount = 0;
    for (const tools::Mesh& m : scene->meshes) {
        vertexCount += m.vertices.size();
        indexCount += m.indices.size();
    }
    SFX_TRY(host_.makeBuffer(vertexCount * sizeof(tools::Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, &vertices_));
    SFX_TRY(host_.makeBuffer(indexCount * sizeof(uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, &indices_));
    auto* v = static_cast<tools::Vertex*>(vertices_.mapped);
    auto* i = static_cast<uint32_t*>(indices_.mapped);
    uint32_t firstIndex = 0;
    int32_t vertexOffset = 0;
    for (size_t k = 0; k < scene->meshes.size(); ++k) {
        const tools::Mesh& m = scene->meshes[k];
        std::memcpy(v + vertexOffset, m.vertices.data(), m.vertices.size() * sizeof(tools::Vertex));
        std::memcpy(i + firstIndex, m.indices.data(), m.indices.size() * sizeof(uint32_t));
        meshes_.push_back({firstIndex, uint32_t(m.indices.size()), vertexOffset, m.model, m.model});
        if (m.vertices.size() > 1000) bunny_ = k;  // the floor is one quad
        firstIndex += uint32_t(m.indices.size());
        vertexOffset += int32_t(m.vertices.size());
    }
    baseBunnyModel_ = meshes_[bunny_].model;
    target_ = scene->target;
    const glm::dvec3 offset = scene->eye - scene->target;
    orbitRadius_ = std::hypot(offset.x, offset.z);
    orbitHeight_ = offset.y;
    orbitAngle_ = std::atan2(offset.z, offset.x);

    SFX_TRY(host_.makeBuffer(sizeof(SceneUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &sceneUniforms_));
    SceneUniforms u{};
    store(u.projection, camera_.projection);
    u.viewport[0] = float(options_.width);
    u.viewport[1] = float(options_.height);
    const float colours[2][4] = {{0.78f, 0.76f, 0.7f, 1}, {0.9f, 0.62f, 0.45f, 1}};
    for (size_t k = 0; k < meshes_.size() && k < 8; ++k) std::memcpy(u.colours[k], colours[k == bunny_ ? 1 : 0], 16);
    std::memcpy(sceneUniforms_.mapped, &u, sizeof(u));
    return Status::ok();
}

Status EngineRenderer::createTargets() {
    const uint32_t w = options_.width, h = options_.height;
    SFX_TRY(host_.makeImage(VK_FORMAT_D32_SFLOAT,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, w, h,
                            &depth_));
    SFX_TRY(host_.makeImage(VK_FORMAT_R16G16B16A16_SFLOAT, kGBufferUsage, w, h, &normals_));
    SFX_TRY(host_.makeImage(VK_FORMAT_R16G16_SFLOAT, kGBufferUsage, w, h, &velocity_));
    SFX_TRY(host_.makeImage(VK_FORMAT_R8G8B8A8_UNORM, kGBufferUsage, w, h, &albedo_));
    SFX_TRY(host_.makeImage(VK_FORMAT_R16_SFLOAT, kGBufferUsage, w, h, &aoImage_));
    SFX_TRY(host_.makeImage(VK_FORMAT_R16G16B16A16_SFLOAT, kGBufferUsage, w, h, &lit_));
    SFX_TRY(host_.makeImage(VK_FORMAT_R16G16B16A16_SFLOAT, kGBufferUsage, w, h, &blurred_));
    SFX_TRY(host_.makeImage(VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, w, h, &final_));
    // Readback of the largest image (RGBA16F), for readImage() only.
    SFX_TRY(host_.makeBuffer(VkDeviceSize(w) * h * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, &readback_));
    SFX_TRY(host_.makeCommands(&pool_, &cb_, &fence_));

    // Every image starts in the layout it has between frames (contractLayout), so the SDK's
    // first use of an imported one finds the layout the import promised.
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    if (vkBeginCommandBuffer(cb_, &bi) != VK_SUCCESS) return {StatusCode::DeviceError, "vkBeginCommandBuffer failed"};
    for (HostImageKind k : {HostImageKind::Depth, HostImageKind::Normals, HostImageKind::Velocity, HostImageKind::Albedo, HostImageKind::Ao,
                            HostImageKind::Lit, HostImageKind::Blurred, HostImageKind::Final})
        imageBarrier(cb_, image(k), VK_IMAGE_LAYOUT_UNDEFINED, contractLayout(k), VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                     VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT);
    if (vkEndCommandBuffer(cb_) != VK_SUCCESS) return {StatusCode::DeviceError, "vkEndCommandBuffer failed"};
    SFX_TRY(host_.submit(cb_, fence_));
    inFlight_ = true;
    return finish();
}

Status EngineRenderer::createPipelines() {
    SFX_TRY(host_.makeSampler(&sampler_));
    SFX_TRY(host_.makeSetLayout({{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}},
                                &gbufferSetLayout_));
    std::vector<VkDescriptorSetLayoutBinding> lighting;
    for (uint32_t b = 0; b < 3; ++b) lighting.push_back({b, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, &sampler_});
    SFX_TRY(host_.makeSetLayout(lighting, &lightingSetLayout_));
    SFX_TRY(host_.makeSetLayout({{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, &sampler_}}, &presentSetLayout_));
    SFX_TRY(host_.makeDescriptorPool(3, 1, 4, &descriptorPool_));
    SFX_TRY(host_.allocateSet(descriptorPool_, gbufferSetLayout_, &gbufferSet_));
    SFX_TRY(host_.allocateSet(descriptorPool_, lightingSetLayout_, &lightingSet_));
    SFX_TRY(host_.allocateSet(descriptorPool_, presentSetLayout_, &presentSet_));

    PipelineDesc g;
    g.vertexCode = k_gbuffer_vert;
    g.vertexWords = std::size(k_gbuffer_vert);
    g.fragmentCode = k_gbuffer_frag;
    g.fragmentWords = std::size(k_gbuffer_frag);
    g.colorFormats = {normals_.format, velocity_.format, albedo_.format};
    g.depthFormat = depth_.format;
    g.meshVertices = true;
    g.setLayout = gbufferSetLayout_;
    g.pushConstantBytes = 128;  // two mat4: the minimum every device guarantees
    SFX_TRY(host_.makePipeline(g, &gbufferLayout_, &gbufferPipeline_));
    PipelineDesc l;
    l.vertexCode = k_fullscreen_vert;
    l.vertexWords = std::size(k_fullscreen_vert);
    l.fragmentCode = k_lighting_frag;
    l.fragmentWords = std::size(k_lighting_frag);
    l.colorFormats = {lit_.format};
    l.setLayout = lightingSetLayout_;
    SFX_TRY(host_.makePipeline(l, &lightingLayout_, &lightingPipeline_));
    PipelineDesc p = l;
    p.fragmentCode = k_present_frag;
    p.fragmentWords = std::size(k_present_frag);
    p.colorFormats = {final_.format};
    p.setLayout = presentSetLayout_;
    return host_.makePipeline(p, &presentLayout_, &presentPipeline_);
}

// The SDK on the host's device; the host's images become SDK textures with the layouts they
// hold between the host's passes (docs/integration.md, "Host images and the state contract").
Status EngineRenderer::connectSdk() {
    DeviceOptions options;
    options.validation = options_.validation;
    vulkan::ExternalVulkan external{host_.instance, host_.physical,        host_.device,     host_.queue,
                                    host_.family,   vkGetInstanceProcAddr, host_.debugUtils, host_.synchronization2};
    Result<std::unique_ptr<Device>> device = vulkan::wrapDevice(external, options);
    if (!device) return device.status();
    sfx_ = std::move(device.value());

    auto import = [&](HostImageKind kind, uint32_t usage, TextureHandle* out) -> Status {
        const HostImage& img = image(kind);
        vulkan::ExternalImage e;
        e.image = img.image;
        e.vkFormat = img.format;
        e.width = img.width;
        e.height = img.height;
        e.vkUsage = img.usage;
        e.usage = usage;
        e.view = img.view;
        e.layout = contractLayout(kind);
        Result<TextureHandle> t = vulkan::importImage(*sfx_, e);
        if (!t) return t.status();
        *out = t.value();
        return Status::ok();
    };
    SFX_TRY(import(HostImageKind::Depth, kTextureSampled, &depthTex_));
    SFX_TRY(import(HostImageKind::Normals, kTextureSampled, &normalTex_));
    SFX_TRY(import(HostImageKind::Velocity, kTextureSampled, &velocityTex_));
    SFX_TRY(import(HostImageKind::Ao, kTextureSampled | kTextureRenderTarget, &aoTex_));
    SFX_TRY(import(HostImageKind::Lit, kTextureSampled, &litTex_));
    SFX_TRY(import(HostImageKind::Blurred, kTextureSampled | kTextureRenderTarget, &blurredTex_));

    const TierProfile& profile = tiers::profile(options_.tier);
    AoSettings ao;
    ao.normals = AoNormals::FromTexture;
    ao.radius = 0.35f;
    Result<std::unique_ptr<AmbientObscurance>> aoEffect = AmbientObscurance::create(
        *sfx_, {options_.width, options_.height, profile, ao, DepthKind::Hardware});
    if (!aoEffect) return aoEffect.status();
    ao_ = std::move(aoEffect.value());
    MotionBlurDesc mb;
    mb.width = options_.width;
    mb.height = options_.height;
    mb.profile = profile;
    mb.colorFormat = Format::RGBA16F;
    mb.depthInput = DepthKind::Hardware;
    Result<std::unique_ptr<MotionBlur>> mbEffect = MotionBlur::create(*sfx_, mb);
    if (!mbEffect) return mbEffect.status();
    mb_ = std::move(mbEffect.value());
    // The velocity spans one frame: a shutter open for the whole frame interval.
    mbSettings_.exposure = 1.0f;
    return Status::ok();
}

// Written once: every set names the same images in every frame.
Status EngineRenderer::writeDescriptorSets() {
    VkDescriptorBufferInfo uniforms{sceneUniforms_.buffer, 0, VK_WHOLE_SIZE};
    const VkDescriptorImageInfo lighting[3] = {{sampler_, albedo_.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
                                               {sampler_, normals_.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
                                               {sampler_, aoImage_.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
    const VkDescriptorImageInfo blurred{sampler_, blurred_.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    std::vector<VkWriteDescriptorSet> writes(3, VkWriteDescriptorSet{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET});
    writes[0].dstSet = gbufferSet_;
    writes[0].descriptorCount = 1;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[0].pBufferInfo = &uniforms;
    writes[1].dstSet = lightingSet_;
    writes[1].descriptorCount = 3;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[1].pImageInfo = lighting;
    writes[2].dstSet = presentSet_;
    writes[2].descriptorCount = 1;
    writes[2].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[2].pImageInfo = &blurred;
    host_.writeDescriptors(writes);
    return Status::ok();
}

const HostImage& EngineRenderer::image(HostImageKind kind) const {
    switch (kind) {
        case HostImageKind::Depth: return depth_;
        case HostImageKind::Normals: return normals_;
        case HostImageKind::Velocity: return velocity_;
        case HostImageKind::Albedo: return albedo_;
        case HostImageKind::Ao: return aoImage_;
        case HostImageKind::Lit: return lit_;
        case HostImageKind::Blurred: return blurred_;
        case HostImageKind::Final: break;
    }
    return final_;
}

// The layout each image holds whenever the host calls into the SDK and between frames: depth
// as the G-buffer pass leaves it, the sampled images read-only, the final image as drawn.
VkImageLayout EngineRenderer::contractLayout(HostImageKind kind) const {
    if (kind == HostImageKind::Depth) return VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    if (kind == HostImageKind::Final) return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    return VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

std::vector<std::string> EngineRenderer::takeValidationMessages() {
    std::vector<std::string> out;
    for (std::string& m : host_.takeMessages()) out.push_back("host: " + m);
    if (sfx_)
        for (std::string& m : sfx_->takeValidationMessages()) out.push_back("sfx: " + m);
    return out;
}

EngineRenderer::~EngineRenderer() {
    if (!host_.device) return;
    vkDeviceWaitIdle(host_.device);
    // The SDK first (its effects, then its device), then the host's own objects.
    ao_.reset();
    mb_.reset();
    sfx_.reset();
    VkDevice d = host_.device;
    for (VkPipeline p : {gbufferPipeline_, lightingPipeline_, presentPipeline_})
        if (p) vkDestroyPipeline(d, p, nullptr);
    for (VkPipelineLayout l : {gbufferLayout_, lightingLayout_, presentLayout_})
        if (l) vkDestroyPipelineLayout(d, l, nullptr);
    if (descriptorPool_) vkDestroyDescriptorPool(d, descriptorPool_, nullptr);
    for (VkDescriptorSetLayout l : {gbufferSetLayout_, lightingSetLayout_, presentSetLayout_})
        if (l) vkDestroyDescriptorSetLayout(d, l, nullptr);
    if (sampler_) vkDestroySampler(d, sampler_, nullptr);
    if (fence_) vkDestroyFence(d, fence_, nullptr);
    if (pool_) vkDestroyCommandPool(d, pool_, nullptr);
    for (HostImage* i : {&depth_, &normals_, &velocity_, &albedo_, &aoImage_, &lit_, &blurred_, &final_}) host_.destroy(*i);
    for (HostBuffer* b : {&vertices_, &indices_, &sceneUniforms_, &readback_}) host_.destroy(*b);
}

}  // namespace sfx::engine
