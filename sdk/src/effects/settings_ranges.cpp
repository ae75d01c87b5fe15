// The settings-range table (sfx/settings_ranges.hpp) and its texts.
#include "sfx/settings_ranges.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "sfx/ao.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx_shared_ao.h"
#include "sfx_shared_ao_horizon.h"
#include "sfx_shared_mb.h"
#include "sfx_shared_oit.h"

namespace sfx {
namespace {

using S = Setting;
constexpr bool kOpen = true, kClosed = false;

// Bounds from the shaders' limits are the shared headers' constants; kAoMinRadius and
// kMbMinSoftDepthExtent say why their minimums are what they are. The epsilon's minimum is the
// float nearest 1e-8, crease.range's the float nearest 0.01 and metresPerUnit's the float nearest 1e-6, so
// the documented minimums can be set.
const SettingRange kRows[] = {
    {S::AoRadius, "AoSettings.radius", kAoMinRadius, 1000, kClosed, kClosed, "world units",
     "world-space sampling radius (every technique; Crease's range is in units of it)"},
    {S::AoMetresPerUnit, "AoSettings.metresPerUnit", double(1e-6f), 1e6, kClosed, kClosed, "m", "metres per world unit (0.01 for centimetres)"},
    {S::AoIntensity, "AoSettings.intensity", 0, 100, kClosed, kClosed, "", "sigma: scales occlusion"},
    {S::AoRadiusExponent, "AoSettings.radiusExponent", 0, 2, kClosed, kClosed, "",
     "A: intensity * (radius in metres / 0.5)^-A, the look following the radius"},
    {S::AoContrast, "AoSettings.contrast", 0.1, 10, kClosed, kClosed, "", "k: visibility = max(0, 1 - occlusion)^k"},
    {S::AoBias, "AoSettings.bias", 0, 1, kClosed, kClosed, "", "Alchemy: beta per unit of depth; Scalable: subtracted from each tap's cosine"},
    {S::AoSumExponent, "AoSettings.sumExponent", 0.5, 4, kClosed, kClosed, "", "Scalable: exponent of the normalised tap sum"},
    {S::AoEpsilon, "AoSettings.epsilon", double(1e-8f), 1, kClosed, kClosed, "radius^2", "guards divisions"},
    {S::AoSamples, "AoSettings.samples", 1, shared::SFX_AO_MAX_SAMPLES, kClosed, kClosed, "taps",
     "taps per pixel (Alchemy, Scalable; even on a mirrored tier); Crease takes 12 or 24"},
    {S::AoBlurRadius, "AoSettings.blurRadius", 1, shared::SFX_AO_MAX_BLUR_RADIUS, kClosed, kClosed, "px",
     "bilateral blur half-width in output pixels"},
    {S::AoDepthLayers, "AoSettings.depthLayers", 1, shared::SFX_AO_MAX_DEPTH_LAYERS, kClosed, kClosed, "layers",
     "opaque depth layers each tap tests: 1 = the visible layer; above 1 up to the tier's aoMaxDepthLayers (1 on current)"},
    {S::AoCreaseRange, "AoSettings.crease.range", double(0.01f), 100, kClosed, kClosed, "radius",
     "Crease: distance at which a tap's influence reaches 0"},
    {S::AoCreaseBias, "AoSettings.crease.bias", 0, 100, kOpen, kClosed, "", "Crease: scales (cos - minimumCrease) before saturating"},
    {S::AoCreaseAverager, "AoSettings.crease.averager", 0, 1000, kOpen, kClosed, "", "Crease: divisor of the tap sum"},
    {S::AoCreaseMinimumCrease, "AoSettings.crease.minimumCrease", -1, 1, kClosed, kOpen, "", "Crease: cosine below which a tap adds nothing"},
    {S::AoHorizonSlices, "AoSettings.horizon.slices", 1, shared::SFX_AO_HORIZON_MAX_SLICES, kClosed, kClosed, "slices",
     "Horizon: screen directions per pixel, each marched both ways"},
    {S::AoHorizonSteps, "AoSettings.horizon.steps", 1, shared::SFX_AO_HORIZON_MAX_STEPS, kClosed, kClosed, "taps",
     "Horizon: depth samples per side of a slice"},
    {S::AoHorizonThickness, "AoSettings.horizon.thickness", 0, 1, kClosed, kClosed, "",
     "Horizon: share of the horizon a lower sample past an occluder leaves (1 = solid occluders)"},
    {S::AoHorizonFalloff, "AoSettings.horizon.falloff", 0, 1, kOpen, kClosed, "radius",
     "Horizon: share of the radius, at its edge, over which a sample fades out"},
    {S::MbMaxRadiusPx, "MotionBlurSettings.maxRadiusPx", 0, shared::SFX_MB_MAX_RADIUS_LIMIT_PX, kOpen, kClosed, "px",
     "maximum blur radius at referenceRows rows (scaled to the output's height)"},
    {S::MbReferenceRows, "MotionBlurSettings.referenceRows", 0, 16384, kClosed, kClosed, "rows", "rows maxRadiusPx is defined at; 0 = no scaling"},
    {S::MbSamples, "MotionBlurSettings.samples", 3, shared::SFX_MB_MAX_TAPS, kClosed, kClosed, "taps",
     "reconstruction taps, centre included, odd (mirrored pairs)"},
    {S::MbSoftDepthExtent, "MotionBlurSettings.softDepthExtent", kMbMinSoftDepthExtent, 1e6f, kClosed, kClosed, "depth units",
     "depth difference over which a sample turns from level to in front or behind"},
    {S::MbCentreWeight, "MotionBlurSettings.centreWeight", 0, 100, kOpen, kClosed, "", "weight of the pixel's own colour; larger = thinner blur"},
    {S::MbExposure, "MotionBlurSettings.exposure", 0, 4, kClosed, kClosed, "", "fraction of the velocity's time span the shutter is open; 0 = off"},
    {S::OitMaxLayers, "TransparencyDesc.maxLayers", 1, shared::SFX_OIT_MAX_KEPT_LAYERS, kClosed, kClosed, "fragments",
     "K: fragments kept exactly per pixel"},
    {S::OitCompressedNodes, "TransparencyDesc.compressedNodes", 0, shared::SFX_OIT_COMPRESSED_NODES, kClosed, kClosed, "nodes",
     "M: nodes per compressed list (high tier); 0 = no compression"},
    {S::OitAoFilterRadius, "TransparencyDesc.ao.filterRadius", 0, shared::SFX_AO_MAX_BLUR_RADIUS, kClosed, kClosed, "px",
     "bilateral filter taps each side of the AO through the layers; 0 = the raw AO"},
    {S::OitDrawOpacity, "TransparentDraw.opacity", 0, 1, kClosed, kClosed, "", "opacity of a transparent draw (and a scene file object's)"},
};
static_assert(std::size(kRows) == size_t(Setting::Count), "one row per Setting");

// The exponent without padding: "1e-08" -> "1e-8", "1e+06" -> "1e6".
std::string trimExponent(std::string s) {
    const size_t e = s.find('e');
    if (e == std::string::npos) return s;
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    if (mantissa.find('.') != std::string::npos) {
        while (mantissa.back() == '0') mantissa.pop_back();
        if (mantissa.back() == '.') mantissa.pop_back();
    }
    std::string sign;
    if (exponent[0] == '-' || exponent[0] == '+') {
        if (exponent[0] == '-') sign = "-";
        exponent.erase(0, 1);
    }
    while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
    return mantissa + "e" + sign + exponent;
}

}  // namespace

std::span<const SettingRange> settingRanges() { return kRows; }

const SettingRange& settingRange(Setting id) { return kRows[size_t(id)]; }

std::string formatSettingNumber(double v) {
    char buf[64];
    const double a = std::fabs(v);
    // Float precision: bounds such as double(1e-8f) print as the value written.
    if (a != 0 && std::isfinite(v) && (a < 1e-3 || a >= 1e5))
        std::snprintf(buf, sizeof buf, "%.5e", v);
    else
        std::snprintf(buf, sizeof buf, "%.6g", v);
    return trimExponent(buf);
}

std::string rangeText(const SettingRange& r) {
    return std::string(r.minOpen ? "(" : "[") + formatSettingNumber(r.min) + ", " + formatSettingNumber(r.max) + (r.maxOpen ? ")" : "]");
}

bool inRange(const SettingRange& r, double v) {
    const bool aboveMin = r.minOpen ? v > r.min : v >= r.min;
    const bool belowMax = r.maxOpen ? v < r.max : v <= r.max;
    return aboveMin && belowMax;
}

std::string settingHelp(Setting id) {
    const SettingRange& r = settingRange(id);
    return std::string(r.description) + ", " + rangeText(r) + (*r.unit ? std::string(" ") + r.unit : std::string());
}

Status checkSetting(Setting id, double v, const std::string& argument, const std::string& note) {
    const SettingRange& r = settingRange(id);
    if (inRange(r, v)) return Status::ok();
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return invalidArgument(argument.empty() ? std::string(r.name) : argument, buf, rangeText(r) + note);
}

std::string settingsMarkdown() {
    std::ostringstream s;
    s << "| setting | allowed | unit | what it is |\n";
    s << "|---|---|---|---|\n";
    for (const SettingRange& r : kRows) s << "| `" << r.name << "` | " << rangeText(r) << " | " << r.unit << " | " << r.description << " |\n";
    return s.str();
}

}  // namespace sfx
