// Settings chosen by a cost budget (sfx/budget.hpp): the choice from a given cost table, its
// named errors, the cost table's file form, and the candidates the tier table yields. No timing:
// every table here is written out.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "sfx/budget.hpp"
#include "sfx/null_device.hpp"
#include "sfx/tiers.hpp"

using namespace sfx;
using namespace sfx::budget;

namespace {

CostTable table() {
    CostTable t{"Test GPU 1.0", Tier::High, Effect::AmbientObscurance, 1920, 1080, {}, 0x0123456789abcdefull};
    t.entries = {{{Effect::AmbientObscurance, "low", AoTechnique::Alchemy, 24.0}, 0.8},
                 {{Effect::AmbientObscurance, "medium", AoTechnique::Alchemy, 26.0}, 1.4},
                 {{Effect::AmbientObscurance, "medium", AoTechnique::Scalable, 26.0}, 1.1},
                 {{Effect::AmbientObscurance, "ultra", AoTechnique::Alchemy, 28.5}, 3.0},
                 {{Effect::AmbientObscurance, "low", AoTechnique::Crease, 22.0}, 0.5}};
    return t;
}

}  // namespace

TEST_CASE("budget: the most accurate candidate that fits, the cheaper of equals", "[budget]") {
    Result<Choice> c = choose(table(), 1.5);
    REQUIRE(c.isOk());
    CHECK(c->chosen.candidate.name() == "medium/scalable");  // 26 dB like medium/alchemy, for 1.1 ms instead of 1.4
    CHECK(c->chosen.milliseconds == 1.1);
    CHECK(c->budgetMs == 1.5);
    CHECK(c->table.entries.size() == 5);
    CHECK(choose(table(), 3.0)->chosen.candidate.name() == "ultra/alchemy");  // a cost equal to the budget fits
    CHECK(choose(table(), 0.9)->chosen.candidate.name() == "low/alchemy");
    CHECK(choose(table(), 0.5)->chosen.candidate.name() == "low/crease");
}

TEST_CASE("budget: nothing fits is OverBudget stating the cheapest cost; bad budgets are named", "[budget]") {
    Result<Choice> none = choose(table(), 0.25);
    REQUIRE(none.status().code() == StatusCode::OverBudget);
    CHECK(none.status().message().find("0.250 ms") != std::string::npos);
    CHECK(none.status().message().find("low/crease") != std::string::npos);
    CHECK(none.status().message().find("0.500 ms") != std::string::npos);
    for (double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
        Result<Choice> r = choose(table(), bad);
        CHECK(r.status().code() == StatusCode::InvalidArgument);
        CHECK(r.status().message().find("budgetMs") != std::string::npos);
    }
    CostTable empty = table();
    empty.entries.clear();
    CHECK(choose(empty, 1.0).status().code() == StatusCode::InvalidArgument);
}

TEST_CASE("budget: a cost table survives its file and a stale one is refused", "[budget]") {
    const std::string dir = (std::filesystem::temp_directory_path() / "sfx-budget-test").string();
    std::filesystem::create_directories(dir);
    const CostTable t = table();
    const std::string path = costTablePath(dir, t.device, t.effect, t.width, t.height);
    CHECK(path.find("Test_GPU_1_0") != std::string::npos);
    CHECK(path.find("1920x1080") != std::string::npos);
    REQUIRE(writeCostTable(path, t).isOk());
    std::vector<Candidate> expected;
    for (const CostEntry& e : t.entries) expected.push_back(e.candidate);
    Result<CostTable> back = readCostTable(path, expected);
    REQUIRE(back.isOk());
    CHECK(back->device == t.device);
    CHECK(back->tier == Tier::High);
    CHECK(back->width == 1920);
    CHECK(back->fingerprint == t.fingerprint);
    REQUIRE(back->entries.size() == t.entries.size());
    for (size_t i = 0; i < t.entries.size(); ++i) CHECK(back->entries[i].milliseconds == Approx(t.entries[i].milliseconds));
    CHECK(choose(back.value(), 1.5)->chosen.candidate.name() == "medium/scalable");
    // Another candidate list (the tier table changed): the file is not a table of these.
    expected.pop_back();
    CHECK(readCostTable(path, expected).status().code() == StatusCode::FileError);
    expected.push_back({Effect::AmbientObscurance, "extreme", AoTechnique::Crease, 0});
    CHECK(readCostTable(path, expected).status().code() == StatusCode::FileError);
    CHECK(readCostTable(dir + "/missing.txt", expected).status().code() == StatusCode::FileError);
    std::filesystem::remove_all(dir);
}

