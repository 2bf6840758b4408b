#pragma once
/// \file
/// The track a "wheelset dynamics" step runs on, as its deck's Rails list asks: rigid rails
/// (the wheelset's equations alone, RigidRails), a rigid body per rail on springs, or a beam per
/// rail on rail seats (RailBeams coupled to the wheelset, BeamRails, the block saddle-point
/// solver). Either way the step sees
/// one system, one constraint set and one saddle-point solver, with the wheelset's unknowns
/// from offset() on.

#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <vector>

#include "framework/deck/parameter_spec.hpp"
#include "framework/solvers/saddle_point_solvers.hpp"
#include "framework/time/sparse_system.hpp"
#include "physics/wheelset_dynamics/rail_beams.hpp"
#include "physics/wheelset_dynamics/wheelset_balance.hpp"

namespace railfe {

/// The Rails list's valid parameters.
ParameterSpec track_rail_parameters();

/// The rails' beams and seats from a Rails list whose Model is "beams". Throws an input error
/// naming the deck \p source, the list's \p path and the parameter for a layout the beams
/// cannot take.
RailBeamLayout rail_beam_layout(const Teuchos::ParameterList& rails, const std::string& source,
                                const std::string& path);

/// The rails' springs from a Rails list whose Model is "springs"; input errors as
/// rail_beam_layout().
RailSpringLayout rail_spring_layout(const Teuchos::ParameterList& rails, const std::string& source,
                                    const std::string& path);

/// The track and the solver pieces that go with it (see the file comment).
class WheelsetTrack {
 public:
  /// The rails of \p rails (its Model; \p source and \p path name it in messages) under
  /// \p wheelset (not owned), the beams' axes under the top of each rail profile of
  /// \p geometry, the irregularities \p lateral and \p vertical (functions of s; right, down),
  /// the wheelset at s = \p start + \p speed t.
  WheelsetTrack(const Teuchos::ParameterList& rails, const std::string& source,
                const std::string& path, const WheelRailGeometry& geometry,
                WheelsetSystem& wheelset, std::function<double(double)> lateral,
                std::function<double(double)> vertical, double start, double speed);
  /// Whether the rails move (springs or beams).
  bool flexible() const { return beams_ != nullptr; }
  /// The wheelset's first unknown in system().
  std::size_t offset() const { return offset_; }
  /// The whole system: the wheelset, or the rails and the wheelset.
  SecondOrderSystem& system() { return *whole_; }
  /// The ties of the internal nodes to the rails.
  ConstraintSet& constraints() { return *constraints_; }
  /// The saddle-point solver for system() and constraints().
  SaddlePointSolver& saddle() { return *saddle_; }
  /// Lateral (right) and vertical (down) irregularity under the wheelset at \p time.
  std::array<double, 2> offsets(double time) const;
  /// Places the internal nodes on the rails and balances the wheelset (and the rails) under
  /// its weight; \p u has system()'s length. With \p rolling (beams only) the rails are balanced
  /// again under the forces of steady rolling at the wheelset's spin (balance_on_rail_beams()).
  WheelsetBalance balance(const WheelRailGeometry& geometry, std::vector<double>& u,
                          bool rolling = false);
  /// Takes the converged contact states of a step (the rails' roll levers).
  void accept(const std::array<ContactState, n_wheelset_contacts>& states);
  /// Vertical displacement of the right and left rail under their tread points at \p time
  /// (m, down; 0 for rigid rails) for the whole system's \p u.
  std::array<double, 2> rail_deflection(double time, const double* u);
  /// The rails' beams or springs (flexible() only).
  const RailBeams& beams() const { return *beams_; }

 private:
  WheelsetSystem& wheelset_;
  std::size_t offset_ = 0;
  std::unique_ptr<RailBeams> beams_;
  std::unique_ptr<SparseLinearSystem> structure_;
  std::unique_ptr<CoupledSystem> coupled_;
  std::unique_ptr<BeamRails> beam_rails_;
  std::unique_ptr<RigidRails> rigid_rails_;
  SecondOrderSystem* whole_ = nullptr;
  ConstraintSet* constraints_ = nullptr;
  std::unique_ptr<SaddlePointSolver> saddle_;
};

}  // namespace railfe
