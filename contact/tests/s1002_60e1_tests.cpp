// The S1002 wheel on the 60E1 rail inclined 1:40 (the Manchester benchmark's profiles), gauge
// 1435 mm, back-to-back 1360 mm, r0 = 460 mm: tread contact when centred. (The flange-contact
// shift and the table-started online search are still being brought up: see issue 5.)
#include <gtest/gtest.h>

#include <cmath>

#include "contact/geometry/contact_table.hpp"
#include "contact/geometry/profile_file.hpp"

namespace railfe {
namespace {

std::shared_ptr<const ProfileCurve> shipped_curve(const std::string& name) {
  const ProfileFile file = read_profile_file(shipped_profile(name));
  std::vector<Vec2> points;
  for (const auto& p : file.points)
    points.push_back({p[0], p[1]});
  return spline_curve(points);
}

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
  for (Side side : {Side::left, Side::right}) {
    const ContactPoint& c = centre.active(side);
    EXPECT_FALSE(c.flange);
    // Near the running circle: within 5 mm of r0 and a tread's contact angle (below 5 degrees).
    EXPECT_NEAR(c.rolling_radius, 0.46, 0.002);
    EXPECT_LT(std::abs(c.contact_angle), 5 * M_PI / 180);
  }
  // Symmetric track and wheelset: equal radii, level axle.
  EXPECT_NEAR(centre.active(Side::right).rolling_radius, centre.active(Side::left).rolling_radius,
              1e-9);
  EXPECT_NEAR(centre.roll, 0, 1e-12);
}

}  // namespace
}  // namespace railfe
