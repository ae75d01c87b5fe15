// Host images in, SDK images out (sfx::vulkan::importImage / nativeImage) on a wrapped host
// device with synchronization validation: AO reads the host's depth and normals and writes the
// host's image; the state contract of docs/integration.md holds in one host command buffer with
// host passes right before and right after the SDK's; bad imports are named errors; the SDK
// never frees a host image.
#include <catch2/catch.hpp>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "analytic_scenes.hpp"
#include "half_bytes.hpp"
#include "host_vulkan.hpp"
#include "sfx/ao.hpp"
#include "sfx/half.hpp"
#include "sfx/tiers.hpp"
#include "sfx/vulkan_device.hpp"
#include "sfx_test_shaders.hpp"
#include "skips.hpp"

using namespace sfx;
using namespace sfx::hostvk;

namespace {

// Two GPU runs of the same AO on the same device and inputs differ by at most one R16F step at 1.
constexpr double kSamePathTolerance = 1.0 / 1024.0;

double maxDifference(const std::vector<double>& a, const std::vector<double>& b) {
    REQUIRE(a.size() == b.size());
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

// AO of the SDK's own textures holding the same inputs: the path the imports must match.
std::vector<double> sdkOwnAo(Device& d, AmbientObscurance& ao, uint32_t w, uint32_t h, Format depthFormat, const std::vector<float>& depth,
                             DepthKind kind, const CameraProjection& camera, const std::vector<float>* normals) {
    TextureHandle depthTex = d.createTexture({w, h, 1, depthFormat, kTextureSampled}).value();
    REQUIRE(d.writeTexture(depthTex, 0, depth.data(), depth.size() * 4).isOk());
    TextureHandle normalTex;
    if (normals) {
        normalTex = d.createTexture({w, h, 1, Format::RGBA32F, kTextureSampled}).value();
        REQUIRE(d.writeTexture(normalTex, 0, normals->data(), normals->size() * 4).isOk());
    }
    TextureHandle out = d.createTexture({w, h, 1, Format::R16F, kTextureSampled | kTextureRenderTarget}).value();
    AoInputs in;
    in.depth = DepthSource{depthTex, kind, camera};
    in.normals = normalTex;
    in.output = out;
    REQUIRE(ao.dispatch(in).isOk());
    std::vector<uint16_t> texels(size_t(w) * h);
    REQUIRE(d.readTexture(out, 0, texels.data(), texels.size() * 2).isOk());
    std::vector<uint8_t> bytes(texels.size() * 2);
    std::memcpy(bytes.data(), texels.data(), bytes.size());
    for (TextureHandle t : {depthTex, normalTex, out})
        if (!t.isNull()) REQUIRE(d.destroyTexture(t).isOk());
    return test::halfBytesToDoubles(bytes);
}

}  // namespace

TEST_CASE("vulkan import: AO reads host depth and normals and writes a host image", "[vulkan][import]") {
    Host host;
    if (!host.create()) SFX_SKIP(host.skipReason);
    const std::unique_ptr<Device> wrapped = wrapValidated(host);
    Device& d = *wrapped;
    constexpr uint32_t w = 160, h = 90;
    const tools::AnalyticScene scene = tools::cornerScene(w, h);
    const std::vector<float> depth(scene.linearDepth.values.begin(), scene.linearDepth.values.end());
    std::vector<float> normals;
    for (const auto& n : scene.normals) normals.insert(normals.end(), {float(n.x), float(n.y), float(n.z), 0.0f});

    {
        HostImage depthImg(host, VK_FORMAT_R32_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                           w, h);
        // Normals in layer 1 of a two-layer array, with the host's view of that layer.
        HostImage normalImg(host, VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, w, h, 2, 1);
        HostImage outImg(
            host, VK_FORMAT_R16_SFLOAT,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, w,
            h);
        hostUpload(host, depthImg, 0, depth.data(), depth.size() * 4, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        hostUpload(host, normalImg, 1, normals.data(), normals.size() * 4, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
        const std::vector<uint16_t> grey(size_t(w) * h, floatToHalf(0.25f));
        hostUpload(host, outImg, 0, grey.data(), grey.size() * 2, VK_IMAGE_LAYOUT_GENERAL);

        vulkan::ExternalImage de;
        de.image = depthImg.image;
        de.vkFormat = VK_FORMAT_R32_SFLOAT;
        de.width = w;
        de.height = h;
        de.vkUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        de.usage = kTextureSampled;
        de.layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        vulkan::ExternalImage ne = de;
        ne.image = normalImg.image;
        ne.vkFormat = VK_FORMAT_UNDEFINED;
        ne.format = Format::RGBA32F;
        ne.layer = 1;
        ne.view = normalImg.view;
        ne.vkUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        vulkan::ExternalImage oe = de;
        oe.image = outImg.image;
        oe.vkFormat = VK_FORMAT_R16_SFLOAT;
        oe.vkUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
            VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        oe.usage = kTextureSampled | kTextureRenderTarget;
        oe.layout = VK_IMAGE_LAYOUT_GENERAL;
        Result<TextureHandle> depthTex = vulkan::importImage(d, de);
        Result<TextureHandle> normalTex = vulkan::importImage(d, ne);
        Result<TextureHandle> outTex = vulkan::importImage(d, oe);
        INFO(depthTex.status().toString() << " / " << normalTex.status().toString() << " / " << outTex.status().toString());
        REQUIRE((depthTex.isOk() && normalTex.isOk() && outTex.isOk()));
        CHECK(d.textureDesc(normalTex.value()).value().format == Format::RGBA32F);

        AoSettings settings;
        settings.normals = AoNormals::FromTexture;
        Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(d, {w, h, tiers::profile(Tier::High), settings, DepthKind::Linear});
        REQUIRE(ao.isOk());
        AoInputs in;
        in.depth = DepthSource{depthTex.value(), DepthKind::Linear, scene.camera};
        in.normals = normalTex.value();
        in.output = outTex.value();
        REQUIRE(ao.value()->dispatch(in).isOk());
        REQUIRE(d.flush().isOk());

        // Read through nativeImage: the host's own objects, in the contract's layout.
        Result<vulkan::NativeImage> native = vulkan::nativeImage(d, outTex.value());
        REQUIRE(native.isOk());
        CHECK(native->image == outImg.image);
        CHECK(native->format == VK_FORMAT_R16_SFLOAT);
        CHECK(native->layout == VK_IMAGE_LAYOUT_GENERAL);
        CHECK(vulkan::nativeImage(d, normalTex.value()).value().view == normalImg.view);
        const std::vector<double> imported = test::halfBytesToDoubles(hostDownload(host, outImg, native->layout, size_t(w) * h * 2));
        const std::vector<double> own = sdkOwnAo(d, *ao.value(), w, h, Format::R32F, depth, DepthKind::Linear, scene.camera, &normals);
        const double diff = maxDifference(imported, own);
        WARN("vulkan import: AO of imported images vs the SDK's own textures, worst pixel " << diff);
        CHECK(diff <= kSamePathTolerance);
        CHECK(*std::min_element(own.begin(), own.end()) < 0.9);  // the corner occludes: not a blank picture

        // readTexture of an imported image works through its transfer usage; the normals lack it.
        std::vector<float> back(size_t(w) * h);
        REQUIRE(d.readTexture(depthTex.value(), 0, back.data(), back.size() * 4).isOk());
        CHECK(back == depth);
        std::vector<float> normalBack(normals.size());
        CHECK(d.readTexture(normalTex.value(), 0, normalBack.data(), normalBack.size() * 4).code() == StatusCode::UnsupportedFeature);

        // destroyTexture forgets: the host's images still work (use after free would be a
        // validation error), with the host's data.
        ao.value().reset();
        for (TextureHandle t : {depthTex.value(), normalTex.value(), outTex.value()}) REQUIRE(d.destroyTexture(t).isOk());
        REQUIRE(d.flush().isOk());
        std::vector<uint8_t> depthBytes = hostDownload(host, depthImg, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, depth.size() * 4);
        CHECK(std::memcmp(depthBytes.data(), depth.data(), depthBytes.size()) == 0);
        CHECK(maxDifference(test::halfBytesToDoubles(hostDownload(host, outImg, VK_IMAGE_LAYOUT_GENERAL, size_t(w) * h * 2)), own) <=
              kSamePathTolerance);
        CHECK(d.destroyTexture(outTex.value()).code() == StatusCode::StaleHandle);
        checkNoMessages(d, host);
    }
}

TEST_CASE("vulkan import: bad imports are named errors", "[vulkan][import]") {
    Host host;
    if (!host.create()) SFX_SKIP(host.skipReason);
    const std::unique_ptr<Device> wrapped = wrapValidated(host);
    Device& d = *wrapped;
    HostImage img(host, VK_FORMAT_R16_SFLOAT, VK_IMAGE_USAGE_SAMPLED_BIT, 16, 16);
    vulkan::ExternalImage good;
    good.image = img.image;
    good.vkFormat = VK_FORMAT_R16_SFLOAT;
    good.width = good.height = 16;
    good.vkUsage = VK_IMAGE_USAGE_SAMPLED_BIT;
    REQUIRE(vulkan::importImage(d, good).isOk());

    auto refused = [&](vulkan::ExternalImage e, const char* argument, const char* allowed) {
        Result<TextureHandle> r = vulkan::importImage(d, e);
        INFO(argument << ": " << r.status().toString());
        REQUIRE_FALSE(r.isOk());
        CHECK(r.status().code() == StatusCode::InvalidArgument);
        CHECK(r.status().message().find(argument) != std::string::npos);
        CHECK(r.status().message().find(allowed) != std::string::npos);
    };
    vulkan::ExternalImage e = good;
    e.image = VK_NULL_HANDLE;
    refused(e, "ExternalImage.image", "VkImage");
    e = good;
    e.vkFormat = VK_FORMAT_UNDEFINED;
    refused(e, "ExternalImage.format", "Undefined");
    e = good;
    e.vkFormat = VK_FORMAT_B8G8R8A8_UNORM;
    refused(e, "ExternalImage.vkFormat", "R16G16B16A16_SFLOAT");
    e = good;
    e.format = Format::R32F;
    refused(e, "ExternalImage.format", "R16F");
    e = good;
    e.usage = kTextureSampled | kTextureRenderTarget;
    refused(e, "ExternalImage.usage", "VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT");
    e = good;
    e.vkUsage = 0;
    refused(e, "ExternalImage.vkUsage", "VkImageUsageFlags");
    e = good;
    e.layout = VK_IMAGE_LAYOUT_UNDEFINED;
    refused(e, "ExternalImage.layout", "SHADER_READ_ONLY_OPTIMAL");
    e = good;
    e.layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    refused(e, "ExternalImage.layout", "COLOR_ATTACHMENT_OPTIMAL");
    e = good;
    e.vkFormat = VK_FORMAT_D32_SFLOAT;
    e.layout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    refused(e, "ExternalImage.layout", "DEPTH_STENCIL_ATTACHMENT");
    e = good;
    e.width = 0;
    refused(e, "importImage", "width");
    CHECK(vulkan::nativeImage(d, TextureHandle{}).status().code() == StatusCode::InvalidHandle);
    checkNoMessages(d, host);
}

// One host command buffer: the host renders depth in its own dynamic-rendering pass, the SDK's
// AO reads it and writes the host's image, and the host samples that image in its own pass right
// after; no barrier of the host's between them (the state contract), validation silent.
TEST_CASE("vulkan import: host passes right before and after the SDK's AO in one command buffer", "[vulkan][import]") {
    Host host;
    if (!host.create()) SFX_SKIP(host.skipReason);
    const std::unique_ptr<Device> wrapped = wrapValidated(host);
    Device& d = *wrapped;
    constexpr uint32_t w = 160, h = 90;
    const CameraProjection camera = tools::AnalyticCamera{}.projection(w, h);
    // A floor receding row by row and a box standing on it, as the stored depth of `camera`.
    auto stored = [&](double z) {
        const glm::dvec4 clip = camera.projection * glm::dvec4(0, 0, -z, 1);
        return float(clip.z / clip.w);
    };
    std::vector<float> depth(size_t(w) * h);
    std::vector<VkClearRect> rects;
    std::vector<float> rectDepth;
    for (uint32_t y = 0; y < h; ++y) {
        rects.push_back({{{0, int32_t(y)}, {w, 1}}, 0, 1});
        rectDepth.push_back(stored(2.0 + 0.04 * (h - y)));
    }
    rects.push_back({{{60, 30}, {40, 40}}, 0, 1});
    rectDepth.push_back(stored(3.0));
    for (size_t r = 0; r < rects.size(); ++r)
        for (uint32_t y = 0; y < rects[r].rect.extent.height; ++y)
            for (uint32_t x = 0; x < rects[r].rect.extent.width; ++x)
                depth[size_t(rects[r].rect.offset.y + y) * w + rects[r].rect.offset.x + x] = rectDepth[r];

    HostImage depthImg(host, VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, w, h);
    HostImage aoImg(host, VK_FORMAT_R16_SFLOAT, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, w, h);
    HostImage target(host, VK_FORMAT_R32_SFLOAT, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, w / 2, h / 2);
    // The AO image starts in the layout the contract names for it.
    host.begin();
    imageBarrier(host.cb, aoImg, 0, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                 VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0);
    host.submitAndWait();

    // The depth in the layout the host's depth pass leaves it, the AO in the one its sampling
    // pass wants; the SDK makes its own view of the AO image.
    const vulkan::ExternalImage de = externalImage(depthImg, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                                   kTextureSampled, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    const vulkan::ExternalImage oe = externalImage(aoImg, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                                   kTextureSampled | kTextureRenderTarget, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                                   /*withView=*/false);
    Result<TextureHandle> depthTex = vulkan::importImage(d, de);
    Result<TextureHandle> aoTex = vulkan::importImage(d, oe);
    INFO(depthTex.status().toString() << " / " << aoTex.status().toString());
    REQUIRE((depthTex.isOk() && aoTex.isOk()));
    AoSettings settings;
    settings.radius = 1.0f;
    Result<std::unique_ptr<AmbientObscurance>> ao = AmbientObscurance::create(d, {w, h, tiers::profile(Tier::High), settings, DepthKind::Hardware});
    REQUIRE(ao.isOk());

    // The host's sampling pass: each target pixel the maximum of a 2x2 block of the AO image
    // (the HAL test program hal_test_downsample, built into a host pipeline).
    Result<const CompiledProgram*> program = test_shaders::find("hal_test_downsample", Tier::High);
    REQUIRE(program.isOk());
    std::vector<VkShaderModule> modules;
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    for (const StageCode& s : program.value()->stages) {
        VkShaderModuleCreateInfo mci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
        mci.codeSize = s.spirv.size() * 4;
        mci.pCode = s.spirv.data();
        VkShaderModule m;
        REQUIRE(vkCreateShaderModule(host.device, &mci, nullptr, &m) == VK_SUCCESS);
        modules.push_back(m);
        VkPipelineShaderStageCreateInfo st{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        st.stage = s.stage == ShaderStage::Vertex ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
        st.module = m;
        st.pName = "main";
        stages.push_back(st);
    }
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo slci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    slci.bindingCount = 1;
    slci.pBindings = &binding;
    VkDescriptorSetLayout setLayout;
    REQUIRE(vkCreateDescriptorSetLayout(host.device, &slci, nullptr, &setLayout) == VK_SUCCESS);
    VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &setLayout;
    VkPipelineLayout pipelineLayout;
    REQUIRE(vkCreatePipelineLayout(host.device, &plci, nullptr, &pipelineLayout) == VK_SUCCESS);
    const VkFormat targetFormat = VK_FORMAT_R32_SFLOAT;
    VkPipelineRenderingCreateInfo rci{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rci.colorAttachmentCount = 1;
    rci.pColorAttachmentFormats = &targetFormat;
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.cullMode = VK_CULL_MODE_NONE;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineColorBlendAttachmentState blendAttachment{};
    blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT;
    VkPipelineColorBlendStateCreateInfo cbs{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cbs.attachmentCount = 1;
    cbs.pAttachments = &blendAttachment;
    const VkDynamicState dynamics[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dyn{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dyn.dynamicStateCount = 2;
    dyn.pDynamicStates = dynamics;
    VkGraphicsPipelineCreateInfo gci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    gci.pNext = &rci;
    gci.stageCount = uint32_t(stages.size());
    gci.pStages = stages.data();
    gci.pVertexInputState = &vi;
    gci.pInputAssemblyState = &ia;
    gci.pViewportState = &vp;
    gci.pRasterizationState = &rs;
    gci.pMultisampleState = &ms;
    gci.pColorBlendState = &cbs;
    gci.pDynamicState = &dyn;
    gci.layout = pipelineLayout;
    VkPipeline pipeline;
    REQUIRE(vkCreateGraphicsPipelines(host.device, VK_NULL_HANDLE, 1, &gci, nullptr, &pipeline) == VK_SUCCESS);
    VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    VkSampler sampler;
    REQUIRE(vkCreateSampler(host.device, &sci, nullptr, &sampler) == VK_SUCCESS);
    VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = 1;
    dpci.poolSizeCount = 1;
    dpci.pPoolSizes = &poolSize;
    VkDescriptorPool descriptorPool;
    REQUIRE(vkCreateDescriptorPool(host.device, &dpci, nullptr, &descriptorPool) == VK_SUCCESS);
    VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dsai.descriptorPool = descriptorPool;
    dsai.descriptorSetCount = 1;
    dsai.pSetLayouts = &setLayout;
    VkDescriptorSet set;
    REQUIRE(vkAllocateDescriptorSets(host.device, &dsai, &set) == VK_SUCCESS);
    // The SDK's output, as nativeImage gives it: the host's image and layout.
    Result<vulkan::NativeImage> native = vulkan::nativeImage(d, aoTex.value());
    REQUIRE(native.isOk());
    CHECK(native->layout == VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    VkDescriptorImageInfo imageInfo{sampler, native->view, native->layout};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &imageInfo;
    vkUpdateDescriptorSets(host.device, 1, &write, 0, nullptr);
    const size_t targetBytes = size_t(w / 2) * (h / 2) * 4;
    HostBuffer readback(host, targetBytes);

    host.begin();
    // Host pass 1: depth, by clears of its rectangles inside the host's dynamic rendering.
    imageBarrier(host.cb, depthImg, 0, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                 0, VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                 VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    VkRenderingAttachmentInfo depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depthAttachment.imageView = depthImg.view;
    depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depthAttachment.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, {w, h}};
    ri.layerCount = 1;
    ri.pDepthAttachment = &depthAttachment;
    vkCmdBeginRendering(host.cb, &ri);
    for (size_t r = 0; r < rects.size(); ++r) {
        VkClearAttachment clear{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {}};
        clear.clearValue.depthStencil = {rectDepth[r], 0};
        vkCmdClearAttachments(host.cb, 1, &clear, 1, &rects[r]);
    }
    vkCmdEndRendering(host.cb);
    // The SDK, straight after, into the same command buffer.
    REQUIRE(vulkan::setCommandBuffer(d, host.cb).isOk());
    AoInputs in;
    in.depth = DepthSource{depthTex.value(), DepthKind::Hardware, camera};
    in.output = aoTex.value();
    REQUIRE(ao.value()->dispatch(in).isOk());
    REQUIRE(d.flush().isOk());
    // Host pass 2: samples the AO image, straight after.
    imageBarrier(host.cb, target, 0, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target.view;
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo ri2{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri2.renderArea = {{0, 0}, {w / 2, h / 2}};
    ri2.layerCount = 1;
    ri2.colorAttachmentCount = 1;
    ri2.pColorAttachments = &color;
    vkCmdBeginRendering(host.cb, &ri2);
    vkCmdBindPipeline(host.cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    vkCmdBindDescriptorSets(host.cb, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout, 0, 1, &set, 0, nullptr);
    const VkViewport viewport{0, 0, float(w / 2), float(h / 2), 0, 1};
    const VkRect2D scissor{{0, 0}, {w / 2, h / 2}};
    vkCmdSetViewport(host.cb, 0, 1, &viewport);
    vkCmdSetScissor(host.cb, 0, 1, &scissor);
    vkCmdDraw(host.cb, 3, 1, 0, 0);
    vkCmdEndRendering(host.cb);
    imageBarrier(host.cb, target, 0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                 VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {w / 2, h / 2, 1};
    vkCmdCopyImageToBuffer(host.cb, target.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(host.cb, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
    host.submitAndWait();
    std::vector<double> hostResult(size_t(w / 2) * (h / 2));
    for (size_t i = 0; i < hostResult.size(); ++i) {
        float v;
        std::memcpy(&v, static_cast<const uint8_t*>(readback.mapped) + 4 * i, 4);
        hostResult[i] = v;
    }
    checkNoMessages(d, host);

    // The SDK's own path over the same stored depth, reduced as the host's pass does.
    const std::vector<double> own = sdkOwnAo(d, *ao.value(), w, h, Format::D32F, depth, DepthKind::Hardware, camera, nullptr);
    std::vector<double> ownReduced(hostResult.size());
    for (uint32_t y = 0; y < h / 2; ++y)
        for (uint32_t x = 0; x < w / 2; ++x) {
            auto at = [&](uint32_t px, uint32_t py) { return own[size_t(py) * w + px]; };
            ownReduced[size_t(y) * (w / 2) + x] = std::max(std::max(at(2 * x, 2 * y), at(2 * x + 1, 2 * y)),
                                                           std::max(at(2 * x, 2 * y + 1), at(2 * x + 1, 2 * y + 1)));
        }
    const double diff = maxDifference(hostResult, ownReduced);
    WARN("vulkan import: AO between host passes vs the SDK's own path, worst pixel " << diff);
    CHECK(diff <= kSamePathTolerance);
    CHECK(*std::min_element(own.begin(), own.end()) < 0.9);  // the box occludes the floor
    checkNoMessages(d, host);

    ao.value().reset();
    REQUIRE(d.destroyTexture(depthTex.value()).isOk());
    REQUIRE(d.destroyTexture(aoTex.value()).isOk());
    REQUIRE(d.flush().isOk());
    vkDestroyDescriptorPool(host.device, descriptorPool, nullptr);
    vkDestroySampler(host.device, sampler, nullptr);
    vkDestroyPipeline(host.device, pipeline, nullptr);
    vkDestroyPipelineLayout(host.device, pipelineLayout, nullptr);
    vkDestroyDescriptorSetLayout(host.device, setLayout, nullptr);
    for (VkShaderModule m : modules) vkDestroyShaderModule(host.device, m, nullptr);
}
