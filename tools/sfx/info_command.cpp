#include <algorithm>
#include <iostream>
#include <ostream>

#include "cli_common.hpp"
#include "commands.hpp"

namespace sfx::cli {
namespace {

std::string yesNo(bool b) { return b ? "yes" : "no"; }

// One printed parameter of a preset: its label and how its value reads.
struct ParameterRow {
    const char* label;
    std::string (*value)(const TierProfile&);
};
const ParameterRow kParameterRows[] = {
    {"scalable AO taps", [](const TierProfile& p) { return std::to_string(p.aoScalableTaps); }},
    {"scalable AO mirrored pairs", [](const TierProfile& p) { return yesNo(p.aoScalableMirrored); }},
    {"scalable AO radius clamp (px)",
     [](const TierProfile& p) { return p.aoScalableMaxRadiusPx > 0 ? std::to_string(int(p.aoScalableMaxRadiusPx)) : std::string("none"); }},
    {"depth MIP levels read by AO", [](const TierProfile& p) { return std::to_string(p.aoDepthMipLevels); }},
    {"Alchemy samples per pixel", [](const TierProfile& p) { return std::to_string(p.aoAlchemySamples); }},
    {"AO bilateral blur half-width (px)", [](const TierProfile& p) { return std::to_string(p.aoBlurRadiusPx); }},
    {"AO blur depth source",
     [](const TierProfile& p) {
         return std::string(p.aoPackedDepthTarget ? "key packed in the RGBA8 AO target" : "linear depth texture (RG16F AO target)");
     }},
    {"motion blur taps (centre included)", [](const TierProfile& p) { return std::to_string(p.mbTaps); }},
    {"motion blur max radius (px at 720 rows)", [](const TierProfile& p) { return std::to_string(int(p.mbMaxRadiusPx)); }},
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
        for (const tiers::ShaderDefine& d : tiers::shaderDefines(r.tier))
            defines += (defines.empty() ? "" : ", ") + d.name + "=" + d.value;
        out << "| " << toString(r.tier) << " | " << r.summary << " | "
            << (r.ceiling == CapabilityCeiling::None ? std::string("none") : std::string(toString(r.ceiling))) << " | "
            << dialects << " | " << defines << " |\n";
    }

    out << "\n";
    std::vector<std::string> presetNames;
    for (const tiers::TierRow& r : table)
        for (const tiers::Preset& p : r.presets) presetNames.push_back(std::string(toString(r.tier)) + " " + p.name);
    header("parameter", presetNames);
    for (const ParameterRow& row : kParameterRows) {
        out << "| " << row.label;
        for (const tiers::TierRow& r : table)
            for (const tiers::Preset& p : r.presets) out << " | " << row.value(p.params);
        out << " |\n";
    }
}

}  // namespace

Command addInfoCommand(CLI::App& app) {
    Command c;
    c.app = app.add_subcommand("info", "List the backends of this build, what each device can do, and the tier it gets");
    static bool rules = false;
    c.app->add_flag("--rules", rules, "print the tier rules and per-tier parameters as a Markdown table and exit");
    c.run = [] {
        if (rules) {
            printRules(std::cout);
            return 0;
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
