#pragma once
/// \file
/// Checkpoint files of explicit runs: one binary file per rank, <step>.checkpoint.<rank> in the
/// results directory, holding named arrays of doubles. Files are written to a temporary name and
/// renamed, so an interruption at any moment leaves the previous checkpoint intact.

#include <string>
#include <vector>

#include "framework/base/parallel.hpp"

namespace railfe {

/// The sections of one rank's checkpoint, in order.
using CheckpointSections = std::vector<std::vector<double>>;

/// Writes \p sections to \p path (via path + ".tmp" and a rename) with the number of ranks
/// \p n_ranks in the header. Throws RunError if the file cannot be written.
void write_checkpoint(const std::string& path, int n_ranks, const CheckpointSections& sections);

/// Reads what write_checkpoint() wrote. Throws RunError, naming \p path, if the file is damaged,
/// was written by a run on a different number of ranks than \p n_ranks, or is in another format
/// (another version of railfe, whose sections this one would misread).
CheckpointSections read_checkpoint(const std::string& path, int n_ranks);

/// Whether every rank of \p comm finds its file \p path (collective).
bool checkpoint_exists(const std::string& path, const Communicator& comm);

}  // namespace railfe
