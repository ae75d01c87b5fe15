// validateAoSettings / resolveAoConfig on settings and profiles from fuzzer bytes: a named
// InvalidArgument or a config inside the documented ranges (finite numbers, 1..64 samples,
// blur radius <= SFX_AO_MAX_BLUR_RADIUS, at least one depth MIP level read, horizon's slices and
// steps within the shader's limits).
#include <cstdlib>

#include "fuzz_values.hpp"
#include "sfx/ao.hpp"
#include "sfx_shared_ao_horizon.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace sfx;
    FuzzedDataProvider in(data, size);
    const TierProfile profile = fuzz::hostileProfile(in);
    AoSettings s;
    s.technique = AoTechnique(in.ConsumeIntegralInRange<uint32_t>(0, kAoTechniqueCount));
    s.radius = fuzz::hostileFloat(in);
    s.intensity = fuzz::hostileOptionalFloat(in);
    s.contrast = fuzz::hostileOptionalFloat(in);
    s.bias = fuzz::hostileOptionalFloat(in);
    s.epsilon = fuzz::hostileFloat(in);
    s.samples = fuzz::hostileOptionalCount(in);
    s.blur = in.ConsumeBool();
    s.blurRadius = fuzz::hostileOptionalCount(in);
    s.normals = AoNormals(in.ConsumeIntegralInRange<uint32_t>(0, 3));
    s.crease.range = fuzz::hostileOptionalFloat(in);
    s.crease.bias = fuzz::hostileOptionalFloat(in);
    s.crease.averager = fuzz::hostileFloat(in);
    s.crease.minimumCrease = fuzz::hostileFloat(in);
    s.crease.fadeStart = fuzz::hostileFloat(in);
    s.crease.fadeEnd = fuzz::hostileFloat(in);
    const uint32_t mipLevelsAllowed = in.ConsumeIntegralInRange<uint32_t>(1, 16);
    const uint32_t outputRows = in.ConsumeIntegralInRange<uint32_t>(1, 16384);  // a context's height
    s.sumExponent = fuzz::hostileOptionalFloat(in);
    s.horizon.slices = fuzz::hostileOptionalCount(in);
    s.horizon.steps = fuzz::hostileOptionalCount(in);
    s.horizon.thickness = fuzz::hostileOptionalFloat(in);
    s.horizon.falloff = fuzz::hostileOptionalFloat(in);
    // Last, and only where input is left, so the corpus written before them keeps its meaning.
    if (in.remaining_bytes() > 0) {
        s.metresPerUnit = fuzz::hostileFloat(in);
        s.radiusExponent = fuzz::hostileOptionalFloat(in);
    }

    const Status valid = validateAoSettings(s, profile);
    Result<AoConfig> config = resolveAoConfig(s, profile, mipLevelsAllowed, outputRows);
    if (bool(valid) != bool(config)) std::abort();  // resolve validates exactly as validate does
    if (!config) {
        if (!fuzz::namesField(config.status(), {"AoSettings.", "AoDesc.profile"})) std::abort();
        return 0;
    }
    const AoConfig& c = config.value();
    for (double v : {c.radius, c.intensity, c.contrast, c.bias, c.sumExponent, c.epsilon, c.spiralTurns, c.maxRadiusPx})
        if (!std::isfinite(v)) std::abort();
    // A radius-following intensity stays inside the intensity's own range.
    if (!(c.intensity >= 0 && c.intensity <= 100)) std::abort();
    if (c.samples < 1 || c.samples > uint32_t(shared::SFX_AO_MAX_SAMPLES)) std::abort();
    if (c.mirrored && c.samples % 2 != 0) std::abort();
    if (c.blurRadius > uint32_t(shared::SFX_AO_MAX_BLUR_RADIUS)) std::abort();
    if (c.depthMipLevels < 1 || c.depthMipLevels > mipLevelsAllowed) std::abort();
    // Crease's range in world units: the range (in radii) times the radius, both bounded.
    if (!(c.crease.range > 0) || !std::isfinite(c.crease.range)) std::abort();
    if (c.maxRadiusPx < 0) std::abort();
    // Horizon's loops are specialisation constants the shader is built for; its thickness and
    // falloff make a finite blend and a finite 1 / (falloff * radius).
    const AoHorizonConfig& h = c.horizon;
    if (h.slices < 1 || h.slices > uint32_t(shared::SFX_AO_HORIZON_MAX_SLICES) || h.steps < 1 || h.steps > uint32_t(shared::SFX_AO_HORIZON_MAX_STEPS))
        std::abort();
    if (!(h.thickness >= 0 && h.thickness <= 1) || !(h.falloff > 0 && h.falloff <= 1) || !std::isfinite(1.0 / (h.falloff * c.radius))) std::abort();
    return 0;
}
