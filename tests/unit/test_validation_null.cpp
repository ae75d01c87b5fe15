// The validation parity cases (tests/conformance/validation_cases.cpp) on the null backend itself.
// Its hooks check nothing but a timer's state (Device's front end checks every call before them,
// as for every backend), so each case giving the table's code and the message it spells out shows
// that the front end alone makes the shared checks. Run on the null device of each capability
// set: full features, the GL ES 3.0 ceiling, and the crafted devices that reach the other rules.
#include <catch2/catch.hpp>

#include "sfx/null_device.hpp"
#include "validation_cases.hpp"

using namespace sfx;

TEST_CASE("null backend: every validation case refused with the table's code and message", "[null][validation]") {
    std::set<validation::Error> exercised;
    for (CapabilityCeiling ceiling : {CapabilityCeiling::None, CapabilityCeiling::GLES30}) {
        std::unique_ptr<Device> device = null::createDevice(DeviceOptions{ceiling, true});
        for (validation::Error e : test::runValidationCases(*device, false)) exercised.insert(e);
    }
    for (const DeviceCaps& caps : test::craftedNullCaps()) {
        std::unique_ptr<Device> device = null::createDevice(caps);
        for (validation::Error e : test::runValidationCases(*device, false)) exercised.insert(e);
    }
    test::checkEveryRuleExercised(exercised);
}
