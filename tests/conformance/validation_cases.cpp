// The invalid calls of the validation parity test, one table row per call (validation_cases.hpp).
#include "validation_cases.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <string_view>

#include "sfx/motion_blur.hpp"
#include "sfx/null_device.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shaders.hpp"
#include "sfx_test_shaders.hpp"

namespace sfx::test {

Objects::~Objects() {
    for (auto it = undo_.rbegin(); it != undo_.rend(); ++it) (*it)();
}

TextureHandle Objects::texture(uint32_t w, uint32_t h, Format f, uint32_t usage, uint32_t mips) {
    Result<TextureHandle> t = dev.createTexture({w, h, mips, f, usage, "validation case"});
    INFO("createTexture " << toString(f) << ": " << t.status().toString());
    REQUIRE(t.isOk());
    undo_.push_back([this, h = t.value()] { (void)dev.destroyTexture(h); });
    return t.value();
}

BufferHandle Objects::buffer(uint64_t size, uint32_t usage) {
    Result<BufferHandle> b = dev.createBuffer({size, usage, "validation case"});
    INFO("createBuffer: " << b.status().toString());
    REQUIRE(b.isOk());
    undo_.push_back([this, h = b.value()] { (void)dev.destroyBuffer(h); });
    return b.value();
}

SamplerHandle Objects::sampler(const SamplerDesc& desc) {
    Result<SamplerHandle> s = dev.createSampler(desc);
    INFO("createSampler: " << s.status().toString());
    REQUIRE(s.isOk());
    undo_.push_back([this, h = s.value()] { (void)dev.destroySampler(h); });
    return s.value();
}

ProgramHandle Objects::program(const CompiledProgram& p) {
    Result<ProgramHandle> h = dev.createProgram(p);
    INFO("createProgram " << p.name << ": " << h.status().toString());
    REQUIRE(h.isOk());
    undo_.push_back([this, h = h.value()] { (void)dev.destroyProgram(h); });
    return h.value();
}

ProgramHandle Objects::program(const char* name, Tier tier) { return program(shaderProgram(name, tier)); }

PipelineHandle Objects::graphics(const char* name, std::vector<Format> colors, Format depth, VertexLayout layout, Tier tier) {
    GraphicsPipelineDesc d;
    d.program = program(name, tier);
    d.colorFormats = std::move(colors);
    d.depthFormat = depth;
    d.vertexLayout = std::move(layout);
    Result<PipelineHandle> p = dev.createGraphicsPipeline(d);
    INFO("createGraphicsPipeline " << name << ": " << p.status().toString());
    REQUIRE(p.isOk());
    undo_.push_back([this, h = p.value()] { (void)dev.destroyPipeline(h); });
    return p.value();
}

PipelineHandle Objects::computeFrom(const CompiledProgram& prog) {
    Result<PipelineHandle> p = dev.createComputePipeline({program(prog)});
    INFO("createComputePipeline " << prog.name << ": " << p.status().toString());
    REQUIRE(p.isOk());
    undo_.push_back([this, h = p.value()] { (void)dev.destroyPipeline(h); });
    return p.value();
}

PipelineHandle Objects::compute(const char* name) { return computeFrom(shaderProgram(name, Tier::High)); }

const CompiledProgram& shaderProgram(const char* name, Tier tier) {
    // Test programs live in their own library (sfx_test_shaders), the rest in the runtime's.
    Result<const CompiledProgram*> p = test_shaders::find(name, tier);
    if (!p) p = shaders::find(name, tier);
    INFO(name << ": " << p.status().toString());
    REQUIRE(p.isOk());
    return *p.value();
}

Status tryProgram(Objects& o, const CompiledProgram& p) {
    Result<ProgramHandle> h = o.dev.createProgram(p);
    if (h.isOk()) (void)o.dev.destroyProgram(h.value());
    return h.status();
}

VertexLayout meshLayout() { return {28, {{0, VertexFormat::Float3, 0}, {1, VertexFormat::Float4, 12}}}; }

Format firstLackingWhere(const std::array<bool, size_t(Format::Count)>& has, const std::function<bool(Format)>& eligible) {
    for (uint32_t f = 1; f < uint32_t(Format::Count); ++f)
        if (!has[f] && eligible(Format(f))) return Format(f);
    return Format::Undefined;
}
Format firstNonBlendableTarget(const DeviceCaps& c) {
    return firstLackingWhere(c.blendableFormat, [&](Format f) { return !isDepthFormat(f) && !isIntegerFormat(f) && c.renderableFormat[size_t(f)]; });
}

namespace {

using validation::Error;
using Caps = DeviceCaps;

bool noCompute(const Caps& c) { return !c.computeShaders; }
// The first format the device cannot sample (render to); Undefined when it has none.
Format firstLacking(const std::array<bool, size_t(Format::Count)>& has) {
    return firstLackingWhere(has, [](Format) { return true; });
}
// A colour format the device lacks storage for.
Format firstNonStorageColour(const DeviceCaps& c) {
    return firstLackingWhere(c.storageFormat, [](Format f) { return !isDepthFormat(f); });
}
CompiledProgram copyProgram() { return shaderProgram("copy", Tier::Current); }

// A 16x8 RGBA16F motion blur of the current tier dispatched into a host output of this size,
// format and usage; the colour and depth inputs are valid.
bool motionBlurRuns(const Caps& c) {
    return c.renderableFormat[size_t(Format::RGBA16F)] && c.renderableFormat[size_t(Format::RG16F)] && c.sampledFormat[size_t(Format::D32F)];
}
Status motionBlurInto(Objects& o, uint32_t w, uint32_t h, Format format, uint32_t usage) {
    MotionBlurDesc desc;
    desc.width = 16;
    desc.height = 8;
    desc.profile = tiers::profile(Tier::Current);
    Result<std::unique_ptr<MotionBlur>> mb = MotionBlur::create(o.dev, desc);
    INFO("MotionBlur::create: " << mb.status().toString());
    REQUIRE(mb.isOk());
    MotionBlurInputs in;
    in.color = o.texture(16, 8, Format::RGBA16F, kTextureSampled);
    in.depth.texture = o.texture(16, 8, Format::D32F, kTextureSampled);
    in.output = o.texture(w, h, format, usage);
    return mb.value()->dispatch(in);
}

std::vector<ValidationCase> makeCases() {
    std::vector<ValidationCase> v;
    auto add = [&](const char* what, Error rule, std::function<bool(const Caps&)> applies, std::function<std::string(const Caps&)> expected,
                   std::function<Status(Objects&)> call) {
        v.push_back({what, rule, std::move(applies), std::move(expected), std::move(call)});
    };
    auto fixed = [](std::string s) { return [s](const Caps&) { return s; }; };

    // ---- Handles ---------------------------------------------------------------------------
    add("null handle", Error::HandleNull, {}, fixed("buffer is a null buffer handle; allowed a buffer this device created"),
        [](Objects& o) { return o.dev.destroyBuffer(BufferHandle{}); });
    add("handle of another device", Error::HandleForeign, {},
        fixed("texture is a texture handle of another device; allowed a texture this device created"), [](Objects& o) {
            auto other = null::createDevice();
            TextureHandle t = other->createTexture({4, 4, 1, Format::RGBA8, kTextureSampled}).value();
            return o.dev.destroyTexture(t);
        });
    add("handle past the pool", Error::HandleUnknown, {},
        fixed("texture is not a texture handle of this device; allowed a texture this device created"), [](Objects& o) {
            TextureHandle t = o.texture(4, 4, Format::RGBA8, kTextureSampled);
            return o.dev.destroyTexture(TextureHandle{t.bits + 1000});
        });
    add("destroyed handle", Error::HandleStale, {}, fixed("texture names a destroyed texture; allowed a texture that is still alive"),
        [](Objects& o) {
            TextureHandle t = o.dev.createTexture({4, 4, 1, Format::RGBA8, kTextureSampled}).value();
            (void)o.dev.destroyTexture(t);
            return o.dev.destroyTexture(t);
        });

    // ---- Descriptions ----------------------------------------------------------------------
    add(
        "zero width", Error::TextureWidth, {},
        [](const Caps& c) { return "TextureDesc.width is 0; allowed [1, " + str(c.limits.maxTextureSize) + "]"; },
        [](Objects& o) {
            return o.dev.createTexture({0, 4, 1, Format::RGBA8, kTextureSampled}).status();
        });
    add(
        "height over the limit", Error::TextureHeight, {},
        [](const Caps& c) {
            return "TextureDesc.height is " + str(c.limits.maxTextureSize + 1) + "; allowed [1, " + str(c.limits.maxTextureSize) + "]";
        },
        [](Objects& o) {
            return o.dev.createTexture({4, o.dev.caps().limits.maxTextureSize + 1, 1, Format::RGBA8, kTextureSampled}).status();
        });
    add(
        "render target beyond the framebuffer limit", Error::TextureRenderTargetSize,
        [](const Caps& c) { return c.limits.maxRenderTargetWidth < c.limits.maxTextureSize; },
        [](const Caps& c) {
            return "TextureDesc is " + str(c.limits.maxRenderTargetWidth + 1) + "x4 with usage render-target; allowed at most " +
                str(c.limits.maxRenderTargetWidth) + "x" + str(c.limits.maxRenderTargetHeight) + " (the device's framebuffer and viewport limits)";
        },
        [](Objects& o) {
            return o.dev.createTexture({o.dev.caps().limits.maxRenderTargetWidth + 1, 4, 1, Format::RGBA8, kTextureSampled | kTextureRenderTarget})
                .status();
        });
    add("too many mips", Error::TextureMipLevels, {}, fixed("TextureDesc.mipLevels is 4; allowed [1, 3] for 4x4"), [](Objects& o) {
        return o.dev.createTexture({4, 4, 4, Format::RGBA8, kTextureSampled}).status();
    });
    add("unknown format", Error::TextureFormatUnknown, {},
        fixed("TextureDesc.format is 999, not a Format; allowed R8, RGBA8, R16F, RG16F, RGBA16F, R32F, RG32F, RGBA32F, R32UI, "
              "D16, D24S8 or D32F"),
        [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, Format(999), kTextureSampled}).status();
        });
    add("no usage", Error::TextureUsage, {},
        fixed("TextureDesc.usage is none; allowed a non-empty combination of sampled, render-target and storage"), [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, Format::RGBA8, 0}).status();
        });
    add("unknown usage bit", Error::TextureUsage, {},
        fixed("TextureDesc.usage is sampled | 0x10 (unknown); allowed a non-empty combination of sampled, render-target and storage"),
        [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, Format::RGBA8, kTextureSampled | 0x10}).status();
        });
    add(
        "format the device cannot sample", Error::TextureFormatNotSampled,
        [](const Caps& c) { return firstLacking(c.sampledFormat) != Format::Undefined; },
        [](const Caps& c) {
            return std::string("TextureDesc.format is ") + toString(firstLacking(c.sampledFormat)) +
                ", which this device cannot sample; allowed with usage sampled: " + formatList([&](Format f) { return c.sampledFormat[size_t(f)]; });
        },
        [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, firstLacking(o.dev.caps().sampledFormat), kTextureSampled}).status();
        });
    add(
        "format the device cannot render to", Error::TextureFormatNotRenderable,
        [](const Caps& c) { return firstLacking(c.renderableFormat) != Format::Undefined; },
        [](const Caps& c) {
            return std::string("TextureDesc.format is ") + toString(firstLacking(c.renderableFormat)) +
                ", which this device cannot render to; allowed with usage render-target: " +
                formatList([&](Format f) { return c.renderableFormat[size_t(f)]; });
        },
        [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, firstLacking(o.dev.caps().renderableFormat), kTextureRenderTarget}).status();
        });
    add(
        "storage texture without storage images", Error::TextureStorageUnsupported, [](const Caps& c) { return !c.storageImages; },
        [](const Caps& c) { return "TextureDesc.usage includes storage, but this device has no storage images" + ceiling(c); },
        [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, Format::R32F, kTextureStorage}).status();
        });
    add(
        "depth storage texture", Error::TextureStorageDepth, [](const Caps& c) { return c.storageImages; },
        fixed("TextureDesc.format is D32F, a depth format, which cannot be a storage image; allowed a colour format with usage "
              "storage"),
        [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, Format::D32F, kTextureStorage}).status();
        });
    add(
        "storage texture of a format without storage", Error::TextureFormatNotStorage,
        [](const Caps& c) { return c.storageImages && firstNonStorageColour(c) != Format::Undefined; },
        [](const Caps& c) {
            return std::string("TextureDesc.format is ") + toString(firstNonStorageColour(c)) +
                ", which this device cannot use as a storage image; allowed with usage storage: " +
                formatList([&](Format f) { return c.storageFormat[size_t(f)]; });
        },
        [](Objects& o) {
            return o.dev.createTexture({4, 4, 1, firstNonStorageColour(o.dev.caps()), kTextureStorage}).status();
        });
    add(
        "empty buffer", Error::BufferSize, {}, [](const Caps& c) { return "BufferDesc.size is 0; allowed [1, " + str(c.limits.maxBufferSize) + "]"; },
        [](Objects& o) {
            return o.dev.createBuffer({0, kBufferUniform}).status();
        });
    add("buffer without usage", Error::BufferUsage, {},
        fixed("BufferDesc.usage is none; allowed a non-empty combination of uniform, storage, vertex and index"), [](Objects& o) {
            return o.dev.createBuffer({16, 0}).status();
        });
    add("buffer with unknown usage bits", Error::BufferUsage, {},
        fixed("BufferDesc.usage is vertex | 0x30 (unknown); allowed a non-empty combination of uniform, storage, vertex and index"), [](Objects& o) {
            return o.dev.createBuffer({16, kBufferVertex | 0x30}).status();
        });
    add(
        "storage buffer without storage buffers", Error::BufferStorageUnsupported, [](const Caps& c) { return !c.storageBuffers; },
        [](const Caps& c) { return "BufferDesc.usage includes storage, but this device has no storage buffers" + ceiling(c); },
        [](Objects& o) {
            return o.dev.createBuffer({16, kBufferStorage}).status();
        });
    add(
        "uniform buffer over the block size", Error::BufferUniformSize,
        [](const Caps& c) { return c.limits.maxUniformBlockSize + 16 <= c.limits.maxBufferSize; },
        [](const Caps& c) {
            return "BufferDesc.size is " + str(c.limits.maxUniformBlockSize + 16) + "; allowed [1, " + str(c.limits.maxUniformBlockSize) +
                "] for a buffer with usage uniform";
        },
        [](Objects& o) {
            return o.dev.createBuffer({o.dev.caps().limits.maxUniformBlockSize + 16, kBufferUniform}).status();
        });
    add("unknown filter", Error::SamplerFilter, {}, fixed("SamplerDesc.magFilter is 7; allowed Nearest or Linear"), [](Objects& o) {
        return o.dev.createSampler({Filter::Linear, Filter(7)}).status();
    });
    add("unknown address mode", Error::SamplerAddress, {}, fixed("SamplerDesc.address is 3; allowed ClampToEdge, Repeat or MirroredRepeat"),
        [](Objects& o) {
            SamplerDesc d;
            d.address = AddressMode(3);
            return o.dev.createSampler(d).status();
        });

    // ---- Programs --------------------------------------------------------------------------
    const char* stagesAllowed = "allowed a vertex and a fragment stage, or one compute stage";
    add("program without stages", Error::ProgramNoStages, {}, fixed(std::string("program 'copy' has no stages; ") + stagesAllowed), [](Objects& o) {
        CompiledProgram p = copyProgram();
        p.stages.clear();
        return tryProgram(o, p);
    });
    add("compute with graphics stages", Error::ProgramMixedStages, {},
        fixed(std::string("program 'copy' mixes compute with graphics stages; ") + stagesAllowed), [](Objects& o) {
            CompiledProgram p = copyProgram();
            p.stages.push_back(p.stages[0]);
            p.stages.back().stage = ShaderStage::Compute;
            return tryProgram(o, p);
        });
    add("vertex stage alone", Error::ProgramMissingStage, {},
        fixed(std::string("program 'copy' lacks a vertex or a fragment stage; ") + stagesAllowed), [](Objects& o) {
            CompiledProgram p = copyProgram();
            p.stages.resize(1);
            return tryProgram(o, p);
        });
    add(
        "compute program without compute", Error::ProgramComputeUnsupported, noCompute,
        [](const Caps& c) { return "program 'hal_atomic_count' is a compute program, but this device has no compute shaders" + ceiling(c); },
        [](Objects& o) { return tryProgram(o, shaderProgram("hal_atomic_count", Tier::High)); });
    add(
        "storage buffer without storage buffers", Error::ProgramStorageBufferUnsupported, [](const Caps& c) { return !c.storageBuffers; },
        [](const Caps& c) { return "program 'copy' uses storage buffer 'Extra', but this device has no storage buffers" + ceiling(c); },
        [](Objects& o) {
            CompiledProgram p = copyProgram();
            p.resources.push_back({"Extra", "Extra", ResourceKind::StorageBuffer, 5, stageBit(ShaderStage::Fragment), 16});
            return tryProgram(o, p);
        });
    add(
        "fragment-stage storage without fragment stores", Error::ProgramFragmentStorageUnsupported,
        [](const Caps& c) { return c.storageBuffers && !c.fragmentStoresAndAtomics; },
        [](const Caps& c) {
            return "program 'copy' uses 'uNodes' from its fragment stage, but this device has no fragment-stage stores and atomics" + ceiling(c);
        },
        [](Objects& o) {
            CompiledProgram p = copyProgram();
            p.resources.push_back({"uNodes", "uNodes", ResourceKind::StorageBuffer, 5, stageBit(ShaderStage::Fragment), 0});
            return tryProgram(o, p);
        });
    add(
        "storage image without storage images", Error::ProgramStorageImageUnsupported, [](const Caps& c) { return !c.storageImages; },
        [](const Caps& c) { return "program 'copy' uses storage image 'uExtra', but this device has no storage images" + ceiling(c); },
        [](Objects& o) {
            CompiledProgram p = copyProgram();
            p.resources.push_back({"uExtra", "uExtra", ResourceKind::StorageImage, 5, stageBit(ShaderStage::Fragment), 0});
            return tryProgram(o, p);
        });
    add(
        "empty SPIR-V", Error::ProgramNoSpirv, [](const Caps& c) { return c.dialect == ShaderDialect::Spirv; },
        fixed("program 'copy' has no valid SPIR-V module for its vertex stage (empty, or a bad magic number)"),
        [](Objects& o) {
            CompiledProgram p = copyProgram();
            p.stages[0].spirv.clear();
            return tryProgram(o, p);
        });
    add(
        "program of a tier that does not target the dialect", Error::ProgramTierDialect,
        [](const Caps& c) { return c.dialect == ShaderDialect::Essl300 || c.dialect == ShaderDialect::Glsl330; },
        [](const Caps& c) {
            return std::string("program 'depth_mip' is built for the high tier, whose dialects do not include ") + toString(c.dialect) +
                "; allowed a program of a tier that targets it";
        },
        [](Objects& o) { return tryProgram(o, shaderProgram("depth_mip", Tier::High)); });
    add(
        "no text for the dialect", Error::ProgramNoSource, [](const Caps& c) { return c.dialect != ShaderDialect::Spirv; },
        [](const Caps& c) { return std::string("program 'copy' has no ") + toString(c.dialect) + " source for its fragment stage"; },
        [](Objects& o) {
            CompiledProgram p = copyProgram();
            p.stages[1].glsl[size_t(o.dev.caps().dialect)].clear();
            return tryProgram(o, p);
        });

    // ---- Effect inputs ---------------------------------------------------------------------
    add("motion blur output of another size", Error::MotionBlurOutputSize, motionBlurRuns,
        fixed("MotionBlurInputs.output is 8x8; allowed 16x8, the MotionBlur size"),
        [](Objects& o) { return motionBlurInto(o, 8, 8, Format::RGBA16F, kRenderable); });
    add("motion blur output of another format", Error::MotionBlurOutputFormat, motionBlurRuns,
        fixed("MotionBlurInputs.output format is RGBA8; allowed RGBA16F, the MotionBlurDesc.colorFormat"),
        [](Objects& o) { return motionBlurInto(o, 16, 8, Format::RGBA8, kRenderable); });
    add("motion blur output that is not a render target", Error::MotionBlurOutputUsage, motionBlurRuns,
        fixed("MotionBlurInputs.output has usage sampled; allowed a texture with usage render-target"),
        [](Objects& o) { return motionBlurInto(o, 16, 8, Format::RGBA16F, kTextureSampled); });
    return v;
}

}  // namespace

