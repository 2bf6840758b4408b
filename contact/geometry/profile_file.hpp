#pragma once
/// \file
/// Wheel and rail profiles as SIMPACK writes them (.prw wheel, .prr rail): a header with the
/// profile type, a spline block with the length unit, and the point list between point.begin
/// and point.end, one "y z [weight]" per line. Lines or line ends after '!' or '%' are comments.

#include <array>
#include <string>
#include <vector>

namespace railfe {

/// What a profile describes.
enum class ProfileType {
  rail,  ///< header type 0
  wheel  ///< header type 1
};

/// A profile as read from a file.
struct ProfileFile {
  std::string source;                    ///< the file, for messages
  ProfileType type = ProfileType::rail;  ///< from the header
  std::string comment;                   ///< the spline block's comment, if any
  /// (y, z) in metres, y strictly increasing. Coordinates are as the file lists them: for the
  /// Manchester benchmark's S1002 wheel, y is lateral from the running point (the flange on +y,
  /// its back face near y = 70 mm) and z grows radially outwards (the flange tip at z = 28 mm).
  std::vector<std::array<double, 2>> points;
};

/// Reads a SIMPACK profile. Lengths are divided by the file's units.len.f (1000 for mm). The
/// spline block's processing settings (shift, rotate, bound, mirror, inversion, smoothing) are
/// not applied; the points are taken as listed and returned in increasing y. Throws InputError
/// naming the file (and line) when it is missing or unreadable, has no type or length unit, lists
/// no points, or lists them out of order or twice (y must be strictly monotonic).
ProfileFile read_profile_file(const std::string& path);

/// Path of a profile file shipped with railfe in inputs/profiles (e.g. "MBench_S1002_v3.prw").
std::string shipped_profile(const std::string& file_name);

}  // namespace railfe
