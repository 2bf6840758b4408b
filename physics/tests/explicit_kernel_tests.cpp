// The explicit hex8 kernel against what must hold for any element: the patch test on a distorted
// mesh (interior forces cancel, stresses exact), objectivity (a rotated state has rotated stress
// and the same energies), hourglass vectors blind to linear fields, the stable step of a cube;
// plus the event measurements and the checkpoint file format.
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "framework/base/error.hpp"
#include "framework/mesh/box_generator.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/elements/hex8_one_point.hpp"
#include "physics/explicit/checkpoint.hpp"
#include "physics/explicit/convected_start.hpp"
#include "physics/explicit/explicit_output.hpp"
#include "physics/explicit/explicit_solver.hpp"
#include "physics/explicit/lanczos.hpp"
#include "physics/explicit/solid_kernel.hpp"
#include "physics/materials/elastic_material.hpp"

namespace railfe {
namespace {

constexpr double kYoung = 210e9, kPoisson = 0.3, kDensity = 7850;

// A 2 x 2 x 2 box with its centre node moved off the grid (a distorted patch), on one rank.
struct Patch {
  Communicator comm{MPI_COMM_SELF};
  Mesh mesh;
  std::unique_ptr<MeshPartition> partition;
  std::unique_ptr<MaterialTable> materials;
  std::vector<double> x;  // local node coordinates
  GlobalIndex centre = 13;

  /// \p counts elements of 0.1 m along x, y, z; \p jitter moves every node by up to that much
  /// along each axis (a smooth pseudo-random pattern), on top of the centre node's move.
  explicit Patch(bool distort = true, std::array<int, 3> counts = {2, 2, 2}, double jitter = 0) {
    BoxSpec spec;
    spec.elements = counts;
    spec.lengths = {0.1 * counts[0], 0.1 * counts[1], 0.1 * counts[2]};
    mesh = generate_box(spec);
    if (distort) {
      mesh.coordinates[3 * centre] += 0.013;
      mesh.coordinates[3 * centre + 1] -= 0.021;
      mesh.coordinates[3 * centre + 2] += 0.008;
    }
    for (std::size_t k = 0; k < mesh.coordinates.size(); ++k)
      mesh.coordinates[k] += jitter * std::sin(2.3 * static_cast<double>(k) + 0.4);
    partition = std::make_unique<MeshPartition>(mesh, comm, PartitionMethod::block);
    Teuchos::ParameterList list;
    auto& steel = list.sublist("steel");
    steel.set("Young's modulus", kYoung);
    steel.set("Poisson's ratio", kPoisson);
    steel.set("Density", kDensity);
    steel.set("Blocks", Teuchos::Array<std::string>(1, "block_1"));
    materials = std::make_unique<MaterialTable>(list, mesh, "test");
    for (LocalIndex node = 0; node < partition->n_local_nodes(); ++node)
      x.insert(x.end(), partition->coordinates(node), partition->coordinates(node) + 3);
  }
  std::size_t n_values() const { return x.size(); }
};

// Kernel settings without bulk viscosity: elastic and hourglass forces only.
SolidKernelSettings elastic_settings() {
  SolidKernelSettings settings;
  settings.bulk_linear = settings.bulk_quadratic = 0;
  return settings;
}

Eigen::Matrix3d rotation() {
  return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
}

TEST(ExplicitKernel, OnePointPatchTestOnDistortedMesh) {
  for (const bool batched : {true, false}) {
    Patch patch;
    SolidKernelSettings settings = elastic_settings();
    settings.batched = batched;
    const SolidElements elements =
        build_solid_elements(*patch.partition, *patch.materials, settings);
    // A homogeneous deformation u = A X: every element has F = I + A exactly.
    Eigen::Matrix3d A;
    A << 1e-3, 2e-4, -3e-4, 5e-4, -7e-4, 1e-4, 2e-4, 3e-4, 6e-4;
    std::vector<double> u(patch.n_values()), v(patch.n_values(), 0.0), f(patch.n_values(), 0.0);
    for (std::size_t n = 0; n < u.size() / 3; ++n) {
      const Eigen::Vector3d X(patch.x[3 * n], patch.x[3 * n + 1], patch.x[3 * n + 2]);
      const Eigen::Vector3d displacement = A * X;
      for (int d = 0; d < 3; ++d)
        u[3 * n + d] = displacement[d];
    }
    const SolidForceTotals totals =
        add_internal_forces(elements, settings, patch.x.data(), u.data(), v.data(), f.data());
    // The interior node's forces cancel (the patch test) and no hourglass energy appears.
    const LocalIndex centre = patch.partition->local_node(patch.centre);
    const double scale = std::abs(f[0]) + std::abs(f[1]) + std::abs(f[2]);
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(f[3 * centre + d], 0.0, 1e-12 * scale) << (batched ? "batched" : "scalar");
    EXPECT_NEAR(totals.hourglass_energy, 0.0, 1e-20);
    // Stress and energy are the St. Venant-Kirchhoff values of F = I + A.
    const Eigen::Matrix3d F = Eigen::Matrix3d::Identity() + A;
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    const double lambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson));
    const double mu = kYoung / (2 * (1 + kPoisson));
    const Eigen::Matrix3d S = lambda * E.trace() * Eigen::Matrix3d::Identity() + 2 * mu * E;
    const Eigen::Matrix3d sigma = F * S * F.transpose() / F.determinant();
    const double energy_density = 0.5 * lambda * std::pow(E.trace(), 2) + mu * E.squaredNorm();
    EXPECT_NEAR(totals.strain_energy, energy_density * 0.008, 1e-10 * energy_density * 0.008);
    for (LocalIndex e = 0; e < elements.n_elements; ++e) {
      double stress[6];
      element_cauchy_stress(elements, e, u.data(), stress);
      EXPECT_NEAR(stress[0], sigma(0, 0), 1e-9 * std::abs(sigma(0, 0)));
      EXPECT_NEAR(stress[3], sigma(0, 1), 1e-9 * std::abs(sigma(0, 0)));
      EXPECT_NEAR(stress[5], sigma(2, 0), 1e-9 * std::abs(sigma(0, 0)));
    }
  }
}

