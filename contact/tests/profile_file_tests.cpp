// Profile files: the shipped S1002 wheel (units, order, the benchmark's coordinates), the
// benchmark's rail read from its SIMPACK and its MiniProf file alike, two-column text, and the
// files and point lists the readers and checks must refuse or smooth.
#include <gtest/gtest.h>

#include <cmath>
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

TEST(ProfileFile, MiniProfAndSimpackFilesOfTheBenchmarkRailAgree) {
  const ProfileFile simpack = read_profile_file(shipped_profile("MBench_UIC60_v3.prr"));
  const ProfileFile miniprof = read_profile_file(shipped_profile("MBench_UIC60_v3.ban"));
  EXPECT_EQ(miniprof.type, ProfileType::rail);
  ASSERT_EQ(miniprof.points.size(), simpack.points.size());
  for (std::size_t i = 0; i < simpack.points.size(); ++i) {
    ASSERT_NEAR(miniprof.points[i][0], simpack.points[i][0], 1e-12) << i;
    ASSERT_NEAR(miniprof.points[i][1], simpack.points[i][1], 1e-12) << i;
  }
}

// Writes profile files into a scratch folder.
class ProfileFiles : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(dir_); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  // A SIMPACK rail listing \p points ("y z" lines).
  std::string rail(const std::string& name, const std::string& points) {
    return write(name,
                 "header.begin\n  type = 0  ! rail\nheader.end\nspline.begin\n"
                 "  units.len.f = 1000.\npoint.begin\n" +
                     points + "point.end\nspline.end\n");
  }
  std::string refusal(const std::string& path, const ProfileReadSettings& checks = {}) {
    return input_error_of([&] { read_profile_file(path, checks); });
  }
  fs::path dir_ = fs::temp_directory_path() / "railfe_profile_tests";
};

// A smooth rail crown: z = y^2 / 600 (mm), y from -20 to 20 mm in 1 mm steps.
std::string crown_points(std::function<double(int)> bump = [](int) { return 0.0; }) {
  std::string text;
  for (int y = -20; y <= 20; ++y)
    text += std::to_string(y) + " " + std::to_string(y * y / 600.0 + bump(y)) + "\n";
  return text;
}

TEST_F(ProfileFiles, ReadsCommentsInEitherOrderAndTwoColumnText) {
  // '%' lines and '!' line ends are skipped; a decreasing list comes back increasing.
  const ProfileFile rail_file =
      read_profile_file(rail("ok.prr", "% 9 9\n3 0.015 ! first\n2 0\n-1 0.0015 1.0\n"));
  EXPECT_EQ(rail_file.type, ProfileType::rail);
  ASSERT_EQ(rail_file.points.size(), 3u);
  EXPECT_DOUBLE_EQ(rail_file.points[0][0], -0.001);
  EXPECT_DOUBLE_EQ(rail_file.points[0][1], 0.0015e-3);
  EXPECT_DOUBLE_EQ(rail_file.points[2][0], 0.003);
  EXPECT_EQ(rail_file.lines[0], 10);  // the line each point came from, for messages

  const ProfileFile text =
      read_profile_file(write("crown.csv", "# y, z (mm)\n-1, 0.1\n0;0\n1 0.1\n"));
  EXPECT_EQ(text.type, ProfileType::unspecified);
  ASSERT_EQ(text.points.size(), 3u);
  EXPECT_DOUBLE_EQ(text.points[2][1], 0.1e-3);
}

TEST_F(ProfileFiles, RefusesUnreadableFiles) {
  auto message = refusal((dir_ / "missing.prr").string());
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
  message = refusal(write("profile.xyz", "1 2\n"));
  EXPECT_NE(message.find("unknown profile format '.xyz'"), std::string::npos) << message;
  message = refusal(rail("empty.prr", ""));
  EXPECT_NE(message.find("lists no profile points"), std::string::npos) << message;
  message = refusal(rail("text.prr", "1 0\n2 abc\n"));
  EXPECT_NE(message.find("'line 8': 'abc'"), std::string::npos) << message;
  message = refusal(write("unit.prr", "header.begin\ntype = 1\nheader.end\n"));
  EXPECT_NE(message.find("no length unit"), std::string::npos) << message;
  message = refusal(write("short.ban", "ColumnDef=X,Y\nXYPoints=4\n1 0\n2 0.1\n3 0.3\n"));
  EXPECT_NE(message.find("declares 4 points but the file lists 3"), std::string::npos) << message;
  message = refusal(write("columns.ban", "ColumnDef=Y,X\n1 0\n"));
  EXPECT_NE(message.find("no ColumnDef=X,Y"), std::string::npos) << message;
  message = refusal(write("three.txt", "1 2 3\n"));
  EXPECT_NE(message.find("'line 1': needs exactly two numbers"), std::string::npos) << message;
}

