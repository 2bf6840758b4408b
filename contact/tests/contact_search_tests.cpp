// Contact search against exact geometries (lines and circular arcs, where the contact point,
// angle and curvatures are known in closed form), Klingel's wavelength of a cone, and the S1002
// wheel on the 60E1 rail.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/geometry/conicity.hpp"
#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/elastic_wheelset.hpp"
#include "contact/geometry/profile_file.hpp"

namespace railfe {
namespace {

constexpr double kRail = 0.3;  // crown radius of the exact rail (m)

// A circular rail crown of radius 0.3 m reaching 20 mm below its top, top at (0, 0).
std::shared_ptr<const ProfileCurve> crown() {
  const double reach = std::acos(1 - 0.020 / kRail);
  return arc_curve({0, kRail}, kRail, -M_PI / 2 - reach, -M_PI / 2 + reach);
}

// Where the crown's gauge point sits relative to its top.
double crown_gauge_offset(const TrackLayout& track) {
  return std::sqrt(kRail * kRail - std::pow(kRail - track.gauge_depth, 2));
}

// A track whose crown tops lie under the wheels' running points (y = 0.75 m).
TrackLayout exact_track() {
  TrackLayout track;
  track.profile_inclined = true;
  track.gauge = 2 * (0.75 - crown_gauge_offset(track));
  return track;
}

TEST(ContactSearch, CylinderOnCrownTouchesAtTheTopWithTheCrownsCurvature) {
  const TrackLayout track = exact_track();
  WheelsetLayout wheelset;
  // A cylindrical wheel (flat profile) from the flange back to the field side.
  auto wheel = line_curve({-0.07, 0}, {wheelset.flange_back, 0});
  WheelRailGeometry geometry(crown(), std::move(wheel), track, wheelset);
  const double crown_y = track.gauge / 2 + crown_gauge_offset(track);
  for (double roll : {0.0, 0.01}) {
    const WheelsetPose pose{0.001, -0.0005, roll, 0};
    const GapSample start = least_gap_sample(geometry, TrackSide::right, false, pose);
    const ContactPoint c =
        search_contact(geometry, TrackSide::right, false, pose, start.s_wheel, start.s_rail);
    ASSERT_EQ(c.status, SearchStatus::converged) << status_name(c.status);
    // The rail normal is the wheel's axle-normal: tilted by the roll, away from the flange.
    EXPECT_NEAR(c.contact_angle, -roll, 1e-12);
    EXPECT_NEAR(c.rail_point.y, crown_y + kRail * std::sin(roll), 1e-9 * kRail);
    EXPECT_NEAR(c.rail_point.z, kRail * (1 - std::cos(roll)), 1e-9 * kRail);
    EXPECT_NEAR(c.rail_lateral_curvature, 1 / kRail, 1e-9 / kRail);
    EXPECT_NEAR(c.wheel_lateral_curvature, 0, 1e-9 / kRail);
    // Gap: the crown's distance to the rolled cylinder (radius r0 about the wheelset centre).
    const Vec2 centre{pose.lateral, pose.vertical - wheelset.nominal_radius};
    const double crown_to_axle =
        std::cos(roll) * (kRail - centre.z) - std::sin(roll) * (crown_y - centre.y);
    EXPECT_NEAR(c.gap, crown_to_axle - kRail - wheelset.nominal_radius, 1e-12);
    EXPECT_LT(c.iterations, 10);
  }
}

TEST(ContactSearch, CircleInCircleTouchesOnTheLineOfCentres) {
  const TrackLayout track = exact_track();
  WheelsetLayout wheelset;
  // A concave wheel tread of radius 0.5 m through the running point, in the wheel's (y, z
  // radially out) coordinates: its centre of curvature lies outside the wheel, at z = +0.5.
  const double wheel_radius = 0.5;
  auto wheel = arc_curve({0, wheel_radius}, wheel_radius, -M_PI / 2 - 0.15, -M_PI / 2 + 0.15);
  WheelRailGeometry geometry(crown(), std::move(wheel), track, wheelset);
  const double crown_y = track.gauge / 2 + crown_gauge_offset(track);
  const double running_y = wheelset.back_to_back / 2 + wheelset.flange_back;
  const WheelsetPose pose{0.004, -0.001, 0, 0};
  const GapSample start = least_gap_sample(geometry, TrackSide::right, false, pose);
  const ContactPoint c =
      search_contact(geometry, TrackSide::right, false, pose, start.s_wheel, start.s_rail);
  ASSERT_EQ(c.status, SearchStatus::converged) << status_name(c.status);
  // In track coordinates the wheel's centre of curvature lies r0 + 0.5 below the axle, the
  // rail's 0.3 below the crown top; the rail circle sits inside the wheel circle.
  const Vec2 wheel_centre{running_y + pose.lateral, pose.vertical + wheel_radius};
  const Vec2 rail_centre{crown_y, kRail};
  const double dy = rail_centre.y - wheel_centre.y, dz = rail_centre.z - wheel_centre.z;
  const double distance = std::hypot(dy, dz);
  // The contact lies on the ray from the wheel's centre through the rail's; the rail normal
  // points along it.
  const Vec2 u{dy / distance, dz / distance};
  EXPECT_NEAR(c.rail_point.y, rail_centre.y + kRail * u.y, 1e-9 * kRail);
  EXPECT_NEAR(c.rail_point.z, rail_centre.z + kRail * u.z, 1e-9 * kRail);
  EXPECT_NEAR(c.contact_angle, std::atan2(-u.y, -u.z), 1e-9);
  EXPECT_NEAR(c.gap, wheel_radius - kRail - distance, 1e-12);
  EXPECT_NEAR(c.rail_lateral_curvature, 1 / kRail, 1e-9 / kRail);
  EXPECT_NEAR(c.wheel_lateral_curvature, -1 / wheel_radius, 1e-9 / wheel_radius);
  EXPECT_NEAR(c.relative_curvature_lateral(), 0.5 * (1 / kRail - 1 / wheel_radius), 1e-9);
}

TEST(ContactSearch, ConeOnCrownTouchesWhereTheSlopesMatch) {
  const TrackLayout track = exact_track();
  WheelsetLayout wheelset;
  const double gamma = 1.0 / 40;
  // Radius grows towards the flange: z = gamma y.
  auto wheel = line_curve({-0.06, -0.06 * gamma}, {0.07, 0.07 * gamma});
  WheelRailGeometry geometry(crown(), std::move(wheel), track, wheelset);
  const double crown_y = track.gauge / 2 + crown_gauge_offset(track);
  const WheelsetPose pose{0.002, 0, 0, 0};
  const GapSample start = least_gap_sample(geometry, TrackSide::right, false, pose);
  const ContactPoint c =
      search_contact(geometry, TrackSide::right, false, pose, start.s_wheel, start.s_rail);
  ASSERT_EQ(c.status, SearchStatus::converged) << status_name(c.status);
  const double delta = std::atan(gamma);
  EXPECT_NEAR(c.contact_angle, delta, 1e-12);
  EXPECT_NEAR(c.rail_point.y, crown_y - kRail * std::sin(delta), 1e-9 * kRail);
  EXPECT_NEAR(c.rail_point.z, kRail * (1 - std::cos(delta)), 1e-9 * kRail);
  // Rolling radius: the cone's radius at the wheel point above the rail point.
  const double running_y = wheelset.back_to_back / 2 + wheelset.flange_back;
  const double y_profile = running_y - (c.rail_point.y - pose.lateral);
  const double expected_radius = wheelset.nominal_radius + gamma * y_profile;
  EXPECT_NEAR(c.rolling_radius, expected_radius, 1e-5 * expected_radius);
  // Along the rolling direction the cone's normal curvature is cos(delta) / r.
  EXPECT_NEAR(c.wheel_rolling_curvature, std::cos(delta) / c.rolling_radius, 1e-9);
}

TEST(ElasticWheelset, ConeOnCrownGivesHertzForTheLoad) {
  // 1:40 cones on 300 mm crowns under 100 kN: each wheel carries W / 2 vertically on a normal
  // tilted by atan(1/40), so N = W / (2 cos delta); the cone's normal curvature along the
  // rolling direction is cos(delta) / r, the crown's lateral one 1 / R; and as a line sinking
  // onto a circle the wheel approaches the crown by its vertical sink times cos(delta).
  const TrackLayout track = exact_track();
  WheelsetLayout wheelset;
  const double gamma = 1.0 / 40, load = 100e3;
  auto wheel = line_curve({-0.06, -0.06 * gamma}, {0.07, 0.07 * gamma});
  WheelRailGeometry geometry(crown(), std::move(wheel), track, wheelset);
  const RigidContact rigid = solve_rigid_contact(geometry, 0, 0, nullptr);
  ASSERT_TRUE(rigid.converged);
  const double modulus = contact_modulus({210e9, 0.28}, {210e9, 0.28});
  const ElasticContact elastic = solve_elastic_contact(geometry, rigid, 0, load, modulus);
  ASSERT_TRUE(elastic.converged) << elastic.failure;
  const double delta = std::atan(gamma);
  for (TrackSide side : {TrackSide::left, TrackSide::right}) {
    const ElasticPatch& patch = elastic.patches[static_cast<int>(side)][0];
    ASSERT_TRUE(patch.loaded());
    EXPECT_FALSE(elastic.patches[static_cast<int>(side)][1].loaded());
    EXPECT_NEAR(std::abs(patch.point.contact_angle), delta, 1e-9);
    const double radius = patch.point.rolling_radius;
    const HertzContact exact = hertz_contact(std::cos(delta) / (2 * radius), 0.5 / kRail, modulus,
                                             load / (2 * std::cos(delta)));
    EXPECT_NEAR(patch.hertz.load, exact.load, 1e-9 * exact.load);
    EXPECT_NEAR(patch.hertz.a, exact.a, 1e-6 * exact.a);
    EXPECT_NEAR(patch.hertz.b, exact.b, 1e-6 * exact.b);
    EXPECT_NEAR(patch.hertz.pressure, exact.pressure, 1e-6 * exact.pressure);
    EXPECT_NEAR((elastic.pose.vertical - rigid.vertical) * std::cos(delta), exact.approach,
                1e-6 * exact.approach);
  }
  EXPECT_NEAR(elastic.roll_residual, 0, 1e-10 * load);
  EXPECT_NEAR(elastic.lateral_force, 0, 1e-9 * load);
}

TEST(Conicity, KlingelWavelengthOfAConicalWheelset) {
  // Klingel's rails are knife edges: the contact stays put on them. A 10 mm crown comes close
  // (a 0.3 m crown moves the contact by R phi as the wheelset rolls: about 1 % on lambda).
  TrackLayout track = exact_track();
  track.gauge_depth = 0.005;
  WheelsetLayout wheelset;
  const double gamma = 1.0 / 40, edge = 0.010;
  track.gauge = 2 * (0.75 - std::sqrt(edge * edge - std::pow(edge - track.gauge_depth, 2)));
  auto rail = arc_curve({0, edge}, edge, -M_PI / 2 - 1.2, -M_PI / 2 + 1.2);
  auto wheel = line_curve({-0.06, -0.06 * gamma}, {0.07, 0.07 * gamma});
  WheelRailGeometry geometry(std::move(rail), std::move(wheel), track, wheelset);
  const ContactTable table(geometry, 0.005, 101);
  const double e = table.half_contact_distance(), r0 = table.centred_rolling_radius();
  auto delta_r = [&](double y) {
    const auto& rows = table.rows();
    const double position = (y - rows.front().lateral) / (rows[1].lateral - rows[0].lateral);
    const std::size_t i =
        std::min<std::size_t>(static_cast<std::size_t>(position), rows.size() - 2);
    const double w = position - static_cast<double>(i);
    return (1 - w) * table.rolling_radius_difference(i) +
           w * table.rolling_radius_difference(i + 1);
  };
  // As the wheelset rolls by -dr / 2e, the wheel point above each edge moves by r0 times the
  // roll towards the larger radius: dr = 2 gamma y (1 + gamma r0 / e), 1.5 % above Klingel's
  // first-order 2 gamma y for this wheelset.
  const double rolling = gamma * (1 + gamma * r0 / e);
  for (double y : {-0.002, 0.001, 0.003})
    EXPECT_NEAR(delta_r(y), 2 * rolling * y, 2e-3 * std::abs(2 * rolling * y)) << "y = " << y;
  const double lambda = kinematic_wavelength(delta_r, e, r0, 0.002);
  EXPECT_NEAR(lambda, klingel_wavelength(r0, e, rolling), 0.005 * lambda);
  EXPECT_NEAR(lambda, klingel_wavelength(r0, e, gamma), 0.01 * lambda);
  EXPECT_NEAR(equivalent_conicity(lambda, e, r0), rolling, 0.005 * rolling);
}

}  // namespace
}  // namespace railfe
