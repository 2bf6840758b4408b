#pragma once
/// \file
/// Small second-order systems on dense Eigen matrices: a base that supplies factor() and solve()
/// (LU with partial pivoting) from a tangent the derived class writes, and a linear system
/// M a + C v + K u = f(t). For tests, studies and models of a few hundred unknowns; a module with
/// a distributed mesh implements SecondOrderSystem over its Tpetra objects instead.

#include <Eigen/Dense>

#include <functional>

#include "framework/time/second_order_system.hpp"

namespace railfe {

/// A SecondOrderSystem with a constant dense mass matrix and a dense tangent.
class DenseSecondOrderSystem : public SecondOrderSystem {
 public:
  /// A system with mass matrix \p mass (square, regular for the initial acceleration).
  explicit DenseSecondOrderSystem(Eigen::MatrixXd mass);

  /// The number of rows of M.
  std::size_t n_unknowns() const override { return static_cast<std::size_t>(mass_.rows()); }
  /// y = M x.
  void apply_mass(const double* x, double* y) override;
  /// y = K_R x with the matrix given to set_rayleigh_stiffness().
  void apply_rayleigh_stiffness(const double* x, double* y) override;
  /// Forms A from M, tangent() at (u, v) and K_R without factoring it (matrix() then holds it):
  /// for block solvers that border A with constraint rows, where A alone may be singular. A
  /// system whose tangent is mostly constant may form A faster itself (write it to
  /// matrix_to_form()).
  virtual void form_matrix(const double* u, const double* v,
                           const MatrixCoefficients& coefficients);
  /// Forms A (form_matrix()) and LU-factors it; throws RunError when A is singular to working
  /// precision.
  void factor(const double* u, const double* v, const MatrixCoefficients& coefficients) override;
  /// x = A⁻¹ rhs.
  void solve(const double* rhs, double* x) override;
  /// The nonzero entries of the A of the last factor().
  void matrix_entries(std::vector<MatrixEntry>& entries) const override;
  /// The A of the last factor() call (n × n).
  const Eigen::MatrixXd& matrix() const { return matrix_; }

  /// Writes K_t = ∂f_int/∂u and C_t = ∂f_int/∂v at (u, v); both come in sized n × n.
  virtual void tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
                       Eigen::MatrixXd& damping) = 0;
  /// Sets K_R, the stiffness of Rayleigh damping (n × n).
  void set_rayleigh_stiffness(Eigen::MatrixXd stiffness) { rayleigh_ = std::move(stiffness); }
  /// The mass matrix.
  const Eigen::MatrixXd& mass() const { return mass_; }

 protected:
  /// The A that form_matrix() writes (sized n × n by the caller).
  Eigen::MatrixXd& matrix_to_form() { return matrix_; }

 private:
  Eigen::MatrixXd mass_, rayleigh_, tangent_stiffness_, tangent_damping_, matrix_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

/// M a + C v + K u = f(t) with constant matrices; K is also the Rayleigh stiffness K_R.
class LinearDenseSystem : public DenseSecondOrderSystem {
 public:
  /// The system with mass \p mass, damping \p damping, stiffness \p stiffness and load \p load
  /// (writes f(t) to its second argument; empty: no load).
  LinearDenseSystem(Eigen::MatrixXd mass, Eigen::MatrixXd damping, Eigen::MatrixXd stiffness,
                    std::function<void(double, double*)> load = {});

  /// True: factor once per step size.
  bool is_linear() const override { return true; }
  /// K u + C v.
  void internal_force(const double* u, const double* v, double* force) override;
  /// f(t), or zero.
  void external_force(double time, double* force) override;
  /// K and C.
  void tangent(const double* u, const double* v, Eigen::MatrixXd& stiffness,
               Eigen::MatrixXd& damping) override;

 private:
  Eigen::MatrixXd damping_, stiffness_;
  std::function<void(double, double*)> load_;
};

}  // namespace railfe