// The statics one-point stiffness (hex8_one_point.hpp) must be the kernel's tangent, or a static
// preload would not start an explicit run in equilibrium: on the distorted patch, K u equals the
// central difference (f(u) − f(−u)) / 2 of the kernel's forces (the quadratic terms of St.
// Venant–Kirchhoff cancel; the cubic ones are 1e-12 of the force at strains of 1e-6).
TEST(ExplicitKernel, OnePointStiffnessIsTheKernelsTangent) {
  for (const bool batched : {true, false}) {
    Patch patch;
    SolidKernelSettings settings = elastic_settings();
    settings.batched = batched;
    settings.hourglass_coefficient = 0.05;
    const SolidElements elements =
        build_solid_elements(*patch.partition, *patch.materials, settings);
    const std::size_t n = patch.n_values();
    std::vector<double> u(n), minus_u(n), v(n, 0.0), f_plus(n, 0.0), f_minus(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      u[k] = 1e-7 * std::sin(1.7 * static_cast<double>(k) + 0.3);  // no linear field: hourglass too
      minus_u[k] = -u[k];
    }
    add_internal_forces(elements, settings, patch.x.data(), u.data(), v.data(), f_plus.data());
    add_internal_forces(elements, settings, patch.x.data(), minus_u.data(), v.data(),
                        f_minus.data());
    std::vector<double> ku(n, 0.0);
    const LameConstants lame = patch.materials->of_block(0).lame();
    double hourglass_share = 0;
    for (LocalIndex e = 0; e < elements.n_elements; ++e) {
      const LocalIndex* nodes = &elements.nodes[8 * static_cast<std::size_t>(e)];
      double x[8][3];
      for (int a = 0; a < 8; ++a)
        for (int d = 0; d < 3; ++d)
          x[a][d] = patch.x[3 * nodes[a] + d];
      double k_one_point[576], k_no_hourglass[576];
      hex8_one_point_stiffness(x, lame, settings.hourglass_coefficient, k_one_point);
      hex8_one_point_stiffness(x, lame, 0, k_no_hourglass);
      for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 24; ++j) {
          const double uj = u[3 * nodes[j / 3] + j % 3];
          ku[3 * nodes[i / 3] + i % 3] += k_one_point[24 * i + j] * uj;
          hourglass_share += std::abs((k_one_point[24 * i + j] - k_no_hourglass[24 * i + j]) * uj);
        }
    }
    ASSERT_GT(hourglass_share, 0);  // the displacement excites the hourglass modes
    double scale = 0;
    for (double value : ku)
      scale = std::max(scale, std::abs(value));
    for (std::size_t k = 0; k < n; ++k) {
      const double tangent = 0.5 * (f_plus[k] - f_minus[k]);
      EXPECT_NEAR(tangent, ku[k], 1e-9 * scale) << "value " << k << (batched ? " batched" : "");
    }
  }
}

