// The motion blur family tables of docs/motion_blur.md, written from bench_mb_families' CSVs so
// that tools/run_trade.sh regenerates the page's figures with the CSVs: per family and speed the
// scores against a stored baseline (the 2012 reconstruction), per-family means, the independent
// square's rows, the rasterised families, and the tier promise over a speed sweep and over many
// layouts of each family.
#pragma once

#include <string>
#include <vector>

#include "sfx/status.hpp"

namespace sfx::tools {

// One row of a bench_mb_families CSV (or of the baseline, which has fewer columns: a column a
// file lacks reads NaN, as does "-").
struct MbFamilyRow {
    std::string family, split, tier, source;
    double speed = 0;
    int layout = 0;  // the seed the family was laid out from; 0 where the CSV has none
    double moving = 0, frame = 0, leading = 0, trailing = 0, rows = 0;
    double inputMoving = 0, inputLeading = 0, inputTrailing = 0, inputRows = 0;
    double residual = 0;  // the truth's residual noise as PSNR (dB)
};

// Reads every row of `path`. FileError when unreadable, InvalidArgument naming the file and line
// when a row has a column count other than the header's.
Result<std::vector<MbFamilyRow>> readMbFamilyCsv(const std::string& path);

// `setup` opens each section: what was run, where. The tables use the CPU reference's rows and
// state how far the backends' rows are from them.
// The 2D families: per family and speed the scores and their change against `before`, the
// per-family means over the speeds of 2 px and more, and the square's rows.
std::string mbFamilyTables(const std::vector<MbFamilyRow>& rows, const std::vector<MbFamilyRow>& before, const std::string& setup);
// The rasterised families: per family and speed, and the per-family means.
std::string mbRasterTables(const std::vector<MbFamilyRow>& rows, const std::string& setup);
// A sweep: per family and region the worst high - current tier and its speed, and at how many
// speeds the high tier is below the current one by more than 0.005 dB somewhere.
std::string mbSweepTable(const std::vector<MbFamilyRow>& rows, const std::string& setup);
// Many layouts of each family (bench_mb_families --layouts): per family and region the worst
// mean over the layouts of high - current tier and its speed, how many cases (speed x layout)
// have the high tier below the current one by more than 0.005 dB, and the worst single case.
std::string mbLayoutsTable(const std::vector<MbFamilyRow>& rows, const std::string& setup);

}  // namespace sfx::tools
