#include <iostream>

#include "cli_common.hpp"
#include "commands.hpp"

namespace sfx::cli {

Command addInfoCommand(CLI::App& app) {
    Command c;
    c.app = app.add_subcommand("info", "List the backends of this build, what each device can do, and the tier it gets");
    static bool rules = false;
    c.app->add_flag("--rules", rules, "print the tier rules and per-tier parameters as a Markdown table and exit");
    c.run = [] {
        if (rules) {
            std::cout << "| rule | current | high |\n| --- | --- | --- |\n";
            for (const tiers::Requirement& r : tiers::requirements(Tier::High)) {
                bool inCurrent = false;
                for (const tiers::Requirement& cr : tiers::requirements(Tier::Current))
                    inCurrent |= std::string(cr.what) == r.what;
                std::cout << "| " << r.what << " | " << (inCurrent ? "required" : "-") << " | required |\n";
            }
            const TierProfile& cur = tiers::profile(Tier::Current);
            const TierProfile& high = tiers::profile(Tier::High);
            std::cout << "\n| parameter | current | high |\n| --- | --- | --- |\n";
            auto row = [](const char* name, auto a, auto b) { std::cout << "| " << name << " | " << a << " | " << b << " |\n"; };
            row("scalable AO taps", cur.aoScalableTaps, high.aoScalableTaps);
            row("scalable AO mirrored pairs", cur.aoScalableMirrored ? "yes" : "no", high.aoScalableMirrored ? "yes" : "no");
            row("scalable AO radius clamp (px)", cur.aoScalableMaxRadiusPx > 0 ? std::to_string(int(cur.aoScalableMaxRadiusPx)) : "none",
                high.aoScalableMaxRadiusPx > 0 ? std::to_string(int(high.aoScalableMaxRadiusPx)) : "none");
            row("depth MIP levels read by AO", cur.aoDepthMipLevels, high.aoDepthMipLevels);
            row("Alchemy samples per pixel", cur.aoAlchemySamples, high.aoAlchemySamples);
            row("AO bilateral blur half-width (px)", cur.aoBlurRadiusPx, high.aoBlurRadiusPx);
            row("AO blur depth source", cur.aoPackedDepthTarget ? "key packed in the RGBA8 AO target" : "linear depth texture (RG16F AO target)",
                high.aoPackedDepthTarget ? "key packed in the RGBA8 AO target" : "linear depth texture (RG16F AO target)");
            row("motion blur taps (centre included)", cur.mbTaps, high.mbTaps);
            row("motion blur max radius (px at 720 rows)", cur.mbMaxRadiusPx, high.mbMaxRadiusPx);
            row("motion blur jitter", cur.mbJitterSize == 2 ? "checkerboard" : "4x4", high.mbJitterSize == 2 ? "checkerboard" : "4x4 randomised");
            row("A-buffer OIT", cur.abufferOit ? "yes" : "no (documented fallback)", high.abufferOit ? "yes" : "no");
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
