// Entry point of the conformance tests: opens the device named on the command line once,
// runs the Catch2 session, and fails the run on any validation message. Cases that do not
// apply to the device are not run (and not counted): [gl] cases run only on GL backends. A
// backend that cannot be opened, or a case that cannot run (SFX_SKIP), makes the run
// "skipped" for CTest, or a failure under SFX_REQUIRE_ALL_BACKENDS=1.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>

#include "skips.hpp"
#include "test_device.hpp"

namespace sfx::test {
namespace {
std::unique_ptr<Device> gDevice;
BackendConfig gConfig;
Tier gTier = Tier::High;
std::vector<std::string> gAllMessages;
}  // namespace

Device& device() { return *gDevice; }
const BackendConfig& backendConfig() { return gConfig; }
Tier tier() { return gTier; }
const TierProfile& tierProfile() { return tiers::profile(gTier); }
std::string label() { return toString(gConfig) + "/" + toString(gTier); }

std::vector<std::string> takeValidationMessages() {
    std::vector<std::string> m = gDevice->takeValidationMessages();
    gAllMessages.insert(gAllMessages.end(), m.begin(), m.end());
    return m;
}

std::string outputDir() {
    const char* env = std::getenv("SFX_TEST_OUTPUT");
    std::string dir = env && *env ? env : SFX_TEST_OUTPUT_DEFAULT;
    std::filesystem::create_directories(dir);
    return dir;
}

std::string sourceDir() {
    const char* env = std::getenv("SFX_SOURCE_DIR");
    return env && *env ? env : SFX_SOURCE_DIR;
}

}  // namespace sfx::test

int main(int argc, char** argv) {
    using namespace sfx;
    Catch::Session session;
    std::string backendName = "vulkan", tierName = kTierNames[kTierCount - 1];  // the highest tier
    using namespace Catch::clara;
    auto cli = session.cli() | Opt(backendName, "backend")["--backend"]("vulkan, gles, gl-egl, gl-osmesa, null") |
        Opt(tierName, "tier")["--tier"]("a tier: " + tierNameList() + " (a lower one is opened under its capability ceiling)");
    session.cli(cli);
    if (int rc = session.applyCommandLine(argc, argv); rc != 0) return rc;

    if (!parseBackendConfig(backendName, &test::gConfig)) {
        std::cerr << "--backend '" << backendName << "' is unknown; allowed vulkan, gles, gl-egl, gl-osmesa, null\n";
        return 2;
    }
    if (!parseTier(tierName, &test::gTier)) {
        std::cerr << "--tier '" << tierName << "' is unknown; allowed " << tierNameList() << "\n";
        return 2;
    }
    DeviceOptions options;
    options.validation = true;
    options.ceiling = tiers::row(test::gTier).ceiling;
    Result<std::unique_ptr<Device>> device = openDevice(test::gConfig, options);
    if (!device) {
        const bool required = test::requireAllBackends();
        const bool absent = device.status().code() == StatusCode::BackendUnavailable;
        std::cerr << (absent && !required ? "SKIPPED: " : "FAILED: ") << "backend " << backendName
                  << " could not be opened: " << device.status().toString() << "\n";
        return absent && !required ? test::kSkipExitCode : 1;
    }
    test::gDevice = std::move(device.value());
    Result<tiers::TierChoice> choice = tiers::choose(test::gDevice->caps(), test::gTier);
    std::cout << "device: " << test::gDevice->caps().summary() << "\n";
    if (!choice) {
        std::cerr << "FAILED: " << choice.status().toString() << "\n";
        return 1;
    }
    std::cout << "tier: " << choice->reason << "\n";

    // Cases for another kind of device are filtered out, so they are neither run nor passed.
    const BackendKind kind = test::gDevice->caps().backend;
    if (kind != BackendKind::GL && kind != BackendKind::GLES) {
        session.configData().testsOrTags.push_back("~[gl]");
        std::cout << "not run here: cases tagged [gl] (GL backends only)\n";
    }

    int rc = session.run();
    test::takeValidationMessages();
    if (!test::gAllMessages.empty()) {
        std::cerr << "FAILED: " << test::gAllMessages.size() << " validation message(s):\n";
        for (const auto& m : test::gAllMessages) std::cerr << "  " << m << "\n";
        rc = rc ? rc : 1;
    }
    test::gDevice.reset();
    return test::finishRun(rc);
}
