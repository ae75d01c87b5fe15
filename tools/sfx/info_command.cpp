#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <ostream>

#include "cli_common.hpp"
#include "commands.hpp"
#include "sfx/budget.hpp"
#include "sfx/settings_ranges.hpp"

namespace sfx::cli {
namespace {

std::string yesNo(bool b) { return b ? "yes" : "no"; }

enum class LookOf { Alchemy, Scalable, Crease, Horizon };
std::string look(const AoLook& l, LookOf t) {
    char buf[96];
    if (t == LookOf::Crease)
        std::snprintf(buf, sizeof buf, "%g, %g, %g, %g", l.intensity, l.contrast, l.creaseRange, l.creaseBias);
    else if (t == LookOf::Scalable)
        std::snprintf(buf, sizeof buf, "%g, %g, %g, %g", l.intensity, l.contrast, l.bias, l.sumExponent);
    else if (t == LookOf::Horizon)
        std::snprintf(buf, sizeof buf, "%g", l.contrast);  // its look is the power alone
    else
        std::snprintf(buf, sizeof buf, "%g, %g, %g", l.intensity, l.contrast, l.bias);
    return buf;
}

// One printed parameter of a preset: its label and how its value reads.
struct ParameterRow {
    const char* label;
    std::string (*value)(const TierProfile&);
};
const ParameterRow kParameterRows[] = {
    {"AO technique (an AoSettings without one)", [](const TierProfile& p) { return std::string(toString(p.aoTechnique)); }},
    {"scalable AO taps", [](const TierProfile& p) { return std::to_string(p.aoScalableTaps); }},
    {"scalable AO mirrored pairs", [](const TierProfile& p) { return yesNo(p.aoScalableMirrored); }},
    {"scalable AO radius clamp (px at 720 rows)",
     [](const TierProfile& p) { return p.aoScalableMaxRadiusPx > 0 ? std::to_string(int(p.aoScalableMaxRadiusPx)) : std::string("none"); }},
    {"depth MIP levels read by AO", [](const TierProfile& p) { return std::to_string(p.aoDepthMipLevels); }},
    {"Alchemy samples per pixel", [](const TierProfile& p) { return std::to_string(p.aoAlchemySamples); }},
    {"crease AO taps per pixel",
     [](const TierProfile& p) {
         return std::string(p.aoCreaseTaps == 24 ? "24 (the 11x11 stippled diamond)" : "12 (half the diamond, by checkerboard)");
     }},
    {"horizon AO slices x steps per side",
     [](const TierProfile& p) { return std::to_string(p.aoHorizonSlices) + " x " + std::to_string(p.aoHorizonSteps); }},
    {"horizon AO thickness, falloff (share of the radius)",
     [](const TierProfile& p) { return formatSettingNumber(p.aoHorizonThickness) + ", " + formatSettingNumber(p.aoHorizonFalloff); }},
    {"AO resolution (obscurance and blur)",
     [](const TierProfile& p) { return std::string(p.aoHalfResolution ? "half, depth-aware upsample" : "full"); }},
    {"AO depth layers at most (multilayer AO)",
     [](const TierProfile& p) { return p.aoMaxDepthLayers > 1 ? std::to_string(p.aoMaxDepthLayers) : std::string("1 (single layer only)"); }},
    {"AO bilateral blur half-width (px)", [](const TierProfile& p) { return std::to_string(p.aoBlurRadiusPx); }},
    {"AO blur depth source",
     [](const TierProfile& p) {
         return std::string(p.aoPackedDepthTarget ? "key packed in the RGBA8 AO target"
                                                  : "linear depth carried in the float AO target (RG32F; RGBA32F for crease)");
     }},
    {"alchemy AO look (intensity, contrast, bias)", [](const TierProfile& p) { return look(p.aoLook[0], LookOf::Alchemy); }},
    {"scalable AO look (intensity, contrast, bias, sum exponent)", [](const TierProfile& p) { return look(p.aoLook[1], LookOf::Scalable); }},
    {"crease AO look (intensity, contrast, range, bias)", [](const TierProfile& p) { return look(p.aoLook[2], LookOf::Crease); }},
    {"horizon AO look (a power on the visibility)", [](const TierProfile& p) { return look(p.aoLook[3], LookOf::Horizon); }},
    {"AO looks' radius exponent (alchemy, scalable, crease, horizon)",
     [](const TierProfile& p) {
         char buf[96];
         std::snprintf(buf, sizeof buf, "%g, %g, %g, %g", p.aoLook[0].radiusExponent, p.aoLook[1].radiusExponent, p.aoLook[2].radiusExponent,
                       p.aoLook[3].radiusExponent);
         return std::string(buf);
     }},
    {"motion blur taps (centre included)", [](const TierProfile& p) { return std::to_string(p.mbTaps); }},
    {"motion blur max radius (px at 720 rows)", [](const TierProfile& p) { return std::to_string(int(p.mbMaxRadiusPx)); }},
    {"motion blur tile edge (px at 720 rows)", [](const TierProfile& p) { return std::to_string(int(p.mbTilePx)); }},
    {"motion blur jitter", [](const TierProfile& p) { return std::string(p.mbJitterSize == 2 ? "checkerboard" : "4x4 randomised"); }},
    {"A-buffer OIT", [](const TierProfile& p) { return std::string(p.abufferOit ? "yes" : "no (documented fallback)"); }},
};

// The tier table as Markdown (docs/tiers.md holds exactly these tables): the requirements
// (every rule of any tier, in first-checked order), what each tier's row says besides, and the
// parameters of every preset.
void printRules(std::ostream& out) {
    const std::vector<tiers::TierRow>& table = tiers::table();
    auto header = [&](const char* first, const std::vector<std::string>& columns) {
        out << "| " << first;
        for (const std::string& c : columns) out << " | " << c;
        out << " |\n| ---";
        for (size_t i = 0; i < columns.size(); ++i) out << " | ---";
        out << " |\n";
    };
    std::vector<std::string> tierNames;
    for (const tiers::TierRow& r : table) tierNames.push_back(toString(r.tier));
    header("rule", tierNames);
    std::vector<std::string> rules;
    for (const tiers::TierRow& r : table)
        for (const tiers::Requirement& q : r.requirements)
            if (std::find(rules.begin(), rules.end(), q.what) == rules.end()) rules.push_back(q.what);
    for (const std::string& rule : rules) {
        out << "| " << rule;
        for (const tiers::TierRow& r : table) {
            bool required = false;
            for (const tiers::Requirement& q : r.requirements) required |= rule == q.what;
            out << " | " << (required ? "required" : "-");
        }
        out << " |\n";
    }

    out << "\n";
    header("tier", {"for", "ceiling holding a device to it", "GL dialects", "shader defines (generated)"});
    for (const tiers::TierRow& r : table) {
        std::string dialects, defines;
        for (ShaderDialect d : r.glDialects) dialects += (dialects.empty() ? "" : ", ") + std::string(toString(d));
        for (const tiers::ShaderDefine& d : tiers::shaderDefines(r.tier)) defines += (defines.empty() ? "" : ", ") + d.name + "=" + d.value;
        out << "| " << toString(r.tier) << " | " << r.summary << " | "
            << (r.ceiling == CapabilityCeiling::None ? std::string("none") : std::string(toString(r.ceiling))) << " | " << dialects << " | "
            << defines << " |\n";
    }

    out << "\n";
    std::vector<std::string> presetNames;
    for (const tiers::TierRow& r : table)
        for (const Preset& p : r.presets) presetNames.push_back(std::string(toString(r.tier)) + " " + p.name);
    header("parameter", presetNames);
    for (const ParameterRow& row : kParameterRows) {
        out << "| " << row.label;
        for (const tiers::TierRow& r : table)
            for (const Preset& p : r.presets) out << " | " << row.value(p.params);
        out << " |\n";
    }
}

// The platform's cache directory (XDG base directories): $XDG_CACHE_HOME/scalablefx, else
// ~/.cache/scalablefx; with neither variable set, sfx-cost-cache under the working directory.
std::string defaultCostCacheDir() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/') return std::string(xdg) + "/scalablefx";
    if (const char* home = std::getenv("HOME"); home && *home) return std::string(home) + "/.cache/scalablefx";
    return "sfx-cost-cache";
}

// The limits and formats the tiers and effects rely on, and the limits recorded for the host only.
void printLimitsAndFormats(std::ostream& out, const DeviceCaps& caps) {
    const DeviceLimits& l = caps.limits;
    out << "  limits: textures up to " << l.maxTextureSize << ", render targets up to " << l.maxRenderTargetWidth << "x" << l.maxRenderTargetHeight
        << ", " << l.maxColorAttachments << " colour attachments, " << l.subPixelPrecisionBits << " sub-pixel bits, uniform blocks "
        << l.maxUniformBlockSize << " bytes, storage buffers " << l.maxStorageBufferSize << " bytes, compute work groups "
        << l.maxComputeWorkGroupInvocations << " invocations and " << l.maxComputeWorkGroupCount[0] << "x" << l.maxComputeWorkGroupCount[1] << "x"
        << l.maxComputeWorkGroupCount[2] << " groups, " << l.maxTextureBindings << " texture bindings\n";
    // A sample count mask as its counts, "1/2/4".
    auto counts = [](uint32_t mask) {
        std::string list;
        for (uint32_t k = 0; k < 32; ++k)
            if (mask & (1u << k)) list += (list.empty() ? "" : "/") + std::to_string(1u << k);
        return list.empty() ? std::string("none") : list;
    };
    out << "  samples per pixel (recorded, the SDK makes single-sampled textures): colour attachments " << counts(l.framebufferColorSampleCounts)
        << ", depth attachments " << counts(l.framebufferDepthSampleCounts) << ", sampled colour " << counts(l.sampledImageColorSampleCounts)
        << ", sampled depth " << counts(l.sampledImageDepthSampleCounts) << "; texel buffers (recorded, the SDK makes none) "
        << l.maxTexelBufferElements << " texels\n";
    auto formats = [](const std::array<bool, size_t(Format::Count)>& has) {
        std::string list;
        for (size_t f = 1; f < size_t(Format::Count); ++f)
            if (has[f]) list += std::string(list.empty() ? "" : " ") + toString(Format(f));
        return list.empty() ? std::string("none") : list;
    };
    out << "  formats sampled: " << formats(caps.sampledFormat) << "; render targets: " << formats(caps.renderableFormat)
        << "; filterable: " << formats(caps.filterableFormat) << "; blendable: " << formats(caps.blendableFormat)
        << "; storage: " << formats(caps.storageFormat) << "\n";
}

struct BudgetFlags {
    double budgetMs = 0;  // 0: no budget asked for
    std::string size = "1920x1080", effect = "ao", cacheDir = defaultCostCacheDir();
    bool recalibrate = false;
};

// --budget: the calibrated cost table of the best device and the most accurate preset that fits.
int printBudgetChoice(const BudgetFlags& f) {
    const std::string cmd = "info";
    uint32_t w = 0, h = 0;
    if (std::sscanf(f.size.c_str(), "%ux%u", &w, &h) != 2 || w == 0 || h == 0)
        return fail(cmd, invalidArgument("--size", "'" + f.size + "'", "WIDTHxHEIGHT, e.g. 1920x1080"));
    budget::Effect effect;
    if (!budget::parseEffect(f.effect, &effect)) return fail(cmd, invalidArgument("--effect", "'" + f.effect + "'", "ao or motion-blur"));
    DeviceOptions deviceOptions;
    deviceOptions.validation = false;  // it would be timed too
    Result<DeviceSelection> best = openBestDevice(deviceOptions);
    if (!best) return fail(cmd, best.status());
    Device& dev = *best->device;
    std::cout << "device: " << dev.caps().summary() << "\n";
    budget::CalibrationOptions options;
    options.cacheDir = f.cacheDir;
    options.recalibrate = f.recalibrate;
    Result<budget::CostTable> table = budget::costTable(dev, tiers::row(best->tier.tier).presets, effect, w, h, options);
    if (!table) return fail(cmd, table.status());
    std::cout << "cost table (" << budget::toString(effect) << ", " << w << "x" << h << ", tier " << toString(table->tier)
              << "; measured on this device, cached in " << budget::costTablePath(f.cacheDir, dev.caps(), effect, w, h) << "):\n";
    for (const budget::CostEntry& e : table->entries) {
        char line[160];
        std::snprintf(line, sizeof line, "  %-20s %9.3f ms  PSNR %6.2f dB\n", e.candidate.name().c_str(), e.milliseconds, e.candidate.psnrDb);
        std::cout << line;
    }
    Result<budget::Choice> choice = budget::choose(table.value(), f.budgetMs);
    if (!choice) return fail(cmd, choice.status());
    char line[200];
    std::snprintf(line, sizeof line, "choice within %.3f ms: %s (%.3f ms, PSNR %.2f dB)\n", f.budgetMs, choice->chosen.candidate.name().c_str(),
                  choice->chosen.milliseconds, choice->chosen.candidate.psnrDb);
    std::cout << line;
    return 0;
}

}  // namespace

