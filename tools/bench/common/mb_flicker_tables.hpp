// The flicker tables of docs/motion_blur.md ("Stable under motion"), written from
// bench_mb_flicker's CSV so that tools/run_trade.sh regenerates them with it: temporal PSNR per
// family, speed and tier at the tiers' defaults, the jitter patterns compared at the longer
// radius, and the figures the page states from them (the bound the jitter pattern adds).
#pragma once

#include <string>

#include "sfx/status.hpp"

namespace sfx::tools {

// The section's Markdown from the CSV at `csvPath`; `setup` opens it (what was run).
// FileError when unreadable, InvalidArgument naming a missing column.
Result<std::string> mbFlickerTables(const std::string& csvPath, const std::string& setup);

}  // namespace sfx::tools
