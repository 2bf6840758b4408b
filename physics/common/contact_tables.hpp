#pragma once
/// \file
/// The rows a contact pair writes, shared by the steps that have contact: a history row (forces
/// in the contact frame, friction bound, area, active and slipping nodes, penetration, energies)
/// and the patch rows (per active slave node: position, pressure, shear, slip). The contact
/// frame is n (the force-weighted mean normal, master towards slave), t1 (the pair's
/// Longitudinal direction projected onto the contact plane) and t2 = n x t1.

#include <string>
#include <vector>

namespace railfe {

class ContactPairs;
class CsvWriter;
class PenaltyContactPair;

/// Column names of a pair's history file.
const std::vector<std::string>& contact_history_columns();

/// The history row of \p pair at \p time (s), in the order of contact_history_columns().
std::vector<double> contact_history_row(double time, const PenaltyContactPair& pair);

/// Column names of a patch file.
const std::vector<std::string>& contact_patch_columns();

/// Writes one row per active slave node of \p pair at \p time (s) to \p file (global node
/// numbers from \p contact).
void write_contact_patch(CsvWriter& file, double time, const PenaltyContactPair& pair,
                         const ContactPairs& contact);

}  // namespace railfe
