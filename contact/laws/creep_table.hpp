#pragma once
/// \file
/// A creep-force table in the role of Kalker's USETAB: forces of the exact steady-rolling solver
/// tabulated once over the semi-axis ratio and three normalized creepages, then interpolated.
/// By similarity (Hertzian patch, quasi-identical bodies, Coulomb friction), the forces over μN
/// and the moment over μNa depend only on a/b, Poisson's ratio and
///   s_ξ = ξ G / (μ p0),  s_η = η G / (μ p0),  s_φ = φ a G / (μ p0).
/// Each creepage axis is tabulated in t = s / (1 + |s|), so a finite table spans all creepages
/// (beyond its last node the forces are those of the last node: saturated). Linear in ln(a/b),
/// cubic (Catmull-Rom) in t_ξ, t_η and t_φ.

#include <array>
#include <string>
#include <vector>

#include "contact/laws/kalker_linear.hpp"

namespace railfe {

/// The table's nodes.
struct CreepTableAxes {
  std::vector<double> ratios;  ///< a/b, increasing
  std::vector<double> t;       ///< creepage nodes in t = s / (1 + |s|), increasing, symmetric
  double poisson = 0.3;        ///< Poisson's ratio the table was made for
  int grid = 30;               ///< exact solver's elements per side
};

/// A creep-force table.
class CreepTable {
 public:
  /// Reads \p path (written by write()). Throws InputError naming the file when it is missing
  /// or malformed.
  explicit CreepTable(const std::string& path);
  /// The table shipped in inputs/kalker (ν = 0.3).
  static const CreepTable& shipped();
  /// Builds the table by running the exact solver at every node (slow: minutes), reporting
  /// progress through \p progress (done, total) when given.
  static void build(const CreepTableAxes& axes, const std::string& path,
                    void (*progress)(int, int) = nullptr);
  /// Forces for semi-axes \p a × \p b, combined shear modulus \p G, Poisson's ratio \p nu (must
  /// be the table's), normal force \p load, friction \p friction and creepages \p creep. Throws
  /// std::invalid_argument outside the table's ratios or at another Poisson's ratio.
  CreepForces forces(double a, double b, double G, double nu, double load, double friction,
                     const Creepages& creep) const;
  /// The table's nodes.
  const CreepTableAxes& axes() const { return axes_; }

 private:
  CreepTableAxes axes_;
  std::vector<double> log_ratios_;
  // [ratio][tx][ty][tphi][3]: Fx / μN, Fy / μN, Mz / (μN a).
  std::vector<double> values_;
  std::size_t index(std::size_t r, std::size_t i, std::size_t j, std::size_t k) const;
};

}  // namespace railfe
