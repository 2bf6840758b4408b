// HHT-α with Lagrange multipliers (NewtonStepSolver::constrain): tied masses against the single
// mass they make, a prescribed motion, and the block (Schur complement) solver, through the
// factor's halves (sparse forward solves) and through full solves, against the monolithic
// UMFPACK one on rows that move every step.
#include <gtest/gtest.h>

#include <cmath>

#include "framework/solvers/saddle_point_solvers.hpp"
#include "framework/time/hht_integrator.hpp"
#include "framework/time/sparse_system.hpp"

namespace railfe {
namespace {

using Matrix = Eigen::MatrixXd;

// A SparseLinearSystem that hides its factor's halves: the block solver's full-solve path.
class WithoutHalves : public SparseLinearSystem {
 public:
  using SparseLinearSystem::SparseLinearSystem;
  bool has_triangular_factor() const override { return false; }
};

Matrix scalar(double x) {
  return Matrix::Constant(1, 1, x);
}

// Fixed rows, or a row that slides along a chain: u_vehicle − [(1−w) u_i + w u_{i+1}] = g.
class TestConstraints : public ConstraintSet {
 public:
  TestConstraints(std::size_t vehicle, double speed, std::size_t chain, double amplitude = 0)
      : vehicle_(vehicle), speed_(speed), chain_(chain), amplitude_(amplitude) {}
  void rows_at(double time, ConstraintRows& rows) override {
    const double position = std::fmod(speed_ * time, static_cast<double>(chain_ - 1));
    const std::size_t i = static_cast<std::size_t>(position);
    const double w = position - static_cast<double>(i);
    rows.start_row(amplitude_ * std::sin(5 * time));
    rows.add_entry(vehicle_, 1.0);
    rows.add_entry(i, -(1 - w));
    rows.add_entry(i + 1, -w);
  }

