#include "truth_cache.hpp"

#include <chrono>
#include <filesystem>
#include <sstream>

#include "sfx/truth_file.hpp"

namespace sfx::tools {

std::string truthCachePath(const std::string& cacheDir, const TruthScene& scene, const truth::Settings& s) {
    std::ostringstream key;
    key << cacheDir << "/v" << kTruthVersion << "_" << scene.name << "_" << scene.camera.width << "x" << scene.camera.height << "_r" << s.radius
        << "_n" << s.samples << "_s" << s.seed << ".exr";
    return key.str();
}

Result<truth::Image> cachedTruth(const std::string& cacheDir, const TruthScene& scene, const truth::Settings& settings, double* seconds) {
    const std::string path = truthCachePath(cacheDir, scene, settings);
    *seconds = 0;
    if (std::filesystem::exists(path)) {
        Result<truth::Image> cached = truth::readImageFile(path);
        if (cached && cached->width == scene.camera.width && cached->height == scene.camera.height) {
            cached->samples = settings.samples;
            return cached;
        }
    }
    const auto start = std::chrono::steady_clock::now();
    Result<std::unique_ptr<truth::Tracer>> tracer = truth::Tracer::create(scene.geometry);
    if (!tracer) return tracer.status();
    Result<truth::Image> image = tracer.value()->trace(scene.camera, settings);
    if (!image) return image.status();
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::filesystem::create_directories(cacheDir);
    SFX_TRY(truth::writeImageFile(path, image.value()));
    return image;
}

}  // namespace sfx::tools
