// The S1002 wheel on the 60E1 rail inclined 1:40 (the Manchester benchmark's profiles), gauge
// 1435 mm, back-to-back 1360 mm, r0 = 460 mm: tread contact when centred, flange contact from
// about 6 mm, Δr continuous except where the contact point jumps, a table that leaves no
// penetration anywhere on either wheel, and a table-started online search that agrees with it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/elastic_wheelset.hpp"
#include "contact/geometry/profile_file.hpp"

namespace railfe {
namespace {

const WheelRailGeometry& benchmark_geometry() {
  static const WheelRailGeometry geometry = [] {
    TrackLayout track;
    track.profile_inclined = true;  // the benchmark's rail is already canted
    return WheelRailGeometry(shipped_curve("MBench_UIC60_v3.prr"),
                             shipped_curve("MBench_S1002_v3.prw"), track, WheelsetLayout{});
  }();
  return geometry;
}

TEST(S1002On60E1, CentredWheelsetTouchesOnTheTread) {
  const RigidContact centre = solve_rigid_contact(benchmark_geometry(), 0, 0, nullptr);
  ASSERT_TRUE(centre.converged);
  for (TrackSide side : {TrackSide::left, TrackSide::right}) {
    const ContactPoint& c = centre.active(side);
    EXPECT_FALSE(c.flange);
    // Near the running circle: within 5 mm of r0 and a tread's contact angle (below 5 degrees).
    EXPECT_NEAR(c.rolling_radius, 0.46, 0.002);
    EXPECT_LT(std::abs(c.contact_angle), 5 * M_PI / 180);
  }
  // Symmetric track and wheelset: equal radii, level axle.
  EXPECT_NEAR(centre.active(TrackSide::right).rolling_radius,
              centre.active(TrackSide::left).rolling_radius, 1e-9);
  EXPECT_NEAR(centre.roll, 0, 1e-12);
}

TEST(S1002On60E1, ElasticCentredWheelsetSplitsTheLoadEvenly) {
  const RigidContact rigid = solve_rigid_contact(benchmark_geometry(), 0, 0, nullptr);
  const double load = 100e3, modulus = contact_modulus({210e9, 0.28}, {210e9, 0.28});
  const ElasticContact elastic =
      solve_elastic_contact(benchmark_geometry(), rigid, 0, load, modulus);
  ASSERT_TRUE(elastic.converged) << elastic.failure;
  const ElasticPatch &left = elastic.patches[0][0], &right = elastic.patches[1][0];
  ASSERT_TRUE(left.loaded() && right.loaded());
  EXPECT_NEAR(left.hertz.load, right.hertz.load, 1e-8 * load);
  EXPECT_NEAR(-(left.force_z + right.force_z), load, 1e-8 * load);
  EXPECT_NEAR(left.force_y + right.force_y, 0, 1e-8 * load);
  EXPECT_NEAR(elastic.pose.roll, 0, 1e-12);
  // The wheelset sinks: the elastic position lies below the rigid one by about the approach.
  EXPECT_GT(elastic.pose.vertical, rigid.vertical);
  EXPECT_NEAR(elastic.pose.vertical - rigid.vertical, right.hertz.approach,
              0.2 * right.hertz.approach);
}

TEST(S1002On60E1, ElasticFlangeContactBalancesTheForces) {
  // At 8 mm the right wheel touches on its flange: with the load, tread and flange both carry.
  const RigidContact rigid = solve_rigid_contact(benchmark_geometry(), 0.008, 0, nullptr);
  ASSERT_TRUE(rigid.converged);
  const double load = 100e3, modulus = contact_modulus({210e9, 0.28}, {210e9, 0.28});
  const ElasticContact elastic =
      solve_elastic_contact(benchmark_geometry(), rigid, 0, load, modulus);
  ASSERT_TRUE(elastic.converged) << elastic.failure;
  ASSERT_TRUE(elastic.patches[1][1].loaded());
  double vertical = 0, lateral = 0, moment = 0;
  for (const auto& side : elastic.patches)
    for (const ElasticPatch& patch : side) {
      if (!patch.loaded())
        continue;
      // Each patch's force lies along its normal with Hertz's magnitude.
      EXPECT_NEAR(std::hypot(patch.force_y, patch.force_z), patch.hertz.load,
                  1e-12 * patch.hertz.load);
      vertical += patch.force_z;
      lateral += patch.force_y;
      moment += (patch.point.rail_point.y - elastic.pose.lateral) * patch.force_z -
                (patch.point.rail_point.z - (elastic.pose.vertical - 0.46)) * patch.force_y;
    }
  EXPECT_NEAR(-vertical, load, 1e-8 * load);
  EXPECT_NEAR(moment, 0, 1e-8 * load);
  EXPECT_NEAR(lateral, elastic.lateral_force, 1e-9 * load);
  // The flange pushes the wheelset back towards the centre.
  EXPECT_LT(elastic.lateral_force, 0);
}

// The table at 0.01 mm steps over ±15 mm, shared by the tests below.
const ContactTable& fine_table() {
  static const ContactTable table(benchmark_geometry(), 0.015, 3001);
  return table;
}

TEST(S1002On60E1, FlangeContactFromAboutSixMillimetresOnBothSides) {
  const ContactTable& table = fine_table();
  for (const auto& row : table.rows())
    ASSERT_TRUE(row.converged) << "shift " << row.lateral;
  const double right = table.flange_contact_shift(TrackSide::right);
  EXPECT_NEAR(right, 0.006, 0.0015);
  EXPECT_NEAR(table.flange_contact_shift(TrackSide::left), -right, 1e-9);
  // Mirror symmetry of the whole table: Δr(-y) = -Δr(y).
  const std::size_t n = table.rows().size();
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_NEAR(table.rolling_radius_difference(i), -table.rolling_radius_difference(n - 1 - i),
                1e-9);
  // On the flange the contact angle is steep.
  for (const auto& row : table.rows())
    if (row.lateral >= right) {
      EXPECT_GT(row.active(TrackSide::right).contact_angle, 30 * M_PI / 180);
    }
}

TEST(S1002On60E1, RollingRadiusDifferenceJumpsOnlyWhereTheContactPointJumps) {
  const ContactTable& table = fine_table();
  const double flange = table.flange_contact_shift(TrackSide::right);
  int flange_jumps = 0;
  for (std::size_t i = 1; i < table.rows().size(); ++i) {
    const RigidContact &a = table.rows()[i - 1], &b = table.rows()[i];
    double move = 0, angle_step = 0;
    for (TrackSide side : {TrackSide::left, TrackSide::right}) {
      move = std::max(move, std::abs(b.active(side).rail_point.y - a.active(side).rail_point.y));
      angle_step = std::max(angle_step,
                            std::abs(b.active(side).contact_angle - a.active(side).contact_angle));
    }
    const double dr_step =
        std::abs(table.rolling_radius_difference(i) - table.rolling_radius_difference(i - 1));
    if (move < 0.002) {
      // The contact point moved continuously over the 0.01 mm step: so did Δr and the angle.
      EXPECT_LT(dr_step, 0.5e-3) << "shift " << b.lateral;
      EXPECT_LT(angle_step, 5 * M_PI / 180) << "shift " << b.lateral;
    } else if (b.lateral == flange) {
      // Onto the flange: Δr and the contact angle jump.
      ++flange_jumps;
      EXPECT_GT(dr_step, 4e-3);
      EXPECT_GT(angle_step, 25 * M_PI / 180);
    }
  }
  EXPECT_EQ(flange_jumps, 1);
}

TEST(S1002On60E1, TableLeavesNoPenetrationAnywhereOnEitherWheel) {
  // The table tracks local minima and samples each part 100 times for lower ones; a 40 times
  // denser scan must find nothing the table missed.
  const ContactTable table(benchmark_geometry(), 0.015, 121);
  for (const auto& row : table.rows()) {
    const WheelsetPose pose{row.lateral, row.vertical, row.roll, 0};
    for (TrackSide side : {TrackSide::left, TrackSide::right})
      for (bool flange : {false, true}) {
        const GapSample least = least_gap_sample(benchmark_geometry(), side, flange, pose, 4000);
        EXPECT_GT(least.gap, -1e-8) << "shift " << row.lateral;
      }
  }
}

TEST(S1002On60E1, TableStartedSearchAgreesAndConvergesInAFewIterations) {
  // Start from a coarse table (0.25 mm steps) at the shifts of the fine one, half-way between
  // the coarse rows, in the fine table's rigid pose: the search must find the fine table's
  // contact, or say it did not.
  const ContactTable coarse(benchmark_geometry(), 0.015, 121);
  const ContactTable& fine = fine_table();
  int searches = 0, agreed = 0, refused = 0, most_iterations = 0;
  for (std::size_t i = 0; i < fine.rows().size(); i += 25) {
    const RigidContact& row = fine.rows()[i];
    const WheelsetPose pose{row.lateral, row.vertical, row.roll, 0};
    for (TrackSide side : {TrackSide::left, TrackSide::right}) {
      const ContactPoint& expected = row.active(side);
      const auto start = coarse.start(side, expected.flange, row.lateral);
      const ContactPoint found =
          search_contact(benchmark_geometry(), side, expected.flange, pose, start[0], start[1]);
      ++searches;
      if (!found.valid()) {
        ++refused;
        continue;
      }
      most_iterations = std::max(most_iterations, found.iterations);
      // A valid point is a true gap minimum: the expected one, or (near a jump, where the start
      // lies in the other basin) one with a gap no lower than it.
      if (std::abs(found.rail_point.y - expected.rail_point.y) < 1e-6) {
        ++agreed;
        EXPECT_NEAR(found.gap, 0, 1e-9);
      } else {
        EXPECT_GT(found.gap, -1e-9) << "shift " << row.lateral;
      }
    }
  }
  EXPECT_LE(most_iterations, 8);
  EXPECT_GE(agreed, searches - 8) << refused << " refused";
}

TEST(S1002On60E1, PlainNewtonFromTheCentreFailsWhereTheTableStartDoesNot) {
  // Stability where the method fails: shifts 0 to 15 mm towards the right flange, right wheel,
  // in the fine table's pose. Plain Newton started from the centred contact stops at the part's
  // end on every flange contact and mostly elsewhere; the trust region started from a 0.25 mm
  // table finds the table's contact in a few iterations, and where it lands in another basin
  // (next to a contact jump) that is still a true gap minimum, never a penetrating point.
  const ContactTable coarse(benchmark_geometry(), 0.015, 121);
  const ContactTable& fine = fine_table();
  const RigidContact& centre = fine.rows()[fine.rows().size() / 2];
  int shifts = 0, newton_correct = 0, newton_flange = 0, table_correct = 0, most_iterations = 0;
  for (std::size_t i = fine.rows().size() / 2; i < fine.rows().size(); i += 10, ++shifts) {
    const RigidContact& row = fine.rows()[i];
    const ContactPoint& expected = row.active(TrackSide::right);
    const WheelsetPose pose{row.lateral, row.vertical, row.roll, 0};
    const ContactPoint& centred = centre.parts[1][expected.flange ? 1 : 0];
    SearchSettings plain;
    plain.use_trust_region = false;
    const ContactPoint newton =
        search_contact(benchmark_geometry(), TrackSide::right, expected.flange, pose,
                       centred.s_wheel, centred.s_rail, plain);
    const bool newton_ok =
        newton.valid() && std::abs(newton.rail_point.y - expected.rail_point.y) < 1e-9;
    newton_correct += newton_ok;
    newton_flange += expected.flange && newton_ok;
    const auto start = coarse.start(TrackSide::right, expected.flange, row.lateral);
    const ContactPoint tabled = search_contact(benchmark_geometry(), TrackSide::right,
                                               expected.flange, pose, start[0], start[1]);
    ASSERT_TRUE(tabled.valid()) << "shift " << row.lateral;
    EXPECT_GT(tabled.gap, -1e-9) << "shift " << row.lateral;
    table_correct += std::abs(tabled.rail_point.y - expected.rail_point.y) < 1e-9;
    most_iterations = std::max(most_iterations, tabled.iterations);
  }
  EXPECT_EQ(newton_flange, 0);
  EXPECT_LT(newton_correct, shifts / 3);
  EXPECT_GE(table_correct, shifts - 2);
  EXPECT_LE(most_iterations, 8);
}

// The measured heavy-haul pair: the rail's head overhangs (y turns back on both flanks), the
// wheel is listed from its flange back towards the field side (mirrored, running point 70 mm
// from the back).
const WheelRailGeometry& worn_pair() {
  static const WheelRailGeometry geometry = [] {
    ProfileReadSettings wheel_axes;
    wheel_axes.mirror_y = true;
    wheel_axes.y_origin = 0.070;
    auto curve = [](const std::string& name, const ProfileReadSettings& settings) {
      std::vector<Vec2> points;
      for (const auto& p : read_profile_file(shipped_profile(name), settings).points)
        points.push_back({p[0], p[1]});
      return spline_curve(points);
    };
    return WheelRailGeometry(curve("site_b_hr.prr", {}), curve("worn_high_mileage.prw", wheel_axes),
                             TrackLayout{}, WheelsetLayout{});
  }();
  return geometry;
}

TEST(MeasuredProfiles, WornWheelOnWornHighRailClosesOrSaysSo) {
  // Within +-8.5 mm every row closes. From 8.7 mm, where the worn flange (78 degrees) comes into
  // contact, rows do not close, and they say so (converged false): no pose has both wheels
  // touching there (next test). No row that closed penetrates anywhere.
  const WheelRailGeometry& geometry = worn_pair();
  const ContactTable table(geometry, 0.015, 121);
  for (const auto& row : table.rows()) {
    if (std::abs(row.lateral) <= 0.0085 + 1e-12) {
      EXPECT_TRUE(row.converged) << "shift " << row.lateral;
    }
    if (!row.converged)
      continue;
    const WheelsetPose pose{row.lateral, row.vertical, row.roll, 0};
    for (TrackSide side : {TrackSide::left, TrackSide::right})
      for (bool flange : {false, true})
        EXPECT_GT(least_gap_sample(geometry, side, flange, pose, 2000).gap, -1e-8)
            << "shift " << row.lateral;
  }
}

// Least gap of the tread or flange of \p side in \p pose: the local search from the best of
// 2000 samples.
double part_gap(const WheelRailGeometry& geometry, TrackSide side, bool flange,
                const WheelsetPose& pose) {
  const GapSample s = least_gap_sample(geometry, side, flange, pose, 2000);
  const ContactPoint c = search_contact(geometry, side, flange, pose, s.s_wheel, s.s_rail);
  return c.valid() ? c.gap : s.gap;
}

TEST(MeasuredProfiles, WornPairPastItsFlangeContactHasNoPoseWithBothWheelsTouching) {
  // Why the worn pair's rows from 8.7 mm do not close: the worn flange (78.6 degrees) is steeper
  // than atan(2e / r0) = 73 degrees, so rolling the wheelset to lower the left wheel swings the
  // right flange into the rail (its gap grows with roll, the tread's falls). Of the three parts
  // that can touch (left tread, right tread, right flange), closing any two leaves the third
  // penetrating or the left wheel lifted: there is no rigid pose with both wheels touching.
  // Newton on the wheelset's vertical position and roll closes the two given parts.
  const WheelRailGeometry& geometry = worn_pair();
  struct Part {
    TrackSide side;
    bool flange;
  };
  const Part left_tread{TrackSide::left, false}, right_tread{TrackSide::right, false},
      right_flange{TrackSide::right, true};
  const auto third_gap = [&](double lateral, Part a, Part b, Part third) {
    double vertical = 1.8e-4, roll = 8.4e-5;
    for (int iteration = 0; iteration < 30; ++iteration) {
      const auto gaps = [&](double v, double r) {
        const WheelsetPose pose{lateral, v, r, 0};
        return std::array<double, 2>{part_gap(geometry, a.side, a.flange, pose),
                                     part_gap(geometry, b.side, b.flange, pose)};
      };
      const std::array<double, 2> g = gaps(vertical, roll), gv = gaps(vertical + 1e-7, roll),
                                  gr = gaps(vertical, roll + 1e-7);
      if (std::abs(g[0]) + std::abs(g[1]) < 1e-11)
        break;
      const double a00 = (gv[0] - g[0]) / 1e-7, a01 = (gr[0] - g[0]) / 1e-7,
                   a10 = (gv[1] - g[1]) / 1e-7, a11 = (gr[1] - g[1]) / 1e-7;
      const double det = a00 * a11 - a01 * a10;
      vertical -= (a11 * g[0] - a01 * g[1]) / det;
      roll -= (-a10 * g[0] + a00 * g[1]) / det;
    }
    return part_gap(geometry, third.side, third.flange, WheelsetPose{lateral, vertical, roll, 0});
  };
  for (double lateral : {0.00875, 0.010}) {
    // Both treads touching: the right flange penetrates (54 um at 8.75 mm).
    EXPECT_LT(third_gap(lateral, left_tread, right_tread, right_flange), -1e-5) << lateral;
    // Left tread and right flange: the right tread penetrates (0.48 mm at 8.75 mm).
    EXPECT_LT(third_gap(lateral, left_tread, right_flange, right_tread), -1e-4) << lateral;
    // The right wheel on tread and flange: the left wheel is lifted (0.17 mm at 8.75 mm, 4.1 mm
    // at 10 mm).
    EXPECT_GT(third_gap(lateral, right_tread, right_flange, left_tread), 1e-4) << lateral;
  }
  // At 8.5 mm, before the flange touches, both treads close with the flange clear.
  EXPECT_GT(third_gap(0.0085, left_tread, right_tread, right_flange), 0) << 0.0085;
}

}  // namespace
}  // namespace railfe
