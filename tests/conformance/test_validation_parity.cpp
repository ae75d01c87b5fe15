// Validation parity: each invalid call of validation_cases.cpp, made on the device under test and
// on a null device posing with the same caps, gives the table's code and the same message on
// both, and that message is the sentence the case spells out. Run per backend and tier, so every
// backend is held to the same words; tests/unit/test_validation_null.cpp runs the same cases on
// the null backend itself. The null devices with crafted caps reach the rules no device here
// breaks (a format it cannot sample), and a last check makes sure every row has a case.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string_view>

#include "sfx/null_device.hpp"
#include "test_device.hpp"
#include "validation_cases.hpp"

using namespace sfx;
using validation::Error;

TEST_CASE("validation parity: every invalid call gives the table's code and message, as on a null device", "[hal][validation]") {
    const std::set<Error> exercised = test::runValidationCases(test::device(), true);
    INFO(test::label() << ": " << exercised.size() << " of " << size_t(Error::Count) << " rules exercised");
    CHECK(!exercised.empty());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("validation parity: every rule of the table has a case that breaks it", "[hal][validation]") {
    std::set<Error> exercised = test::runValidationCases(test::device(), false);
    for (const DeviceCaps& caps : test::craftedNullCaps()) {
        std::unique_ptr<Device> d = null::createDevice(caps);
        for (Error e : test::runValidationCases(*d, false)) exercised.insert(e);
    }
    test::checkEveryRuleExercised(exercised);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("validation parity: every row reads as a sentence with its code", "[hal][validation]") {
    for (uint32_t i = 0; i < uint32_t(Error::Count); ++i) {
        const validation::ErrorEntry& e = validation::entry(Error(i));
        INFO(e.name << ": " << e.message);
        CHECK(size_t(e.error) == i);
        CHECK(e.code != StatusCode::Ok);
        const std::string_view m = e.message;
        CHECK(m.find("is without") == std::string_view::npos);
        CHECK(m.find("0x") == std::string_view::npos);
        // Every refusal of an argument says what is allowed (or, for a binding, which ones exist).
        if (e.code == StatusCode::InvalidArgument)
            CHECK((m.find("allowed") != std::string_view::npos || m.find("its bindings are") != std::string_view::npos ||
                   m.find("needs") != std::string_view::npos));
    }
}

TEST_CASE("validation parity: a pipeline outlives its program on every backend", "[hal][validation]") {
    test::Objects o(test::device());
    GraphicsPipelineDesc pd;
    pd.program = test::device().createProgram(test::shaderProgram("copy", Tier::Current)).value();
    pd.colorFormats = {Format::RGBA8};
    Result<PipelineHandle> pipeline = test::device().createGraphicsPipeline(pd);
    REQUIRE(pipeline.isOk());
    SFX_REQUIRE_OK(test::device().destroyProgram(pd.program));
    DrawDesc d;
    d.pipeline = pipeline.value();
    d.bindings.textures = {{0, o.texture(8, 8, Format::RGBA8, kTextureSampled)}};
    RenderPassDesc pass;
    pass.colors = {{o.texture(8, 8, Format::RGBA8, test::kRenderable), 0}};
    SFX_REQUIRE_OK(test::device().renderPass(pass, {&d, 1}));
    SFX_REQUIRE_OK(test::device().flush());
    SFX_REQUIRE_OK(test::device().destroyPipeline(pipeline.value()));
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
