#pragma once
/// \file
/// Sweeps of a "vehicle dynamics" step: its Sweep list names speeds, span lengths and deviation
/// amplitudes, and the step runs every combination as a case of its own, the cases dealt out
/// over the MPI ranks (case i on rank i mod ranks, each case on one rank). Every case writes its
/// histories as <step>_case<i>_*.csv; rank 0 writes one table, <step>_sweep.csv, and its chart.
/// A case that stops (Newton fails, a wheelset leaves the rails) is reported in the table with
/// where it stopped, and the sweep goes on: the failures are what a stability sweep looks for.

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <string>
#include <vector>

#include "framework/app/module.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "physics/common/structure_deviation.hpp"

namespace railfe {

/// What changes from case to case.
struct VehicleCase {
  double speed = 0;                      ///< V (m/s)
  double end_time = 0;                   ///< simulated time (s)
  StructureDeviationSettings deviation;  ///< shape, span, amplitude
};

/// How a case ended.
struct CaseOutcome {
  std::string stop;       ///< "" when it ran to its end time, else why it stopped
  double stopped_at = 0;  ///< when it stopped (s)
  std::string message;    ///< the error that stopped it, if any
};

/// The Sweep list's valid parameters.
ParameterSpec vehicle_sweep_parameters();

/// Whether the step list \p step (validated or as the deck gives it) names sweep cases.
bool names_sweep_cases(const Teuchos::ParameterList& step);

/// The cases of the Sweep list of \p step, every combination of its lists, each missing list
/// taking \p base's value; each case runs over the track length of \p base (End time × Speed).
/// Empty when the list names nothing. Throws an input error (deck \p source, list \p path) for
/// Spans or Amplitudes without a Structure deviation.
std::vector<VehicleCase> sweep_cases(const Teuchos::ParameterList& step, const VehicleCase& base,
                                     const std::string& source, const std::string& path);

/// Runs one case in the context given (its step name is the case's file prefix, its summary
/// the case's own).
using CaseRunner = std::function<CaseOutcome(StepContext&, const VehicleCase&)>;

/// Runs \p cases over the ranks with \p run (see the file comment); adds the sweep's figures
/// to the summary under \p section (collective).
void run_sweep(StepContext& context, const std::vector<VehicleCase>& cases, const CaseRunner& run,
               const std::string& section);

}  // namespace railfe
