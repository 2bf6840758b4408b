// Rail sections from their drawings: the EN 13674-1 section properties (a check of every arc,
// line and fillet of the outline), the Manchester benchmark's 60E1 head, which was digitized
// independently of railfe, the JIS E 1101 60 kg rail's stated dimensions, and tangency at every
// join of every drawing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/geometry/profile_file.hpp"
#include "contact/geometry/rail_drawing.hpp"

using namespace railfe;

namespace {

void expect_closed_and_smooth_where_drawn(const RailOutline& outline) {
  const auto& s = outline.segments;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto& next = s[(i + 1) % s.size()];
    EXPECT_NEAR(s[i].end[0], next.start[0], 1e-12) << outline.name << " segment " << i;
    EXPECT_NEAR(s[i].end[1], next.start[1], 1e-12) << outline.name << " segment " << i;
  }
}

// The running surface's lowest end: where the gauge corner meets the head's side.
SectionPoint corner_end(const RailOutline& outline) {
  SectionPoint low{0, 0};
  for (std::size_t i : outline.running_surface) {
    for (const SectionPoint& end : {outline.segments[i].start, outline.segments[i].end})
      low = end[1] < low[1] ? end : low;
  }
  return low;
}

// The left half's segment that contains the point of the outline at height v on the side u < 0
// (the first one met going down the left half).
const OutlineSegment& left_segment_at(const RailOutline& outline, double v) {
  const std::size_t n = outline.segments.size();
  for (std::size_t i = n / 2; i < n; ++i) {
    const auto& s = outline.segments[i];
    if ((s.start[1] - v) * (s.end[1] - v) <= 0)
      return s;
  }
  throw std::logic_error("no segment at that height");
}

}  // namespace

TEST(RailDrawing, SectionPropertiesMatchTheStandardsTables) {
  // EN 13674-1 tables: 54E1 A = 69.77 cm², I = 2337.9 cm⁴ (horizontal axis); 60E1 A = 76.70
  // cm², I = 3038.3 cm⁴ and 512.3 cm⁴ (vertical axis). Rounded to the last digit given.
  struct Published {
    const char* name;
    double area_cm2, inertia_h_cm4, inertia_v_cm4, height_mm, head_mm, foot_mm;
  };
  for (const Published& p : {Published{"54E1", 69.77, 2337.9, 0, 159, 70, 140},
                             Published{"60E1", 76.70, 3038.3, 512.3, 172, 72, 150}}) {
    const RailOutline outline = rail_outline(p.name);
    expect_closed_and_smooth_where_drawn(outline);
    const SectionProperties props = section_properties(outline);
    EXPECT_NEAR(props.area * 1e4, p.area_cm2, 0.006) << p.name;
    EXPECT_NEAR(props.inertia_horizontal * 1e8, p.inertia_h_cm4, 0.06) << p.name;
    if (p.inertia_v_cm4 > 0) {
      EXPECT_NEAR(props.inertia_vertical * 1e8, p.inertia_v_cm4, 0.06) << p.name;
    }
    EXPECT_NEAR(props.centroid[0], 0, 1e-12) << p.name;
    double lowest = 0, widest = 0;
    for (const auto& s : outline.segments) {
      lowest = std::min({lowest, s.start[1], s.end[1]});
      widest = std::max({widest, std::abs(s.start[0]), std::abs(s.end[0])});
    }
    EXPECT_NEAR(-lowest * 1e3, p.height_mm, 1e-9) << p.name;
    EXPECT_NEAR(2 * widest * 1e3, p.foot_mm, 1e-9) << p.name;
    // The head's width is drawn where the 13 mm corner meets the 1:20 side: the lowest point of
    // the running surface.
    const SectionPoint low = corner_end(outline);
    const double head = outline_width_at(outline, low[1]);
    EXPECT_NEAR(head, 2 * std::abs(low[0]), 1e-6) << p.name;
    EXPECT_NEAR(head * 1e3, p.head_mm, 1e-3) << p.name;
  }
}

TEST(RailDrawing, The60E1HeadMatchesTheManchesterBenchmarksProfile) {
  // The benchmark's UIC60 profile is canted 1:40 with its own origin: fit the cant angle and
  // the offset, then every point of the running surface (down to 30 mm below the crown) lies
  // within the file's digitization of the drawing's exact arcs.
  const ProfileFile file =
      read_profile_file(shipped_profile("MBench_UIC60_v3.prr"), {}, ProfileType::rail);
  const RailOutline outline = rail_outline("60E1");
  std::vector<SectionPoint> head;
  for (const auto& q : file.points) {
    if (q[1] < 0.030)
      head.push_back(q);
  }
  ASSERT_GT(head.size(), 300u);
  // File (y, z down) to drawing (u, v up): rotate by the cant and shift.
  auto residuals = [&](const double x[3], double* worst) {
    double sum = 0, most = 0;
    for (const auto& q : head) {
      const double y = q[0] - x[1], z = q[1] - x[2];
      const double u = std::cos(x[0]) * y + std::sin(x[0]) * z;
      const double v = -(-std::sin(x[0]) * y + std::cos(x[0]) * z);
      const double d = distance_to_outline(outline, {u, v});
      sum += d * d;
      most = std::max(most, d);
    }
    if (worst)
      *worst = most;
    return std::sqrt(sum / head.size());
  };
  double x[3] = {-std::atan(1.0 / 40), -0.0075, 0}, step[3] = {1e-3, 1e-4, 1e-4};
  double best = residuals(x, nullptr);
  for (int sweep = 0; sweep < 200 && step[1] > 1e-9; ++sweep) {
    bool improved = false;
    for (int k = 0; k < 3; ++k) {
      for (double sign : {-1.0, 1.0}) {
        double y[3] = {x[0], x[1], x[2]};
        y[k] += sign * step[k];
        const double r = residuals(y, nullptr);
        if (r < best) {
          best = r, std::copy(y, y + 3, x), improved = true;
        }
      }
    }
    if (!improved) {
      for (double& s : step)
        s /= 2;
    }
  }
  double worst = 0;
  residuals(x, &worst);
  EXPECT_NEAR(1 / std::tan(-x[0]), 40, 0.1);  // the file's cant is 1:40
  EXPECT_LT(best, 20e-6);                     // rms distance
  EXPECT_LT(worst, 40e-6);
}