std::vector<ValidationCase> pipelineAndCommandCases();

// Whether `message` is the rule's template with its "{}" filled in.
static bool matchesTemplate(validation::Error rule, const std::string& message) {
    const std::string_view t = validation::entry(rule).message;
    std::vector<std::string_view> pieces;
    for (size_t start = 0;;) {
        const size_t hole = t.find("{}", start);
        pieces.push_back(t.substr(start, hole == std::string_view::npos ? std::string_view::npos : hole - start));
        if (hole == std::string_view::npos) break;
        start = hole + 2;
    }
    if (message.compare(0, pieces.front().size(), pieces.front()) != 0) return false;
    size_t at = pieces.front().size();
    for (size_t i = 1; i < pieces.size(); ++i) {
        const size_t found = i + 1 == pieces.size() ? message.rfind(pieces[i]) : message.find(pieces[i], at);
        if (found == std::string::npos || found < at) return false;
        at = found + pieces[i].size();
    }
    return pieces.size() == 1 ? message.size() == at : at == message.size();
}

static void checkRefusal(const ValidationCase& c, const Status& s, const DeviceCaps& caps, const char* device) {
    const validation::ErrorEntry& e = validation::entry(c.rule);
    INFO(device << ": " << c.what << " (" << e.name << ") -> " << s.toString());
    CHECK(s.code() == e.code);
    CHECK(matchesTemplate(c.rule, s.message()));
    const std::string expected = c.expected(caps);
    if (!expected.empty()) CHECK(s.message() == expected);
}

