// Ray-traced truth images (sfx/truth.hpp) cached on disk, so that a second benchmark or fit run
// only renders the effects: keyed by scene (and view) name, size, radius, sample count and seed.
#pragma once

#include <string>

#include "truth_scenes.hpp"

namespace sfx::tools {

// Bumped when the tracer's definition or the scenes' geometry change, so stale cached truth
// images are not read.
inline constexpr int kTruthVersion = 1;

// The file a truth is cached in under cacheDir.
std::string truthCachePath(const std::string& cacheDir, const TruthScene& scene, const truth::Settings& settings);

// The truth of `scene` from the cache, or traced (and then cached). *seconds: the trace time,
// 0 when it was read from the cache.
Result<truth::Image> cachedTruth(const std::string& cacheDir, const TruthScene& scene, const truth::Settings& settings, double* seconds);

}  // namespace sfx::tools