TEST(ExplicitKernel, RotatedStateHasRotatedForcesAndEqualEnergies) {
  for (const bool full : {false, true}) {
    Patch patch;
    SolidKernelSettings settings = elastic_settings();
    settings.full_integration = full;
    const SolidElements elements =
        build_solid_elements(*patch.partition, *patch.materials, settings);
    // Any deformation, hourglass modes included; then the same deformation rotated by R.
    std::vector<double> u(patch.n_values()), u_rotated(patch.n_values()), v(patch.n_values(), 0.0);
    const Eigen::Matrix3d R = rotation();
    for (std::size_t n = 0; n < u.size() / 3; ++n) {
      const Eigen::Vector3d X(patch.x[3 * n], patch.x[3 * n + 1], patch.x[3 * n + 2]);
      const Eigen::Vector3d d(1e-4 * std::sin(31 * X[0] + 7 * X[1] * X[2]),
                              2e-4 * std::cos(17 * X[1] * X[0]), 1e-4 * X[2] * X[0] * 40);
      const Eigen::Vector3d rotated = R * (X + d) - X;
      for (int k = 0; k < 3; ++k) {
        u[3 * n + k] = d[k];
        u_rotated[3 * n + k] = rotated[k];
      }
    }
    std::vector<double> f(patch.n_values(), 0.0), f_rotated(patch.n_values(), 0.0);
    const auto totals =
        add_internal_forces(elements, settings, patch.x.data(), u.data(), v.data(), f.data());
    const auto rotated = add_internal_forces(elements, settings, patch.x.data(), u_rotated.data(),
                                             v.data(), f_rotated.data());
    EXPECT_NEAR(rotated.strain_energy, totals.strain_energy, 1e-10 * totals.strain_energy);
    EXPECT_NEAR(rotated.hourglass_energy, totals.hourglass_energy,
                1e-10 * totals.strain_energy + 1e-30);
    if (!full) {
      EXPECT_GT(totals.hourglass_energy, 0.0);
    }
    double largest = 0;
    for (double value : f)
      largest = std::max(largest, std::abs(value));
    for (std::size_t n = 0; n < u.size() / 3; ++n) {
      const Eigen::Vector3d expected = R * Eigen::Vector3d(f[3 * n], f[3 * n + 1], f[3 * n + 2]);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(f_rotated[3 * n + k], expected[k], 1e-9 * largest) << (full ? "full" : "one");
    }
  }
}

