#include "bench_device.hpp"

#include <iostream>

#include "sfx/half.hpp"
#include "sfx/tiers.hpp"

namespace sfx::tools {

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

Result<std::unique_ptr<Device>> openNamedForTier(const std::string& backend, Tier tier) {
    for (const BackendConfig& config : compiledBackends())
        if (config.backend != BackendKind::Null && toString(config) == backend) return openForTier(config, tier);
    return Status{StatusCode::InvalidArgument, "backend " + backend + " is not compiled in"};
}

Status forEachDevice(const std::vector<std::string>& backends, const std::vector<Tier>& tierList, const std::string& program,
                     const std::function<Status(Device&, const std::string& backend, Tier)>& run) {
    for (const std::string& backend : backends)
        for (Tier tier : tierList) {
            BackendConfig config;
            if (!parseBackendConfig(backend, &config))
                return invalidArgument("--backends", "'" + backend + "'", "vulkan, gles, gl, gl-egl, gl-osmesa");
            Result<std::unique_ptr<Device>> dev = openForTier(config, tier);
            if (!dev) {
                std::cout << program << ": skipping " << backend << "/" << toString(tier) << ": " << dev.status().toString() << std::endl;
                continue;
            }
            if (Status st = run(*dev.value(), backend, tier); !st) return Status{st.code(), backend + "/" + toString(tier) + ": " + st.message()};
        }
    return Status::ok();
}

Format aoOutputFormat(const Device& device) { return device.caps().renderableFormat[size_t(Format::R32F)] ? Format::R32F : Format::RGBA8; }

Result<reference::Grid> readVisibility(Device& dev, TextureHandle texture, Format format, uint32_t w, uint32_t h) {
    const size_t n = size_t(w) * h;
    reference::Grid out(w, h);
    if (format == Format::R32F) {
        std::vector<float> px(n);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size() * sizeof(float)));
        for (size_t i = 0; i < n; ++i) out.values[i] = px[i];
    } else if (format == Format::R16F) {
        std::vector<uint16_t> px(n);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size() * sizeof(uint16_t)));
        for (size_t i = 0; i < n; ++i) out.values[i] = double(halfToFloat(px[i]));
    } else {
        std::vector<uint8_t> px(n * 4);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size()));
        for (size_t i = 0; i < n; ++i) out.values[i] = px[i * 4] / 255.0;
    }
    return out;
}

Result<std::vector<glm::dvec3>> readBentNormals(Device& dev, TextureHandle texture, Format format, uint32_t w, uint32_t h) {
    const size_t n = size_t(w) * h;
    std::vector<glm::dvec3> out(n);
    if (format == Format::RGBA8) {
        std::vector<uint8_t> px(n * 4);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size()));
        for (size_t i = 0; i < n; ++i) out[i] = glm::dvec3(px[i * 4], px[i * 4 + 1], px[i * 4 + 2]) / 255.0 * 2.0 - 1.0;
    } else if (format == Format::RGBA16F) {
        std::vector<uint16_t> px(n * 4);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size() * sizeof(uint16_t)));
        for (size_t i = 0; i < n; ++i) out[i] = glm::dvec3(halfToFloat(px[i * 4]), halfToFloat(px[i * 4 + 1]), halfToFloat(px[i * 4 + 2]));
    } else {
        std::vector<float> px(n * 4);
        SFX_TRY(dev.readTexture(texture, 0, px.data(), px.size() * sizeof(float)));
        for (size_t i = 0; i < n; ++i) out[i] = glm::dvec3(px[i * 4], px[i * 4 + 1], px[i * 4 + 2]);
    }
    return out;
}

}  // namespace sfx::tools
