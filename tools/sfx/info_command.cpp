#include <iostream>

#include "cli_common.hpp"
#include "commands.hpp"

namespace sfx::cli {

Command addInfoCommand(CLI::App& app) {
    Command c;
    c.app = app.add_subcommand("info", "List the backends of this build, what each device can do, and the tier it gets");
    c.run = [] {
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