// Runs every case that applies on `device`; its null twin (same caps) must give the same status.
// Returns the rules it exercised.
std::set<validation::Error> runValidationCases(Device& device, bool withTwin) {
    std::set<validation::Error> exercised;
    const DeviceCaps& caps = device.caps();
    std::unique_ptr<Device> twin = null::createDevice(caps);
    for (const ValidationCase& c : validationCases()) {
        if (c.applies && !c.applies(caps)) continue;
        Status onDevice;
        {
            Objects objects(device);
            onDevice = c.call(objects);
        }
        Status onTwin;
        if (withTwin) {
            Objects objects(*twin);
            onTwin = c.call(objects);
        }
        if (c.onlyOn && !c.onlyOn(caps)) {
            // A check only another API makes: the call is valid here.
            INFO(c.what << " on " << toString(caps.backend) << " -> " << onDevice.toString());
            CHECK(onDevice.isOk());
            continue;
        }
        checkRefusal(c, onDevice, caps, toString(caps.backend));
        if (withTwin && !c.onlyOn) {
            INFO("null twin of " << toString(caps.backend) << ": " << c.what);
            CHECK(onTwin.code() == onDevice.code());
            CHECK(onTwin.message() == onDevice.message());
        }
        exercised.insert(c.rule);
    }
    return exercised;
}

