#include "physics/elements/beam_interpolation.hpp"

#include "physics/elements/timoshenko_bending.hpp"

namespace railfe {

Eigen::Matrix<double, 3, 12> beam_translation_interpolation(const BeamElement& beam, double xi) {
  const double length = beam.length();
  const auto [phi_y, phi_z] = beam.shear_parameters();
  Eigen::Matrix<double, 3, 12> local = Eigen::Matrix<double, 3, 12>::Zero();
  local(0, 0) = 1 - xi;  // axial: linear
  local(0, 6) = xi;
  // Bending in x–y: (u_y, θ_z) with θ_z = du_y/dx; in x–z: (u_z, θ_y) with θ_y = −du_z/dx.
  const Eigen::Vector4d in_xy = timoshenko_shape(xi, phi_y, length).deflection;
  const Eigen::Vector4d in_xz = timoshenko_shape(xi, phi_z, length).deflection;
  const int xy_dofs[4] = {1, 5, 7, 11}, xz_dofs[4] = {2, 4, 8, 10};
  const double xz_signs[4] = {1, -1, 1, -1};
  for (int k = 0; k < 4; ++k) {
    local(1, xy_dofs[k]) = in_xy[k];
    local(2, xz_dofs[k]) = xz_signs[k] * in_xz[k];
  }
  // Local DOFs are T u_e (T = diag(R, R, R, R), R = axes); translations back to global by Rᵀ.
  const Eigen::Matrix3d& axes = beam.axes();
  Eigen::Matrix<double, 3, 12> global;
  for (int block = 0; block < 4; ++block)
    global.block<3, 3>(0, 3 * block) = axes.transpose() * local.block<3, 3>(0, 3 * block) * axes;
  return global;
}

}  // namespace railfe
