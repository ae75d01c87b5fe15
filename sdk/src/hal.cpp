#include <algorithm>
#include <atomic>
#include <cstring>

#include "sfx/hal.hpp"

namespace sfx {

uint16_t nextDeviceSerial() {
    static std::atomic<uint32_t> counter{0};
    uint32_t s;
    do {
        s = (counter.fetch_add(1) + 1) & 0xffffu;
    } while (s == 0);
    return uint16_t(s);
}

const char* toString(Tier tier) { return uint32_t(tier) < kTierCount ? kTierNames[uint32_t(tier)] : "unknown"; }

bool parseTier(const std::string& text, Tier* out) {
    for (uint32_t i = 0; i < kTierCount; ++i)
        if (text == kTierNames[i]) {
            *out = Tier(i);
            return true;
        }
    return false;
}

std::string tierNameList() {
    std::string s;
    for (uint32_t i = 0; i < kTierCount; ++i) s += std::string(i == 0 ? "" : i + 1 == kTierCount ? " or " : ", ") + kTierNames[i];
    return s;
}

const char* toString(BackendKind kind) {
    switch (kind) {
        case BackendKind::Null: return "null";
        case BackendKind::Vulkan: return "vulkan";
        case BackendKind::GLES: return "gles";
        case BackendKind::GL: return "gl";
    }
    return "unknown";
}

namespace {
struct FormatInfo {
    const char* name;
    uint32_t bytes;
    uint32_t channels;
    bool depth;
    bool integer;
};
constexpr FormatInfo kFormats[] = {
    {"Undefined", 0, 0, false, false}, {"R8", 1, 1, false, false},      {"RGBA8", 4, 4, false, false}, {"R16F", 2, 1, false, false},
    {"RG16F", 4, 2, false, false},     {"RGBA16F", 8, 4, false, false}, {"R32F", 4, 1, false, false},  {"RG32F", 8, 2, false, false},
    {"RGBA32F", 16, 4, false, false},  {"R32UI", 4, 1, false, true},    {"D16", 2, 1, true, false},    {"D24S8", 4, 1, true, false},
    {"D32F", 4, 1, true, false},
};
static_assert(std::size(kFormats) == size_t(Format::Count));
const FormatInfo& info(Format f) {
    size_t i = size_t(f);
    return kFormats[i < std::size(kFormats) ? i : 0];
}
}  // namespace

const char* toString(Format format) { return info(format).name; }
uint32_t bytesPerTexel(Format format) { return info(format).bytes; }
bool isDepthFormat(Format format) { return info(format).depth; }
bool isIntegerFormat(Format format) { return info(format).integer; }
uint32_t channelCount(Format format) { return info(format).channels; }

const char* toString(TimingSource source) { return source == TimingSource::GpuTimestamps ? "GPU timestamps" : "wall clock after glFinish"; }

const char* toString(CapabilityCeiling ceiling) { return ceiling == CapabilityCeiling::GLES30 ? "GL ES 3.0" : "none"; }

const char* toString(ShaderDialect dialect) {
    switch (dialect) {
        case ShaderDialect::Spirv: return "spirv";
        case ShaderDialect::Essl300: return "essl300";
        case ShaderDialect::Essl310: return "essl310";
        case ShaderDialect::Glsl330: return "glsl330";
        case ShaderDialect::Glsl450: return "glsl450";
        case ShaderDialect::Count: break;
    }
    return "unknown";
}

bool parseShaderDialect(const std::string& text, ShaderDialect* out) {
    for (uint32_t i = 0; i < uint32_t(ShaderDialect::Count); ++i) {
        if (text == toString(ShaderDialect(i))) {
            *out = ShaderDialect(i);
            return true;
        }
    }
    return false;
}

const char* toString(ShaderStage stage) {
    switch (stage) {
        case ShaderStage::Vertex: return "vertex";
        case ShaderStage::Fragment: return "fragment";
        case ShaderStage::Compute: return "compute";
    }
    return "unknown";
}

const char* toString(ResourceKind kind) {
    switch (kind) {
        case ResourceKind::UniformBuffer: return "uniform buffer";
        case ResourceKind::SampledTexture: return "sampled texture";
        case ResourceKind::StorageBuffer: return "storage buffer";
        case ResourceKind::StorageImage: return "storage image";
    }
    return "unknown";
}

bool CompiledProgram::usesStorage() const {
    return std::any_of(resources.begin(), resources.end(),
                       [](const ShaderResource& r) { return r.kind == ResourceKind::StorageBuffer || r.kind == ResourceKind::StorageImage; });
}

const ShaderResource* CompiledProgram::findResource(const std::string& resourceName) const {
    for (const ShaderResource& r : resources)
        if (r.name == resourceName) return &r;
    return nullptr;
}

std::string DeviceCaps::summary() const {
    std::string s = std::string(toString(backend)) + " via " + platform + ": " + apiName + " on " + deviceName + ", shaders " + toString(dialect);
    if (ceiling != CapabilityCeiling::None) s += ", capability ceiling " + std::string(toString(ceiling));
    s += ", compute " + std::string(computeShaders ? "yes" : "no");
    s += ", storage buffers " + std::string(storageBuffers ? "yes" : "no");
    s += ", atomics " + std::string(atomics ? "yes" : "no");
    s += ", fragment stores " + std::string(fragmentStoresAndAtomics ? "yes" : "no");
    s += ", float targets " + std::string(floatRenderTargets ? "yes" : "no");
    s += ", clip depth " + std::string(clipDepth == ClipDepthRange::ZeroToOne ? "[0,1]" : "[-1,1]");
    s += ", timing: " + std::string(toString(timing));
    return s;
}

uint32_t mipExtent(uint32_t base, uint32_t mip) { return mip >= 32 ? 1u : std::max(1u, base >> mip); }

uint32_t maxMipLevels(uint32_t width, uint32_t height) {
    uint32_t m = std::max(width, height), levels = 1;
    while (m > 1) {
        m >>= 1;
        ++levels;
    }
    return levels;
}

uint64_t mipLevelBytes(const TextureDesc& desc, uint32_t mip) {
    return uint64_t(mipExtent(desc.width, mip)) * mipExtent(desc.height, mip) * bytesPerTexel(desc.format);
}

uint64_t textureBytes(const TextureDesc& desc) {
    uint64_t bytes = 0;
    for (uint32_t m = 0; m < desc.mipLevels; ++m) bytes += mipLevelBytes(desc, m);
    return bytes;
}

}  // namespace sfx
