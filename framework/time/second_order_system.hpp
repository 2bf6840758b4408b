#pragma once
/// \file
/// What an implicit module hands the HHT-α Newton solver (framework/time/newton_step.hpp): the
/// semi-discrete system M a + f_int(u, v) = f_ext(t), with its consistent tangent and a linear
/// solve. Arrays are the rank's owned unknowns (length n_unknowns()); a distributed system
/// gathers ghost values itself and sums dot products over ranks, so the integrator never sees
/// Tpetra. A small system can derive from DenseSecondOrderSystem (framework/time/dense_system.hpp)
/// instead of writing factor() and solve().

#include <cstddef>
#include <vector>

namespace railfe {

/// The matrix a Newton iteration solves with:
/// A = mass·M + damping·C_t(u, v) + stiffness·K_t(u, v) + rayleigh_stiffness·K_R, where
/// C_t = ∂f_int/∂v, K_t = ∂f_int/∂u and K_R is the constant stiffness of Rayleigh damping.
struct MatrixCoefficients {
  double mass = 0;       ///< coefficient of M
  double damping = 0;    ///< coefficient of the tangent damping C_t
  double stiffness = 0;  ///< coefficient of the tangent stiffness K_t
  double rayleigh_stiffness =
      0;  ///< coefficient of K_R (zero without stiffness-proportional damping)
};

/// Whether \p a and \p b are the same coefficients (a factorization made for one serves both).
inline bool same_coefficients(const MatrixCoefficients& a, const MatrixCoefficients& b) {
  return a.mass == b.mass && a.damping == b.damping && a.stiffness == b.stiffness &&
         a.rayleigh_stiffness == b.rayleigh_stiffness;
}

/// One entry of a sparse matrix, for solvers that assemble the whole saddle-point matrix.
struct MatrixEntry {
  std::size_t row = 0;     ///< row (unknown index)
  std::size_t column = 0;  ///< column (unknown index)
  double value = 0;        ///< value (entries at the same place add up)
};

/// A second-order system M a + f_int(u, v) = f_ext(t), seen through the operations an implicit
/// integrator needs. Rayleigh damping C_R = a M + b K_R is added by the integrator (its force
/// a M v + b K_R v and its share of the matrix); f_int holds only the system's own forces
/// (elastic, contact, discrete dampers).
class SecondOrderSystem {
 public:
  virtual ~SecondOrderSystem() = default;

  /// Number of unknowns this rank owns: the length of every array passed in and out.
  virtual std::size_t n_unknowns() const = 0;
  /// Whether M, C_t and K_t are constant and f_int = K u + C v. The integrator then factors A
  /// once per step size and takes one solve per step, with no Newton iteration.
  virtual bool is_linear() const { return false; }
  /// Writes f_int(u, v) to \p force.
  virtual void internal_force(const double* u, const double* v, double* force) = 0;
  /// Writes f_ext(\p time) to \p force.
  virtual void external_force(double time, double* force) = 0;
  /// y = M x.
  virtual void apply_mass(const double* x, double* y) = 0;
  /// y = K_R x, the constant stiffness of Rayleigh damping. Only called when the stiffness
  /// coefficient b ≠ 0; the default throws std::logic_error.
  virtual void apply_rayleigh_stiffness(const double* x, double* y);
  /// Assembles A (see MatrixCoefficients) with C_t and K_t at (\p u, \p v) and factors it (or
  /// builds its preconditioner) for the solve() calls that follow. Throws RunError when A is
  /// singular.
  virtual void factor(const double* u, const double* v, const MatrixCoefficients& coefficients) = 0;
  /// Solves A x = \p rhs with the A of the last factor() call.
  virtual void solve(const double* rhs, double* x) = 0;
  /// Solves A X = B for \p n_columns right-hand sides stored one column after another (each of
  /// length n_unknowns()). The default calls solve() per column; a system whose linear solver
  /// passes over its factor once for a block (LinearSolver::solve_block) overrides it.
  virtual void solve_columns(const double* rhs, std::size_t n_columns, double* x);
  /// y = A x with the A of the last factor() call, for solvers that check a coupled solution
  /// end to end. Returns false (the default) when the system cannot.
  virtual bool apply_matrix(const double* x, double* y);
  /// Appends the entries of the A of the last factor() call to \p entries (for a monolithic
  /// saddle-point solve). The default throws std::logic_error.
  virtual void matrix_entries(std::vector<MatrixEntry>& entries) const;
  /// Σ x_i y_i over every rank's owned unknowns. The default sums this rank's only (serial).
  virtual double dot(const double* x, const double* y) const;
};

}  // namespace railfe
