// The validation parity cases (tests/conformance/validation_cases.cpp) on the null backend itself:
// it validates every call as a real backend does, so each case gives the table's code and the
// message the case spells out, on the null device of each capability set: full features, the
// GL ES 3.0 ceiling, and the crafted devices that reach the remaining rules.
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
