// The allowed range of every numeric public setting, written once: the effects' validation, the
// sfx CLI's help and checks, the scene renderer and scene-file reader and docs/settings.md (`sfx info --settings`)
// all read this table.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "sfx/status.hpp"

namespace sfx {

enum class Setting : uint32_t {
    AoRadius,
    AoMetresPerUnit,
    AoIntensity,
    AoRadiusExponent,
    AoContrast,
    AoBias,
    AoSumExponent,
    AoEpsilon,
    AoSamples,
    AoBlurRadius,
    AoDepthLayers,
    AoCreaseRange,
    AoCreaseBias,
    AoCreaseAverager,
    AoCreaseMinimumCrease,
    AoHorizonSlices,
    AoHorizonSteps,
    AoHorizonThickness,
    AoHorizonFalloff,
    MbMaxRadiusPx,
    MbReferenceRows,
    MbSamples,
    MbSoftDepthExtent,
    MbCentreWeight,
    MbExposure,
    OitMaxLayers,
    OitCompressedNodes,
    OitAoFilterRadius,
    OitDrawOpacity,
    Count,
};

struct SettingRange {
    Setting id;
    const char* name;  // as messages name it: "AoSettings.radius"
    double min, max;
    bool minOpen, maxOpen;  // exclusive bound: "(" or ")"
    const char* unit;       // "" when unitless
    const char* description;
};

std::span<const SettingRange> settingRanges();  // every row, in Setting order
const SettingRange& settingRange(Setting id);

std::string formatSettingNumber(double v);      // "1e-4", "0.5", "1000"
std::string rangeText(const SettingRange& r);   // "[1e-4, 1000]", "(0, 100]"
bool inRange(const SettingRange& r, double v);  // false for NaN
// "<description>, <range>[ unit]": the CLI's help text for the setting.
std::string settingHelp(Setting id);
// Ok inside the range; else InvalidArgument "<argument> is <v>; allowed <range>[<note>]".
// argument defaults to the row's name; note is appended to the range (", or unset for the tier's").
Status checkSetting(Setting id, double v, const std::string& argument = {}, const std::string& note = {});
// The table as Markdown (docs/settings.md holds it; CTest docs.settings compares).
std::string settingsMarkdown();

}  // namespace sfx
