// Generated tables inside hand-written Markdown pages: a program owns the text between its
// "<!-- name: begin -->" and "<!-- name: end -->" markers and replaces only that.
#pragma once

#include <string>

#include "sfx/status.hpp"

namespace sfx::tools {

// Replaces what lies between the markers of `name` in the file at `path` (appending the markers
// with `text` when they are missing, creating the file when it is). FileError when unwritable.
Status replaceMarkdownSection(const std::string& path, const std::string& name, const std::string& text);

// A table cell: v with `digits` decimals, "inf" for an infinity (an exact PSNR).
std::string fixed(double v, int digits);
// The same with "-" for NaN (a mask with no pixel, a case not run).
std::string fixedOrDash(double v, int digits = 2);
// A signed difference with `digits` decimals ("+0.00", never "-0.00"), "-" when not finite.
std::string signedFixed(double v, int digits);
// v as %g writes it: a speed, a radius (6, 7.5, 0.5).
std::string compactNumber(double v);

}  // namespace sfx::tools
