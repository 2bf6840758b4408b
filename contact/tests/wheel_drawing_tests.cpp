// Wheel profiles from their drawings: the Shinkansen-type 860 mm conic-and-arc wheel against
// the dimensions it is drawn to (1:40 cone through the tape circle, R1000 tread arc, 70° flange,
// flange height and thickness), tangency at every join, the sampled profile that decks use
// against the exact drawing, and the wheel on the JIS 60 kg rail: a 1:40 cone on the 1:40 rail
// gives Δr = 2 y / 40 while the contact stays on the cone.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/profile_drawing.hpp"
#include "contact/geometry/rail_drawing.hpp"
#include "contact/geometry/wheel_drawing.hpp"

namespace railfe {
namespace {

double slope(const SectionPoint& direction) {
  return direction[1] / direction[0];
}

// The point of the outline's segment \p s at height z (lines only).
double y_at_height(const OutlineSegment& s, double z) {
  return s.start[0] + (z - s.start[1]) / (s.end[1] - s.start[1]) * (s.end[0] - s.start[0]);
}

TEST(WheelDrawing, Shinkansen860HasItsDrawnDimensions) {
  const WheelOutline wheel = wheel_outline("Shinkansen860");
  // Cone, tread arc, root fillet, flange face, tip arc, back face.
  const auto& s = wheel.segments;
  ASSERT_EQ(s.size(), 6u);
  EXPECT_NEAR(wheel.nominal_radius, 0.43, 1e-15);
  EXPECT_NEAR(wheel.flange_back, 0.065, 1e-15);
  // The cone: 1:40 from the rim's field side (125 mm from the back face) to the tape circle,
  // which it passes at z = 0 (radius 0.43 m).
  ASSERT_FALSE(s[0].is_arc);
  EXPECT_NEAR(slope(segment_tangent(s[0], false)), 1.0 / 40, 1e-15);
  EXPECT_NEAR(s[0].start[0], 0.065 - 0.125, 1e-15);
  EXPECT_NEAR(s[0].end[0], 0, 1e-15);
  EXPECT_NEAR(s[0].end[1], 0, 1e-15);
  // The tread arc: R1000, concave (turning towards the outside), from the tape circle.
  ASSERT_TRUE(s[1].is_arc);
  EXPECT_NEAR(s[1].radius, 1.0, 1e-15);
  EXPECT_EQ(s[1].turn, 1);
  EXPECT_GT(s[1].centre[1], 0.9);
  // The root fillet R15, concave too, then the straight face at 70° to the axle.
  ASSERT_TRUE(s[2].is_arc);
  EXPECT_NEAR(s[2].radius, 0.015, 1e-15);
  EXPECT_EQ(s[2].turn, 1);
  ASSERT_FALSE(s[3].is_arc);
  const SectionPoint face = segment_tangent(s[3], false);
  EXPECT_NEAR(std::atan2(face[1], face[0]) * 180 / M_PI, 70, 1e-12);
  // Flange 30 mm thick 15 mm above the tape circle (on the straight face), 30 mm high.
  ASSERT_LT(s[3].start[1], 0.015);
  ASSERT_GT(s[3].end[1], 0.015);
  EXPECT_NEAR(wheel.flange_back - y_at_height(s[3], 0.015), 0.030, 1e-12);
  ASSERT_TRUE(s[4].is_arc);
  EXPECT_EQ(s[4].turn, -1);
  EXPECT_NEAR(s[4].centre[1] + s[4].radius, 0.030, 1e-12);  // the tip's top: flange height
  // The tip arc touches the back face, which runs straight down at the flange back.
  EXPECT_NEAR(s[4].centre[0] + s[4].radius, 0.065, 1e-12);
  EXPECT_NEAR(s[5].start[0], 0.065, 1e-12);
  EXPECT_NEAR(s[5].end[0], 0.065, 1e-12);
  EXPECT_LT(s[5].end[1], s[5].start[1]);
}

TEST(WheelDrawing, EveryJoinIsTangent) {
  // Each join continues the direction of travel: the arc of the tread leaves the cone along it,
  // and the fillets meet both their curves tangentially.
  const auto& s = wheel_outline("Shinkansen860").segments;
  for (std::size_t i = 0; i + 1 < s.size(); ++i) {
    EXPECT_NEAR(s[i].end[0], s[i + 1].start[0], 1e-15) << "join " << i;
    EXPECT_NEAR(s[i].end[1], s[i + 1].start[1], 1e-15) << "join " << i;
    const SectionPoint a = segment_tangent(s[i], true), b = segment_tangent(s[i + 1], false);
    EXPECT_NEAR(a[0] * b[0] + a[1] * b[1], 1, 1e-12) << "join " << i;
  }
}

TEST(WheelDrawing, DimensionsThatLeaveNoFlangeAreRefused) {
  ConicArcWheel flat;
  flat.flange_height = 10;  // below where the thickness is measured
  EXPECT_THROW(conic_arc_wheel("flat", flat), std::invalid_argument);
  EXPECT_THROW(wheel_outline("S1002"), std::invalid_argument);
}

TEST(WheelDrawing, SplinedProfileFollowsTheDrawing) {
  // The profile decks use: the drawing sampled 0.2 mm apart and splined. Midway between the
  // samples it stays within a micrometre of the exact lines and arcs (most of it far closer).
  const WheelOutline wheel = wheel_outline("Shinkansen860");
  const auto curve = drawing_curve("Shinkansen860", ProfileType::wheel);
  double worst = 0;
  for (double s = curve->begin(); s < curve->end(); s += 1.3e-4) {
    const Vec2 p = curve->at(s).p;
    worst = std::max(worst, distance_to_segments(wheel.segments, {p.y, p.z}));
  }
  EXPECT_LT(worst, 1e-6);
}

// The drawn wheel on the drawn JIS 60 kg rail, 1:40, on 1067 mm gauge with 990 mm between the
// flange backs (as inputs/scenes/jis60_shinkansen_on_track.xml).
WheelRailGeometry jis_geometry() {
  TrackLayout track;
  track.gauge = 1.067;
  track.gauge_depth = 0.016;
  track.inclination = 1.0 / 40;
  track.profile_inclined = false;
  WheelsetLayout wheelset;
  wheelset.back_to_back = 0.990;
  wheelset.flange_back = 0.065;
  wheelset.nominal_radius = 0.43;
  return WheelRailGeometry(drawing_curve("JIS60", ProfileType::rail),
                           drawing_curve("Shinkansen860", ProfileType::wheel), track, wheelset);
}

TEST(WheelDrawing, TreadAndFlangeSplitInTheMiddleOfTheRoot) {
  // The root is an R15 arc from 18.9 to 32.4 mm: concave alike all along, so the split between
  // tread and flange lies inside it, away from its ends (where the spline through the points
  // rings and the most concave sample would fall), and root contacts count as flange contacts.
  const WheelRailGeometry geometry = jis_geometry();
  for (TrackSide side : {TrackSide::left, TrackSide::right}) {
    const double eta = geometry.wheel(side).at(geometry.flange_split(side)).p.y;
    const double y = 0.560 - std::abs(eta);  // from the tape circle towards the flange
    EXPECT_GT(y, 0.0219);
    EXPECT_LT(y, 0.0294);
  }
}

// Δr of a rigid wheelset of cones (slope λ, radius r0 at a from the axle's middle) on two
// circular crowns (radius R, centres c either side): both cone lines lie R from the crown
// centres, which fixes the roll φ and the centres' depth H below the axle for each shift y:
//   sin φ (λ H - c) = λ y cos φ,   cos φ (λ c + H) + y sin φ = r0 + λ a + R √(1 + λ²),
// and then Δr = 2 λ (y cos φ - H sin φ) (≈ 2 λ y c / (c - λ (r0 + R)): the crowns' roll
// correction, as for wheelset_cone_on_crown).
double cone_on_crowns(double y, double lambda, double r0, double a, double radius, double c) {
  const double m = r0 + lambda * a + radius * std::sqrt(1 + lambda * lambda);
  double phi = 0, h = m - lambda * c;
  for (int k = 0; k < 100; ++k) {
    phi = std::atan(lambda * y / (lambda * h - c));
    h = (m - y * std::sin(phi)) / std::cos(phi) - lambda * c;
  }
  return 2 * lambda * (y * std::cos(phi) - h * std::sin(phi));
}

TEST(WheelDrawing, ConeOnTheJis60CrownGivesTheConeOnCrownsRollingRadii) {
  // The 1:40 cone on the 1:40 rail touches where the rail's surface slopes 1:40 in the track:
  // the R600 crown's top. The contact stays there and on the cone (which ends at the tape
  // circle) while the flange-side wheel's contact, which starts about 6 mm field-side of its
  // tape circle, slides along the cone: Δr follows cone_on_crowns to a few nanometres.
  const WheelRailGeometry geometry = jis_geometry();
  const ContactTable table(geometry, 0.005, 51);
  const double lambda = 1.0 / 40, delta = std::atan(lambda);
  // The crown centre: 600 mm below and inboard of the centred contact point along its normal.
  const std::size_t centre = table.rows().size() / 2;
  const double c =
      table.rows()[centre].active(TrackSide::right).rail_point.y + 0.6 * std::sin(delta);
  for (std::size_t i = 0; i < table.rows().size(); ++i) {
    const RigidContact& row = table.rows()[i];
    ASSERT_TRUE(row.converged) << row.lateral;
    EXPECT_NEAR(table.rolling_radius_difference(i),
                cone_on_crowns(row.lateral, lambda, 0.43, 0.56, 0.6, c), 5e-9)
        << row.lateral;
    for (TrackSide side : {TrackSide::left, TrackSide::right}) {
      EXPECT_FALSE(row.active(side).flange);
      EXPECT_NEAR(row.active(side).contact_angle, delta, 1e-3);
    }
  }
  // The centred contact lies on the cone, about 6 mm field-side of the tape circle.
  const double y_on_wheel = 0.560 - table.half_contact_distance();
  EXPECT_LT(y_on_wheel, -0.005);
  EXPECT_GT(y_on_wheel, -0.008);
  EXPECT_NEAR(table.centred_rolling_radius(), 0.43 + y_on_wheel / 40, 1e-7);
}

}  // namespace
}  // namespace railfe
