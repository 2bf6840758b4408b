#pragma once
/// \file
/// The rows a contact pair writes, shared by the steps that have contact: a history row (forces
/// in the contact frame, friction bound, area, active and slipping nodes, penetration, energies)
/// and the patch rows (per active slave node: position, pressure, shear, slip, and the node's
/// contact area, so that pressure and shear times area sum to the forces). The contact
/// frame is n (the force-weighted mean normal, master towards slave), t1 (the pair's
/// Longitudinal direction projected onto the contact plane) and t2 = n x t1.

#include <array>
#include <string>
#include <vector>

namespace railfe {

class ContactPairs;
class PenaltyContactPair;

/// The contact frame of \p pair at its last evaluation: n, t1, t2 (see the file comment).
std::array<std::array<double, 3>, 3> contact_frame(const PenaltyContactPair& pair);

/// Column names of a pair's history file.
const std::vector<std::string>& contact_history_columns();

/// The history row of \p pair at \p time (s), in the order of contact_history_columns().
std::vector<double> contact_history_row(double time, const PenaltyContactPair& pair);

/// Column names of a patch file.
const std::vector<std::string>& contact_patch_columns();

/// The rows of a patch file: one per active slave node of \p pair at \p time (s), in the order
/// of contact_patch_columns() (global node numbers from \p contact).
std::vector<std::vector<double>> contact_patch_rows(double time, const PenaltyContactPair& pair,
                                                    const ContactPairs& contact);

/// Names of the contact's nodal fields in Exodus snapshots: pressure (Pa), shear traction x, y,
/// z (Pa), slip velocity x, y, z (m/s) and status (0 open, 1 stick, 2 slip), all on slave nodes
/// and 0 elsewhere.
const std::vector<std::string>& contact_nodal_field_names();

/// Adds the nodal fields of every pair of \p contact at its last evaluation to \p values, which
/// holds \p width numbers per owned node with the contact's fields from \p offset on. A node that
/// is a slave of several pairs sums their tractions and keeps the larger status.
void add_contact_nodal_fields(const ContactPairs& contact, std::vector<double>& values, int width,
                              int offset);

}  // namespace railfe
