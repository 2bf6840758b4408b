// Natural frequencies of beams assembled from BeamElement against closed forms: simply
// supported and cantilever Euler–Bernoulli beams (bending), a cantilever in torsion, and a stocky
// simply supported Timoshenko beam (Timoshenko's frequency equation), with consistent and lumped
// mass, on meshes of 5, 10, 20 and 40 elements. The documented meshes, where the first three
// modes are within 0.5 %: 20 elements for bending with consistent mass, 40 for lumped mass and
// for torsion (linear interpolation). The consistent mass converges from above (a Rayleigh–Ritz
// bound); the lumped one from below for the Euler–Bernoulli beam and for torsion (observed, not a
// bound: the stocky Timoshenko beam's first mode comes from above). Also: an inclined free–free
// beam has the spectrum of the same beam along x, with six rigid-body modes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "physics/tests/beam_line_model.hpp"
#include "physics/tests/beam_test_data.hpp"

namespace railfe {
namespace {

using test::steel;

constexpr double kPi = 3.14159265358979323846;
constexpr int kModes = 3;
const std::vector<int> kMeshes{5, 10, 20, 40};

// A beam along x from 0 to \p length, local y = global y (so local axes are the global ones).
struct StraightBeam {
  double length;
  BeamSection section;
  bool rotary_inertia;
  std::vector<int> components;                   // the DOFs kept at every node
  std::function<std::vector<int>(int n)> fixed;  // the DOFs held at n elements
  int documented_consistent = 20;                // the mesh within 0.5 % with consistent mass
  int documented_lumped = 40;                    // and with lumped mass
  bool lumped_from_below = true;  // whether the lumped mass's error is checked to be negative
};

// Frequencies of the first kModes modes at \p n elements.
Eigen::VectorXd frequencies(const StraightBeam& beam, int n, BeamMass kind) {
  const test::LineModel model =
      test::assemble_line(n, {0, 0, 0}, {beam.length, 0, 0}, {0, 1, 0}, steel(), beam.section, kind,
                          beam.rotary_inertia);
  return test::natural_frequencies(model, test::kept_dofs(n, beam.components, beam.fixed(n)))
      .head(kModes);
}

// Relative errors on every mesh against \p exact (Hz), printed; checks the documented mesh's
// accuracy, the direction of convergence and that the error falls with refinement.
void check_convergence(const char* name, const StraightBeam& beam,
                       const std::vector<double>& exact) {
  for (BeamMass kind : {BeamMass::consistent, BeamMass::lumped}) {
    const bool consistent = kind == BeamMass::consistent;
    std::vector<double> previous(kModes, 1e300);
    for (int n : kMeshes) {
      const Eigen::VectorXd f = frequencies(beam, n, kind);
      for (int k = 0; k < kModes; ++k) {
        const double error = f(k) / exact[k] - 1;
        std::printf("%-28s %-10s n %2d mode %d: %12.6f Hz, exact %12.6f Hz, error %+.4f %%\n", name,
                    consistent ? "consistent" : "lumped", n, k + 1, f(k), exact[k], 100 * error);
        if (consistent) {
          EXPECT_GT(error, -1e-9) << name << " n " << n << " mode " << k + 1;
        } else if (beam.lumped_from_below) {
          EXPECT_LT(error, 1e-9) << name << " n " << n << " mode " << k + 1;
        }
        EXPECT_LT(std::abs(error), previous[k]) << name << " n " << n << " mode " << k + 1;
        previous[k] = std::abs(error);
        if (n == (consistent ? beam.documented_consistent : beam.documented_lumped)) {
          EXPECT_LT(std::abs(error), 0.005) << name << " n " << n << " mode " << k + 1;
        }
      }
    }
  }
}

// The ends' DOFs \p components of nodes 0 and n (n < 0: node 0 only).
std::function<std::vector<int>(int)> held(std::vector<int> components, bool both_ends) {
  return [components, both_ends](int n) {
    std::vector<int> dofs;
    for (int c : components) {
      dofs.push_back(c);
      if (both_ends)
        dofs.push_back(6 * n + c);
    }
    return dofs;
  };
}

// Root of f on [a, b] (a sign change) by bisection.
double bisect(const std::function<double(double)>& f, double a, double b) {
  for (int i = 0; i < 200; ++i) {
    const double m = (a + b) / 2;
    (f(a) * f(m) <= 0 ? b : a) = m;
  }
  return (a + b) / 2;
}

const double kRho = test::kDensity, kE = test::kYoung;

TEST(BeamFrequencies, SimplySupportedEulerBernoulli) {
  // Bending in the x–z plane (u_z, θ_y), u_z held at both ends: f_k = (kπ/L)² √(EI/ρA) / 2π.
  const StraightBeam beam{4.0,
                          euler_bernoulli(rectangle_section(0.05, 0.1, test::kPoisson)),
                          false,
                          {2, 4},
                          held({2}, true)};
  std::vector<double> exact;
  for (int k = 1; k <= kModes; ++k)
    exact.push_back(std::pow(k * kPi / beam.length, 2) *
                    std::sqrt(kE * beam.section.iy / (kRho * beam.section.area)) / (2 * kPi));
  check_convergence("simply supported (EB)", beam, exact);
}

TEST(BeamFrequencies, CantileverEulerBernoulli) {
  // Bending in the x–y plane (u_y, θ_z), clamped at x = 0: β_k L the roots of cos β cosh β = −1.
  const StraightBeam beam{2.5,
                          euler_bernoulli(rectangle_section(0.08, 0.05, test::kPoisson)),
                          false,
                          {1, 5},
                          held({1, 5}, false)};
  std::vector<double> exact;
  for (int k = 1; k <= kModes; ++k) {
    const double beta =
        bisect([](double x) { return std::cos(x) * std::cosh(x) + 1; }, (k - 1) * kPi, k * kPi);
    exact.push_back(std::pow(beta / beam.length, 2) *
                    std::sqrt(kE * beam.section.iz / (kRho * beam.section.area)) / (2 * kPi));
  }
  EXPECT_NEAR(exact[0] / (std::pow(1.8751040687 / beam.length, 2) *
                          std::sqrt(kE * beam.section.iz / (kRho * beam.section.area)) / (2 * kPi)),
              1, 1e-9);  // the tabulated first root
  check_convergence("cantilever (EB)", beam, exact);
}

TEST(BeamFrequencies, CantileverTorsion) {
  // θ_x clamped at x = 0, circular section (J = I_p): f_k = (2k − 1)/(4L) √(G J / (ρ I_p)).
  const StraightBeam beam{3.0, circle_section(0.1, test::kPoisson), true, {3}, held({3}, false), 40,
                          40};
  const double ip = beam.section.iy + beam.section.iz;
  std::vector<double> exact;
  for (int k = 1; k <= kModes; ++k)
    exact.push_back((2 * k - 1) / (4 * beam.length) *
                    std::sqrt(steel().shear_modulus * beam.section.torsion / (kRho * ip)));
  check_convergence("cantilever torsion", beam, exact);
}

// Lower root ω² of Timoshenko's frequency equation for a simply supported beam, wavenumber k:
// (κGA k² − ρAω²)(EI k² + κGA − ρIω²) − (κGA k)² = 0.
double timoshenko_omega2(double k, double EI, double kGA, double rhoA, double rhoI) {
  const double a = rhoA * rhoI, b = rhoA * (EI * k * k + kGA) + rhoI * kGA * k * k;
  const double c = kGA * EI * k * k * k * k;
  return 2 * c / (b + std::sqrt(b * b - 4 * a * c));
}

TEST(BeamFrequencies, SimplySupportedTimoshenko) {
  // A stocky beam (L/h = 6), bending in x–z with shear (Cowper's κ) and rotary inertia.
  const BeamSection section = rectangle_section(0.1, 0.3, test::kPoisson);
  const StraightBeam beam{1.8, section, true, {2, 4}, held({2}, true), 20, 40, false};
  std::vector<double> exact;
  for (int k = 1; k <= kModes; ++k) {
    const double omega2 = timoshenko_omega2(k * kPi / beam.length, kE * section.iy,
                                            steel().shear_modulus * section.shear_area_z,
                                            kRho * section.area, kRho * section.iy);
    exact.push_back(std::sqrt(omega2) / (2 * kPi));
    // Shear and rotary inertia matter here: Euler–Bernoulli would be off by far more than 0.5 %.
    const double eb = std::pow(k * kPi / beam.length, 2) *
                      std::sqrt(kE * section.iy / (kRho * section.area)) / (2 * kPi);
    std::printf("Timoshenko mode %d: %.6f Hz, Euler-Bernoulli %.6f Hz (%+.2f %%)\n", k,
                exact.back(), eb, 100 * (eb / exact.back() - 1));
    EXPECT_GT(eb / exact.back() - 1, 0.02);
  }
  check_convergence("simply supported (Timoshenko)", beam, exact);
}

TEST(BeamFrequencies, InclinedFreeBeamHasTheSpectrumOfTheBeamAlongX) {
  const BeamSection section = rectangle_section(0.06, 0.15, test::kPoisson);
  const double L = 2.0;
  const int n = 8;
  const std::vector<int> all = test::kept_dofs(n, {0, 1, 2, 3, 4, 5}, {});
  for (BeamMass kind : {BeamMass::consistent, BeamMass::lumped}) {
    const Eigen::VectorXd along_x = test::natural_frequencies(
        test::assemble_line(n, {0, 0, 0}, {L, 0, 0}, {0, 1, 0}, steel(), section, kind), all);
    const Eigen::VectorXd inclined = test::natural_frequencies(
        test::assemble_line(n, test::inclined_start(),
                            test::inclined_start() + L * test::inclined_direction(),
                            test::inclined_orientation(), steel(), section, kind),
        all);
    for (int i = 0; i < 6; ++i)
      EXPECT_LT(inclined(i), 1e-5 * inclined(6)) << "rigid-body mode " << i;
    EXPECT_GT(inclined(6), 1);
    for (int i = 6; i < inclined.size(); ++i)
      EXPECT_NEAR(inclined(i) / along_x(i), 1, 1e-9) << "mode " << i;
  }
}

}  // namespace
}  // namespace railfe
