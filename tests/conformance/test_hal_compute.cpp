// HAL conformance: compute: storage buffers, atomics and storage images on the high tier; refused under the
// ceiling.
// Runs on whatever backend and tier the run opened (tests/support/hal_fixture.hpp).
#include "hal_fixture.hpp"

using namespace sfx;
using namespace sfx::test;

TEST_CASE("hal: compute, storage buffers and atomics on the high tier; refused under the ceiling", "[hal]") {
    const CompiledProgram& counting = program("hal_atomic_count", Tier::High);
    if (test::tier() == Tier::Current) {
        CHECK_FALSE(dev().caps().computeShaders);
        CHECK(dev().caps().limits.maxStorageBufferSize == 0);
        CHECK(dev().createProgram(counting).status().code() == StatusCode::UnsupportedFeature);
        CHECK(dev().createBuffer({64, kBufferStorage}).status().code() == StatusCode::UnsupportedFeature);
        DispatchDesc d;
        CHECK(dev().dispatch(d).code() == StatusCode::UnsupportedFeature);
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return;
    }
    REQUIRE(dev().caps().computeShaders);
    REQUIRE(dev().caps().atomics);
    Cleanup c;
    const uint32_t invocations = 256;  // 4 groups of 64
    std::vector<uint32_t> initial(2 + invocations, 0);
    BufferHandle counters = makeBuffer(c, initial.size() * 4, kBufferStorage, initial.data());
    ProgramHandle prog = makeProgram(c, counting);
    Result<PipelineHandle> pipeline = dev().createComputePipeline({prog, "hal_atomic_count"});
    REQUIRE(pipeline.isOk());
    c.steps.push_back([p = pipeline.value()] { (void)dev().destroyPipeline(p); });
    DispatchDesc d;
    d.pipeline = pipeline.value();
    d.groupsX = invocations / 64;
    d.bindings.storageBuffers = {{gen::hal_atomic_count::Counters, counters}};
    SFX_REQUIRE_OK(dev().dispatch(d));
    SFX_REQUIRE_OK(dev().dispatch(d));  // twice: the second sees the first's atomics
    std::vector<uint32_t> out(initial.size());
    SFX_REQUIRE_OK(dev().readBuffer(counters, 0, out.data(), out.size() * 4));
    CHECK(out[0] == 2 * invocations);
    CHECK(out[1] == 2 * (invocations * (invocations - 1) / 2));
    for (uint32_t i = 0; i < invocations; ++i) REQUIRE(out[2 + i] == 3 * i);
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}

TEST_CASE("hal: compute writes a storage image mip, then it is sampled (high tier)", "[hal]") {
    if (test::tier() == Tier::Current) {
        CHECK(dev().createTexture({8, 8, 1, Format::R32F, kTextureStorage}).status().code() == StatusCode::UnsupportedFeature);
        SFX_REQUIRE_NO_VALIDATION_MESSAGES();
        return;
    }
    Cleanup c;
    TextureHandle image = makeTexture(c, 32, 16, Format::R32F, kTextureSampled | kTextureStorage, 2);
    ProgramHandle prog = makeProgram(c, program("hal_test_storage_image"));
    Result<PipelineHandle> pipeline = dev().createComputePipeline({prog, "hal_test_storage_image"});
    REQUIRE(pipeline.isOk());
    c.steps.push_back([p = pipeline.value()] { (void)dev().destroyPipeline(p); });
    DispatchDesc d;
    d.pipeline = pipeline.value();
    d.groupsX = 2;  // mip 1 is 16x8
    d.groupsY = 1;
    d.bindings.storageImages = {{gen::hal_test_storage_image::uImage, image, 1}};
    SFX_REQUIRE_OK(dev().dispatch(d));
    std::vector<float> texels = readLevel<float>(image, 1);
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 0; x < 16; ++x) REQUIRE(texels[y * 16 + x] == float(x + 16 * y));
    if (renderable(Format::R32F)) {
        REQUIRE(sampledThroughCopy(c, image, 16, 8, 1) == texels);
    }
    SFX_REQUIRE_NO_VALIDATION_MESSAGES();
}
