#pragma once
/// \file
/// Wheel and rail profiles placed on a track, as decks give them: the "Profiles" and "Track"
/// sublists shared by the steps that work on contact geometry (wheelset on track, wheelset
/// dynamics), and the geometry built from them with errors that name the deck, the parameter
/// and the file.

#include <memory>

#include "contact/geometry/wheel_rail_geometry.hpp"
#include "framework/app/module.hpp"

namespace railfe {

/// The "Profiles" sublist: profile files and their checks.
ParameterSpec profile_parameters();
/// The "Track" sublist: track and wheelset dimensions.
ParameterSpec track_parameters();
/// Reads the profiles of the step \p step (its Profiles and Track sublists) and places them;
/// warnings go to standard error on rank 0. Throws InputError naming the deck, the parameter
/// and the file.
std::shared_ptr<WheelRailGeometry> read_profile_geometry(const Teuchos::ParameterList& step,
                                                         const CheckContext& context);

}  // namespace railfe
