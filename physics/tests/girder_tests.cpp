// The girders a vehicle crosses (RailBeams' GirderLayout) against closed forms of beam theory:
// a simply supported span under a midspan load (P L³ / 48 EI), its first bending frequencies
// (Rayleigh beam), a two-span continuous girder loaded at the middle of one span
// (23 P L³ / 1536 EI), and the ties to rigid track off the structure.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

#include "physics/wheelset_dynamics/rail_beams.hpp"

namespace railfe {
namespace {

constexpr double kPi = 3.14159265358979323846;

GirderLayout girder(int spans, double pier_stiffness) {
  GirderLayout layout;
  layout.material = isotropic_beam_material(3.1e10, 0.2, 12000.0 / 4.0);
  layout.section.area = 4.0;
  layout.section.iy = 2.5;   // vertical bending
  layout.section.iz = 15.0;  // lateral bending
  layout.section.torsion = 5.0;
  layout.section.shear_area_y = layout.section.shear_area_z =
      std::numeric_limits<double>::infinity();
  layout.start = 100;
  layout.span = 20;
  layout.spans = spans;
  layout.elements_per_span = 16;
  layout.bearing_stiffness = {pier_stiffness, pier_stiffness, pier_stiffness, pier_stiffness};
  return layout;
}

// The static displacement along global direction \p d (1 lateral, 2 vertical) at track
// position \p s under a load \p P there, along d.
double deflection(const RailBeams& girders, double s, int d, double P) {
  const BeamPath& path = girders.path(TrackSide::right);
  std::size_t element;
  double xi;
  EXPECT_TRUE(path.locate(s - girders.origin(), element, xi));
  const PathElement& piece = path.element(element);
  // A node at s: take the element's end a (xi 0) or b (xi 1).
  const long unknown = piece.unknowns[(xi > 0.5 ? 6 : 0) + d];
  Eigen::VectorXd load = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(girders.n_unknowns()));
  load[unknown] = P;
  const Eigen::MatrixXd K(girders.stiffness());
  const Eigen::VectorXd u = K.ldlt().solve(load);
  return u[unknown];
}

TEST(Girders, SimplySupportedSpanDeflectsAsBeamTheoryUnderAMidspanLoad) {
  const RailBeams girders(girder(1, 1e9), 1.5);
  const double P = 1e5, L = 20, E = 3.1e10;
  EXPECT_NEAR(deflection(girders, 110, 2, P), P * L * L * L / (48 * E * 2.5),
              1e-9 * P * L * L * L / (48 * E * 2.5));
  EXPECT_NEAR(deflection(girders, 110, 1, P), P * L * L * L / (48 * E * 15.0),
              1e-9 * P * L * L * L / (48 * E * 15.0));
}

TEST(Girders, FirstVerticalBendingFrequencyOfASpan) {
  const RailBeams girders(girder(1, 1e9), 1.5);
  const Eigen::MatrixXd K(girders.stiffness()), M(girders.mass());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K, M);
  ASSERT_EQ(modes.info(), Eigen::Success);
  // A simply supported Rayleigh beam (the consistent mass carries rotary inertia, which a
  // section this deep feels): ω = (π/L)² √(EI/m) / √(1 + (I/A)(π/L)²), for vertical (I = 2.5)
  // and lateral (I = 15) bending, the span's two lowest modes.
  const double m = 12000, L = 20, E = 3.1e10, A = 4, k2 = std::pow(kPi / L, 2);
  const double vertical = k2 * std::sqrt(E * 2.5 / m) / std::sqrt(1 + 2.5 / A * k2);
  const double lateral = k2 * std::sqrt(E * 15.0 / m) / std::sqrt(1 + 15.0 / A * k2);
  const auto omega = modes.eigenvalues().cwiseSqrt();
  EXPECT_NEAR(omega[0], vertical, 1e-4 * vertical);  // 16 elements
  EXPECT_NEAR(omega[1], lateral, 1e-4 * lateral);
}

TEST(Girders, TwoSpanContinuousGirderOnStiffPiers) {
  const RailBeams girders(girder(2, 1e16), 1.5);
  const double P = 1e5, L = 20, E = 3.1e10;
  const double expected = 23 * P * L * L * L / (1536 * E * 2.5);
  EXPECT_NEAR(deflection(girders, 110, 2, P), expected, 1e-6 * expected);
}

TEST(Girders, WheelsetOffTheStructureIsTiedToRigidTrack) {
  const RailBeams girders(girder(2, 1e9), 1.5);
  EXPECT_TRUE(girders.rigid_beyond());
  // A wheelset 10 m before the structure and one on it (s = 110 at t = 0).
  BeamRails rails(girders, girders.n_unknowns(), {}, [](double) { return 0.001; }, 90, 0,
                  {{0, 6}, {20, 6 + 12 + 6}});
  ConstraintRows rows;
  rails.rows_at(0, rows);
  ASSERT_EQ(rows.size(), 2u * 12u);
  for (std::size_t r = 0; r < 12; ++r) {
    EXPECT_EQ(rows.offsets[r + 1] - rows.offsets[r], 1u);  // the internal node alone
    EXPECT_GE(rows.columns[rows.offsets[r]], girders.n_unknowns());
  }
  EXPECT_DOUBLE_EQ(rows.rhs[2], 0.001);  // the vertical irregularity
  for (std::size_t r = 12; r < 24; ++r)
    EXPECT_GT(rows.offsets[r + 1] - rows.offsets[r], 1u);  // tied to the girder
  EXPECT_THROW(RailBeams(girder(0, 1e9), 1.5), std::invalid_argument);
}

}  // namespace
}  // namespace railfe