// The batched kernel (8 or 4 elements per SIMD batch) is the scalar kernel's arithmetic on lanes:
// forces, energies, powers and the stable step must equal the scalar kernel's to round-off, for
// each hourglass form and each batch width this CPU runs. 3 x 3 x 2 elements make two full
// batches of 8 and a last one of two (four and a half of 4: padded with copies whose results must
// not count); every node is moved, strains are large (~1 %), the displacement excites the
// hourglass modes, and the velocities compress some elements and stretch others, so that lanes
// of one batch take both sides of the bulk viscosity's switch.
TEST(ExplicitKernel, BatchedKernelEqualsScalarKernelToRoundOff) {
  std::vector<int> widths;
  for (const int lanes : {8, 4})
    if (batched_kernel_supports(lanes))
      widths.push_back(lanes);
  if (widths.empty())
    GTEST_SKIP() << "neither AVX-512 nor AVX2 here: add_internal_forces() runs the scalar kernel";
  EXPECT_EQ(batched_kernel_lanes(), widths.front());
  Patch patch(true, {3, 3, 2}, 0.012);
  const std::size_t n = patch.n_values();
  std::vector<double> u(n), v(n);
  for (std::size_t k = 0; k < n; ++k) {
    u[k] = 1e-3 * std::sin(1.7 * static_cast<double>(k) + 0.3);
    v[k] = 2.0 * std::cos(0.9 * static_cast<double>(k) + 1.1);
  }
  for (const HourglassForm form :
       {HourglassForm::stiffness, HourglassForm::viscous, HourglassForm::none}) {
    SolidKernelSettings settings;
    settings.hourglass = form;
    const SolidElements elements =
        build_solid_elements(*patch.partition, *patch.materials, settings);
    ASSERT_EQ(elements.n_elements, 18);
    // Both signs of the volume rate div v = Σ_a v_a · ∇N̄_a occur (small strains: its sign).
    int compressed = 0;
    for (LocalIndex e = 0; e < elements.n_elements; ++e) {
      double div = 0;
      for (int a = 0; a < 8; ++a)
        for (int i = 0; i < 3; ++i)
          div += v[3 * elements.nodes[8 * e + a] + i] * elements.gradients[24 * e + 8 * i + a];
      compressed += div < 0;
    }
    ASSERT_GT(compressed, 0);
    ASSERT_LT(compressed, elements.n_elements);

    std::vector<double> f_scalar(n, 0.0);
    settings.batched = false;
    const SolidForceTotals scalar = add_internal_forces(elements, settings, patch.x.data(),
                                                        u.data(), v.data(), f_scalar.data());
    double largest = 0;
    for (double value : f_scalar)
      largest = std::max(largest, std::abs(value));
    EXPECT_EQ(scalar.hourglass_energy > 0, form == HourglassForm::stiffness);
    EXPECT_EQ(scalar.hourglass_power > 0, form == HourglassForm::viscous);
    EXPECT_GT(scalar.viscous_power, 0.0);
    for (const int lanes : widths) {
      SCOPED_TRACE(std::to_string(lanes) + " lanes");
      std::vector<double> f_batched(n, 0.0);
      settings.batched = true;
      const SolidForceTotals batched = add_internal_forces_batched(
          elements, settings, patch.x.data(), u.data(), v.data(), f_batched.data(), lanes);
      for (std::size_t k = 0; k < n; ++k)
        EXPECT_NEAR(f_batched[k], f_scalar[k], 1e-14 * largest) << "value " << k;
      EXPECT_NEAR(batched.strain_energy, scalar.strain_energy, 1e-14 * scalar.strain_energy);
      EXPECT_NEAR(batched.viscous_power, scalar.viscous_power, 1e-14 * scalar.viscous_power);
      EXPECT_NEAR(batched.hourglass_energy, scalar.hourglass_energy,
                  1e-14 * scalar.hourglass_energy);
      EXPECT_NEAR(batched.hourglass_power, scalar.hourglass_power, 1e-14 * scalar.hourglass_power);
      EXPECT_NEAR(batched.stable_step, scalar.stable_step, 1e-15 * scalar.stable_step);
      EXPECT_EQ(batched.critical_element, scalar.critical_element);
    }
    // The default path takes the widest pass.
    std::vector<double> f_default(n, 0.0), f_widest(n, 0.0);
    add_internal_forces(elements, settings, patch.x.data(), u.data(), v.data(), f_default.data());
    add_internal_forces_batched(elements, settings, patch.x.data(), u.data(), v.data(),
                                f_widest.data(), widths.front());
    EXPECT_EQ(f_default, f_widest);
  }
}

// A batch width the CPU does not run is refused, not run on the wrong instructions.
TEST(ExplicitKernel, BatchedKernelRefusesAWidthTheCpuLacks) {
  Patch patch;
  SolidKernelSettings settings;
  const SolidElements elements = build_solid_elements(*patch.partition, *patch.materials, settings);
  std::vector<double> zero(patch.n_values(), 0.0), f(patch.n_values(), 0.0);
  for (const int lanes : {2, 16})
    EXPECT_THROW(add_internal_forces_batched(elements, settings, patch.x.data(), zero.data(),
                                             zero.data(), f.data(), lanes),
                 std::invalid_argument);
}