TEST_CASE("budget: the candidates are every preset of the tier's row (x technique for AO)", "[budget]") {
    for (Tier tier : {Tier::Current, Tier::High}) {
        const std::vector<Preset>& presets = tiers::row(tier).presets;
        const std::vector<Candidate> ao = candidates(Effect::AmbientObscurance, presets);
        REQUIRE(ao.size() == 4 * presets.size());
        for (size_t i = 0; i < ao.size(); ++i) {
            CHECK(ao[i].preset == presets[i / 4].name);
            CHECK(ao[i].technique == AoTechnique(i % 4));
            CHECK(ao[i].psnrDb == presets[i / 4].accuracy.aoPsnrDb[i % 4]);
        }
        const std::vector<Candidate> mb = candidates(Effect::MotionBlur, presets);
        REQUIRE(mb.size() == presets.size());
        CHECK(mb.front().name() == kDefaultPreset);
    }
    Effect e;
    CHECK(parseEffect("motion-blur", &e));
    CHECK(e == Effect::MotionBlur);
    CHECK_FALSE(parseEffect("oit", &e));
}

TEST_CASE("budget: the cost table wants one tier's presets", "[budget]") {
    std::unique_ptr<Device> device = null::createDevice();
    CalibrationOptions options;
    Status empty = costTable(*device, {}, Effect::AmbientObscurance, 64, 64, options).status();
    CHECK(empty.code() == StatusCode::InvalidArgument);
    CHECK_THAT(empty.message(), Catch::Contains("presets"));
    std::vector<Preset> mixed = tiers::row(Tier::Current).presets;
    mixed.push_back(tiers::row(Tier::High).presets.front());
    Status mixedStatus = costTable(*device, mixed, Effect::MotionBlur, 64, 64, options).status();
    CHECK(mixedStatus.code() == StatusCode::InvalidArgument);
    CHECK_THAT(mixedStatus.message(), Catch::Contains("presets of one tier"));
}

TEST_CASE("budget: the fingerprint follows the device, the presets and the shaders", "[budget]") {
    std::unique_ptr<Device> device = null::createDevice();
    const DeviceCaps& caps = device->caps();
    const std::vector<Preset>& high = tiers::row(Tier::High).presets;
    const uint64_t base = fingerprint(caps, Effect::MotionBlur, high);
    CHECK(fingerprint(caps, Effect::MotionBlur, high) == base);  // the same inputs, the same number
    CHECK(fingerprint(caps, Effect::AmbientObscurance, high) != base);
    CHECK(fingerprint(caps, Effect::MotionBlur, tiers::row(Tier::Current).presets) != base);  // other presets and programs
    std::vector<Preset> changed = high;
    changed.back().params.mbTaps += 2;
    CHECK(fingerprint(caps, Effect::MotionBlur, changed) != base);
    changed = high;
    changed.front().params.aoLook[1].intensity *= 2.0f;
    CHECK(fingerprint(caps, Effect::MotionBlur, changed) != base);
    DeviceCaps otherDriver = caps;
    otherDriver.apiName += " (another driver)";
    CHECK(fingerprint(otherDriver, Effect::MotionBlur, high) != base);
    DeviceCaps otherBackend = caps;
    otherBackend.backend = BackendKind::GLES;
    CHECK(fingerprint(otherBackend, Effect::MotionBlur, high) != base);
    CHECK(costTablePath("cache", otherBackend, Effect::MotionBlur, 64, 64) != costTablePath("cache", caps, Effect::MotionBlur, 64, 64));
}

TEST_CASE("budget: a cached cost table is read back only while it measures the same presets", "[budget]") {
    const std::string dir = (std::filesystem::temp_directory_path() / "sfx-budget-cache-test").string();
    std::filesystem::remove_all(dir);
    std::unique_ptr<Device> device = null::createDevice();
    CalibrationOptions options;
    options.cacheDir = dir;
    options.runs = 1;
    std::vector<Preset> presets = tiers::row(Tier::High).presets;
    Result<CostTable> first = costTable(*device, presets, Effect::MotionBlur, 32, 16, options);
    REQUIRE(first.isOk());
    const std::string path = costTablePath(dir, device->caps(), Effect::MotionBlur, 32, 16);
    REQUIRE(std::filesystem::exists(path));
    // Mark the file's figures, so a table read from it can be told from one measured.
    CostTable marked = first.value();
    for (CostEntry& e : marked.entries) e.milliseconds = 123.0;
    REQUIRE(writeCostTable(path, marked).isOk());
    Result<CostTable> cached = costTable(*device, presets, Effect::MotionBlur, 32, 16, options);
    REQUIRE(cached.isOk());
    CHECK(cached->entries.front().milliseconds == 123.0);
    // Another preset under the same name: the cached figures are not this preset's.
    presets.back().params.mbTaps -= 2;
    Result<CostTable> remeasured = costTable(*device, presets, Effect::MotionBlur, 32, 16, options);
    REQUIRE(remeasured.isOk());
    CHECK(remeasured->fingerprint != marked.fingerprint);
    CHECK(remeasured->entries.front().milliseconds != 123.0);
    std::filesystem::remove_all(dir);
}
