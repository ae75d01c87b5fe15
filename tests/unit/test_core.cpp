// Contract tests of the HAL core on the null backend: handles, descriptions, tiers.
#include <catch2/catch.hpp>

#include "sfx/backends.hpp"
#include "sfx/null_device.hpp"
#include "sfx/tiers.hpp"
#include "sfx_shaders.hpp"
#include "sfx_test_shaders.hpp"

using namespace sfx;

TEST_CASE("handles: stale, foreign and null handles are named errors", "[handles]") {
    auto a = null::createDevice();
    auto b = null::createDevice();
    TextureDesc desc{16, 16, 1, Format::R32F, kTextureSampled | kTextureRenderTarget};
    Result<TextureHandle> ta = a->createTexture(desc);
    REQUIRE(ta.isOk());
    CHECK(b->destroyTexture(ta.value()).code() == StatusCode::ForeignHandle);
    CHECK(a->destroyTexture(TextureHandle{}).code() == StatusCode::InvalidHandle);
    REQUIRE(a->destroyTexture(ta.value()).isOk());
    CHECK(a->destroyTexture(ta.value()).code() == StatusCode::StaleHandle);
    // The slot is reused with a new generation: the old handle stays stale.
    Result<TextureHandle> tb = a->createTexture(desc);
    REQUIRE(tb.isOk());
    CHECK(tb.value() != ta.value());
    CHECK(a->textureDesc(ta.value()).status().code() == StatusCode::StaleHandle);
}

TEST_CASE("tiers: rules pick high, current, or refuse with the unmet requirement", "[tiers]") {
    DeviceCaps caps = null::defaultCaps();
    caps.backend = BackendKind::GLES;
    caps.apiMajor = 3;
    caps.apiMinor = 2;
    caps.apiName = "OpenGL ES 3.2";
    Result<tiers::TierChoice> best = tiers::choose(caps);
    REQUIRE(best.isOk());
    CHECK(best->tier == Tier::High);
    CHECK(best->profile.aoScalableTaps == 9);
    CHECK(best->profile.mbMaxRadiusPx == 18.0f);

    Result<tiers::TierChoice> forced = tiers::choose(caps, Tier::Current);
    REQUIRE(forced.isOk());
    CHECK(forced->tier == Tier::Current);
    CHECK(forced->profile.aoScalableTaps == 4);

    DeviceCaps es30 = null::defaultCaps(CapabilityCeiling::GLES30);
    es30.backend = BackendKind::GLES;
    es30.apiMajor = 3;
    es30.apiMinor = 0;
    Result<tiers::TierChoice> c = tiers::choose(es30);
    REQUIRE(c.isOk());
    CHECK(c->tier == Tier::Current);
    CHECK(c->reason.find("compute shaders") != std::string::npos);

    Result<tiers::TierChoice> refused = tiers::choose(es30, Tier::High);
    REQUIRE_FALSE(refused.isOk());
    CHECK(refused.status().code() == StatusCode::UnsupportedTier);
    CHECK(refused.status().message().find("storage buffers") != std::string::npos);

    es30.renderableFormat[size_t(Format::R32F)] = false;
    Result<tiers::TierChoice> none = tiers::choose(es30);
    REQUIRE_FALSE(none.isOk());
    CHECK(none.status().code() == StatusCode::UnsupportedTier);
    CHECK(none.status().message().find("R32F") != std::string::npos);
}

