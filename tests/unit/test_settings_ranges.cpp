// The settings-range table: one row per setting, its texts, and the effects' messages read it.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>

#include "sfx/ao.hpp"
#include "sfx/motion_blur.hpp"
#include "sfx/settings_ranges.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;

TEST_CASE("settings ranges: one row per setting, in order, each a real range", "[settings]") {
    std::set<std::string> names;
    size_t i = 0;
    for (const SettingRange& r : settingRanges()) {
        CHECK(size_t(r.id) == i++);
        CHECK(names.insert(r.name).second);
        CHECK(r.min < r.max);
        CHECK(*r.description != '\0');
    }
    CHECK(i == size_t(Setting::Count));
}

TEST_CASE("settings ranges: texts and bounds", "[settings]") {
    CHECK(rangeText(settingRange(Setting::AoRadius)) == "[1e-4, 1000]");
    CHECK(rangeText(settingRange(Setting::AoEpsilon)) == "[1e-8, 1]");
    CHECK(rangeText(settingRange(Setting::AoCreaseBias)) == "(0, 100]");
    CHECK(rangeText(settingRange(Setting::AoCreaseMinimumCrease)) == "[-1, 1)");
    CHECK(rangeText(settingRange(Setting::MbSoftDepthExtent)) == "[1e-6, 1e6]");
    const SettingRange& radius = settingRange(Setting::AoRadius);
    CHECK(inRange(radius, kAoMinRadius));
    CHECK(inRange(radius, 1000.0));
    CHECK_FALSE(inRange(radius, std::nextafter(1000.0, 2000.0)));
    CHECK_FALSE(inRange(radius, std::nan("")));
    CHECK(inRange(settingRange(Setting::AoEpsilon), 1e-8f));
    CHECK_FALSE(inRange(settingRange(Setting::AoCreaseBias), 0.0));
    CHECK(settingHelp(Setting::AoRadius).find("[1e-4, 1000] world units") != std::string::npos);
    CHECK(checkSetting(Setting::AoRadius, 2000, "--radius").message() == "--radius is 2000; allowed [1e-4, 1000]");
    CHECK(checkSetting(Setting::AoRadius, 0.5).isOk());
}

TEST_CASE("settings ranges: the effects' messages are the table's", "[settings]") {
    const TierProfile high = tiers::profile(Tier::High);
    AoSettings s;
    s.radius = 2000.0f;
    CHECK(validateAoSettings(s, high).message() == "AoSettings.radius is 2000; allowed [1e-4, 1000]");
    MotionBlurSettings m;
    m.exposure = 5.0f;
    Result<MotionBlurParams> p = resolveMotionBlur(high, m, 720);
    REQUIRE_FALSE(p.isOk());
    CHECK(p.status().message() == "MotionBlurSettings.exposure is 5; allowed [0, 4]");
}
