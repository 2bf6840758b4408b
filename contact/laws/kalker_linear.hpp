#pragma once
/// \file
/// Kalker's linear theory of rolling contact: creep forces proportional to the creepages through
/// the coefficients C11, C22, C23 and C33 of Kalker (1990), Table E.3, interpolated in the
/// semi-axis ratio (shape-preserving cubic in ln(a/b), through every table point) and in
/// Poisson's ratio (quadratic through 0, 0.25 and 0.5). Sign convention: forces on the wheel
/// (body 1) oppose its creepage, Fx = -G c² C11 ξ with c = √(ab).

#include <array>
#include <string>
#include <vector>

namespace railfe {

/// Longitudinal, lateral and spin creepage of a contact: relative velocity of body 1 against
/// body 2 at the contact point divided by the rolling speed.
struct Creepages {
  double longitudinal = 0;  ///< ξ (1)
  double lateral = 0;       ///< η (1)
  double spin = 0;          ///< φ (1/m)
};

/// Creepages from the bodies' velocities at the contact point (m/s, x rolling, y lateral, in the
/// contact plane), their angular velocities about the contact normal (rad/s) and the rolling
/// speed \p speed (m/s > 0).
Creepages creepages(const std::array<double, 2>& velocity_1,
                    const std::array<double, 2>& velocity_2, double normal_spin_1,
                    double normal_spin_2, double speed);

/// Tangential forces and spin moment on body 1.
struct CreepForces {
  double Fx = 0;  ///< N
  double Fy = 0;  ///< N
  double Mz = 0;  ///< N m
};

/// Kalker's four coefficients at one semi-axis ratio and Poisson's ratio.
struct KalkerCoefficients {
  double C11 = 0, C22 = 0, C23 = 0, C33 = 0;  ///< dimensionless
};

/// Kalker's table, interpolated.
class KalkerTable {
 public:
  /// Reads \p path (the CSV layout of inputs/kalker/kalker_cij.csv). Throws InputError naming
  /// the file and line when it is missing or malformed.
  explicit KalkerTable(const std::string& path);
  /// The table shipped in inputs/kalker.
  static const KalkerTable& shipped();
  /// Coefficients at semi-axes \p a (rolling) and \p b (lateral) and Poisson's ratio \p nu.
  /// Throws std::invalid_argument outside the table (a/b from 0.1 to 10, ν from 0 to 0.5).
  KalkerCoefficients at(double a, double b, double nu) const;

 private:
  std::vector<double> log_ratio_;                             // ln(a/b), increasing
  std::array<std::array<std::vector<double>, 3>, 4> values_;  // [coefficient][nu][point]
  std::array<std::array<std::vector<double>, 3>, 4> slopes_;  // shape-preserving slopes
};

/// Kalker's linear creep forces for a contact ellipse \p a × \p b, combined shear modulus \p G
/// and creepages \p creep.
CreepForces kalker_linear(const KalkerCoefficients& c, double G, double a, double b,
                          const Creepages& creep);

/// The constant damping matrix D of the linear theory: (Fx, Fy, Mz) = -D (Δv_x, Δv_y, Δω_z) for
/// relative velocities at rolling speed \p speed. Row-major 3 × 3.
std::array<double, 9> kalker_damping(const KalkerCoefficients& c, double G, double a, double b,
                                     double speed);

}  // namespace railfe