TEST_CASE("texture descriptions: every bad field is a named error", "[hal][bad-input]") {
    auto dev = null::createDevice();
    auto code = [&](TextureDesc d) { return dev->createTexture(d).status().code(); };
    auto message = [&](TextureDesc d) { return dev->createTexture(d).status().message(); };
    TextureDesc ok{64, 32, 1, Format::RGBA8, kTextureSampled};
    CHECK(dev->createTexture(ok).isOk());
    TextureDesc d = ok;
    d.width = 0;
    CHECK(code(d) == StatusCode::InvalidArgument);
    CHECK(message(d).find("TextureDesc.width is 0; allowed [1, 16384]") != std::string::npos);
    d = ok;
    d.height = 100000;
    CHECK(code(d) == StatusCode::InvalidArgument);
    CHECK(message(d).find("TextureDesc.height") != std::string::npos);
    d = ok;
    d.mipLevels = 8;  // 64x32 has 7 levels
    CHECK(code(d) == StatusCode::InvalidArgument);
    CHECK(message(d).find("[1, 7]") != std::string::npos);
    d = ok;
    d.format = Format(999);
    CHECK(code(d) == StatusCode::UnsupportedFormat);
    d = ok;
    d.format = Format::Undefined;
    CHECK(code(d) == StatusCode::UnsupportedFormat);
    d = ok;
    d.usage = 0;
    CHECK(code(d) == StatusCode::InvalidArgument);
}

