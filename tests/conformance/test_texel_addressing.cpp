// sfxTexel (sfx_shared.h) reads texel q as a sample at (q + 0.5) times the reciprocal of the
// texture's size: it must land on q at every index up to the largest texture the HAL allows,
// where the rounding of the reciprocal is largest in texels. The copy program reads this way.
#include <catch2/catch.hpp>

#include <vector>

#include "copy_pass.hpp"
#include "skips.hpp"
#include "test_device.hpp"

using namespace sfx;

TEST_CASE("sfxTexel reads every texel at its own index up to the device's render-target limit", "[hal][texel]") {
    Device& dev = test::device();
    if (dev.caps().backend == BackendKind::Null) SFX_SKIP("the null backend draws nothing: no texel to read on " << test::label());
    // The largest size (16384 on lavapipe and llvmpipe, 8192 on SwiftShader), one below it, and
    // sizes whose reciprocals are not powers of two.
    const DeviceLimits& limits = dev.caps().limits;
    for (bool row : {true, false}) {
        const uint32_t limit = row ? limits.maxRenderTargetWidth : limits.maxRenderTargetHeight;
        for (uint32_t n : {limit, limit - 1, 12345u, 10001u, 6173u}) {
            if (n > limit) continue;
            const uint32_t w = row ? n : 1, h = row ? 1 : n;
            INFO(test::label() << " " << w << "x" << h);
            Result<std::unique_ptr<tools::CopyPass>> copy = tools::makeCopyPass(dev, test::tier(), w, h, Format::R32F);
            SFX_REQUIRE_OK(copy.status());
            std::vector<float> values(n);
            for (uint32_t i = 0; i < n; ++i) values[i] = float(i);  // exact: below 2^24
            SFX_REQUIRE_OK(dev.writeTexture(copy.value()->src, 0, values.data(), values.size() * sizeof(float)));
            SFX_REQUIRE_OK(copy.value()->record());
            SFX_REQUIRE_OK(dev.flush());
            std::vector<float> out(n, -1.0f);
            SFX_REQUIRE_OK(dev.readTexture(copy.value()->dst, 0, out.data(), out.size() * sizeof(float)));
            size_t wrong = 0;
            for (uint32_t i = 0; i < n; ++i)
                if (out[i] != values[i] && wrong++ < 5) UNSCOPED_INFO("texel " << i << " read " << out[i]);
            CHECK(wrong == 0);
        }
    }
}