// Null devices posing as what no device here is: one that samples and renders no RG32F, one
// taking SPIR-V with a storage range below its buffer size, one under the GL ES 3.0 ceiling.
std::vector<DeviceCaps> craftedNullCaps() {
    DeviceCaps lacking = null::defaultCaps();
    lacking.sampledFormat[size_t(Format::RG32F)] = false;
    lacking.renderableFormat[size_t(Format::RG32F)] = false;
    lacking.limits.maxRenderTargetWidth = lacking.limits.maxRenderTargetHeight = 8192;  // SwiftShader's framebuffer limit
    lacking.blendableFormat[size_t(Format::RGBA32F)] = false;                           // GL ES without EXT_float_blend
    lacking.storageFormat[size_t(Format::RG16F)] = false;                               // GL ES 3.1's image formats
    DeviceCaps vulkanLike = null::defaultCaps();
    vulkanLike.dialect = ShaderDialect::Spirv;
    vulkanLike.limits.maxStorageBufferSize = 1u << 20;  // below maxBufferSize, as on real devices
    // Storage for compute only, as GL ES 3.1 may offer (its fragment-stage minimums are 0).
    DeviceCaps computeOnlyStorage = null::defaultCaps();
    computeOnlyStorage.fragmentStoresAndAtomics = false;
    return {lacking, vulkanLike, computeOnlyStorage, null::defaultCaps(CapabilityCeiling::GLES30)};
}

