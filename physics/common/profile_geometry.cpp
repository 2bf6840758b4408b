#include "physics/common/profile_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>

#include "contact/geometry/profile_drawing.hpp"
#include "contact/geometry/profile_file.hpp"
#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"

namespace railfe {

namespace {

// Reads the profile \p file that the deck's \p parameter points to; every error about the file
// names the deck and that parameter too. Warnings (header settings not applied) go to \p warnings.
std::shared_ptr<const ProfileCurve> read_curve(const std::string& file, ProfileType role,
                                               const ProfileReadSettings& checks,
                                               const std::string& deck,
                                               const std::string& parameter,
                                               std::vector<std::string>& warnings) {
  ProfileFile profile;
  try {
    profile = read_profile_file(file, checks, role);
  } catch (const InputError& error) {
    throw_input_error(deck, parameter, std::string("profile file ") + error.what());
  }
  if (profile.type != role && profile.type != ProfileType::unspecified)
    throw_input_error(deck, parameter,
                      "profile file " + file + ": is a " +
                          (profile.type == ProfileType::rail ? "rail" : "wheel") +
                          " profile, given as " + parameter,
                      role == ProfileType::rail ? "a rail profile" : "a wheel profile");
  for (const std::string& warning : profile.warnings)
    warnings.push_back(warning + " (" + deck + ": " + parameter + ")");
  return spline_curve(profile.points);
}

const char* role_name(ProfileType role) {
  return role == ProfileType::rail ? "rail" : "wheel";
}

// "drawing:A, drawing:B, ..." for the drawings of \p role.
std::string drawing_list(ProfileType role) {
  std::string list;
  for (const std::string& name : profile_drawing_names(role))
    list += (list.empty() ? "" : ", ") + std::string(kDrawingPrefix) + name;
  return list;
}

// The drawing \p name that the deck's \p parameter names ("drawing:<name>"), through the same
// checks as a file's points; an unknown name is refused with the drawings the parameter takes.
std::shared_ptr<const ProfileCurve> drawn_curve(const std::string& name, ProfileType role,
                                                const ProfileReadSettings& checks,
                                                const std::string& deck,
                                                const std::string& parameter) {
  const auto names = profile_drawing_names(role);
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    const ProfileType other = role == ProfileType::rail ? ProfileType::wheel : ProfileType::rail;
    const auto others = profile_drawing_names(other);
    const std::string near = closest_name(name, names);
    throw_input_error(deck, parameter,
                      std::find(others.begin(), others.end(), name) != others.end()
                          ? kDrawingPrefix + name + " is a " + role_name(other) + " drawing"
                          : "unknown " + std::string(role_name(role)) + " drawing '" + name + "'" +
                                (near.empty() ? "" : " (did you mean " + near + "?)"),
                      drawing_list(role) + ", or a profile file");
  }
  auto points = profile_drawing_points(name, role);
  check_profile(points, {}, kDrawingPrefix + name, checks);
  return spline_curve(points);
}

}  // namespace

ParameterSpec profile_parameters() {
  ParameterSpec spec("Profile files and their checks.");
  spec.text("Rail", "",
            "Rail profile, right rail, y to the field side, z down (SIMPACK .prr, MiniProf .ban "
            "or two-column text in mm), relative to the deck; empty = the Manchester "
            "benchmark's 60E1 (canted 1:40); or a standard drawing's head, upright: " +
                drawing_list(ProfileType::rail) + ".");
  spec.text("Wheel", "",
            "Wheel profile, y from the running point towards the flange, z radially outwards "
            "(SIMPACK .prw, MiniProf .whl or two-column text in mm); empty = the benchmark's "
            "S1002; or a standard drawing: " +
                drawing_list(ProfileType::wheel) + ".");
  spec.flag("Wheel mirrored", false,
            "The wheel file's y runs towards the field side (as many measured profiles, from the "
            "flange back, list it). Files only: drawings are in railfe's axes.");
  spec.real("Wheel running point", 0,
            "The wheel file's y of the running point (the nominal rolling radius), before "
            "mirroring. Files only: a drawing's running point is its tape circle.",
            "m");
  spec.flag("Rail mirrored", false,
            "The rail file's y runs towards the gauge side. Files only: drawings are in "
            "railfe's axes.");
  spec.flag("Rail canted", true,
            "The rail profile is already drawn at the track's inclination (as the benchmark's "
            "is); false rotates it by Track/Inclination. Files only: a drawing is upright and "
            "always rotated.");
  spec.integer("Smoothing passes", 0,
               "[1 2 1]/4 filter passes on z before the zig-zag and kink checks (measured "
               "profiles).",
               Range::at_least(0));
  spec.real("Kink angle", 20, "One turn of the point list sharper than this is refused.", "degree",
            Range::open(0.0, 180.0));
  spec.real("Zig-zag angle", 10,
            "Two opposite turns in a row both sharper than this are refused (noise).", "degree",
            Range::open(0.0, 180.0));
  return spec;
}

