#pragma once
// A straight line of equal beam elements assembled into dense matrices, and the generalized
// eigenproblem K φ = ω² M φ on a chosen set of DOFs: a small stand-in for the assembly the
// modules will do, for the beam tests only.
#include <vector>

#include <Eigen/Dense>

#include "physics/elements/beam_element.hpp"

namespace railfe::test {

// K and M of \p n elements from \p start to \p end (nodes 0..n, DOF 6 node + component).
struct LineModel {
  Eigen::MatrixXd stiffness, mass;
};

inline LineModel assemble_line(int n, const Eigen::Vector3d& start, const Eigen::Vector3d& end,
                               const Eigen::Vector3d& orientation, const BeamMaterial& material,
                               const BeamSection& section, BeamMass kind,
                               bool rotary_inertia = true) {
  const int size = 6 * (n + 1);
  LineModel model{Eigen::MatrixXd::Zero(size, size), Eigen::MatrixXd::Zero(size, size)};
  for (int e = 0; e < n; ++e) {
    const Eigen::Vector3d a = start + (end - start) * e / n;
    const Eigen::Vector3d b = start + (end - start) * (e + 1) / n;
    const BeamElement beam(a, b, orientation, material, section, rotary_inertia);
    model.stiffness.block<12, 12>(6 * e, 6 * e) += beam.stiffness();
    model.mass.block<12, 12>(6 * e, 6 * e) += beam.mass(kind);
  }
  return model;
}

// The DOFs of nodes 0..n whose component is in \p components, less those listed in \p fixed.
inline std::vector<int> kept_dofs(int n, const std::vector<int>& components,
                                  const std::vector<int>& fixed) {
  std::vector<int> kept;
  for (int node = 0; node <= n; ++node)
    for (int c : components) {
      const int dof = 6 * node + c;
      bool is_fixed = false;
      for (int f : fixed)
        is_fixed = is_fixed || f == dof;
      if (!is_fixed)
        kept.push_back(dof);
    }
  return kept;
}

// Natural frequencies (Hz, ascending) of \p model restricted to \p dofs.
inline Eigen::VectorXd natural_frequencies(const LineModel& model, const std::vector<int>& dofs) {
  const int m = static_cast<int>(dofs.size());
  Eigen::MatrixXd K(m, m), M(m, m);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      K(i, j) = model.stiffness(dofs[i], dofs[j]);
      M(i, j) = model.mass(dofs[i], dofs[j]);
    }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  const double two_pi = 2 * 3.14159265358979323846;
  return solver.eigenvalues().cwiseMax(0).cwiseSqrt() / two_pi;
}

}  // namespace railfe::test