TEST_F(ProfileFiles, ReadsAnOverhangingRailHead) {
  // A 10 mm round head drawn from 120 degrees on one side to 120 on the other: y turns back
  // smoothly on both flanks, as on a measured worn rail.
  std::string points;
  for (int degrees = -120; degrees <= 120; degrees += 10) {
    const double t = degrees * M_PI / 180;
    points += std::to_string(10 * std::sin(t)) + " " + std::to_string(10 - 10 * std::cos(t)) + "\n";
  }
  const ProfileFile head = read_profile_file(rail("head.prr", points));
  ASSERT_EQ(head.points.size(), 25u);
  EXPECT_NEAR(head.points[21][0], 0.010, 1e-9);  // the widest point, beyond the last one's y
  EXPECT_GT(head.points[21][0], head.points.back()[0]);
}

TEST_F(ProfileFiles, RefusesRepeatedUnsortedAndLoopingPoints) {
  auto message = refusal(rail("twice.prr", "1 0\n2 0\n2 0\n3 0\n"));
  EXPECT_NE(message.find("'line 9, point 3 (y = 2 mm, z = 0 mm)': repeats the point before it"),
            std::string::npos)
      << message;
  message = refusal(rail("order.prr", "1 0\n2 0\n1.5 1\n"));
  EXPECT_NE(message.find("'line 9, point 3 (y = 1.5 mm, z = 1 mm)': the list turns back by 117"),
            std::string::npos)
      << message;
  // The list runs right, back left across itself, and on: a loop, found before the order.
  message = refusal(rail("loop.prr", "0 0\n4 0\n4 1\n2 -1\n6 -1\n"));
  EXPECT_NE(message.find("crosses itself (a loop)"), std::string::npos) << message;
}

TEST_F(ProfileFiles, RefusesZigZagsAndKinksUnlessSmoothed) {
  // One point 0.3 mm off a smooth crown: turns of about +-30 degrees either side of it.
  const std::string outlier =
      rail("outlier.prr", crown_points([](int y) { return y == 5 ? 0.3 : 0.0; }));
  auto message = refusal(outlier);
  EXPECT_NE(message.find("zig-zag"), std::string::npos) << message;
  EXPECT_NE(message.find("y = 4 mm"), std::string::npos) << message;
  // A corner: the crown continued by a 45-degree straight.
  std::string corner = crown_points();
  for (int y = 21; y <= 25; ++y)
    corner += std::to_string(y) + " " + std::to_string(400 / 600.0 + (y - 20)) + "\n";
  message = refusal(rail("corner.prr", corner));
  EXPECT_NE(message.find("kink"), std::string::npos) << message;
  // Smoothing takes the outlier down below the limits and leaves the crown where it was.
  ProfileReadSettings smooth;
  smooth.smoothing_passes = 8;
  const ProfileFile smoothed = read_profile_file(outlier, smooth);
  EXPECT_LT(smoothed.points[25][1], 0.3e-3 * 0.5);
  EXPECT_NEAR(smoothed.points[0][1], 400 / 600.0e3, 1e-9);  // the end point is kept
}

TEST_F(ProfileFiles, RefusesMirroredWheelsAndUpsideDownRails) {
  // A wheel whose flange (highest point) lies on -y: a file in the other convention.
  const std::string wheel =
      "header.begin\n  type = 1\nheader.end\nspline.begin\n  units.len.f = 1000.\n"
      "point.begin\n-30 10\n-20 5\n-10 1\n0 0\n10 -0.5\npoint.end\n";
  auto message = refusal(write("mirrored.prw", wheel));
  EXPECT_NE(message.find("flange (its highest point) lies at y <= 0"), std::string::npos)
      << message;
  message = refusal(rail("upside_down.prr", "-10 0\n-5 -0.5\n0 -1\n5 -1.5\n"));
  EXPECT_NE(message.find("rail's top"), std::string::npos) << message;
}

