// HAL conformance: timers: a flushed pass is measured from the backend's timing source.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include <algorithm>

#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: timers measure a flushed pass", "[hal]") {
    Cleanup c;
    TextureHandle target = makeTexture(c, 256, 256, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    PipelineHandle pipeline = fullscreenPipeline(c, "hal_test_pattern", Format::RGBA8);
    const float scale[4] = {0.001f, 0.001f, 0.001f, 1.0f};
    BufferHandle params = makeBuffer(c, sizeof(scale), kBufferUniform, scale);
    Result<TimerHandle> timer = dev().createTimer();
    REQUIRE(timer.isOk());
    c.steps.push_back([t = timer.value()] { (void)dev().destroyTimer(t); });
    CHECK(dev().endTimer(timer.value()).code() == StatusCode::InvalidArgument);  // not begun
    SFX_REQUIRE_OK(dev().beginTimer(timer.value()));
    for (int i = 0; i < 4; ++i) fullscreenPass(target, pipeline, {.uniformBuffers = {{gen::hal_test_pattern::PatternParams, params}}});
    SFX_REQUIRE_OK(dev().endTimer(timer.value()));
    SFX_REQUIRE_OK(dev().flush());
    Result<TimerReading> reading = dev().readTimer(timer.value());
    INFO(reading.status().toString());
    REQUIRE(reading.isOk());
    CHECK(reading->milliseconds > 0.0);
    CHECK(reading->milliseconds < 10000.0);
    CHECK(reading->source == dev().caps().timing);

    // A timer measures the work between its ends: 48 passes over a 512x512 target take longer
    // than one (median of three tries each, so a busy machine does not decide it).
    TextureHandle big = makeTexture(c, 512, 512, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    auto measure = [&](int passes) {
        std::vector<double> ms;
        for (int attempt = 0; attempt < 3; ++attempt) {
            REQUIRE(dev().beginTimer(timer.value()).isOk());
            for (int i = 0; i < passes; ++i) fullscreenPass(big, pipeline, {.uniformBuffers = {{gen::hal_test_pattern::PatternParams, params}}});
            REQUIRE(dev().endTimer(timer.value()).isOk());
            REQUIRE(dev().flush().isOk());
            ms.push_back(dev().readTimer(timer.value())->milliseconds);
        }
        std::sort(ms.begin(), ms.end());
        return ms[1];
    };
    const double light = measure(1), heavy = measure(48);
    INFO(test::label() << ": 1 pass " << light << " ms, 48 passes " << heavy << " ms");
    CHECK(heavy > light);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
