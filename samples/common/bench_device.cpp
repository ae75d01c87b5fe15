#include "bench_device.hpp"

#include "sfx/tiers.hpp"

namespace sfx::samples {

Result<std::unique_ptr<Device>> openForTier(const BackendConfig& config, Tier tier) {
    DeviceOptions options;
    options.validation = false;
    options.ceiling = tiers::row(tier).ceiling;  // the current tier under the GL ES 3.0 ceiling
    Result<std::unique_ptr<Device>> device = openDevice(config, options);
    if (!device) return device.status();
    Result<tiers::TierChoice> choice = tiers::choose(device.value()->caps(), tier);
    if (!choice) return choice.status();
    return device;
}

Format aoOutputFormat(const Device& device) {
    return device.caps().renderableFormat[size_t(Format::R32F)] ? Format::R32F : Format::RGBA8;
}

Result<reference::Grid> readVisibility(Device& dev, TextureHandle texture, Format format, uint32_t w, uint32_t h) {
    const size_t n = size_t(w) * h;
    reference::Grid out(w, h);
    if (format == Format::R32F) {
        std::vector<float> px(n);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size() * sizeof(float)));
        for (size_t i = 0; i < n; ++i) out.values[i] = px[i];
    } else {
        std::vector<uint8_t> px(n * 4);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size()));
        for (size_t i = 0; i < n; ++i) out.values[i] = px[i * 4] / 255.0;
    }
    return out;
}

}  // namespace sfx::samples