// Contact and solid limits: far apart the smaller holds; equal, 0.83 of it (the contact stability
// map's blow-ups from 0.85); in between a linear rise, whichever of the two is smaller; no pair
// (+inf) leaves the solids' step.
TEST(ExplicitStableStep, CoupledLimitIsLoweredOnlyWhereContactAndSolidsAreClose) {
  EXPECT_DOUBLE_EQ(coupled_stable_step(1e-7, 1e-7), 0.83e-7);
  EXPECT_DOUBLE_EQ(coupled_stable_step(1e-7, 1.25e-7), 0.915e-7);
  EXPECT_DOUBLE_EQ(coupled_stable_step(1.25e-7, 1e-7), 0.915e-7);
  EXPECT_DOUBLE_EQ(coupled_stable_step(1e-7, 1.5e-7), 1e-7);
  EXPECT_DOUBLE_EQ(coupled_stable_step(3e-7, 1e-7), 1e-7);
  EXPECT_DOUBLE_EQ(coupled_stable_step(1e-7, 1e300), 1e-7);
  EXPECT_DOUBLE_EQ(coupled_stable_step(1e-7, std::numeric_limits<double>::infinity()), 1e-7);
  // The default Safety factor 0.9 keeps equal limits at 0.75 of the smaller, as docs advise.
  EXPECT_LE(0.9 * coupled_stable_step(1.0, 1.0), 0.75);
  // Continuous and rising as the limits move apart.
  double previous = coupled_stable_step(1.0, 1.0);
  for (double ratio = 1; ratio <= 1.6; ratio += 0.01) {
    const double step = coupled_stable_step(1.0, ratio);
    EXPECT_GE(step, previous);
    EXPECT_LE(step - previous, 0.0035);
    previous = step;
  }
}

TEST(ExplicitKernel, HourglassVectorsIgnoreLinearFields) {
  Patch patch;
  const SolidElements elements =
      build_solid_elements(*patch.partition, *patch.materials, SolidKernelSettings{});
  for (LocalIndex e = 0; e < elements.n_elements; ++e) {
    double vectors[32];
    hourglass_vectors(elements, e, vectors);
    for (int alpha = 0; alpha < 4; ++alpha) {
      const double* gamma = vectors + 8 * alpha;
      double constant = 0, linear[3] = {0, 0, 0};
      for (int a = 0; a < 8; ++a) {
        constant += gamma[a];
        for (int d = 0; d < 3; ++d)
          linear[d] += gamma[a] * patch.x[3 * elements.nodes[8 * e + a] + d];
      }
      EXPECT_NEAR(constant, 0.0, 1e-12);
      for (double value : linear)
        EXPECT_NEAR(value, 0.0, 1e-13);
    }
  }
}

TEST(ExplicitKernel, StableStepOfCubeIsEdgeOverWaveSpeed) {
  Patch patch(false);
  SolidKernelSettings settings;
  const SolidElements elements = build_solid_elements(*patch.partition, *patch.materials, settings);
  const double lambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson));
  const double mu = kYoung / (2 * (1 + kPoisson));
  const double wave_speed = std::sqrt((lambda + 2 * mu) / kDensity);
  for (LocalIndex e = 0; e < elements.n_elements; ++e)
    EXPECT_NEAR(elements.stable_step[e], 0.1 / wave_speed, 1e-12 * 0.1 / wave_speed);
}

TEST(Lanczos, LargestEigenvalueOfASpringChain) {
  // N equal masses between fixed ends: eigenvalues (4k/m) sin²(jπ / (2(N+1))), j = 1..N.
  const int n = 400;
  const double k_over_m = 2.5e7;
  int products = 0;
  auto add_product = [&](const double* q, double* w) {
    ++products;
    for (int i = 0; i < n; ++i)
      w[i] += k_over_m * (2 * q[i] - (i > 0 ? q[i - 1] : 0.0) - (i + 1 < n ? q[i + 1] : 0.0));
  };
  const double exact = 4 * k_over_m * std::pow(std::sin(n * M_PI / (2.0 * (n + 1))), 2);
  std::vector<double> q(n), p(n);
  const double estimate = largest_eigenvalue(
      add_product, n, [](std::size_t i) { return static_cast<GlobalIndex>(i); }, q.data(), p.data(),
      Communicator(MPI_COMM_SELF));
  // The Ritz value approaches from below; the top of this spectrum is as dense as a mesh's.
  EXPECT_LE(estimate, exact * (1 + 1e-12));
  EXPECT_NEAR(estimate, exact, 2e-3 * exact);
  EXPECT_LE(products, 80);
}