Command addInfoCommand(CLI::App& app) {
    Command c;
    c.app = app.add_subcommand("info", "List the backends of this build, what each device can do, and the tier it gets");
    static bool rules = false;
    c.app->add_flag("--rules", rules, "print the tier rules and per-tier parameters as a Markdown table and exit");
    static bool settings = false;
    c.app->add_flag("--settings", settings, "print every numeric setting's allowed range as a Markdown table and exit");
    static BudgetFlags budgetFlags;
    c.app->add_option("--budget", budgetFlags.budgetMs,
                      "a cost budget in ms: print the most accurate preset that fits on the best device, and the table");
    c.app->add_option("--size", budgetFlags.size, "with --budget: the frame size, WIDTHxHEIGHT")->capture_default_str();
    c.app->add_option("--effect", budgetFlags.effect, "with --budget: ao or motion-blur")->capture_default_str();
    c.app
        ->add_option("--cache-dir", budgetFlags.cacheDir,
                     "with --budget: where measured cost tables are cached ($XDG_CACHE_HOME/scalablefx or ~/.cache/scalablefx)")
        ->capture_default_str();
    c.app->add_flag("--recalibrate", budgetFlags.recalibrate, "with --budget: measure the costs again");
    c.run = [] {
        if (rules) {
            printRules(std::cout);
            return 0;
        }
        if (settings) {
            std::cout << settingsMarkdown();
            return 0;
        }
        if (budgetFlags.budgetMs != 0) return printBudgetChoice(budgetFlags);
        Result<std::vector<std::string>> vulkanDevices = describeVulkanDevices();
        if (vulkanDevices) {
            std::cout << "vulkan physical devices (pick one with --device INDEX|NAME):\n";
            for (const std::string& line : vulkanDevices.value()) std::cout << "  " << line << "\n";
        }
        for (const BackendConfig& config : compiledBackends()) {
            for (CapabilityCeiling ceiling : {CapabilityCeiling::None, CapabilityCeiling::GLES30}) {
                DeviceOptions options;
                options.validation = false;
                options.ceiling = ceiling;
                Result<std::unique_ptr<Device>> dev = sfx::openDevice(config, options);
                std::cout << toString(config) << (ceiling == CapabilityCeiling::None ? "" : " (ceiling GL ES 3.0)") << ": ";
                if (!dev) {
                    std::cout << "unavailable: " << dev.status().toString() << "\n";
                    continue;
                }
                std::cout << dev.value()->caps().summary() << "\n";
                if (config.backend == BackendKind::Vulkan) std::cout << "  device: " << dev.value()->caps().deviceChoice << "\n";
                printLimitsAndFormats(std::cout, dev.value()->caps());
                Result<tiers::TierChoice> t = tiers::choose(dev.value()->caps());
                std::cout << "  " << (t ? t->reason : t.status().toString()) << "\n";
            }
        }
        Result<DeviceSelection> best = openBestDevice();
        if (!best) return fail("info", best.status());
        std::cout << "best: " << best->reason << "\n";
        return 0;
    };
    return c;
}

}  // namespace sfx::cli
