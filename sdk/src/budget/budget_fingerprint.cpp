// What a cost table measured, as one number: the device and API that ran it, every candidate's
// preset parameters and the code of the tier's programs. A table cached before any of them
// changed (another driver, a tier table with other presets, other shaders) is measured again
// rather than read.
#include <string_view>
#include <type_traits>

#include "sfx/budget.hpp"
#include "sfx_shaders.hpp"

namespace sfx::budget {
namespace {

// FNV-1a, 64 bits: stable across compilers and runs, which a cache file needs.
struct Fnv1a {
    uint64_t h = 14695981039346656037ull;
    void bytes(const void* data, size_t n) {
        const auto* b = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    }
    template <class T>
    void value(T v) {
        static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>);
        bytes(&v, sizeof v);
    }
    void text(std::string_view s) {
        value(uint64_t(s.size()));
        bytes(s.data(), s.size());
    }
};

// Every field of the profile, so a changed preset changes the number. The size check stops a
// field added to TierProfile (or removed from it) from building until it is listed here: one
// left out would keep cached costs of presets that differ in it. Every member is 4 bytes or a
// bool, laid out alike on the ABIs the SDK builds for.
static_assert(sizeof(TierProfile) == 196, "TierProfile changed: fingerprint its fields in addProfile, then update this size");
void addProfile(Fnv1a& f, const TierProfile& p) {
    f.value(p.tier), f.value(p.aoTechnique), f.value(p.aoScalableTaps), f.value(p.aoScalableMirrored), f.value(p.aoScalableMaxRadiusPx);
    f.value(p.aoUsesDepthMip), f.value(p.aoDepthMipLevels), f.value(p.aoAlchemySamples), f.value(p.aoBlurRadiusPx), f.value(p.aoCreaseTaps);
    f.value(p.aoHorizonSlices), f.value(p.aoHorizonSteps), f.value(p.aoHorizonThickness);
    f.value(p.aoHorizonFalloff);
    for (const AoLook& l : p.aoLook)
        f.value(l.intensity), f.value(l.contrast), f.value(l.bias), f.value(l.sumExponent), f.value(l.creaseRange), f.value(l.creaseBias),
            f.value(l.radiusExponent);
    f.value(p.aoPackedDepthTarget), f.value(p.aoHalfResolution), f.value(p.aoMaxDepthLayers);
    f.value(p.mbTaps), f.value(p.mbMaxRadiusPx), f.value(p.mbTilePx), f.value(p.mbJitterSize), f.value(p.abufferOit);
}

}  // namespace

uint64_t fingerprint(const DeviceCaps& caps, Effect effect, const std::vector<Preset>& presets) {
    Fnv1a f;
    f.value(caps.backend);
    f.text(caps.apiName);
    f.text(caps.deviceName);
    f.value(effect);
    for (const Preset& p : presets) {
        f.text(p.name);
        addProfile(f, p.params);
    }
    const Tier tier = presets.empty() ? Tier::Current : presets.front().params.tier;
    for (const CompiledProgram& program : shaders::all()) {
        if (program.tier != tier) continue;
        f.text(program.name);
        for (const StageCode& stage : program.stages) {
            f.value(stage.stage);
            f.bytes(stage.spirv.data(), stage.spirv.size() * sizeof(uint32_t));
            for (const std::string& glsl : stage.glsl) f.text(glsl);
        }
    }
    return f.h;
}

}  // namespace sfx::budget