TEST_F(ProfileFiles, RefusesUpsideDownWheelsInEveryFormat) {
  // A flanged wheel in mm: a 1:40 tread and a smooth flange 28 mm high at y = 50.
  auto wheel = [](double sign_y, double sign_z) {
    std::string text;
    for (int k = 0; k <= 250; ++k) {
      const double y = -60 + 0.5 * k;
      const double z = y / 40 + 28 * std::exp(-std::pow((y - 50) / 15, 2));
      text += std::to_string(sign_y * y) + " " + std::to_string(sign_z * z) + "\n";
    }
    return text;
  };
  EXPECT_EQ(input_error_of([&] {
              read_profile_file(write("wheel.txt", wheel(1, 1)), {}, ProfileType::wheel);
            }),
            "");
  // Upside down: the highest point moves to the field side.
  auto message = input_error_of(
      [&] { read_profile_file(write("upside_down.txt", wheel(1, -1)), {}, ProfileType::wheel); });
  EXPECT_NE(message.find("upside_down.txt"), std::string::npos) << message;
  EXPECT_NE(message.find("upside down"), std::string::npos) << message;
  // Turned over (mirrored and upside down): the flange becomes a groove below the tread.
  message = input_error_of(
      [&] { read_profile_file(write("turned.txt", wheel(-1, -1)), {}, ProfileType::wheel); });
  EXPECT_NE(message.find("turned.txt"), std::string::npos) << message;
  EXPECT_NE(message.find("the wheel is upside down"), std::string::npos) << message;
  EXPECT_NE(message.find("z radially outwards"), std::string::npos) << message;
}

TEST_F(ProfileFiles, RefusesAProfileInTheWrongLengthUnit) {
  // A crown listed in mm with units.len.f = 1 (metres) would be 40 m wide.
  const std::string metres = write("metres.prr",
                                   "header.begin\n  type = 0\nheader.end\nspline.begin\n"
                                   "  units.len.f = 1.\npoint.begin\n" +
                                       crown_points() + "point.end\nspline.end\n");
  const std::string message = refusal(metres);
  EXPECT_NE(message.find("40.0"), std::string::npos) << message;
  EXPECT_NE(message.find("units.len.f"), std::string::npos) << message;
}

TEST_F(ProfileFiles, SaysADirectoryIsADirectory) {
  fs::create_directories(dir_ / "profile.prw");
  const std::string message = refusal((dir_ / "profile.prw").string());
  EXPECT_NE(message.find("is a directory"), std::string::npos) << message;
}

TEST_F(ProfileFiles, WarnsAboutSimpackProcessingFlagsItDoesNotApply) {
  const std::string crown = crown_points();
  const std::string flagged =
      write("flagged.prr",
            "header.begin\n  type = 0\nheader.end\nspline.begin\n  mirror.y = 0\n"
            "  mirror.z = 1\n  inversion = 1\n  shift.y = +0.0e+00\n  units.len.f = 1000.\n"
            "point.begin\n" +
                crown + "point.end\nspline.end\n");
  const ProfileFile profile = read_profile_file(flagged);
  ASSERT_EQ(profile.warnings.size(), 2u);
  EXPECT_NE(profile.warnings[0].find("flagged.prr"), std::string::npos) << profile.warnings[0];
  EXPECT_NE(profile.warnings[0].find("mirror.z = 1"), std::string::npos) << profile.warnings[0];
  EXPECT_NE(profile.warnings[1].find("inversion = 1"), std::string::npos) << profile.warnings[1];
  EXPECT_TRUE(read_profile_file(rail("plain.prr", crown)).warnings.empty());
}

TEST(ProfileChecks, LongStraightRunsAreNoLoop) {
  // A drawn 1:20 head side sampled every 0.2 mm (as drawings are, profile_drawing.hpp): exactly
  // collinear points, whose cross products far apart are round-off of the coordinates rather
  // than of the short segments; they must not be taken for a crossing.
  std::vector<std::array<double, 2>> points;
  const std::array<double, 2> a{-0.0337383, 0.0380724}, b{-0.0325, 0.0133073};
  for (int k = 0; k <= 125; ++k)
    points.push_back({a[0] + k / 125.0 * (b[0] - a[0]), a[1] + k / 125.0 * (b[1] - a[1])});
  EXPECT_NO_THROW(check_profile(points, {}, "side", {}));
}

}  // namespace
}  // namespace railfe
