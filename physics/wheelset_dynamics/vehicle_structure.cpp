#include "physics/wheelset_dynamics/vehicle_structure.hpp"

#include <Teuchos_Array.hpp>

#include <cmath>
#include <limits>
#include <sstream>

#include "framework/base/error.hpp"
#include "framework/output/run_summary.hpp"
#include "physics/elements/beam_interpolation.hpp"

namespace railfe {

ParameterSpec vehicle_structure_parameters() {
  ParameterSpec spec(
      "What carries the track. The defaults of the girders are a representative single-track "
      "share of a 20 m prestressed-concrete Shinkansen girder (docs/vehicle_parameters.md), "
      "not a published structure.");
  spec.choice("Model", "rigid",
              {{"rigid",
                "rigid ground (the roller rig of a test plant): the rails follow the "
                "irregularities and the Structure deviation alone"},
               {"girders",
                "a girder continuous over its spans, on bearings at the piers between them, "
                "held at the abutments, the rails fixed to it and deflecting with it; rigid "
                "track before and after"}},
              "How the structure moves.");
  spec.real("Start", 0,
            "Track position s where the first span begins; the vehicle must start before it.", "m");
  spec.real("Span", 20, "Length of each span.", "m", Range::positive());
  spec.integer("Spans", 2, "Number of spans.", Range::at_least(1));
  spec.integer("Elements per span", 8, "Beam elements in a span.", Range::at_least(1));
  spec.real("Young's modulus", 3.1e10, "Of the girder (concrete of 40 N/mm^2).", "Pa",
            Range::positive());
  spec.real("Poisson's ratio", 0.2, "Of the girder (G = E / 2(1 + nu)).", "",
            Range::closed(0, 0.5));
  spec.real("Area", 4.0, "Cross-section area of the girder.", "m^2", Range::positive());
  spec.real("Mass per length", 12000,
            "Girder, track slab and rails per metre of track (the density is this over Area).",
            "kg/m", Range::positive());
  spec.real("Vertical bending inertia", 2.5, "About the girder's horizontal axis.", "m^4",
            Range::positive());
  spec.real("Lateral bending inertia", 15, "About the girder's vertical axis.", "m^4",
            Range::positive());
  spec.real("Torsion constant", 5, "Saint-Venant J of the girder.", "m^4", Range::positive());
  spec.real("Axis depth", 1.5, "The girder's axis below the top of the rails.", "m",
            Range::non_negative());
  spec.real_array("Bearing stiffness", {1e9, 1e9, 5e9, 1e10},
                  "Per pier between two spans along x, y, z (N/m) and about x (N m/rad), "
                  "bearing and pier in series; all positive. The abutments at both ends hold "
                  "the girder's ends.",
                  "N/m", 4, Range::positive());
  spec.real_array("Bearing damping", {0, 0, 0, 0},
                  "Per pier along x, y, z (N s/m) and about x (N m s/rad).", "N s/m", 4,
                  Range::non_negative());
  spec.real_array("Rayleigh damping", {0, 6.4e-4},
                  "Of the girders: C = a_m M + a_k K, {a_m (1/s), a_k (s)}; the default gives 2 % "
                  "at 10 Hz, the first vertical mode of the default girder.",
                  "", 2, Range::non_negative());
  spec.only_when(
      "Model", {"girders"},
      {"Start", "Span", "Spans", "Elements per span", "Young's modulus", "Poisson's ratio", "Area",
       "Mass per length", "Vertical bending inertia", "Lateral bending inertia", "Torsion constant",
       "Axis depth", "Bearing stiffness", "Bearing damping", "Rayleigh damping"});
  return spec;
}

bool structure_is_girders(const Teuchos::ParameterList& structure) {
  return structure.get<std::string>("Model") == "girders";
}

namespace {

template <std::size_t N>
std::array<double, N> entries(const Teuchos::ParameterList& list, const char* key) {
  const auto given = list.get<Teuchos::Array<double>>(key);
  std::array<double, N> values{};
  for (std::size_t i = 0; i < N; ++i)
    values[i] = given[i];
  return values;
}

}  // namespace

GirderLayout girder_layout(const Teuchos::ParameterList& structure, const std::string& source,
                           const std::string& path) {
  // One span has no pier: bearings given for it would be ignored.
  if (structure.get<int>("Spans") == 1)
    for (const char* key : {"Bearing stiffness", "Bearing damping"})
      if (!structure.getEntry(key).isDefault())
        throw_input_error(source, path + "/" + key,
                          "is given for a single span, which has no pier to put it on (the "
                          "abutments hold the girder's ends)",
                          "Spans of 2 or more, or no bearings");
  GirderLayout layout;
  const double area = structure.get<double>("Area");
  layout.material = isotropic_beam_material(structure.get<double>("Young's modulus"),
                                            structure.get<double>("Poisson's ratio"),
                                            structure.get<double>("Mass per length") / area);
  layout.section.area = area;
  layout.section.iy = structure.get<double>("Vertical bending inertia");
  layout.section.iz = structure.get<double>("Lateral bending inertia");
  layout.section.torsion = structure.get<double>("Torsion constant");
  layout.section.shear_area_y = layout.section.shear_area_z =
      std::numeric_limits<double>::infinity();
  layout.start = structure.get<double>("Start");
  layout.span = structure.get<double>("Span");
  layout.spans = structure.get<int>("Spans");
  layout.elements_per_span = structure.get<int>("Elements per span");
  layout.axis_depth = structure.get<double>("Axis depth");
  layout.bearing_stiffness = entries<4>(structure, "Bearing stiffness");
  layout.bearing_damping = entries<4>(structure, "Bearing damping");
  layout.rayleigh = entries<2>(structure, "Rayleigh damping");
  return layout;
}

void check_deviation_on_girders(const GirderLayout& layout,
                                const StructureDeviationSettings& deviation,
                                const std::string& source, const std::string& path) {
  if (deviation.shape == DeviationShape::none)
    return;
  // The deviation displaces two spans between piers: they must be two of the girders.
  const double span = deviation.span;
  const double first = (deviation.start - layout.start) / span;
  const bool aligned = std::abs(first - std::round(first)) < 1e-6 && std::round(first) >= 0 &&
                       std::round(first) + 2 <= layout.spans;
  if (!aligned) {
    std::ostringstream what;
    what << "(" << layout.spans << " spans from s = " << layout.start
         << " m) does not hold the Structure deviation's two spans of " << span
         << " m from s = " << deviation.start << " m";
    throw_input_error(source, path, what.str(),
                      "girders whose spans include the deviation's two, its Start on a pier");
  }
}

VehicleStructure::VehicleStructure(const GirderLayout& layout, const WheelRailGeometry& geometry,
                                   VehicleSystem& vehicle)
    : layout_(layout) {
  const double top =
      std::min(rail_top(geometry, TrackSide::right)[1], rail_top(geometry, TrackSide::left)[1]);
  girders_ = std::make_unique<RailBeams>(layout, top + layout.axis_depth);
  structure_ = std::make_unique<SparseLinearSystem>(girders_->mass(), girders_->damping(),
                                                    girders_->stiffness());
  coupled_ = std::make_unique<CoupledSystem>(*structure_, vehicle);
  structure_->check_solutions(false);  // the block solver checks the coupled solution
}

std::array<double, 2> VehicleStructure::displacement(double s, const double* u) const {
  const BeamPath& path = girders_->path(TrackSide::right);
  std::size_t element;
  double xi;
  if (!path.locate(s - girders_->origin(), element, xi))
    return {0, 0};
  const PathElement& piece = path.element(element);
  const auto N = beam_translation_interpolation(piece.beam, xi);
  std::array<double, 2> d{};
  for (int j = 0; j < 12; ++j)
    if (piece.unknowns[j] >= 0) {
      d[0] += N(1, j) * u[piece.unknowns[j]];
      d[1] += N(2, j) * u[piece.unknowns[j]];
    }
  return d;
}

namespace {

std::vector<std::string> girder_columns(int spans) {
  std::vector<std::string> columns{"time_s"};
  for (int i = 1; i <= spans; ++i) {
    columns.push_back("span" + std::to_string(i) + "_midspan_y_m");
    columns.push_back("span" + std::to_string(i) + "_midspan_z_m");
  }
  return columns;
}

}  // namespace

GirderRecorder::GirderRecorder(StepContext& context, const VehicleStructure& structure, bool writes)
    : structure_(structure),
      file_(context.output.staging_path(context.step_name + "_girders.csv"),
            girder_columns(structure.layout().spans), writes),
      peaks_(static_cast<std::size_t>(structure.layout().spans), {0.0, 0.0}) {}

void GirderRecorder::record(double time, const double* u, bool write_row) {
  std::vector<double> row{time};
  const GirderLayout& layout = structure_.layout();
  for (int i = 0; i < layout.spans; ++i) {
    const auto d = structure_.displacement(layout.start + (i + 0.5) * layout.span, u);
    for (int c = 0; c < 2; ++c) {
      peaks_[i][c] = std::max(peaks_[i][c], std::abs(d[c]));
      row.push_back(d[c]);
    }
  }
  if (write_row)
    file_.write_row(row);
}

void GirderRecorder::finish(RunSummary& summary, const std::string& section) const {
  for (std::size_t i = 0; i < peaks_.size(); ++i) {
    const std::string span = "span " + std::to_string(i + 1);
    summary.add(section, "peak lateral midspan displacement, " + span, peaks_[i][0], "m");
    summary.add(section, "peak vertical midspan displacement, " + span, peaks_[i][1], "m");
  }
}

}  // namespace railfe