TEST_CASE("texture and buffer transfers check sizes, ranges and mips", "[hal][bad-input]") {
    auto dev = null::createDevice();
    TextureHandle t = dev->createTexture({4, 4, 3, Format::R32F, kTextureSampled}).value();
    std::vector<float> level0(16, 1.0f), level1(4, 2.0f);
    CHECK(dev->writeTexture(t, 0, level0.data(), 64).isOk());
    CHECK(dev->writeTexture(t, 1, level1.data(), 16).isOk());
    CHECK(dev->writeTexture(t, 0, level0.data(), 60).code() == StatusCode::InvalidArgument);
    CHECK(dev->writeTexture(t, 3, level0.data(), 4).code() == StatusCode::InvalidArgument);
    std::vector<float> back(4);
    REQUIRE(dev->readTexture(t, 1, back.data(), 16).isOk());
    CHECK(back == level1);

    CHECK(dev->createBuffer({0, kBufferUniform}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev->createBuffer({16, 0}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev->createBuffer({1u << 20, kBufferUniform}).status().code() == StatusCode::InvalidArgument);
    BufferHandle b = dev->createBuffer({64, kBufferUniform}).value();
    uint8_t bytes[64] = {};
    CHECK(dev->writeBuffer(b, 60, bytes, 8).code() == StatusCode::InvalidArgument);
    CHECK(dev->writeBuffer(b, 0, bytes, 64).isOk());
    CHECK(dev->readBuffer(b, 0, bytes, 0).code() == StatusCode::InvalidArgument);
}

TEST_CASE("capability ceiling refuses storage, compute and high-tier-only programs", "[hal][ceiling]") {
    DeviceOptions options;
    options.ceiling = CapabilityCeiling::GLES30;
    auto dev = null::createDevice(options);
    Result<BufferHandle> storage = dev->createBuffer({256, kBufferStorage});
    CHECK(storage.status().code() == StatusCode::UnsupportedFeature);
    CHECK(storage.status().message().find("ceiling") != std::string::npos);
    Result<const CompiledProgram*> atomic = test_shaders::find("hal_atomic_count", Tier::High);
    REQUIRE(atomic.isOk());
    CHECK(dev->createProgram(*atomic.value()).status().code() == StatusCode::UnsupportedFeature);
    DispatchDesc d;
    CHECK(dev->dispatch(d).code() == StatusCode::UnsupportedFeature);
}

TEST_CASE("embedded shader library has every program for its tiers", "[shaders]") {
    CHECK(shaders::find("linearize_depth", Tier::Current).isOk());
    CHECK(shaders::find("linearize_depth", Tier::High).isOk());
    CHECK(shaders::find("depth_mip", Tier::High).isOk());
    Result<const CompiledProgram*> missing = shaders::find("no_such_program", Tier::High);
    CHECK(missing.status().code() == StatusCode::InvalidArgument);
    CHECK(missing.status().message().find("linearize_depth") != std::string::npos);
    // Test and sample programs live in their own libraries, not in the runtime's.
    CHECK(shaders::find("hal_test_pattern", Tier::High).status().code() == StatusCode::InvalidArgument);
    CHECK(shaders::find("raster_gbuffer", Tier::High).status().code() == StatusCode::InvalidArgument);
    CHECK(test_shaders::find("hal_test_pattern", Tier::High).isOk());
    for (const CompiledProgram& p : shaders::all()) {
        INFO(p.name << " " << toString(p.tier));
        for (const StageCode& s : p.stages) {
            CHECK(s.spirv.size() > 5);
            // Every tier runs on GL ES 3.1 and GL 4.3 (the dialects per tier: test_tier_table.cpp).
            CHECK_FALSE(s.glsl[size_t(ShaderDialect::Essl310)].empty());
            CHECK_FALSE(s.glsl[size_t(ShaderDialect::Glsl450)].empty());
        }
    }
}

TEST_CASE("backend names parse, and unknown ones are refused", "[backends][bad-input]") {
    BackendConfig c;
    REQUIRE(parseBackendConfig("gl", &c));
    CHECK(toString(c) == "gl-osmesa");
    REQUIRE(parseBackendConfig("gles", &c));
    CHECK(c.backend == BackendKind::GLES);
    CHECK_FALSE(parseBackendConfig("metal", &c));
    CHECK_FALSE(parseBackendConfig("", &c));
    // The null backend opens anywhere; it reaches no tier, and says why.
    Result<std::unique_ptr<Device>> dev = openDevice({BackendKind::Null, ""});
    REQUIRE(dev.isOk());
    Result<tiers::TierChoice> tier = tiers::choose(dev.value()->caps());
    CHECK(tier.status().code() == StatusCode::UnsupportedTier);
    CHECK(tier.status().message().find("rasterising device") != std::string::npos);
}

TEST_CASE("handles: a slot whose generation runs out is retired, never reused", "[handles]") {
    HandlePool<TextureTag, int> pool(7, "texture");
    TextureHandle first = pool.insert(1);
    TextureHandle h = first;
    for (int i = 0; i < 70000; ++i) {
        pool.remove(h);
        h = pool.insert(i);
        REQUIRE(pool.check(first, "first").code() == StatusCode::StaleHandle);
    }
    // The first slot was retired after 65535 reuses; the pool moved on to a new one.
    CHECK(h.bits != first.bits);
    CHECK(pool.aliveCount() == 1);
}

TEST_CASE("results: the value of an error Result is a value-initialised T, never undefined", "[status]") {
    Result<std::unique_ptr<Device>> device = Status{StatusCode::BackendUnavailable, "no driver"};
    CHECK_FALSE(device.isOk());
    CHECK(device.value() == nullptr);
    CHECK(device.status().code() == StatusCode::BackendUnavailable);
    CHECK(device.status().message() == "no driver");
    std::unique_ptr<Device> moved = std::move(device).value();
    CHECK(moved == nullptr);

    const Result<int> number = invalidArgument("n", "-1", "0..3");
    CHECK(number.value() == 0);
    CHECK(*number == 0);
    Result<std::string> text = Status{StatusCode::FileError, "missing"};
    CHECK(text->empty());
    Result<TextureHandle> texture = Status{StatusCode::InvalidHandle, "gone"};
    CHECK(texture.value().isNull());
    // Writing through an error Result's value touches only that Result.
    text.value() = "written";
    CHECK(Result<std::string>(Status{StatusCode::FileError, "x"}).value().empty());

    // An Ok Status carries no value, so a Result made from one is an error, not an empty success.
    Result<int> fromOk = Status::ok();
    CHECK_FALSE(fromOk.isOk());
    CHECK(fromOk.status().code() == StatusCode::InvalidArgument);

    Result<int> good = 7;
    CHECK(good.isOk());
    CHECK(good.value() == 7);
}

TEST_CASE("device options: API validation is off unless the host asks for it", "[hal][options]") {
    DeviceOptions options;
    CHECK_FALSE(options.validation);
    CHECK_FALSE(options.log);
}