// Rows that need a host's own Vulkan objects or GL context, each with its case there: a host
// command buffer (tests/vulkan/test_vulkan_external.cpp records into one), the host-integration
// entry points (tests/vulkan/test_vulkan_entry_points.cpp; GlNoCurrentContext and DeviceWrongApi
// of the GL calls in tests/conformance/test_gl_import.cpp).
static const std::set<Error> kHostCommandBufferRows = {
    Error::HostCommandBufferRead,      Error::TimerHostPending,   Error::ExternalObjectNull,       Error::ExternalQueueFamily,
    Error::ExternalQueueFamilyFlags,   Error::ExternalApiVersion, Error::ExternalSynchronization2, Error::DeviceWrongApi,
    Error::HostCommandBufferOwnDevice, Error::GlNoCurrentContext};

void checkEveryRuleExercised(const std::set<validation::Error>& exercised) {
    std::set<Error> withCase;
    for (const ValidationCase& c : validationCases()) withCase.insert(c.rule);
    for (uint32_t i = 0; i < uint32_t(Error::Count); ++i) {
        const Error e = Error(i);
        if (kHostCommandBufferRows.count(e)) continue;
        INFO("rule " << validation::entry(e).name << ": " << validation::entry(e).message);
        CHECK(withCase.count(e) == 1);
        // API-specific rows are refused only on their backend; elsewhere the case shows the call is valid.
        const bool apiSpecific = std::any_of(validationCases().begin(), validationCases().end(),
                                             [&](const ValidationCase& c) { return c.rule == e && c.onlyOn; });
        if (!apiSpecific) CHECK(exercised.count(e) == 1);
    }
}

const std::vector<ValidationCase>& validationCases() {
    static const std::vector<ValidationCase> cases = [] {
        std::vector<ValidationCase> all = makeCases();
        for (ValidationCase& c : pipelineAndCommandCases()) all.push_back(std::move(c));
        return all;
    }();
    return cases;
}

}  // namespace sfx::test