TEST(ConvectedStart, LinearDisplacementOnDistortedMesh) {
  // u = A X is steady in a frame moving at c: the convective rate at a node moving at v is
  // A (v - c) exactly, interior and boundary nodes alike (every element's gradient is A).
  for (const int points : {1, 8}) {
    Patch patch;
    SolidKernelSettings settings = elastic_settings();
    settings.full_integration = points == 8;
    const SolidElements elements =
        build_solid_elements(*patch.partition, *patch.materials, settings);
    Eigen::Matrix3d A;
    A << 1e-3, 2e-4, -3e-4, 5e-4, -7e-4, 1e-4, 2e-4, 3e-4, 6e-4;
    const Eigen::Vector3d c(27.8, 0.1, -0.2), omega(0, 60, 5);
    const std::size_t n = patch.n_values() / 3;
    std::vector<double> u(3 * n), v(3 * n);
    std::vector<Eigen::Vector3d> rigid(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector3d X(patch.x[3 * k], patch.x[3 * k + 1], patch.x[3 * k + 2]);
      rigid[k] = c + omega.cross(X);  // a rolling body's rigid velocity
      for (int d = 0; d < 3; ++d) {
        u[3 * k + d] = (A * X)[d];
        v[3 * k + d] = rigid[k][d];
      }
    }
    std::vector<bool> skip(n, false);
    skip[0] = true;  // a node another part drives keeps its velocity
    add_convected_velocity(elements, u.data(), {c[0], c[1], c[2]}, static_cast<LocalIndex>(n),
                           nullptr, skip, v.data());
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector3d expected =
          skip[k] ? rigid[k] : Eigen::Vector3d(rigid[k] + A * (rigid[k] - c));
      for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(v[3 * k + d], expected[d], 1e-12 * rigid[k].norm())
            << "node " << k << ", " << points << " points";
    }
  }
}

TEST(HistoryEvents, ArrivalAndPeriodOfASampledSine) {
  HistoryEvents events;
  const double period = 0.37, dt = 0.37 / 50.3;
  for (int n = 0; n <= 1000; ++n) {
    const double t = n * dt;
    events.sample(t, t < 0.1 ? 0.0 : std::sin(2 * M_PI * (t - 0.1) / period), 0.5, 0.0);
  }
  // Upward crossings of a sine: linear interpolation is exact to O(dt^3) at its inflection.
  EXPECT_NEAR(events.period(), period, 1e-6 * period);
  // First |value| = 0.5 at t = 0.1 + period / 12, within the linear interpolation error.
  EXPECT_NEAR(events.arrival_time, 0.1 + period / 12, 1e-3 * period);
  EXPECT_NEAR(std::abs(events.peak_value), 1.0, 1e-2);
}

TEST(Checkpoint, RoundTripAndRefusals) {
  const std::string path = testing::TempDir() + "/railfe_checkpoint_test";
  const CheckpointSections sections = {{1.5, 2.5}, {}, {3, 4, 5}};
  write_checkpoint(path, 2, sections);
  EXPECT_EQ(read_checkpoint(path, 2), sections);
  EXPECT_THROW(read_checkpoint(path, 1), RunError);
  // A file cut short is refused, not half read.
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() - 5);
  EXPECT_THROW(read_checkpoint(path, 2), RunError);
  // Another format (an older railfe's layout: 2 lacks the step calibration, 3 the penalty
  // flexibility) is refused with its number, not misread.
  for (const char format : {'1', '2', '3'}) {
    write_checkpoint(path, 2, sections);
    {
      std::fstream file(path, std::ios::binary | std::ios::in | std::ios::out);
      file.seekp(7);
      file.put(format);
    }
    try {
      read_checkpoint(path, 2);
      ADD_FAILURE() << "a checkpoint of format " << format << " was read";
    } catch (const RunError& error) {
      EXPECT_NE(std::string(error.what()).find(std::string("in format ") + format),
                std::string::npos)
          << error.what();
    }
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace railfe
