// The backends compared with each other: the same inputs through every backend this machine
// has, at both tiers, must give the same outputs within the sum of their reference tolerances
// (and exactly where the pass is a pure copy).
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <algorithm>

#include <cmath>
#include <cstdlib>
#include <map>

#include "sfx/backends.hpp"
#include "sfx/depth.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shared.h"

using namespace sfx;

namespace {

struct Opened {
    std::string name;
    std::unique_ptr<Device> device;
};

// Every compiled backend at `tier` (current: under the GL ES 3.0 ceiling). An absent backend
// is reported; with SFX_REQUIRE_ALL_BACKENDS set it fails the test.
std::vector<Opened> openAll(Tier tier) {
    std::vector<Opened> out;
    for (const BackendConfig& config : compiledBackends()) {
        DeviceOptions options;
        options.validation = true;
        options.ceiling = tiers::row(tier).ceiling;
        Result<std::unique_ptr<Device>> device = openDevice(config, options);
        if (!device) {
            WARN("backend " << toString(config) << " skipped: " << device.status().toString());
            if (std::getenv("SFX_REQUIRE_ALL_BACKENDS")) FAIL("every backend is required here");
            continue;
        }
        out.push_back({toString(config), std::move(device.value())});
    }
    return out;
}

void requireNoValidation(std::vector<Opened>& devices) {
    for (Opened& o : devices) {
        auto messages = o.device->takeValidationMessages();
        for (const auto& m : messages) UNSCOPED_INFO(o.name << " validation: " << m);
        REQUIRE(messages.empty());
    }
}

}  // namespace

TEST_CASE("linear depth and its pyramid agree across backends", "[cross-backend][depth]") {
    for (Tier tier : {Tier::High, Tier::Current}) {
        std::vector<Opened> devices = openAll(tier);
        if (devices.size() < 2) {
            WARN("fewer than two backends at tier " << toString(tier) << ": nothing to compare");
            continue;
        }
        const uint32_t W = 45, H = 29;
        const uint32_t levels = std::min(4u, tiers::profile(tier).aoDepthMipLevels);  // the tier's pyramid, up to 4
        PerspectiveDesc pd;
        pd.aspect = double(W) / H;
        pd.reversedZ = true;
        pd.farPlane = std::numeric_limits<double>::infinity();
        CameraProjection cam = makePerspective(pd).value();
        std::vector<float> stored(size_t(W) * H);
        for (size_t i = 0; i < stored.size(); ++i)
            stored[i] = float(storedDepthFromLinear(cam, 0.1 * std::pow(500.0, double(i) / double(stored.size()))));

        std::map<std::string, std::vector<std::vector<float>>> results;
        for (Opened& o : devices) {
            INFO(o.name << " / " << toString(tier));
            Device& d = *o.device;
            TextureHandle src = d.createTexture({W, H, 1, Format::R32F, kTextureSampled}).value();
            REQUIRE(d.writeTexture(src, 0, stored.data(), stored.size() * 4).isOk());
            auto linear = LinearDepth::create(d, {W, H, tier, levels});
            INFO(linear.status().toString());
            REQUIRE(linear.isOk());
            REQUIRE(linear.value()->dispatch({src, DepthKind::Hardware, cam}).isOk());
            for (uint32_t m = 0; m < levels; ++m) {
                std::vector<float> level(size_t(mipExtent(W, m)) * mipExtent(H, m));
                REQUIRE(d.readTexture(linear.value()->texture(), m, level.data(), level.size() * 4).isOk());
                results[o.name].push_back(std::move(level));
            }
            (void)d.destroyTexture(src);
        }
        requireNoValidation(devices);
        const auto& first = results.begin();
        for (auto it = std::next(results.begin()); it != results.end(); ++it) {
            INFO(first->first << " vs " << it->first << " at tier " << toString(tier));
            // Reversed-Z is well conditioned: a few ulps each way (docs/conformance.md). The
            // pyramid levels copy the same source texels on every backend, so they agree within
            // the same bound.
            for (uint32_t m = 0; m < levels; ++m) {
                REQUIRE(first->second[m].size() == it->second[m].size());
                for (size_t i = 0; i < first->second[m].size(); ++i) {
                    const double a = first->second[m][i], b = it->second[m][i];
                    INFO("level " << m << " texel " << i << ": " << a << " vs " << b);
                    REQUIRE(std::abs(a - b) <= 2.0 * a * 10.0 * std::ldexp(1.0, -23));
                }
            }
        }
    }
}

TEST_CASE("openBestDevice picks the highest tier and says why", "[cross-backend][selection]") {
    DeviceOptions options;
    options.validation = false;
    Result<DeviceSelection> best = openBestDevice(options);
    INFO(best.status().toString());
    REQUIRE(best.isOk());
    // Every backend here reaches the high tier; the first in preference order wins the tie.
    CHECK(best->tier.tier == Tier::High);
    CHECK(toString(best->config) == toString(compiledBackends().front()));
    CHECK(best->reason.find(toString(best->config)) != std::string::npos);
    CHECK(best->reason.find("tier 'high'") != std::string::npos);
    CHECK(best->rejected.size() + 1 == compiledBackends().size());

    // Under the ceiling every device reaches only the current tier, and says what it lacks.
    options.ceiling = CapabilityCeiling::GLES30;
    Result<DeviceSelection> capped = openBestDevice(options);
    REQUIRE(capped.isOk());
    CHECK(capped->tier.tier == Tier::Current);
    CHECK(capped->tier.reason.find("compute shaders") != std::string::npos);
}
