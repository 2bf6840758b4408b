// SIMPACK profile files: the shipped S1002 wheel (units, order, the benchmark's coordinates) and
// the files the reader must refuse.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "contact/geometry/profile_file.hpp"
#include "framework/base/error.hpp"
#include "framework/testing/input_error.hpp"

namespace railfe {
namespace {

namespace fs = std::filesystem;

TEST(ProfileFile, ReadsTheS1002Wheel) {
  const ProfileFile profile = read_profile_file(shipped_profile("MBench_S1002_v3.prw"));
  EXPECT_EQ(profile.type, ProfileType::wheel);
  EXPECT_NE(profile.comment.find("S1002"), std::string::npos);
  ASSERT_EQ(profile.points.size(), 399u);  // the first listed point is commented out
  // Listed from the flange back (y = 69.6 mm) to the field side (y = -60 mm), in mm.
  EXPECT_DOUBLE_EQ(profile.points.front()[0], -0.060);
  EXPECT_DOUBLE_EQ(profile.points.front()[1], -2.6356764e-3);
  EXPECT_DOUBLE_EQ(profile.points.back()[0], 69.612628e-3);
  for (std::size_t i = 1; i < profile.points.size(); ++i)
    ASSERT_GT(profile.points[i][0], profile.points[i - 1][0]);
  // The flange tip stands 28 mm above the running point (y = 0, z = 0).
  double tip = 0;
  for (const auto& point : profile.points)
    tip = std::max(tip, point[1]);
  EXPECT_NEAR(tip, 0.028, 1e-6);
}

TEST(ProfileFile, RefusesWhatItCannotUse) {
  const auto dir = fs::temp_directory_path() / "railfe_profile_tests";
  fs::create_directories(dir);
  const std::string header =
      "header.begin\n  type = 0  ! rail\nheader.end\nspline.begin\n  units.len.f = 1000.\n";
  auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  auto message = input_error_of([&] { read_profile_file((dir / "missing.prr").string()); });
  EXPECT_NE(message.find("not found"), std::string::npos) << message;

  message = input_error_of([&] {
    read_profile_file(write("empty.prr", header + "  point.begin\n  point.end\nspline.end\n"));
  });
  EXPECT_NE(message.find("lists no profile points"), std::string::npos) << message;

  message = input_error_of([&] {
    read_profile_file(write("twice.prr", header + "point.begin\n1 0\n2 0\n2 1\npoint.end\n"));
  });
  EXPECT_NE(message.find("'line 9': y = 2 is listed twice"), std::string::npos) << message;

  message = input_error_of([&] {
    read_profile_file(write("order.prr", header + "point.begin\n1 0\n2 0\n1.5 1\npoint.end\n"));
  });
  EXPECT_NE(message.find("breaks the order"), std::string::npos) << message;

  message = input_error_of([&] {
    read_profile_file(write("text.prr", header + "point.begin\n1 0\n2 abc\npoint.end\n"));
  });
  EXPECT_NE(message.find("'abc'"), std::string::npos) << message;

  message = input_error_of(
      [&] { read_profile_file(write("unit.prr", "header.begin\ntype = 1\nheader.end\n")); });
  EXPECT_NE(message.find("no length unit"), std::string::npos) << message;

  // Comments ('%' lines, '!' line ends) are skipped; a decreasing list comes back increasing.
  const ProfileFile rail = read_profile_file(
      write("ok.prr", header + "point.begin\n% 9 9\n3 1 ! first\n2 0\n-1 4 1.0\npoint.end\n"));
  EXPECT_EQ(rail.type, ProfileType::rail);
  ASSERT_EQ(rail.points.size(), 3u);
  EXPECT_DOUBLE_EQ(rail.points[0][0], -0.001);
  EXPECT_DOUBLE_EQ(rail.points[0][1], 0.004);
  EXPECT_DOUBLE_EQ(rail.points[2][0], 0.003);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace railfe
