// Truth images as files (.pfm or .exr): channel 0 = visibility, channel 1 = surface mask
// (1 = surface, 0 = sky). The sample count is not stored; the cache key carries it.
#pragma once

#include <string>

#include "sfx/truth.hpp"

namespace sfx::truth {

Status writeImageFile(const std::string& path, const Image& image);
// FileError when the file is unreadable or has fewer than two channels.
Result<Image> readImageFile(const std::string& path);

}  // namespace sfx::truth
