// Device::stats() on the null backend: live and created counts follow creates and destroys,
// and the bytes held follow the textures and buffers alive.
#include <catch2/catch.hpp>

#include "sfx/null_device.hpp"

using namespace sfx;

TEST_CASE("null device: stats count creations, destructions and bytes held", "[stats]") {
    DeviceOptions options;
    options.validation = true;  // as every test device
    auto dev = null::createDevice(options);
    const DeviceStats empty = dev->stats();
    CHECK(empty == DeviceStats{});

    const TextureDesc td{8, 4, 2, Format::RGBA8, kTextureSampled, "stats"};
    TextureHandle t = dev->createTexture(td).value();
    BufferHandle b = dev->createBuffer({256, kBufferUniform, "stats"}).value();
    SamplerHandle s = dev->createSampler({}).value();
    TimerHandle timer = dev->createTimer().value();
    DeviceStats now = dev->stats();
    CHECK(now.textures == ObjectCount{1, 1});
    CHECK(now.buffers == ObjectCount{1, 1});
    CHECK(now.samplers == ObjectCount{1, 1});
    CHECK(now.timers == ObjectCount{1, 1});
    CHECK(now.programs == ObjectCount{0, 0});
    CHECK(now.deviceMemoryBytes == 8 * 4 * 4 + 4 * 2 * 4 + 256);  // both mips and the buffer
    CHECK(textureBytes(td) == 8 * 4 * 4 + 4 * 2 * 4);

    REQUIRE(dev->destroyTexture(t).isOk());
    REQUIRE(dev->destroyBuffer(b).isOk());
    now = dev->stats();
    CHECK(now.textures == ObjectCount{0, 1});  // the total stays: a profiler sees churn
    CHECK(now.buffers == ObjectCount{0, 1});
    CHECK(now.deviceMemoryBytes == 0);

    // Reading stats makes nothing, and a failed create counts nothing.
    CHECK(dev->createTexture({0, 4, 1, Format::RGBA8}).status().code() == StatusCode::InvalidArgument);
    CHECK(dev->stats() == now);
    REQUIRE(dev->destroySampler(s).isOk());
    REQUIRE(dev->destroyTimer(timer).isOk());
    CHECK(dev->stats().samplers == ObjectCount{0, 1});
}
