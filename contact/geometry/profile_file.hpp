#pragma once
/// \file
/// Wheel and rail profile files, told apart by their extension:
/// - SIMPACK (.prw wheel, .prr rail): a header with the profile type, a spline block with the
///   length unit, and the point list between point.begin and point.end, one "y z [weight]" per
///   line. Lines or line ends after '!' or '%' are comments.
/// - MiniProf (.whl wheel, .ban rail): "Key=Value" header lines (ColumnDef must start X,Y;
///   XYPoints, when given, must match), then "X Y" lines in mm, a leading '"' allowed. y = -X,
///   z = Y (checked on the Manchester benchmark's rail, which ships in both formats).
/// - Two-column text (.txt, .dat, .csv): "y z" in mm in SIMPACK's axes, separated by blanks,
///   commas or semicolons; '#' starts a comment. The type is the caller's to say.
/// Every list then passes check_profile (profile_checks.hpp).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "contact/geometry/profile_checks.hpp"
#include "contact/geometry/profile_curve.hpp"

namespace railfe {

/// What a profile describes.
enum class ProfileType {
  rail,        ///< SIMPACK header type 0, MiniProf .ban
  wheel,       ///< SIMPACK header type 1, MiniProf .whl
  unspecified  ///< two-column text
};

/// A profile as read from a file.
struct ProfileFile {
  std::string source;                    ///< the file, for messages
  ProfileType type = ProfileType::rail;  ///< from the header
  std::string comment;                   ///< the spline block's comment, if any
  /// (y, z) in metres, listed from the smaller to the larger y end (y need not be monotonic in
  /// between). Coordinates are as the file lists them: for the
  /// Manchester benchmark's S1002 wheel, y is lateral from the running point (the flange on +y,
  /// its back face near y = 70 mm) and z grows radially outwards (the flange tip at z = 28 mm).
  std::vector<std::array<double, 2>> points;
  std::vector<int> lines;  ///< each point's line in the file
  /// Header settings the reader does not apply (a SIMPACK spline block's mirror, inversion,
  /// shift or rotation that is not neutral), one line each naming the file and the setting:
  /// the caller prints them, since the points are taken as listed.
  std::vector<std::string> warnings;
};

/// Reads a profile file of any of the formats above (lengths in metres, listed from the smaller
/// to the larger y end) after moving y to \p checks' origin and mirroring it, and checks it with
/// \p checks. The SIMPACK spline block's processing
/// settings (shift, rotate, bound, mirror, inversion, smoothing) are not applied; those that are
/// not neutral are listed in ProfileFile::warnings. The profile must be the right way up for
/// \p role (a two-column file takes the role it is given as): a wheel's flange (its highest
/// point) on +y, above its running point; a rail's top its lowest z, inside the profile, with
/// the head's sides falling away from it. Throws InputError naming the file (and line) when it
/// is missing, a directory, unreadable or fails a check.
ProfileFile read_profile_file(const std::string& path, const ProfileReadSettings& checks = {},
                              ProfileType role = ProfileType::unspecified);

/// Path of a profile file shipped with railfe in inputs/profiles (e.g. "MBench_S1002_v3.prw").
std::string shipped_profile(const std::string& file_name);

/// The shipped profile \p file_name read with the default checks and splined through its points
/// as listed (for tests, studies and benchmarks; decks go through their Profiles settings).
std::shared_ptr<const ProfileCurve> shipped_curve(const std::string& file_name);

}  // namespace railfe
