#pragma once
/// \file
/// Standard drawings used as contact profiles: a deck names one as "drawing:<name>" where it
/// would give a profile file. The drawing's exact lines and arcs are sampled densely and the
/// points go through the same checks and spline as a file's, in the same axes: a rail's head
/// (right rail: y to the field side, z down, upright), a wheel's tread and flange (y from the
/// tape circle towards the flange, z radially outwards).

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "contact/geometry/profile_curve.hpp"
#include "contact/geometry/profile_file.hpp"

namespace railfe {

/// What a deck writes before a drawing's name to use it as a profile.
inline constexpr const char* kDrawingPrefix = "drawing:";

/// The drawings that can be used as a profile of \p role (rail or wheel).
std::vector<std::string> profile_drawing_names(ProfileType role);

/// Points of the drawing \p name as a profile of \p role, (y, z) in metres, listed from the
/// smaller y end, 0.2 mm apart at most. Throws std::invalid_argument for a name that is not in
/// profile_drawing_names(role).
std::vector<std::array<double, 2>> profile_drawing_points(const std::string& name,
                                                          ProfileType role);

/// The drawing \p name splined through profile_drawing_points (for tests and studies; decks go
/// through their Profiles settings).
std::shared_ptr<const ProfileCurve> drawing_curve(const std::string& name, ProfileType role);

}  // namespace railfe
