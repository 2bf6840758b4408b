#include "physics/wheelset_dynamics/wheelset_track.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/geometry/rail_drawing.hpp"
#include "framework/base/error.hpp"

namespace railfe {

ParameterSpec track_rail_parameters() {
  ParameterSpec spec("The rails under the wheelset.");
  spec.choice("Model", "rigid",
              {{"rigid", "rigid lines that follow the irregularities"},
               {"springs",
                "a rigid body per rail under the wheelset, moving with it, on springs and "
                "dampers along y, z and about its axis"},
               {"beams", "a beam per rail on rail seats, each a spring-damper to the ground"}},
              "How the rails move.");
  spec.choice("Section", "60E1",
              {{"60E1", "from the EN 13674-1 drawing (A, I and centroid computed)"},
               {"54E1", "from the EN 13674-1 drawing"},
               {"custom", "Area, bending inertias and Axis depth as given"}},
              "The rail's cross-section: beams take A, the I and the centroid (their axis); "
              "springs the centroid alone, as the roll axis.");
  spec.real("Area", 0, "Cross-section area.", "m^2", Range::non_negative());
  spec.real("Vertical bending inertia", 0, "About the horizontal axis.", "m^4",
            Range::non_negative());
  spec.real("Lateral bending inertia", 0, "About the vertical axis.", "m^4", Range::non_negative());
  spec.real("Axis depth", 0, "The centroid below the top of the rail.", "m", Range::non_negative());
  spec.real("Torsion constant", 0,
            "Saint-Venant J of the section; must be given with beams (railfe does not compute "
            "it for a rail).",
            "m^4", Range::non_negative());
  spec.choice("Beam theory", "euler-bernoulli",
              {{"euler-bernoulli", "no shear deformation"},
               {"timoshenko", "shear deformation with Shear areas"}},
              "Bending of the rail beams.");
  spec.real_array("Shear areas", {0, 0}, "kappa A for lateral (y) and vertical (z) shear.", "m^2",
                  2, Range::non_negative());
  spec.real("Young's modulus", 210e9, "Rail steel.", "Pa", Range::positive());
  spec.real("Poisson's ratio", 0.3, "Rail steel (G = E / 2(1 + nu)).", "", Range::closed(0, 0.5));
  spec.real("Density", 7850, "Rail steel.", "kg/m^3", Range::non_negative());
  spec.real("Length", 30,
            "Of each rail, from s = 0, a whole number of Seat spacings. Start and the whole run "
            "must lie on it, best a few metres from its free ends.",
            "m", Range::positive());
  spec.real("Seat spacing", 0.6, "Between rail seats (seats at s = 0, a, 2a, ...).", "m",
            Range::positive());
  spec.integer("Elements per span", 4, "Beam elements between two seats.", Range::at_least(1));
  spec.real_array("Seat stiffness", {0, 0, 0, 0},
                  "Per seat and rail along x, y, z (N/m) and about x (roll, N m/rad); all "
                  "positive.",
                  "N/m", 4, Range::non_negative());
  spec.real_array("Seat damping", {0, 0, 0, 0},
                  "Per seat and rail along x, y, z (N s/m) and about x (N m s/rad).", "N s/m", 4,
                  Range::non_negative());
  spec.choice("Mass", "consistent",
              {{"consistent", "the beams' consistent mass"}, {"lumped", "HRZ-lumped"}},
              "The rails' mass matrix.");
  spec.real("Rail mass", 0, "Springs: each rail's mass moving with the wheelset (0: massless).",
            "kg", Range::non_negative());
  spec.real("Rail roll inertia", 0, "Springs: each rail's inertia about its axis.", "kg m^2",
            Range::non_negative());
  spec.real_array("Spring stiffness", {0, 0, 0},
                  "Springs: per rail along y, z (N/m) and about its axis (N m/rad); all "
                  "positive.",
                  "N/m", 3, Range::non_negative());
  spec.real_array("Spring damping", {0, 0, 0},
                  "Springs: per rail along y, z (N s/m) and about its axis (N m s/rad).", "N s/m",
                  3, Range::non_negative());
  spec.only_when("Model", {"beams", "springs"}, {"Section", "Axis depth"});
  spec.only_when(
      "Model", {"beams"},
      {"Area", "Vertical bending inertia", "Lateral bending inertia", "Torsion constant",
       "Beam theory", "Shear areas", "Young's modulus", "Poisson's ratio", "Density", "Length",
       "Seat spacing", "Elements per span", "Seat stiffness", "Seat damping", "Mass"});
  spec.only_when("Model", {"springs"},
                 {"Rail mass", "Rail roll inertia", "Spring stiffness", "Spring damping"});
  spec.only_when("Section", {"custom"},
                 {"Area", "Vertical bending inertia", "Lateral bending inertia", "Axis depth"});
  spec.only_when("Beam theory", {"timoshenko"}, {"Shear areas"});
  return spec;
}

namespace {

// The array \p key of \p rails (N entries, the spec's length), refused unless every entry is
// positive: a rail free to move along a direction cannot carry a load.
template <std::size_t N>
std::array<double, N> positive_entries(const Teuchos::ParameterList& rails, const char* key,
                                       const std::string& source, const std::string& path,
                                       const char* allowed) {
  const auto given = rails.get<Teuchos::Array<double>>(key);
  std::array<double, N> values;
  for (std::size_t d = 0; d < N; ++d) {
    values[d] = given[d];
    if (!(values[d] > 0))
      throw_input_error(source, path + "/" + key,
                        "has a zero entry: a rail free to move along that direction cannot "
                        "carry a load",
                        allowed);
  }
  return values;
}

// The centroid of the named drawing below its top (m).
double drawing_axis_depth(const std::string& name) {
  const RailOutline outline = rail_outline(name);
  double top = -std::numeric_limits<double>::infinity();
  for (const SectionPoint& point : sample_outline(outline, 1e-3))
    top = std::max(top, point[1]);
  return top - section_properties(outline).centroid[1];
}

}  // namespace

RailSpringLayout rail_spring_layout(const Teuchos::ParameterList& rails, const std::string& source,
                                    const std::string& path) {
  RailSpringLayout layout;
  layout.mass = rails.get<double>("Rail mass");
  layout.roll_inertia = rails.get<double>("Rail roll inertia");
  layout.stiffness =
      positive_entries<3>(rails, "Spring stiffness", source, path,
                          "three positive stiffnesses (y, z in N/m, roll in N m/rad)");
  const auto damping = rails.get<Teuchos::Array<double>>("Spring damping");
  std::copy(damping.begin(), damping.end(), layout.damping.begin());
  const std::string name = rails.get<std::string>("Section");
  layout.axis_depth = name == "custom" ? rails.get<double>("Axis depth") : drawing_axis_depth(name);
  return layout;
}

RailBeamLayout rail_beam_layout(const Teuchos::ParameterList& rails, const std::string& source,
                                const std::string& path) {
  RailBeamLayout layout;
  layout.material =
      isotropic_beam_material(rails.get<double>("Young's modulus"),
                              rails.get<double>("Poisson's ratio"), rails.get<double>("Density"));
  const std::string name = rails.get<std::string>("Section");
  BeamSection& section = layout.section;
  if (name == "custom") {
    section.area = rails.get<double>("Area");
    section.iy = rails.get<double>("Vertical bending inertia");
    section.iz = rails.get<double>("Lateral bending inertia");
    layout.axis_depth = rails.get<double>("Axis depth");
    for (const char* key : {"Area", "Vertical bending inertia", "Lateral bending inertia"})
      if (!(rails.get<double>(key) > 0))
        throw_input_error(source, path + "/" + key, "must be given with Section custom",
                          "a positive value");
  } else {
    const SectionProperties properties = section_properties(rail_outline(name));
    section.area = properties.area;
    section.iy = properties.inertia_horizontal;
    section.iz = properties.inertia_vertical;
    layout.axis_depth = drawing_axis_depth(name);
  }
  section.torsion = rails.get<double>("Torsion constant");
  if (!(section.torsion > 0))
    throw_input_error(source, path + "/Torsion constant", "must be given with rail beams",
                      "a positive J (m^4), from the rail's data");
  const bool timoshenko = rails.get<std::string>("Beam theory") == "timoshenko";
  const auto shear = rails.get<Teuchos::Array<double>>("Shear areas");
  if (timoshenko && !(shear[0] > 0 && shear[1] > 0))
    throw_input_error(source, path + "/Shear areas", "must be given with Beam theory timoshenko",
                      "two positive shear areas (lateral, vertical)");
  const double infinite = std::numeric_limits<double>::infinity();
  section.shear_area_y = timoshenko ? shear[0] : infinite;
  section.shear_area_z = timoshenko ? shear[1] : infinite;
  layout.length = rails.get<double>("Length");
  layout.seat_spacing = rails.get<double>("Seat spacing");
  layout.elements_per_span = rails.get<int>("Elements per span");
  layout.seat_stiffness =
      positive_entries<4>(rails, "Seat stiffness", source, path,
                          "four positive stiffnesses (x, y, z in N/m, roll in N m/rad)");
  const auto damping = rails.get<Teuchos::Array<double>>("Seat damping");
  std::copy(damping.begin(), damping.end(), layout.seat_damping.begin());
  const double spans = layout.length / layout.seat_spacing;
  if (std::abs(spans - std::round(spans)) > 1e-9 * spans)
    throw_input_error(source, path + "/Length", "is not a whole number of Seat spacings",
                      "a multiple of Seat spacing");
  layout.mass =
      rails.get<std::string>("Mass") == "lumped" ? BeamMass::lumped : BeamMass::consistent;
  return layout;
}

WheelsetTrack::WheelsetTrack(const Teuchos::ParameterList& rails, const std::string& source,
                             const std::string& path, const WheelRailGeometry& geometry,
                             WheelsetSystem& wheelset, std::function<double(double)> lateral,
                             std::function<double(double)> vertical, double start, double speed)
    : wheelset_(wheelset) {
  const std::string model = rails.get<std::string>("Model");
  if (model == "rigid") {
    rigid_rails_ =
        std::make_unique<RigidRails>(std::move(lateral), std::move(vertical), start, speed);
    whole_ = &wheelset;
    constraints_ = rigid_rails_.get();
    saddle_ = std::make_unique<MonolithicSaddlePointSolver>(wheelset);
    return;
  }
  const auto right = rail_top(geometry, TrackSide::right);
  const auto left = rail_top(geometry, TrackSide::left);
  auto place = [&](const auto& layout) {
    beams_ = std::make_unique<RailBeams>(
        layout, std::array<double, 2>{right[0], left[0]},
        std::array<double, 2>{right[1] + layout.axis_depth, left[1] + layout.axis_depth});
  };
  if (model == "springs")
    place(rail_spring_layout(rails, source, path));
  else
    place(rail_beam_layout(rails, source, path));
  structure_ =
      std::make_unique<SparseLinearSystem>(beams_->mass(), beams_->damping(), beams_->stiffness());
  offset_ = structure_->n_unknowns();
  coupled_ = std::make_unique<CoupledSystem>(*structure_, wheelset);
  beam_rails_ = std::make_unique<BeamRails>(*beams_, offset_, std::move(lateral),
                                            std::move(vertical), start, speed);
  whole_ = coupled_.get();
  constraints_ = beam_rails_.get();
  saddle_ = std::make_unique<BlockSaddlePointSolver>(*coupled_);
  structure_->check_solutions(false);  // the block solver checks the coupled solution
}

std::array<double, 2> WheelsetTrack::offsets(double time) const {
  return beam_rails_ ? beam_rails_->offsets(time) : rigid_rails_->offsets(time);
}

WheelsetBalance WheelsetTrack::balance(const WheelRailGeometry& geometry, std::vector<double>& u,
                                       bool rolling) {
  if (rolling)
    return balance_on_rail_beams(wheelset_, geometry, *beam_rails_, *structure_, u, true);
  const auto offset = offsets(0);
  for (int k = 0; k < n_wheelset_contacts; ++k) {
    u[offset_ + 6 + 3 * k + 1] = offset[0];
    u[offset_ + 6 + 3 * k + 2] = offset[1];
  }
  if (!flexible()) {
    std::vector<double> uv(u.begin() + static_cast<long>(offset_), u.end());
    const WheelsetBalance result = balance_wheelset(wheelset_, geometry, uv);
    std::copy(uv.begin(), uv.end(), u.begin() + static_cast<long>(offset_));
    return result;
  }
  return balance_on_rail_beams(wheelset_, geometry, *beam_rails_, *structure_, u, false);
}

void WheelsetTrack::accept(const std::array<ContactState, n_wheelset_contacts>& states) {
  if (beam_rails_)
    beam_rails_->set_levers(states);
}

std::array<double, 2> WheelsetTrack::rail_deflection(double time, const double* u) {
  if (!beam_rails_)
    return {0, 0};
  const auto displacement = beam_rails_->rail_displacements(time, u);
  return {displacement[2], displacement[3 * 2 + 2]};  // the right and left treads' z
}

}  // namespace railfe
