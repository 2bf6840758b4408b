#pragma once
/// \file
/// Checks of a profile's point list before it is splined: repeated points, loops, points out of
/// order (the list reversing its direction of travel), zig-zags (alternating sharp turns,
/// typically measurement noise) and kinks (one sharp turn). y need not be monotonic: a measured
/// rail head may overhang. Each is refused with the file, the point's line and what to do; zig-zags
/// and kinks can instead be smoothed away on request.

#include <array>
#include <string>
#include <vector>

namespace railfe {

/// How a profile file is taken: its axes, the limits of the checks and the optional smoothing.
struct ProfileReadSettings {
  /// The file's y points the other way (for a wheel: towards the field side).
  bool mirror_y = false;
  /// The file's y (before mirroring, m) that becomes y = 0: a wheel's running point.
  double y_origin = 0;
  double kink_angle_degrees = 20;    ///< one turn sharper than this is a kink
  double zigzag_angle_degrees = 10;  ///< two opposite turns both sharper than this: a zig-zag
  int smoothing_passes = 0;          ///< [1 2 1]/4 filter passes on z before the turn checks
};

/// Checks \p points (y, z in metres, as listed) and smooths them when asked. \p lines gives each
/// point's line in \p source, for messages. Throws InputError at the first problem.
void check_profile(std::vector<std::array<double, 2>>& points, const std::vector<int>& lines,
                   const std::string& source, const ProfileReadSettings& settings);

}  // namespace railfe
