// HAL conformance: reusable recordings (Device::beginRecording / beginReplay). A replay runs the
// recorded passes with the buffers' and textures' contents of the moment; a replay whose calls,
// objects or resource states differ from the recording is refused as stale and runs nothing;
// calls that cannot happen inside an open recording are refused by name. Where a device keeps
// no recordings (GL, or Vulkan with DeviceOptions::reuseRecordings off) every call is the named
// UnsupportedFeature. Runs on whatever backend and tier the run opened.
#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

namespace {

const float kOld[4] = {0.2f, 0.4f, 0.6f, 1.0f};  // 51, 102, 153, 255 in RGBA8
const float kNew[4] = {1.0f, 0.0f, 0.8f, 0.0f};  // 255, 0, 204, 0

// Every texel of an RGBA8 texture is `expected` (0..1 floats, as the uniform test shader writes them).
void checkFilled(TextureHandle t, const float (&expected)[4], const char* what) {
    const std::vector<uint8_t> texels = readLevel<uint8_t>(t);
    size_t wrong = 0;
    for (size_t i = 0; i < texels.size(); i += 4)
        for (size_t k = 0; k < 4; ++k)
            if (texels[i + k] != uint8_t(expected[k] * 255.0f + 0.5f)) ++wrong;
    INFO(what << ": " << wrong << " wrong channels of " << texels.size());
    CHECK(wrong == 0);
}

// The uniform test pass into `first`, then the copy program from `first` into `second` (R32F),
// and from the host's `input` into `third`: a written texture read by the next pass, a uniform
// read by the first, and a texture the passes only read.
struct ThreePasses {
    Cleanup& c;
    TextureHandle first, second, input, third;
    PipelineHandle fill, copy;
    BufferHandle params;
    explicit ThreePasses(Cleanup& cleanup)
        : c(cleanup),
          first(makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled | kTextureRenderTarget)),
          second(makeTexture(c, kW, kH, Format::R32F, kTextureSampled | kTextureRenderTarget)),
          input(makeTexture(c, kW, kH, Format::R32F, kTextureSampled)),
          third(makeTexture(c, kW, kH, Format::R32F, kTextureSampled | kTextureRenderTarget)),
          fill(fullscreenPipeline(c, "hal_test_uniform", Format::RGBA8)),
          copy(fullscreenPipeline(c, "copy", Format::R32F)),
          params(makeBuffer(c, sizeof(kOld), kBufferUniform, kOld)) {
        writeInput(0.25f);
    }
    void writeInput(float value) const {
        const std::vector<float> texels(size_t(kW) * kH, value);
        SFX_REQUIRE_OK(dev().writeTexture(input, 0, texels.data(), texels.size() * sizeof(float)));
    }
    void record(TextureHandle target) const {
        fullscreenPass(target, fill, {.uniformBuffers = {{gen::hal_test_uniform::ColorParams, params}}});
        fullscreenPass(second, copy, {.textures = {{gen::copy::uSource, target, 0, 1}}});
        fullscreenPass(third, copy, {.textures = {{gen::copy::uSource, input, 0, 1}}});
    }
    // The end of a frame: flush, then what the passes wrote, read back (every frame the same
    // reads, so every frame starts from the same states). `red`: the uniform's red, `copied`: the input.
    void checkFrame(const float (&color)[4], float copied, const char* what) const {
        SFX_REQUIRE_OK(dev().flush());
        checkFilled(first, color, what);
        INFO(what);
        CHECK(readLevel<float>(second)[0] == Approx(color[0]).margin(1.0 / 255));
        CHECK(readLevel<float>(third)[0] == copied);
    }
};

// Where the device keeps no recordings the case has nothing to run: the UnsupportedFeature case
// checks what such a device answers.
bool keepsNone() {
    if (dev().caps().reusableRecordings) return false;
    SUCCEED("no recordings on this device (the UnsupportedFeature case covers it)");
    return true;
}

}  // namespace

