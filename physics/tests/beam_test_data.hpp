#pragma once
// Material and geometry shared by the beam tests: steel, and an inclined beam whose local axes
// are not the global ones, so that every test also exercises the rotation to global axes.
#include <Eigen/Dense>

#include "physics/elements/beam_element.hpp"

namespace railfe::test {

inline constexpr double kYoung = 210e9, kPoisson = 0.3, kDensity = 7850;

inline BeamMaterial steel() {
  return isotropic_beam_material(kYoung, kPoisson, kDensity);
}

// Start, unit direction and orientation vector of the inclined beam.
inline Eigen::Vector3d inclined_start() {
  return {0.3, -0.2, 0.5};
}
inline Eigen::Vector3d inclined_direction() {
  return Eigen::Vector3d(1, 2, -0.5).normalized();
}
inline Eigen::Vector3d inclined_orientation() {
  return {0.2, -0.1, 1};
}

}  // namespace railfe::test
