// HAL conformance: the limits recorded for the host only (sample counts, texel buffers) hold
// what the APIs promise, so a query that read nothing or the wrong value is caught here.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

namespace {
constexpr uint32_t kOneSample = 0x1, kFourSamples = 0x4;
constexpr uint32_t kUpTo64Samples = 0x7F;  // the most any API names
}  // namespace

TEST_CASE("hal: sample counts and the texel buffer size meet the API's minimums", "[hal]") {
    const DeviceCaps& c = dev().caps();
    const DeviceLimits& l = c.limits;
    INFO(test::label() << ": colour attachments " << l.framebufferColorSampleCounts << ", depth attachments " << l.framebufferDepthSampleCounts
                       << ", sampled colour " << l.sampledImageColorSampleCounts << ", sampled depth " << l.sampledImageDepthSampleCounts
                       << ", texel buffers " << l.maxTexelBufferElements);
    // Vulkan requires 1 and 4 samples on attachments; GL ES 3.0 and GL 3.3 a MAX_SAMPLES of 4.
    for (uint32_t mask : {l.framebufferColorSampleCounts, l.framebufferDepthSampleCounts}) {
        CHECK((mask & (kOneSample | kFourSamples)) == (kOneSample | kFourSamples));
        CHECK((mask & ~kUpTo64Samples) == 0);
    }
    if (c.ceiling == CapabilityCeiling::GLES30) {
        // GL ES 3.0 has neither multisampled textures nor texture buffers.
        CHECK(l.sampledImageColorSampleCounts == kOneSample);
        CHECK(l.sampledImageDepthSampleCounts == kOneSample);
        CHECK(l.maxTexelBufferElements == 0);
    } else {
        // Vulkan requires 1 and 4 samples on sampled images; GL ES 3.1 and GL 3.2 one at least.
        const uint32_t required = c.backend == BackendKind::Vulkan ? kOneSample | kFourSamples : kOneSample;
        for (uint32_t mask : {l.sampledImageColorSampleCounts, l.sampledImageDepthSampleCounts}) {
            CHECK((mask & required) == required);
            CHECK((mask & ~kUpTo64Samples) == 0);
        }
        // 65536 texels is every API's least; GL ES before 3.2 may have no texture buffers at all.
        const bool mayLack = c.backend == BackendKind::GLES && c.apiMajor == 3 && c.apiMinor < 2;
        if (!mayLack || l.maxTexelBufferElements != 0) CHECK(l.maxTexelBufferElements >= 65536);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
