// The conformance run's figures for docs/portability.md: one row per effect, with the driver,
// backend and tier it ran on, the worst pixel and the mean absolute error against the CPU
// reference, appended to portability_rows.md in the run's output directory (started afresh by
// the run's first row). tools/write_portability_table.sh gathers the rows of every run into
// the page; docs.portability checks that the page lists every row the runs wrote.
#pragma once

#include <string>

namespace sfx::test {

void addPortabilityRow(const std::string& effect, double worstPixel, double meanAbsError);

}  // namespace sfx::test
