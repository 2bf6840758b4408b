// Rail sections from their EN 13674-1 drawings: the published section properties (a check of
// every arc, line and fillet of the outline) and the Manchester benchmark's 60E1 head, which
// was digitized independently of railfe.

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
    SectionPoint low{0, 0};
    for (std::size_t i : outline.running_surface) {
      for (const SectionPoint& end : {outline.segments[i].start, outline.segments[i].end})
        low = end[1] < low[1] ? end : low;
    }
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
