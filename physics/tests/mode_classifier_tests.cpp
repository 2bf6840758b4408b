// The mode classifier against analytic mode shapes of a thin ring and an annular disc: flexure
// out of plane and in plane, nodal circles, rigid-body modes, mixtures that must stay ambiguous,
// and invariance to phase, doublet partner, axis direction, origin and node order.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <vector>

#include "framework/base/constants.hpp"
#include "physics/modal/mode_classifier.hpp"

namespace railfe {
namespace {

using Vector3 = std::array<double, 3>;

// Position of a node in cylindrical coordinates about the test's own axis.
struct Cylindrical {
  double radius;
  double angle;
  double axial;
};

// (u_r, u_θ, u_a) of a mode at a node.
using CylindricalField = std::function<Vector3(const Cylindrical&)>;
// Cartesian displacement at a Cartesian point (rigid-body modes).
using CartesianField = std::function<Vector3(const Vector3&)>;

// An orthonormal right-handed frame (first, second, axis) placed at origin. The default matches
// the classifier's documented angle reference for the default y axis (θ from x toward −z), so
// that phase angles can be checked.
struct TestFrame {
  Vector3 origin{0, 0, 0};
  Vector3 first{1, 0, 0};
  Vector3 second{0, 0, -1};
  Vector3 axis{0, 1, 0};
};

Vector3 combine(const TestFrame& frame, double along_first, double along_second,
                double along_axis) {
  Vector3 result;
  for (int d = 0; d < 3; ++d) {
    result[d] =
        along_first * frame.first[d] + along_second * frame.second[d] + along_axis * frame.axis[d];
  }
  return result;
}

struct Cloud {
  std::vector<Vector3> points;
  std::vector<Vector3> displacements;
};

// Meridional section points (r, a) of a body, each revolved into a ring of nodes.
struct Section {
  double radius;
  double axial;
  int angles;
};

Cloud revolve(const std::vector<Section>& sections, const CylindricalField& field,
              const TestFrame& frame = {}) {
  Cloud cloud;
  for (const Section& section : sections) {
    for (int k = 0; k < section.angles; ++k) {
      const Cylindrical node{section.radius, 2 * kPi * k / section.angles, section.axial};
      const double c = std::cos(node.angle);
      const double s = std::sin(node.angle);
      Vector3 point = combine(frame, node.radius * c, node.radius * s, node.axial);
      for (int d = 0; d < 3; ++d)
        point[d] += frame.origin[d];
      const Vector3 u = field(node);
      cloud.points.push_back(point);
      cloud.displacements.push_back(combine(frame, u[0] * c - u[1] * s, u[0] * s + u[1] * c, u[2]));
    }
  }
  return cloud;
}

Cloud revolve_cartesian(const std::vector<Section>& sections, const CartesianField& field,
                        const TestFrame& frame = {}) {
  Cloud cloud = revolve(
      sections,
      [](const Cylindrical&) {
        return Vector3{0, 0, 0};
      },
      frame);
  for (std::size_t i = 0; i < cloud.points.size(); ++i)
    cloud.displacements[i] = field(cloud.points[i]);
  return cloud;
}

// A thin ring: centre radius 1, circular cross-section of radius 0.05 sampled at its centre and
// 8 points of its boundary, 48 angles.
std::vector<Section> thin_ring() {
  std::vector<Section> sections{{1.0, 0.0, 48}};
  for (int k = 0; k < 8; ++k) {
    const double psi = 2 * kPi * k / 8;
    sections.push_back({1.0 + 0.05 * std::cos(psi), 0.05 * std::sin(psi), 48});
  }
  return sections;
}

// An annular disc (wheel-like): radii 0.30 to 0.46 by 0.02, three axial layers 0.02 apart;
// web_angles on radii below 0.42 (a coarser web), 64 angles on the rest.
std::vector<Section> disc(int web_angles = 64) {
  std::vector<Section> sections;
  for (int i = 0; i <= 8; ++i) {
    const double radius = 0.30 + 0.02 * i;
    for (double axial : {-0.01, 0.0, 0.01})
      sections.push_back({radius, axial, radius < 0.419 ? web_angles : 64});
  }
  return sections;
}

ModeClass classify(const Cloud& cloud, const TestFrame& frame = {},
                   const ClassifierSettings& settings = {}) {
  AxisymmetricFrame axisymmetric;
  axisymmetric.origin = frame.origin;
  axisymmetric.axis = frame.axis;
  return classify_mode(cloud.points, cloud.displacements, axisymmetric, settings);
}

void expect_class(const ModeClass& result, const std::string& family, int circles, int diameters) {
  EXPECT_EQ(result.family, family) << result.note;
  EXPECT_EQ(result.nodal_circles, circles) << result.note;
  EXPECT_EQ(result.nodal_diameters, diameters) << result.note;
}

// Out-of-plane flexure with one nodal circle at r = 0.38, for n diameters, phase φ.
CylindricalField axial_one_circle(int n, double phase = 0) {
  return [=](const Cylindrical& node) {
    return Vector3{0, 0, std::cos(n * node.angle + phase) * (node.radius - 0.38)};
  };
}

TEST(ModeClassifier, RingOutOfPlaneFlexureIsAxial) {
  for (int n = 0; n <= 6; ++n) {
    SCOPED_TRACE(n);
    const auto field = [n](const Cylindrical& node) {
      return Vector3{0, 0, std::cos(n * node.angle)};
    };
    const ModeClass result = classify(revolve(thin_ring(), field));
    expect_class(result, "axial", 0, n);
    EXPECT_NEAR(result.diameter_share, 1, 1e-9);
    EXPECT_NEAR(result.axial_share, 1, 1e-12);
  }
}

TEST(ModeClassifier, RingInPlaneFlexureIsRadial) {
  // Inextensional flexure of a thin ring: u_θ = −u_r / n in amplitude.
  for (int n = 2; n <= 6; ++n) {
    SCOPED_TRACE(n);
    const auto field = [n](const Cylindrical& node) {
      return Vector3{n * std::cos(n * node.angle), -std::sin(n * node.angle), 0};
    };
    const ModeClass result = classify(revolve(thin_ring(), field));
    expect_class(result, "radial", 0, n);
    EXPECT_NEAR(result.radial_share, n * n / (n * n + 1.0), 1e-9);
  }
}

TEST(ModeClassifier, RingBreathingIsRadialWithoutDiameters) {
  const auto field = [](const Cylindrical&) { return Vector3{1, 0, 0}; };
  expect_class(classify(revolve(thin_ring(), field)), "radial", 0, 0);
}

TEST(ModeClassifier, UniformCircumferentialMotionIsCircumferentialWithoutDiameters) {
  const auto field = [](const Cylindrical&) { return Vector3{0, 1, 0}; };
  expect_class(classify(revolve(thin_ring(), field)), "circumferential", 0, 0);
  expect_class(classify(revolve(disc(), field)), "circumferential", 0, 0);
}

TEST(ModeClassifier, RigidRotationAboutTheAxisIsCircumferential) {
  const TestFrame frame;
  const auto rotation = [&](const Vector3& p) {
    return Vector3{frame.axis[1] * p[2] - frame.axis[2] * p[1],
                   frame.axis[2] * p[0] - frame.axis[0] * p[2],
                   frame.axis[0] * p[1] - frame.axis[1] * p[0]};
  };
  expect_class(classify(revolve_cartesian(thin_ring(), rotation)), "circumferential", 0, 0);
  expect_class(classify(revolve_cartesian(disc(), rotation)), "circumferential", 0, 0);
}

TEST(ModeClassifier, RigidTranslationAlongTheAxisIsAxialWithoutDiameters) {
  const auto translation = [](const Vector3&) { return Vector3{0, 1, 0}; };
  expect_class(classify(revolve_cartesian(thin_ring(), translation)), "axial", 0, 0);
  expect_class(classify(revolve_cartesian(disc(), translation)), "axial", 0, 0);
}

TEST(ModeClassifier, RigidLateralTranslationHasOneDiameterAndAnAmbiguousFamily) {
  // u_r = cos θ, u_θ = −sin θ: equal radial and circumferential energy.
  for (const Vector3& direction : {Vector3{1, 0, 0}, Vector3{0, 0, 1}, Vector3{0.6, 0, -0.8}}) {
    const auto translation = [&](const Vector3&) { return direction; };
    for (const auto& sections : {thin_ring(), disc()}) {
      const ModeClass result = classify(revolve_cartesian(sections, translation));
      expect_class(result, "ambiguous", -1, 1);
      EXPECT_NEAR(result.radial_share, 0.5, 1e-9);
      EXPECT_NE(result.note.find("in-plane energy split"), std::string::npos) << result.note;
    }
  }
}

TEST(ModeClassifier, RigidRockingIsAxialWithOneDiameter) {
  // Rotation about a transverse axis: u_a ∝ r, in-plane motion ∝ a (small).
  for (const Vector3& spin : {Vector3{1, 0, 0}, Vector3{0, 0, 1}}) {
    const auto rocking = [&](const Vector3& p) {
      return Vector3{spin[1] * p[2] - spin[2] * p[1], spin[2] * p[0] - spin[0] * p[2],
                     spin[0] * p[1] - spin[1] * p[0]};
    };
    expect_class(classify(revolve_cartesian(thin_ring(), rocking)), "axial", 0, 1);
    expect_class(classify(revolve_cartesian(disc(), rocking)), "axial", 0, 1);
  }
}

TEST(ModeClassifier, DiscOutOfPlaneModeWithOneNodalCircle) {
  for (int n = 0; n <= 6; ++n) {
    SCOPED_TRACE(n);
    expect_class(classify(revolve(disc(), axial_one_circle(n))), "axial", 1, n);
  }
}

TEST(ModeClassifier, DiscPlateKinematicsWithOneNodalCircle) {
  // Kirchhoff kinematics of w = cos nθ (r − 0.38): u_r = −a ∂w/∂r, u_θ = −(a/r) ∂w/∂θ change
  // sign through the thickness and are small, so the mode stays axial.
  for (int n = 0; n <= 6; ++n) {
    SCOPED_TRACE(n);
    const auto field = [n](const Cylindrical& node) {
      const double w = std::cos(n * node.angle) * (node.radius - 0.38);
      const double dw_dr = std::cos(n * node.angle);
      const double dw_dtheta = -n * std::sin(n * node.angle) * (node.radius - 0.38);
      return Vector3{-node.axial * dw_dr, -node.axial / node.radius * dw_dtheta, w};
    };
    expect_class(classify(revolve(disc(), field)), "axial", 1, n);
  }
}

TEST(ModeClassifier, DiscOutOfPlaneModeWithTwoNodalCircles) {
  for (int n = 0; n <= 4; ++n) {
    SCOPED_TRACE(n);
    const auto field = [n](const Cylindrical& node) {
      return Vector3{0, 0, std::cos(n * node.angle) * (node.radius - 0.33) * (node.radius - 0.41)};
    };
    expect_class(classify(revolve(disc(), field)), "axial", 2, n);
  }
}

TEST(ModeClassifier, DiscRadialModeWithOneNodalCircle) {
  for (int n = 2; n <= 6; ++n) {
    SCOPED_TRACE(n);
    const auto field = [n](const Cylindrical& node) {
      const double shape = node.radius - 0.38;
      return Vector3{n * std::cos(n * node.angle) * shape, -std::sin(n * node.angle) * shape, 0};
    };
    expect_class(classify(revolve(disc(), field)), "radial", 1, n);
  }
}

TEST(ModeClassifier, DiscCircumferentialModeWithOneNodalCircle) {
  // u_θ peaks π/(2n) away from u_r: the line must follow u_θ's own maximum.
  for (int n = 2; n <= 5; ++n) {
    SCOPED_TRACE(n);
    const auto field = [n](const Cylindrical& node) {
      const double shape = node.radius - 0.38;
      return Vector3{std::sin(n * node.angle) * shape, n * std::cos(n * node.angle) * shape, 0};
    };
    expect_class(classify(revolve(disc(), field)), "circumferential", 1, n);
  }
}

TEST(ModeClassifier, PhaseAndDoubletPartnerDoNotMatter) {
  const double phases[] = {0.0, 0.37, 1.1, 2.9, -0.8};
  for (int n = 1; n <= 6; ++n) {
    for (double phase : phases) {
      SCOPED_TRACE(::testing::Message() << "n " << n << " phase " << phase);
      expect_class(classify(revolve(disc(), axial_one_circle(n, phase))), "axial", 1, n);
      const auto ring_field = [=](const Cylindrical& node) {
        return Vector3{0, 0, std::cos(n * node.angle + phase)};
      };
      expect_class(classify(revolve(thin_ring(), ring_field)), "axial", 0, n);
    }
    SCOPED_TRACE(::testing::Message() << "sine partner n " << n);
    expect_class(classify(revolve(disc(), axial_one_circle(n, -kPi / 2))), "axial", 1, n);
  }
}

TEST(ModeClassifier, PhaseAngleIsWhereTheAmplitudeIsLargest) {
  for (int n = 1; n <= 6; ++n) {
    for (double peak : {0.0, 0.2, 1.3}) {
      SCOPED_TRACE(::testing::Message() << "n " << n << " peak " << peak);
      const ModeClass result = classify(revolve(disc(), axial_one_circle(n, -n * peak)));
      const double period = kPi / n;
      const double offset = std::fmod(std::abs(result.phase_angle - peak), period);
      EXPECT_LT(std::min(offset, period - offset), 1e-9);
      EXPECT_GE(result.phase_angle, 0);
      EXPECT_LT(result.phase_angle, period);
    }
  }
}

TEST(ModeClassifier, EqualPowerInTwoHarmonicsIsAmbiguous) {
  const auto field = [](const Cylindrical& node) {
    return Vector3{0, 0, std::cos(2 * node.angle) + std::cos(3 * node.angle)};
  };
  for (const auto& sections : {thin_ring(), disc()}) {
    const ModeClass result = classify(revolve(sections, field));
    expect_class(result, "axial", -1, -1);
    EXPECT_NEAR(result.diameter_share, 0.5, 1e-9);
    EXPECT_NE(result.note.find("no harmonic dominates"), std::string::npos) << result.note;
  }
}

TEST(ModeClassifier, EqualOutOfPlaneAndInPlaneEnergyIsAmbiguous) {
  const auto field = [](const Cylindrical& node) {
    return Vector3{std::cos(3 * node.angle), 0, std::cos(3 * node.angle)};
  };
  const ModeClass result = classify(revolve(disc(), field));
  expect_class(result, "ambiguous", -1, 3);
  EXPECT_NE(result.note.find("out of plane"), std::string::npos) << result.note;
}

TEST(ModeClassifier, IndependentOfAxisDirectionAndOrigin) {
  TestFrame along_z;
  along_z.first = {1, 0, 0};
  along_z.second = {0, 1, 0};
  along_z.axis = {0, 0, 1};
  // A general orientation (axis ∝ (1, 2, 3)) with its angle origin unrelated to the
  // classifier's, and an offset origin.
  TestFrame tilted;
  const double axis_length = std::sqrt(14.0);
  tilted.axis = {1 / axis_length, 2 / axis_length, 3 / axis_length};
  const double first_length = std::sqrt(5.0);
  tilted.first = {2 / first_length, -1 / first_length, 0};
  tilted.second = {tilted.axis[1] * tilted.first[2] - tilted.axis[2] * tilted.first[1],
                   tilted.axis[2] * tilted.first[0] - tilted.axis[0] * tilted.first[2],
                   tilted.axis[0] * tilted.first[1] - tilted.axis[1] * tilted.first[0]};
  tilted.origin = {5, -3, 2};
  const auto radial = [](const Cylindrical& node) {
    const double shape = node.radius - 0.38;
    return Vector3{3 * std::cos(3 * node.angle + 0.4) * shape,
                   -std::sin(3 * node.angle + 0.4) * shape, 0};
  };
  for (const TestFrame& frame : {along_z, tilted}) {
    expect_class(classify(revolve(disc(), axial_one_circle(4, 0.3), frame), frame), "axial", 1, 4);
    expect_class(classify(revolve(disc(), radial, frame), frame), "radial", 1, 3);
    // The axis need not be a unit vector.
    TestFrame scaled = frame;
    for (double& component : scaled.axis)
      component *= 3;
    expect_class(classify(revolve(disc(), axial_one_circle(2), frame), scaled), "axial", 1, 2);
  }
}

TEST(ModeClassifier, IndependentOfNodeOrder) {
  Cloud cloud = revolve(disc(), axial_one_circle(3, 0.7));
  std::vector<std::size_t> order(cloud.points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(42));
  Cloud shuffled;
  for (std::size_t i : order) {
    shuffled.points.push_back(cloud.points[i]);
    shuffled.displacements.push_back(cloud.displacements[i]);
  }
  expect_class(classify(shuffled), "axial", 1, 3);
}

TEST(ModeClassifier, RobustToSmallNoise) {
  Cloud cloud = revolve(disc(), axial_one_circle(3, 0.7));
  std::mt19937 generator(7);
  std::normal_distribution<double> noise(0, 0.002);  // 2.5 % of the rim amplitude 0.08
  for (Vector3& u : cloud.displacements) {
    for (double& component : u)
      component += noise(generator);
  }
  expect_class(classify(cloud), "axial", 1, 3);
}

TEST(ModeClassifier, CoarserWebRingsStillGiveTheNodalCircle) {
  for (int n = 1; n <= 6; ++n) {
    SCOPED_TRACE(n);
    expect_class(classify(revolve(disc(32), axial_one_circle(n, 0.5))), "axial", 1, n);
  }
}

TEST(ModeClassifier, WebRangeLimitsTheNodalCircleLine) {
  ClassifierSettings settings;
  settings.web_inner_radius = 0.39;  // outside the nodal circle at 0.38
  expect_class(classify(revolve(disc(), axial_one_circle(2)), {}, settings), "axial", 0, 2);
  settings.web_inner_radius = 0.31;
  settings.web_outer_radius = 0.45;
  expect_class(classify(revolve(disc(), axial_one_circle(2)), {}, settings), "axial", 1, 2);
}

TEST(ModeClassifier, HarmonicsAboveTheLimitAreAmbiguous) {
  const auto field = [](const Cylindrical& node) {
    return Vector3{0, 0, std::cos(10 * node.angle)};
  };
  expect_class(classify(revolve(disc(), field)), "axial", 0, 10);
  ClassifierSettings settings;
  settings.max_diameters = 6;
  const ModeClass result = classify(revolve(disc(), field), {}, settings);
  expect_class(result, "axial", -1, -1);
  EXPECT_LT(result.diameter_share, 1e-9);
}

TEST(ModeClassifier, ZeroModeIsAmbiguous) {
  const auto field = [](const Cylindrical&) { return Vector3{0, 0, 0}; };
  const ModeClass result = classify(revolve(disc(), field));
  expect_class(result, "ambiguous", -1, -1);
  EXPECT_NE(result.note.find("zero"), std::string::npos) << result.note;
}

TEST(ModeClassifier, StillRimIsAmbiguous) {
  const auto field = [](const Cylindrical& node) {
    return Vector3{0, 0, node.radius < 0.41 ? std::cos(2 * node.angle) : 0.0};
  };
  const ModeClass result = classify(revolve(disc(), field));
  expect_class(result, "ambiguous", -1, -1);
  EXPECT_NE(result.note.find("rim does not move"), std::string::npos) << result.note;
}

TEST(ModeClassifier, RingsOfFewerThanThreeNodesAreSkippedWithANote) {
  std::vector<Section> sections = thin_ring();
  for (Section& section : sections)
    section.angles = 2;
  const auto field = [](const Cylindrical&) { return Vector3{0, 0, 1}; };
  const ModeClass result = classify(revolve(sections, field));
  expect_class(result, "ambiguous", -1, -1);
  EXPECT_NE(result.note.find("fewer than 3 nodes"), std::string::npos) << result.note;
  EXPECT_NE(result.note.find("no rim ring"), std::string::npos) << result.note;
}

TEST(ModeClassifier, NodesOnTheAxisAreIgnored) {
  Cloud cloud = revolve(disc(), axial_one_circle(0));
  cloud.points.push_back({0, 0.0, 0});
  cloud.displacements.push_back({0, -0.2, 0});
  expect_class(classify(cloud), "axial", 1, 0);
}

TEST(ModeClassifier, RejectsInvalidInput) {
  const Cloud cloud = revolve(disc(), axial_one_circle(2));
  AxisymmetricFrame frame;
  const ClassifierSettings settings;
  std::vector<Vector3> short_displacements = cloud.displacements;
  short_displacements.pop_back();
  EXPECT_THROW(classify_mode(cloud.points, short_displacements, frame, settings),
               std::invalid_argument);
  AxisymmetricFrame zero_axis;
  zero_axis.axis = {0, 0, 0};
  EXPECT_THROW(classify_mode(cloud.points, cloud.displacements, zero_axis, settings),
               std::invalid_argument);
  std::vector<Vector3> not_finite = cloud.displacements;
  not_finite[5][1] = std::nan("");
  EXPECT_THROW(classify_mode(cloud.points, not_finite, frame, settings), std::invalid_argument);
  for (const auto& change : std::vector<std::function<void(ClassifierSettings&)>>{
           [](ClassifierSettings& s) { s.rim_fraction = 0; },
           [](ClassifierSettings& s) { s.dominance = 1.5; },
           [](ClassifierSettings& s) { s.family_dominance = 0.5; },
           [](ClassifierSettings& s) { s.noise_fraction = 1; },
           [](ClassifierSettings& s) { s.max_diameters = -1; },
           [](ClassifierSettings& s) { s.relative_tolerance = 0; },
           [](ClassifierSettings& s) { s.web_outer_radius = -1; }}) {
    ClassifierSettings bad;
    change(bad);
    EXPECT_THROW(classify_mode(cloud.points, cloud.displacements, frame, bad),
                 std::invalid_argument);
  }
}

}  // namespace
}  // namespace railfe