 private:
  std::size_t vehicle_;
  double speed_;
  std::size_t chain_;
  double amplitude_;
};

// Two masses on springs tied together move as the single mass m1 + m2 on k1 + k2: HHT-α with
// the α-weighted multiplier term reproduces the single-mass recursion exactly.
TEST(HhtConstraints, TiedMassesMoveAsOneMass) {
  const double m1 = 2, k1 = 50, m2 = 3, k2 = 30, dt = 0.01;
  auto load = [](double t, double* f) { f[0] = 10 * std::sin(3 * t); };
  const NewmarkScheme scheme = NewmarkScheme::hht(-0.1);
  LinearDenseSystem single(scalar(m1 + m2), scalar(0), scalar(k1 + k2), load);
  HhtIntegrator reference(scheme, single);
  double u = 0.1, v = 0, a = 0;
  reference.initialize(0, &u, &v, &a);

  for (int which = 0; which < 2; ++which) {
    LinearDenseSystem structure(scalar(m1), scalar(0), scalar(k1), load);
    LinearDenseSystem vehicle(scalar(m2), scalar(0), scalar(k2));
    CoupledSystem coupled(structure, vehicle);
    TestConstraints tie(1, 0.0, 2);  // u_1 − u_0 = 0
    BlockSaddlePointSolver block(coupled);
    MonolithicSaddlePointSolver monolithic(coupled);
    HhtIntegrator integrator(scheme, coupled);
    integrator.constrain(tie, which == 0 ? static_cast<SaddlePointSolver&>(block) : monolithic);
    std::vector<double> uc{0.1, 0.1}, vc{0, 0}, ac{0, 0};
    integrator.initialize(0, uc.data(), vc.data(), ac.data());
    double ur = 0.1, vr = 0, ar = 0;
    reference.initialize(0, &ur, &vr, &ar);
    EXPECT_NEAR(ac[0], ar, 1e-12);
    for (int step = 0; step < 300; ++step) {
      reference.advance(step * dt, dt, &ur, &vr, &ar);
      integrator.advance(step * dt, dt, uc.data(), vc.data(), ac.data());
      ASSERT_NEAR(uc[0], ur, 1e-12 * 0.1) << "step " << step << " solver " << which;
      ASSERT_NEAR(uc[1], ur, 1e-12 * 0.1);
      ASSERT_NEAR(ac[0], ar, 1e-9);
    }
    // The multiplier is the force in the tie: m2 a + k2 u + λ = 0 on the vehicle, up to the
    // α-weighting of the balance (first order in Δt).
    EXPECT_NEAR(integrator.multipliers()[0], -(m2 * ac[1] + k2 * uc[1]), 0.05);
  }
}

// A mass driven along u = g(t): the constraint holds at every t_{n+1} and the multiplier is the
// driving force −(m g̈ + k g) to the scheme's second order.
TEST(HhtConstraints, PrescribedMotionHoldsAndGivesTheForce) {
  const double m = 4, k = 900, amplitude = 0.01, dt = 1e-3;
  LinearDenseSystem structure(scalar(1), scalar(0), scalar(1));  // a separate dummy DOF
  LinearDenseSystem vehicle(scalar(m), scalar(0), scalar(k));
  CoupledSystem coupled(structure, vehicle);
  class Drive : public ConstraintSet {
   public:
    void rows_at(double time, ConstraintRows& rows) override {
      rows.start_row(0.01 * std::sin(5 * time));
      rows.add_entry(1, 1.0);
    }
  } drive;
  BlockSaddlePointSolver block(coupled);
  HhtIntegrator integrator(NewmarkScheme::hht(-0.05), coupled);
  integrator.constrain(drive, block);
  std::vector<double> u{0, 0}, v{0, amplitude * 5}, a{0, 0};
  integrator.initialize(0, u.data(), v.data(), a.data());
  for (int step = 0; step < 1000; ++step) {
    const double t = (step + 1) * dt;
    integrator.advance(step * dt, dt, u.data(), v.data(), a.data());
    ASSERT_NEAR(u[1], amplitude * std::sin(5 * t), 1e-15);
    const double force = -(m * -25 * amplitude * std::sin(5 * t) + k * amplitude * std::sin(5 * t));
    ASSERT_NEAR(integrator.multipliers()[0], force, 2e-3 * k * amplitude) << "t = " << t;
  }
}

// A chain of springs (sparse structure, CHOLMOD) with a vehicle point whose row slides along it:
// the block solver (factor once, Schur complement) and the monolithic one agree to round-off,
// with a vehicle of regular matrix and with a massless vehicle point (bordered path).
TEST(HhtConstraints, BlockAndMonolithicSolversAgree) {
  const int n = 12;
  std::vector<Eigen::Triplet<double>> kt, mt;
  for (int i = 0; i < n; ++i) {
    mt.emplace_back(i, i, 1.0 + 0.1 * i);
    kt.emplace_back(i, i, 2000.0 + (i == 0 || i == n - 1 ? 1000.0 : 0.0));
    if (i + 1 < n) {
      kt.emplace_back(i, i + 1, -1000.0);
      kt.emplace_back(i + 1, i, -1000.0);
    }
  }
  SparseLinearSystem::Matrix mass(n, n), stiffness(n, n);
  mass.setFromTriplets(mt.begin(), mt.end());
  stiffness.setFromTriplets(kt.begin(), kt.end());
  for (double wheel_mass : {0.5, 0.0}) {
    std::vector<std::vector<double>> histories;
    for (int which = 0; which < 3; ++which) {  // block (halves), monolithic, block (full solves)
      SparseLinearSystem halves(mass, {}, stiffness);
      WithoutHalves full(mass, {}, stiffness);
      SparseLinearSystem& structure = which == 2 ? static_cast<SparseLinearSystem&>(full) : halves;
      Matrix mv(2, 2), kv(2, 2);
      mv << wheel_mass, 0, 0, 5;
      kv << 800, -800, -800, 800;
      LinearDenseSystem vehicle(mv, Matrix::Zero(2, 2), kv, [](double, double* f) {
        f[0] = 0;
        f[1] = -49;
      });
      CoupledSystem coupled(structure, vehicle);
      TestConstraints slide(n, 7.0, n, 0.002);
      BlockSaddlePointSolver block(coupled);
      MonolithicSaddlePointSolver monolithic(coupled);
      HhtIntegrator integrator(NewmarkScheme::hht(-0.1), coupled);
      integrator.constrain(slide, which != 1 ? static_cast<SaddlePointSolver&>(block) : monolithic);
      std::vector<double> u(n + 2, 0.0), v(n + 2, 0.0), a(n + 2, 0.0), history;
      integrator.initialize(0, u.data(), v.data(), a.data());
      for (int step = 0; step < 400; ++step) {
        integrator.advance(step * 2e-3, 2e-3, u.data(), v.data(), a.data());
        history.insert(history.end(), u.begin(), u.end());
        history.push_back(integrator.multipliers()[0]);
      }
      if (which != 1) {
        EXPECT_EQ(structure.has_triangular_factor(), which == 0);
        EXPECT_EQ(coupled.structure_factorizations(), 2u);          // M for a_0, then A once
        EXPECT_LT(block.statistics().worst_backward_error, 1e-12);  // round-off: ~1e3 ε
      }
      histories.push_back(history);
    }
    for (int which : {0, 2}) {
      double scale = 0, difference = 0;
      for (std::size_t i = 0; i < histories[1].size(); ++i) {
        scale = std::max(scale, std::abs(histories[1][i]));
        difference = std::max(difference, std::abs(histories[which][i] - histories[1][i]));
      }
      EXPECT_GT(scale, 0);
      EXPECT_LT(difference, 1e-11 * scale) << "wheel mass " << wheel_mass << ", solver " << which;
    }
  }
}

// A vehicle unknown with neither mass nor stiffness (a contact node out of contact) beside
// others: Eigen's LU skips its zero pivot and its condition estimate can stay finite, so the
// block solver must see the pivot itself and take the bordered path; it then agrees with the
// monolithic solver.
TEST(HhtConstraints, BlockSolverBordersAVehicleWithAnIdleUnknown) {
  const int n = 6;
  SparseLinearSystem::Matrix mass(n, n), stiffness(n, n);
  std::vector<Eigen::Triplet<double>> mt, kt;
  for (int i = 0; i < n; ++i) {
    mt.emplace_back(i, i, 1.0);
    kt.emplace_back(i, i, 1000.0 * (i + 1));
  }
  mass.setFromTriplets(mt.begin(), mt.end());
  stiffness.setFromTriplets(kt.begin(), kt.end());
  class Ties : public ConstraintSet {
   public:
    void rows_at(double time, ConstraintRows& rows) override {
      for (int k = 0; k < 2; ++k) {  // vehicle unknowns 1 and 2 on structure unknowns 2 and 4
        rows.start_row(0.001 * std::sin(20 * time));
        rows.add_entry(n + 1 + k, 1.0);
        rows.add_entry(2 + 2 * k, -1.0);
      }
    }
  } ties;
  std::vector<double> results[2];
  for (int which = 0; which < 2; ++which) {
    SparseLinearSystem structure(mass, {}, stiffness);
    Matrix mv = Matrix::Zero(3, 3), kv = Matrix::Zero(3, 3);
    mv(0, 0) = 7;
    kv(0, 0) = kv(1, 1) = 500;
    kv(0, 1) = kv(1, 0) = -500;  // unknown 2 idle: no mass, no stiffness
    LinearDenseSystem vehicle(mv, Matrix::Zero(3, 3), kv, [](double, double* f) {
      f[0] = -70;
      f[1] = f[2] = 0;
    });
    CoupledSystem coupled(structure, vehicle);
    BlockSaddlePointSolver block(coupled);
    MonolithicSaddlePointSolver monolithic(coupled);
    HhtIntegrator integrator(NewmarkScheme::hht(-0.1), coupled);
    integrator.constrain(ties, which == 0 ? static_cast<SaddlePointSolver&>(block) : monolithic);
    std::vector<double> u(n + 3, 0.0), v(n + 3, 0.0), a(n + 3, 0.0);
    integrator.initialize(0, u.data(), v.data(), a.data());
    for (int step = 0; step < 50; ++step) {
      integrator.advance(step * 1e-3, 1e-3, u.data(), v.data(), a.data());
      results[which].insert(results[which].end(), u.begin(), u.end());
      results[which].push_back(integrator.multipliers()[0]);
    }
  }
  double scale = 0, difference = 0;
  for (std::size_t i = 0; i < results[1].size(); ++i) {
    ASSERT_TRUE(std::isfinite(results[0][i]));
    scale = std::max(scale, std::abs(results[1][i]));
    difference = std::max(difference, std::abs(results[0][i] - results[1][i]));
  }
  EXPECT_GT(scale, 0);
  EXPECT_LT(difference, 1e-11 * scale);
}

// rates_by_differences() on a row that slides along a chain while its right-hand side moves:
// ġ − Ċ u and g̈ − C̈ u − 2 Ċ v in closed form (C is linear in t inside a link, so C̈ = 0).
TEST(HhtConstraints, RatesByDifferencesOfASlidingRow) {
  const double speed = 0.3, amplitude = 0.002, time = 0.5;  // inside link 0: w = 0.15
  TestConstraints slide(4, speed, 4, amplitude);
  const double u[5] = {0.1, -0.2, 0.05, 0, 0.3}, v[5] = {1.0, 2.0, -1.0, 0, 0.5};
  double velocity = 0, acceleration = 0;
  rates_by_differences(slide, time, 1e-4, u, v, 1, &velocity, &acceleration);
  // Row: u_4 − (1 − w) u_0 − w u_1 = A sin 5t, w = speed t: Ċ = speed (e_0 − e_1).
  EXPECT_NEAR(velocity, 5 * amplitude * std::cos(5 * time) - speed * (u[0] - u[1]), 1e-9);
  EXPECT_NEAR(acceleration, -25 * amplitude * std::sin(5 * time) - 2 * speed * (v[0] - v[1]), 1e-6);
}

// A structure whose block solves are off by 1e-6 (its own check turned off, as the block solver
// permits), through the factor's halves or through full solves: the block solver's end-to-end
// check of the structure equations refuses the step.
TEST(HhtConstraints, BlockSolverCatchesAWrongStructureSolve) {
  class Sloppy : public SparseLinearSystem {
   public:
    Sloppy(Eigen::MatrixXd mass, Eigen::MatrixXd stiffness, bool halves)
        : SparseLinearSystem(mass.sparseView(), {}, stiffness.sparseView()), halves_(halves) {}
    bool has_triangular_factor() const override { return halves_; }
    void solve_columns(const double* rhs, std::size_t n_columns, double* x) override {
      SparseLinearSystem::solve_columns(rhs, n_columns, x);
      if (n_columns > 1)
        for (std::size_t i = 0; i < n_columns * n_unknowns(); ++i)
          x[i] *= 1 + 1e-6;
    }
    void forward_solve_sparse(const SparseColumns& b, ForwardSolution& w) override {
      SparseLinearSystem::forward_solve_sparse(b, w);
      w.values *= 1 + 1e-6;
    }

   private:
    bool halves_;
  };
  class TwoRows : public ConstraintSet {
   public:
    void rows_at(double, ConstraintRows& rows) override {
      for (std::size_t i = 0; i < 2; ++i) {
        rows.start_row(0.01);
        rows.add_entry(2, 1.0);
        rows.add_entry(i, -1.0 - static_cast<double>(i));
      }
    }
  };
  for (bool halves : {true, false}) {
    Sloppy structure(Matrix::Identity(2, 2), 100 * Matrix::Identity(2, 2), halves);
    structure.check_solutions(false);
    LinearDenseSystem vehicle(scalar(1), scalar(0), scalar(50));
    CoupledSystem coupled(structure, vehicle);
    TwoRows rows;
    BlockSaddlePointSolver block(coupled);
    HhtIntegrator integrator(NewmarkScheme::hht(0), coupled);
    integrator.constrain(rows, block);
    std::vector<double> u(3, 0.0), v(3, 0.0), a(3, 0.0);
    integrator.initialize(0, u.data(), v.data(), a.data());  // at rest: μ = 0, nothing to see
    try {
      integrator.advance(0, 1e-3, u.data(), v.data(), a.data());  // g = 0.01 pulls: μ ≠ 0
      FAIL() << "expected the end-to-end check to fail, halves " << halves;
    } catch (const RunError& e) {
      EXPECT_NE(std::string(e.what()).find("structure equations"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace railfe
