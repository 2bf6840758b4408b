#pragma once
/// \file
/// Charts are drawn by the matplotlib scripts in regression/charts from the CSV files a step
/// wrote; a missing matplotlib costs the chart, never the run (the step notes it in the summary).

#include <string>
#include <vector>

namespace railfe {

struct StepContext;

/// Runs regression/charts/\p script with \p arguments on rank 0 (Debian's /usr/bin/python3 when
/// present: it has matplotlib, a python3 earlier on PATH may not). On failure adds a warning
/// to the step's summary section \p section.
void draw_chart(StepContext& context, const std::string& section, const std::string& script,
                const std::vector<std::string>& arguments);

}  // namespace railfe