ParameterSpec track_parameters() {
  ParameterSpec spec("Track and wheelset dimensions.");
  // Ranges span the world's gauges (600 mm to 1676 mm) and wheels (tram to locomotive), so
  // a value in the wrong unit is refused here rather than failing the contact search later.
  spec.real("Gauge", 1.435, "Between the rails' gauge points.", "m", Range::closed(0.5, 2.0));
  spec.real("Gauge point depth", 0.014, "Depth of the gauge point below the top of rail.", "m",
            Range::closed(0.001, 0.05));
  spec.real("Inclination", 1.0 / 40, "Rail cant, tan of the angle towards the track centre.", "",
            Range::closed(0.0, 0.2));
  spec.real("Back to back", 1.360, "Between the wheels' flange back faces; within 0.2 m of Gauge.",
            "m", Range::closed(0.4, 1.9));
  spec.real("Flange back", 0.070, "The wheel profile's y of the flange back face.", "m",
            Range::closed(0.0, 0.2));
  spec.real("Nominal radius", 0.46, "Rolling radius at the wheel profile's y = 0.", "m",
            Range::closed(0.1, 1.0));
  return spec;
}

std::shared_ptr<WheelRailGeometry> read_profile_geometry(const Teuchos::ParameterList& step,
                                                         const CheckContext& context) {
  const Deck& deck = context.model.deck();
  const auto& profiles = step.sublist("Profiles");
  ProfileReadSettings checks;
  checks.smoothing_passes = profiles.get<int>("Smoothing passes");
  checks.kink_angle_degrees = profiles.get<double>("Kink angle");
  checks.zigzag_angle_degrees = profiles.get<double>("Zig-zag angle");
  ProfileReadSettings rail_axes = checks, wheel_axes = checks;
  rail_axes.mirror_y = profiles.get<bool>("Rail mirrored");
  wheel_axes.mirror_y = profiles.get<bool>("Wheel mirrored");
  wheel_axes.y_origin = profiles.get<double>("Wheel running point");
  std::vector<std::string> warnings;
  // The profile of \p key: a drawing, or a file (\p shipped when the deck gives none); \p named
  // gets what it was, for messages.
  auto curve = [&](const std::string& key, const std::string& shipped, ProfileType role,
                   const ProfileReadSettings& axes, std::string& named) {
    const auto given = profiles.get<std::string>(key);
    const std::string parameter = context.path + "/Profiles/" + key;
    if (given.rfind(kDrawingPrefix, 0) == 0) {
      named = given;
      return drawn_curve(given.substr(std::string(kDrawingPrefix).size()), role, checks,
                         context.source(), parameter);
    }
    named = given.empty() ? shipped_profile(shipped) : deck.resolve(given);
    return read_curve(named, role, axes, context.source(), parameter, warnings);
  };
  std::string rail_file, wheel_file;
  const auto rail = curve("Rail", "MBench_UIC60_v3.prr", ProfileType::rail, rail_axes, rail_file);
  const auto wheel =
      curve("Wheel", "MBench_S1002_v3.prw", ProfileType::wheel, wheel_axes, wheel_file);
  const bool drawn_rail = rail_file.rfind(kDrawingPrefix, 0) == 0;
  if (context.model.comm().is_root())
    for (const std::string& warning : warnings)
      std::cerr << "warning: " << warning << "\n";
  const auto& t = step.sublist("Track");
  // Gauge and back-to-back differ by the two flanges (75 mm on standard gauge); a flangeless
  // test wheel may even have them the other way round, but never far apart.
  if (std::abs(t.get<double>("Gauge") - t.get<double>("Back to back")) > 0.2)
    throw_input_error(
        context.source(), context.path + "/Track/Back to back",
        CsvWriter::format(t.get<double>("Back to back")) + " m does not fit Track/Gauge = " +
            CsvWriter::format(t.get<double>("Gauge")) + " m: they differ by more than two flanges",
        "within 0.2 m of Gauge (1.360 m for 1.435 m gauge)");
  TrackLayout track{t.get<double>("Gauge"), t.get<double>("Gauge point depth"),
                    t.get<double>("Inclination"), !drawn_rail && profiles.get<bool>("Rail canted")};
  WheelsetLayout wheelset{t.get<double>("Back to back"), t.get<double>("Flange back"),
                          t.get<double>("Nominal radius")};
  try {
    return std::make_shared<WheelRailGeometry>(rail, wheel, track, wheelset);
  } catch (const std::invalid_argument& e) {
    // The profiles read well but do not fit the track's conventions (no running point, no
    // gauge point): name both files and the parameters that move them.
    throw_input_error(context.source(), context.path + "/Profiles",
                      std::string(e.what()) + " (rail " + rail_file + ", wheel " + wheel_file + ")",
                      "a wheel through y = 0 (see Wheel running point, Wheel mirrored) and a rail "
                      "reaching Track/Gauge point depth on its gauge side (see Rail mirrored)");
  }
}

}  // namespace railfe
