#pragma once
/// \file
/// The last line of defence of the output contract: a run that exits 0 never leaves NaN or inf
/// in a result file. Every staged file is scanned before it gets its final name, so the rule
/// holds for every module without each writer having to remember it.

#include <string>

namespace railfe {

/// Where a non-finite value sits in \p path ("row 12, column 'Fx_N': nan"), or "" when the file
/// holds none. CSV, JSON and text files are read as tokens; Exodus II files (.exo) by their
/// variables at every time step; other files (charts, matrices, checkpoints) are not read.
std::string find_non_finite(const std::string& path);

}  // namespace railfe