TEST(RailDrawing, EveryJoinOfEveryDrawingIsTangent) {
  // The drawings join their curves where they touch or by fillets, never at a corner: the
  // direction of travel is continuous all round (the foot's middle and the crown top included).
  for (const std::string& name : rail_drawing_names()) {
    const RailOutline outline = rail_outline(name);
    const auto& s = outline.segments;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const SectionPoint a = segment_tangent(s[i], true);
      const SectionPoint b = segment_tangent(s[(i + 1) % s.size()], false);
      EXPECT_NEAR(a[0] * b[0] + a[1] * b[1], 1, 1e-12) << name << " join after segment " << i;
    }
  }
}

TEST(RailDrawing, Jis60HasTheStandardsDimensions) {
  // JIS E 1101 60 kg: height 174, foot 145, head 65, web 16.5, head depth 49, foot depth 30.1,
  // crown R600, neck radii 19, the foot's top 1:4 (contact/geometry/rail_drawing.cpp: sources).
  const RailOutline outline = rail_outline("JIS60");
  expect_closed_and_smooth_where_drawn(outline);
  double lowest = 0, widest = 0;
  for (const auto& s : outline.segments) {
    lowest = std::min({lowest, s.start[1], s.end[1]});
    widest = std::max({widest, std::abs(s.start[0]), std::abs(s.end[0])});
  }
  EXPECT_NEAR(-lowest, 0.174, 1e-12);
  EXPECT_NEAR(2 * widest, 0.145, 1e-12);
  const SectionPoint low = corner_end(outline);
  EXPECT_NEAR(2 * std::abs(low[0]), 0.065, 1e-9);
  EXPECT_NEAR(outline_width_at(outline, low[1]), 0.065, 1e-6);
  // The web: 16.5 mm thick anywhere between the neck fillets.
  EXPECT_NEAR(outline_width_at(outline, -0.049 - 0.0949 / 2), 0.0165, 1e-6);
  // The crown top lies on the R600 arc, centred on the axis; then R80, R13, the 1:20 side.
  const OutlineSegment& crown = left_segment_at(outline, -1e-9);
  ASSERT_TRUE(crown.is_arc);
  EXPECT_NEAR(crown.radius, 0.600, 1e-12);
  EXPECT_NEAR(crown.centre[0], 0, 1e-12);
  EXPECT_NEAR(crown.centre[1], -0.600, 1e-12);
  const std::size_t top = outline.segments.size() / 2;
  EXPECT_NEAR(outline.segments[top + 1].radius, 0.080, 1e-12);
  EXPECT_NEAR(outline.segments[top + 2].radius, 0.013, 1e-12);
  const SectionPoint side = segment_tangent(outline.segments[top + 3], false);
  EXPECT_NEAR(side[0] / side[1], 1.0 / 20, 1e-12);
  // The necks: R19 above and below the straight web, whose flanks meet the axis 49 mm below the
  // top and 30.1 mm above the bottom; the foot's top falls 1:4 to the edge.
  const OutlineSegment& web = left_segment_at(outline, -0.1);
  ASSERT_FALSE(web.is_arc);
  const OutlineSegment &upper = *(&web - 1), &lower = *(&web + 1), &foot = *(&web + 2);
  EXPECT_NEAR(upper.radius, 0.019, 1e-12);
  EXPECT_NEAR(lower.radius, 0.019, 1e-12);
  ASSERT_FALSE(foot.is_arc);
  const SectionPoint f = segment_tangent(foot, false);
  EXPECT_NEAR(f[1] / f[0], 1.0 / 4, 1e-12);
  EXPECT_NEAR(foot.start[1] + std::abs(foot.start[0]) / 4, -0.174 + 0.0301, 1e-12);
  const SectionPoint u = segment_tangent(*(&upper - 1), false);  // the head's underside
  EXPECT_NEAR(-u[1] / u[0], 1.0 / 4, 1e-12);
  const OutlineSegment& underside = *(&upper - 1);
  EXPECT_NEAR(underside.end[1] - std::abs(underside.end[0]) / 4, -0.049, 1e-12);
  // About 60 kg/m of steel (7850 kg/m^3): the rail's name; the shape above is mostly chosen.
  const double mass = section_properties(outline).area * 7850;
  EXPECT_GT(mass, 59.5);
  EXPECT_LT(mass, 62.0);
}
