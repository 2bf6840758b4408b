#pragma once
/// \file
/// The structure a "vehicle dynamics" step runs over, as its Structure list asks: rigid (the
/// roller rig of a test plant, or a structure too stiff to matter: the rails follow the
/// irregularities and deviations alone) or a girder continuous over its spans on bearings at
/// the piers, which the vehicle's wheel forces deflect while it crosses them (RailBeams'
/// GirderLayout). The deviations stay the rails' offsets either way: a structure displaced
/// before the train comes, which its dynamic deflection adds to.

#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

#include "framework/app/module.hpp"
#include "framework/deck/parameter_spec.hpp"
#include "framework/output/csv_writer.hpp"
#include "framework/time/coupled_system.hpp"
#include "framework/time/sparse_system.hpp"
#include "physics/common/structure_deviation.hpp"
#include "physics/wheelset_dynamics/rail_beams.hpp"
#include "physics/wheelset_dynamics/vehicle_system.hpp"

namespace railfe {

/// The Structure list's valid parameters.
ParameterSpec vehicle_structure_parameters();

/// Whether the Structure list \p structure asks for girders.
bool structure_is_girders(const Teuchos::ParameterList& structure);

/// The girders of a Structure list whose Model is "girders". Throws an input error naming the
/// deck \p source and the list's \p path for bearings given to a single span (no pier).
GirderLayout girder_layout(const Teuchos::ParameterList& structure, const std::string& source,
                           const std::string& path);

/// Throws an input error naming the deck \p source and the Structure list's \p path unless the
/// two spans of \p deviation (if any) are two of the girders of \p layout, whose span the
/// deviation's then replaces (a sweep over spans sweeps both).
void check_deviation_on_girders(const GirderLayout& layout,
                                const StructureDeviationSettings& deviation,
                                const std::string& source, const std::string& path);

/// The girders under a vehicle and the coupled system of both: the girders' unknowns first,
/// the vehicle's from offset() on.
class VehicleStructure {
 public:
  /// The girders of \p layout, their axis Axis depth below the rails' top of \p geometry,
  /// coupled to \p vehicle (not owned).
  VehicleStructure(const GirderLayout& layout, const WheelRailGeometry& geometry,
                   VehicleSystem& vehicle);
  /// The vehicle's first unknown in system().
  std::size_t offset() const { return structure_->n_unknowns(); }
  /// The girders' matrices and path.
  const RailBeams& girders() const { return *girders_; }
  /// Girders and vehicle.
  CoupledSystem& coupled() { return *coupled_; }
  /// Girders and vehicle, as the time integration sees them.
  SecondOrderSystem& system() { return *coupled_; }
  /// The layout.
  const GirderLayout& layout() const { return layout_; }
  /// Lateral (right) and vertical (down) displacement of the girders' axis at track position
  /// \p s for the unknowns \p u (the whole system's); zero off the structure.
  std::array<double, 2> displacement(double s, const double* u) const;

 private:
  GirderLayout layout_;
  std::unique_ptr<RailBeams> girders_;
  std::unique_ptr<SparseLinearSystem> structure_;
  std::unique_ptr<CoupledSystem> coupled_;
};

/// <step>_girders.csv (each span's midspan displacement against time) and the peaks of the
/// run's summary.
class GirderRecorder {
 public:
  /// Opens the file of step \p context for \p structure (not owned); writes when \p writes.
  GirderRecorder(StepContext& context, const VehicleStructure& structure, bool writes);
  /// Takes the converged unknowns \p u at \p time; a row when \p write_row.
  void record(double time, const double* u, bool write_row);
  /// Adds the peaks to \p summary under \p section.
  void finish(RunSummary& summary, const std::string& section) const;

 private:
  const VehicleStructure& structure_;
  CsvWriter file_;
  std::vector<std::array<double, 2>> peaks_;  // per span: lateral, vertical (absolute)
};

}  // namespace railfe