TEST_CASE("hal: recordings are the named UnsupportedFeature where the device keeps none", "[hal][recordings]") {
    if (dev().caps().reusableRecordings) {
        // tests/vulkan checks a Vulkan device opened with DeviceOptions::reuseRecordings off,
        // among the cases that open their own Vulkan devices.
        SUCCEED("this device keeps recordings: the other cases cover them");
        return;
    }
    checkNamed(dev().beginRecording(), StatusCode::UnsupportedFeature, "reusableRecordings");
    checkNamed(dev().endRecording().status(), StatusCode::UnsupportedFeature, "reusableRecordings");
    checkNamed(dev().beginReplay({}), StatusCode::UnsupportedFeature, "reusableRecordings");
    checkNamed(dev().endReplay(), StatusCode::UnsupportedFeature, "reusableRecordings");
    checkNamed(dev().destroyRecording({}), StatusCode::UnsupportedFeature, "reusableRecordings");
}

TEST_CASE("hal: a replay runs the recorded passes on the buffers' and textures' contents of the moment", "[hal][recordings]") {
    if (keepsNone()) return;
    Cleanup c;
    ThreePasses passes(c);
    // Frame 1, recorded from fresh textures: the next frame finds them in other states, and the
    // recording is stale there.
    SFX_REQUIRE_OK(dev().beginRecording());
    passes.record(passes.first);
    Result<RecordingHandle> first = dev().endRecording();
    SFX_REQUIRE_OK(first.status());
    passes.checkFrame(kOld, 0.25f, "frame 1, recorded");
    SFX_REQUIRE_OK(dev().beginReplay(first.value()));
    passes.record(passes.first);
    checkNamed(dev().endReplay(), StatusCode::StaleHandle, "not in the state it was recorded from");
    SFX_REQUIRE_OK(dev().destroyRecording(first.value()));

    // Frame 2, recorded again from the states a frame leaves behind.
    SFX_REQUIRE_OK(dev().beginRecording());
    passes.record(passes.first);
    Result<RecordingHandle> steady = dev().endRecording();
    SFX_REQUIRE_OK(steady.status());
    c.steps.push_back([h = steady.value()] { (void)dev().destroyRecording(h); });
    passes.checkFrame(kOld, 0.25f, "frame 2, recorded");
    const DeviceStats before = dev().stats();
    CHECK(before.recordings.live == 1);

    // Frame 3: the uniform rewritten, the replay reads the new contents.
    SFX_REQUIRE_OK(dev().writeBuffer(passes.params, 0, kNew, sizeof(kNew)));
    SFX_REQUIRE_OK(dev().beginReplay(steady.value()));
    passes.record(passes.first);
    SFX_REQUIRE_OK(dev().endReplay());
    passes.checkFrame(kNew, 0.25f, "frame 3, replayed after the uniform changed");

    // Frame 4: the host uploads the texture the passes only read (which leaves it in another
    // layout) and changes the uniform back: the replay reads both.
    passes.writeInput(0.75f);
    SFX_REQUIRE_OK(dev().writeBuffer(passes.params, 0, kOld, sizeof(kOld)));
    SFX_REQUIRE_OK(dev().beginReplay(steady.value()));
    passes.record(passes.first);
    SFX_REQUIRE_OK(dev().endReplay());
    passes.checkFrame(kOld, 0.75f, "frame 4, replayed after the input and the uniform changed");

    const DeviceStats after = dev().stats();
    CHECK(after.recordings == before.recordings);
    CHECK(after.descriptorSets == before.descriptorSets);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: a replay whose calls, objects or states differ is refused as stale and runs nothing", "[hal][recordings]") {
    if (keepsNone()) return;
    Cleanup c;
    ThreePasses passes(c);
    TextureHandle other = makeTexture(c, kW, kH, Format::RGBA8, kTextureSampled | kTextureRenderTarget);
    const std::vector<uint8_t> marker(size_t(kW) * kH * 4, 7);
    SFX_REQUIRE_OK(dev().writeTexture(other, 0, marker.data(), marker.size()));
    // A warm-up frame, so that the recording below starts from steady states.
    passes.record(passes.first);
    passes.checkFrame(kOld, 0.25f, "warm-up");
    SFX_REQUIRE_OK(dev().beginRecording());
    passes.record(passes.first);
    Result<RecordingHandle> rec = dev().endRecording();
    SFX_REQUIRE_OK(rec.status());
    passes.checkFrame(kOld, 0.25f, "recorded");

    SECTION("another target") {
        SFX_REQUIRE_OK(dev().beginReplay(rec.value()));
        passes.record(other);
        checkNamed(dev().endReplay(), StatusCode::StaleHandle, "the calls differ");
        SFX_REQUIRE_OK(dev().flush());
        CHECK(readLevel<uint8_t>(other) == marker);  // ran nothing
    }
    SECTION("fewer calls") {
        SFX_REQUIRE_OK(dev().beginReplay(rec.value()));
        fullscreenPass(passes.first, passes.fill, {.uniformBuffers = {{gen::hal_test_uniform::ColorParams, passes.params}}});
        checkNamed(dev().endReplay(), StatusCode::StaleHandle, "the calls differ");
    }
    SECTION("an object made since") {
        (void)makeTexture(c, 4, 4, Format::RGBA8, kTextureSampled);
        SFX_REQUIRE_OK(dev().beginReplay(rec.value()));
        passes.record(passes.first);
        checkNamed(dev().endReplay(), StatusCode::StaleHandle, "created or destroyed");
    }
    SECTION("a written texture left in another state") {
        // The host draws into the recording's first target: the recording's barriers no longer fit.
        fullscreenPass(passes.first, passes.fill, {.uniformBuffers = {{gen::hal_test_uniform::ColorParams, passes.params}}});
        SFX_REQUIRE_OK(dev().writeTexture(passes.first, 0, marker.data(), marker.size()));
        SFX_REQUIRE_OK(dev().beginReplay(rec.value()));
        passes.record(passes.first);
        checkNamed(dev().endReplay(), StatusCode::StaleHandle, "not in the state it was recorded from");
        SFX_REQUIRE_OK(dev().flush());
        CHECK(readLevel<uint8_t>(passes.first) == marker);
    }
    SECTION("a recording that wrote a buffer it had read is single-use, and ran in order") {
        SFX_REQUIRE_OK(dev().beginRecording());
        fullscreenPass(passes.first, passes.fill, {.uniformBuffers = {{gen::hal_test_uniform::ColorParams, passes.params}}});
        SFX_REQUIRE_OK(dev().writeBuffer(passes.params, 0, kNew, sizeof(kNew)));
        fullscreenPass(other, passes.fill, {.uniformBuffers = {{gen::hal_test_uniform::ColorParams, passes.params}}});
        Result<RecordingHandle> once = dev().endRecording();
        SFX_REQUIRE_OK(once.status());
        SFX_REQUIRE_OK(dev().flush());
        checkFilled(passes.first, kOld, "the pass before the write");
        checkFilled(other, kNew, "the pass after the write");
        SFX_REQUIRE_OK(dev().beginReplay(once.value()));
        fullscreenPass(passes.first, passes.fill, {.uniformBuffers = {{gen::hal_test_uniform::ColorParams, passes.params}}});
        fullscreenPass(other, passes.fill, {.uniformBuffers = {{gen::hal_test_uniform::ColorParams, passes.params}}});
        checkNamed(dev().endReplay(), StatusCode::StaleHandle, "wrote a resource it had used");
        SFX_REQUIRE_OK(dev().destroyRecording(once.value()));
    }
    SECTION("a recording holding a timer is single-use") {
        Result<TimerHandle> timer = dev().createTimer();
        SFX_REQUIRE_OK(timer.status());
        c.steps.push_back([t = timer.value()] { (void)dev().destroyTimer(t); });
        SFX_REQUIRE_OK(dev().beginRecording());
        SFX_REQUIRE_OK(dev().beginTimer(timer.value()));
        passes.record(passes.first);
        SFX_REQUIRE_OK(dev().endTimer(timer.value()));
        Result<RecordingHandle> timed = dev().endRecording();
        SFX_REQUIRE_OK(timed.status());
        SFX_REQUIRE_OK(dev().flush());
        SFX_REQUIRE_OK(dev().readTimer(timer.value()).status());
        SFX_REQUIRE_OK(dev().beginReplay(timed.value()));
        passes.record(passes.first);
        checkNamed(dev().endReplay(), StatusCode::StaleHandle, "timer");
        SFX_REQUIRE_OK(dev().destroyRecording(timed.value()));
    }
    SECTION("a destroyed recording") {
        SFX_REQUIRE_OK(dev().destroyRecording(rec.value()));
        checkNamed(dev().beginReplay(rec.value()), StatusCode::StaleHandle, "recording");
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return;
    }
    SFX_REQUIRE_OK(dev().destroyRecording(rec.value()));
    SFX_REQUIRE_OK(dev().flush());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: calls that cannot happen inside an open recording or replay are refused by name", "[hal][recordings]") {
    if (keepsNone()) return;
    Cleanup c;
    ThreePasses passes(c);
    checkNamed(dev().endRecording().status(), StatusCode::InvalidArgument, "beginRecording");
    checkNamed(dev().endReplay(), StatusCode::InvalidArgument, "beginReplay");
    checkNamed(dev().beginReplay({}), StatusCode::InvalidHandle, "recording");

    SFX_REQUIRE_OK(dev().beginRecording());
    passes.record(passes.first);
    float red = 0;
    checkNamed(dev().flush(), StatusCode::InvalidArgument, "endRecording");
    std::vector<float> level(size_t(kW) * kH);
    checkNamed(dev().readTexture(passes.second, 0, level.data(), level.size() * sizeof(float)), StatusCode::InvalidArgument, "endRecording");
    checkNamed(dev().readBuffer(passes.params, 0, &red, sizeof red), StatusCode::InvalidArgument, "endRecording");
    checkNamed(dev().beginRecording(), StatusCode::InvalidArgument, "endRecording");
    checkNamed(dev().endReplay(), StatusCode::InvalidArgument, "beginReplay");
    Result<RecordingHandle> rec = dev().endRecording();
    SFX_REQUIRE_OK(rec.status());
    SFX_REQUIRE_OK(dev().flush());
    passes.checkFrame(kOld, 0.25f, "the refused calls left the recording intact");

    SFX_REQUIRE_OK(dev().beginReplay(rec.value()));
    checkNamed(dev().flush(), StatusCode::InvalidArgument, "endReplay");
    checkNamed(dev().beginRecording(), StatusCode::InvalidArgument, "endReplay");
    checkNamed(dev().destroyRecording(rec.value()), StatusCode::InvalidArgument, "endReplay");
    passes.record(passes.first);
    (void)dev().endReplay();  // stale or not: the states of its first frame
    SFX_REQUIRE_OK(dev().destroyRecording(rec.value()));
    SFX_REQUIRE_OK(dev().flush());
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: a call refused while recording is not kept, so a replay making it again is stale", "[hal][recordings]") {
    if (keepsNone()) return;
    Cleanup c;
    ThreePasses passes(c);
    passes.record(passes.first);
    passes.checkFrame(kOld, 0.25f, "warm-up");
    const RenderPassDesc noAttachments{};
    SFX_REQUIRE_OK(dev().beginRecording());
    passes.record(passes.first);
    checkNamed(dev().renderPass(noAttachments, {}), StatusCode::InvalidArgument, "attachment");
    Result<RecordingHandle> rec = dev().endRecording();
    SFX_REQUIRE_OK(rec.status());
    passes.checkFrame(kOld, 0.25f, "recorded");
    // Inside a replay calls are only compared; the refused one was never recorded, so it differs.
    SFX_REQUIRE_OK(dev().beginReplay(rec.value()));
    passes.record(passes.first);
    SFX_REQUIRE_OK(dev().renderPass(noAttachments, {}));
    checkNamed(dev().endReplay(), StatusCode::StaleHandle, "the calls differ");
    SFX_REQUIRE_OK(dev().destroyRecording(rec.value()));
}
