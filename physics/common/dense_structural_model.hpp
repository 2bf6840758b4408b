#pragma once
/// \file
/// A small structural model (a vehicle: point masses, spring–dampers, beams, rigid links) as
/// dense matrices over the motions of the nodes no rigid link carries. Time stepping a vehicle
/// whose forty-odd unknowns are coupled to contact elements at every Newton iteration is faster
/// in dense form than through Tpetra; the element matrices are the ones the distributed
/// assembly uses (structural_element_matrix()), so the modal module sees the same model.

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "framework/mesh/mesh.hpp"
#include "physics/common/structural_sections.hpp"

namespace railfe {

/// M, K and C of a structural mesh over its free nodes' six motions each (see the file comment).
class DenseStructuralModel {
 public:
  /// Assembles every element of \p mesh with a section in \p sections and eliminates the
  /// nodes its rigid_link blocks carry (u_s = u_m + θ_m × r, θ_s = θ_m). Throws InputError
  /// naming \p deck for chained links, a node carried twice or a master that is also carried.
  DenseStructuralModel(const Mesh& mesh, const SectionTable& sections, const std::string& deck);

  /// Number of unknowns: six per free node.
  Eigen::Index n_unknowns() const { return mass_.rows(); }
  /// M over the unknowns.
  const Eigen::MatrixXd& mass() const { return mass_; }
  /// K over the unknowns.
  const Eigen::MatrixXd& stiffness() const { return stiffness_; }
  /// C (the spring–dampers') over the unknowns.
  const Eigen::MatrixXd& damping() const { return damping_; }
  /// First of the six unknowns of free node \p node; -1 for a carried node.
  Eigen::Index unknown_of(GlobalIndex node) const { return first_unknown_[node]; }
  /// The 6 × n_unknowns() matrix that gives node \p node's six motions from the unknowns.
  Eigen::MatrixXd node_motion(GlobalIndex node) const;
  /// The loads of a uniform acceleration field \p g (m/s², the weight under gravity): M times
  /// the rigid translation by g.
  Eigen::VectorXd gravity_load(const Eigen::Vector3d& g) const;

 private:
  Eigen::MatrixXd mass_, stiffness_, damping_;
  Eigen::MatrixXd carry_;  // every node's six motions (rows) from the unknowns
  std::vector<Eigen::Index> first_unknown_;
};

}  // namespace railfe
