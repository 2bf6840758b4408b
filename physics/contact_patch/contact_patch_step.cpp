#include "physics/contact_patch/contact_patch_step.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "contact/laws/creep_table.hpp"
#include "contact/laws/fastsim.hpp"
#include "contact/laws/hertz.hpp"
#include "contact/laws/normal_problem.hpp"
#include "contact/laws/saturation.hpp"
#include "contact/laws/tangential_problem.hpp"
#include "framework/base/error.hpp"
#include "framework/output/csv_writer.hpp"
#include "physics/common/chart_script.hpp"
#include "physics/contact_patch/contact_patch_inverse.hpp"
#include "physics/contact_patch/lateral_separation_file.hpp"

namespace railfe {

namespace {

const std::vector<std::string> kTheories = {
    "linear", "shen-hedrick-elkins", "polach", "fastsim", "table", "exact"};

// Seconds per call of \p f, repeated until a millisecond has passed (cheap theories).
template <class F>
double seconds_per_call(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  int calls = 0;
  double elapsed = 0;
  do {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (elapsed < 1e-3 && calls < 1000000);
  return elapsed / calls;
}

// The Hertz patch the deck describes (cheap: computed at check time too, so that every limit the
// theories have is known before anything runs).
HertzContact deck_hertz(const Teuchos::ParameterList& p) {
  const double E = p.get<double>("Young's modulus"), nu = p.get<double>("Poisson's ratio");
  const double modulus = contact_modulus({E, nu}, {E, nu});
  const double load = p.get<double>("Normal load");
  return p.get<std::string>("Geometry") == "curvatures"
             ? hertz_contact(p.get<double>("A"), p.get<double>("B"), modulus, load)
             : hertz_from_semi_axes(p.get<double>("a"), p.get<double>("b"), modulus, load);
}

// The semi-axes of the ellipse whose Hertz pressure has the second moments of \p patch's
// pressure about its centre: sqrt(5 <x²>), sqrt(5 <y²>) (a non-Hertzian patch's size, measured
// as the explicit runs measure theirs).
std::pair<double, double> moment_semi_axes(const HertzPatch& patch) {
  const ContactGrid& g = patch.kernels->grid();
  double sum = 0, sx = 0, sy = 0, sxx = 0, syy = 0;
  for (int e = 0; e < g.size(); ++e) {
    const double p = patch.normal.pressure[static_cast<std::size_t>(e)];
    const double x = g.x(e % g.mx), y = g.y(e / g.mx);
    sum += p;
    sx += p * x;
    sy += p * y;
    sxx += p * x * x;
    syy += p * y * y;
  }
  const double mx = sx / sum, my = sy / sum;
  return {std::sqrt(5 * std::max(sxx / sum - mx * mx, 0.0)),
          std::sqrt(5 * std::max(syy / sum - my * my, 0.0))};
}

// A value a theory does not define (Polach's spin moment, the linear theory's adhesion share, the
// forces of a case without a unique steady state) is an empty cell, never NaN.
std::string cell(double value) {
  return std::isfinite(value) ? CsvWriter::format(value) : std::string();
}

}  // namespace

ContactPatchStep::ContactPatchStep(const Teuchos::ParameterList& parameters)
    : parameters_(&parameters) {}

void ContactPatchStep::check(const CheckContext& context) {
  const std::string& source = context.source();
  theories_.clear();
  for (const auto& name : parameters_->get<Teuchos::Array<std::string>>("Theories")) {
    if (std::find(kTheories.begin(), kTheories.end(), name) == kTheories.end())
      throw_input_error(source, context.path + "/Theories", "unknown theory '" + name + "'",
                        "linear, shen-hedrick-elkins, polach, fastsim, table, exact");
    if (std::find(theories_.begin(), theories_.end(), name) != theories_.end())
      throw_input_error(source, context.path + "/Theories", "names '" + name + "' twice",
                        "each theory once");
    theories_.push_back(name);
  }
  // Each case: ξ, η, φ, or with Prescribe forces Fx, Fy, φ.
  const bool by_force = parameters_->get<std::string>("Prescribe") == "forces";
  const std::array<const char*, 3> keys =
      by_force ? std::array<const char*, 3>{"Longitudinal force", "Lateral force", "Spin creepage"}
               : std::array<const char*, 3>{"Longitudinal creepage", "Lateral creepage",
                                            "Spin creepage"};
  std::size_t count = 1;
  for (const char* key : keys)
    count = std::max<std::size_t>(count, parameters_->get<Teuchos::Array<double>>(key).size());
  std::vector<std::array<double, 3>> values(count);
  for (int k = 0; k < 3; ++k) {
    const auto& given = parameters_->get<Teuchos::Array<double>>(keys[k]);
    if (given.size() != 1 && static_cast<std::size_t>(given.size()) != count)
      throw_input_error(
          source, context.path + "/" + keys[k],
          "has " + std::to_string(given.size()) + " values, others " + std::to_string(count),
          std::string("1 value or as many as the longest ") +
              (by_force ? "force or spin array" : "creepage array"));
    for (std::size_t c = 0; c < count; ++c)
      values[c][k] = given.size() == 1 ? given[0] : given[c];
  }
  cases_.clear();
  forces_.clear();
  for (const auto& v : values) {
    cases_.push_back(by_force ? Creepages{0, 0, v[2]} : Creepages{v[0], v[1], v[2]});
    if (by_force)
      forces_.push_back({v[0], v[1]});
  }
  const double mu_s = parameters_->get<double>("Static friction");
  const double mu_d = parameters_->get<double>("Dynamic friction");
  if (mu_d > mu_s)
    throw_input_error(source, context.path + "/Dynamic friction", "exceeds the static friction",
                      "0 to Static friction, or negative (Coulomb)");
  if (by_force) {
    if (std::find(theories_.begin(), theories_.end(), "exact") == theories_.end())
      throw_input_error(source, context.path + "/Theories",
                        "lacks 'exact', which Prescribe forces needs to find the creepages",
                        "Theories with exact, or Prescribe creepages");
    const double bound = mu_s * parameters_->get<double>("Normal load");
    for (std::size_t c = 0; c < forces_.size(); ++c) {
      const double size = std::hypot(forces_[c][0], forces_[c][1]);
      if (size >= bound)
        throw_input_error(
            source, context.path + "/Longitudinal force",
            "case " + std::to_string(c) +
                ": the tangential force sqrt(Fx² + Fy²) = " + CsvWriter::format(size) +
                " N reaches the traction bound μs N = " + CsvWriter::format(bound) +
                " N: the patch slides entirely, and steady rolling has no finite creepage for it",
            "Longitudinal and Lateral force with sqrt(Fx² + Fy²) below Static friction × Normal "
            "load");
    }
  }
  if (parameters_->get<double>("Polach slip reduction") >
      parameters_->get<double>("Polach adhesion reduction"))
    throw_input_error(source, context.path + "/Polach slip reduction",
                      "exceeds Polach adhesion reduction", "0 < k_S <= k_A <= 1");
  if (parameters_->get<std::string>("Geometry") == "separation") {
    for (const std::string& name : theories_)
      if (name != "exact")
        throw_input_error(source, context.path + "/Theories",
                          "names '" + name +
                              "', which needs a Hertz ellipse that Geometry 'separation' does "
                              "not have",
                          "{exact} alone, or Geometry curvatures or semi-axes");
    const std::string file = parameters_->get<std::string>("Separation file");
    if (file.empty())
      throw_input_error(source, context.path + "/Separation file",
                        "is empty, which Geometry 'separation' needs",
                        "a CSV file relative to the deck's directory");
    lateral_ = read_lateral_separation(context.model.deck().resolve(file), source,
                                       context.path + "/Separation file");
    return;
  }
  const bool semi_axes = parameters_->get<std::string>("Geometry") == "semi-axes";
  const HertzContact h = deck_hertz(*parameters_);
  const double ratio = h.a / h.b;
  const std::string shape = semi_axes ? "/a" : "/A";
  const std::string shape_names = semi_axes ? "a and b" : "A and B";
  if (!(ratio >= 0.1 && ratio <= 10))
    throw_input_error(
        source, context.path + shape,
        "gives a Hertz ellipse with a / b = " + std::to_string(ratio) + ", outside Kalker's table",
        shape_names + " giving a / b from 0.1 to 10");
  if (std::find(theories_.begin(), theories_.end(), "table") != theories_.end()) {
    const CreepTableAxes& table = CreepTable::shipped().axes();
    const double nu = parameters_->get<double>("Poisson's ratio");
    if (std::abs(nu - table.poisson) > 1e-6)
      throw_input_error(source, context.path + "/Poisson's ratio",
                        "is " + std::to_string(nu) +
                            ", but the creep table (theory 'table') was "
                            "made for " +
                            std::to_string(table.poisson),
                        std::to_string(table.poisson) + ", or drop 'table' from Theories");
    if (ratio < table.ratios.front() * (1 - 1e-12) || ratio > table.ratios.back() * (1 + 1e-12))
      throw_input_error(source, context.path + shape,
                        "gives a / b = " + std::to_string(ratio) +
                            ", outside the creep table's range (theory 'table')",
                        shape_names + " giving a / b from " + std::to_string(table.ratios.front()) +
                            " to " + std::to_string(table.ratios.back()) +
                            ", or drop 'table' from Theories");
  }
}

void ContactPatchStep::run(StepContext& context) {
  const Teuchos::ParameterList& p = *parameters_;
  const double E = p.get<double>("Young's modulus"), nu = p.get<double>("Poisson's ratio");
  const double G = E / (2 * (1 + nu));
  const double load = p.get<double>("Normal load");
  const bool separation = p.get<std::string>("Geometry") == "separation";
  HertzContact h = separation ? HertzContact{} : deck_hertz(p);
  // (Geometry separation runs the exact solver alone, which needs no coefficients.)
  const KalkerCoefficients c =
      separation ? KalkerCoefficients{} : KalkerTable::shipped().at(h.a, h.b, nu);
  FrictionLaw friction;
  friction.static_coefficient = p.get<double>("Static friction");
  const double mu_d = p.get<double>("Dynamic friction");
  friction.dynamic_coefficient = mu_d < 0 ? friction.static_coefficient : mu_d;
  friction.decay = p.get<double>("Friction decay");
  friction.rolling_speed = p.get<double>("Rolling speed");
  PolachParameters polach_law;
  polach_law.friction = friction.static_coefficient;
  polach_law.adhesion_reduction = p.get<double>("Polach adhesion reduction");
  polach_law.slip_reduction = p.get<double>("Polach slip reduction");
  polach_law.friction_ratio = p.get<double>("Polach friction ratio");
  polach_law.friction_decay = p.get<double>("Polach friction decay");
  polach_law.rolling_speed = friction.rolling_speed;
  FastsimSettings fastsim_grid;
  fastsim_grid.cells_x = fastsim_grid.strips = p.get<int>("FASTSIM cells");
  fastsim_grid.bound = p.get<std::string>("FASTSIM bound") == "elliptic" ? TractionBound::elliptic
                                                                         : TractionBound::parabolic;

  // The exact solver's grid and normal solution serve every case.
  const bool exact = std::find(theories_.begin(), theories_.end(), "exact") != theories_.end();
  HertzPatch patch;
  double normal_seconds = 0;
  SeparationPatchInfo refits;
  if (exact) {
    const auto start = std::chrono::steady_clock::now();
    const int m = p.get<int>("Exact grid");
    if (separation) {
      try {
        patch = solve_separation_patch(lateral_, p.get<double>("A"), load, G, nu, m, m, &refits);
      } catch (const std::invalid_argument& e) {
        throw RunError(context.path + "/Separation file: " + e.what());
      }
      const auto [a, b] = moment_semi_axes(patch);
      h.a = a;
      h.b = b;
      h.load = load;
      h.pressure = patch.normal.max_pressure;
      h.approach = patch.normal.approach;
    } else {
      patch = solve_hertz_patch(h, G, nu, m);
    }
    normal_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!patch.normal.converged)
      throw RunError(context.path + ": the exact solver's normal problem did not converge");
  }
  if (!forces_.empty())
    find_creepages(context, patch, friction, p.get<double>("Inverse tolerance"), forces_, cases_);

  const bool root = context.model.comm().is_root();
  // Every file carries the step's name, so two patch steps in one deck keep their results apart.
  const std::string forces_file = context.step_name + "_forces.csv";
  const std::string tractions_file = context.step_name + "_tractions.csv";
  CsvWriter forces(context.output.staging_path(forces_file),
                   {"theory", "case", "xi", "eta", "phi_per_m", "FN_N", "Fx_N", "Fy_N", "Mz_Nm",
                    "a_m", "b_m", "pmax_Pa", "adhesion_fraction", "status", "time_s"},
                   root);
  const bool fields = p.get<bool>("Traction fields");
  std::unique_ptr<CsvWriter> tractions;
  if (fields)
    tractions = std::make_unique<CsvWriter>(
        context.output.staging_path(tractions_file),
        std::vector<std::string>{"theory", "case", "x_m", "y_m", "p_Pa", "qx_Pa", "qy_Pa", "state",
                                 "slip_x", "slip_y"},
        root);
  // The slip (the exact solver's; FASTSIM has none, an empty cell) is dimensionless: times the
  // rolling speed it is the micro-slip velocity.
  auto field = [&](const std::string& theory, std::size_t k, double x, double y, double pressure,
                   double qx, double qy, bool adhesion, double sx, double sy) {
    if (tractions)
      tractions->write_row({theory, std::to_string(k), CsvWriter::format(x), CsvWriter::format(y),
                            CsvWriter::format(pressure), CsvWriter::format(qx),
                            CsvWriter::format(qy), adhesion ? "adhesion" : "slip", cell(sx),
                            cell(sy)});
  };
  int refused = 0;
  auto progress = context.progress("cases", static_cast<double>(cases_.size()));
  for (std::size_t k = 0; k < cases_.size(); ++k) {
    const Creepages& creep = cases_[k];
    for (const std::string& theory : theories_) {
      CreepForces f;
      double seconds = 0, adhesion = std::nan(""), pmax = h.pressure;
      std::string status = "ok";
      if (theory == "linear") {
        seconds = seconds_per_call([&] { f = kalker_linear(c, G, h.a, h.b, creep); });
      } else if (theory == "shen-hedrick-elkins") {
        seconds = seconds_per_call([&] {
          f = shen_hedrick_elkins(kalker_linear(c, G, h.a, h.b, creep), load,
                                  friction.static_coefficient);
        });
      } else if (theory == "polach") {
        seconds = seconds_per_call([&] { f = polach(c, G, h.a, h.b, load, creep, polach_law); });
      } else if (theory == "table") {
        try {
          const CreepTable& table = CreepTable::shipped();  // read once, outside the timing
          seconds = seconds_per_call(
              [&] { f = table.forces(h.a, h.b, G, nu, load, friction.static_coefficient, creep); });
        } catch (const std::invalid_argument& e) {
          throw RunError(context.path + ": creep table: " + e.what() +
                         " (the shipped table covers a/b 0.2 to 5 at Poisson's ratio 0.3)");
        }
      } else if (theory == "fastsim") {
        // Timed for the forces alone, then run once more for the fields.
        FastsimSettings forces_only = fastsim_grid;
        forces_only.fields = false;
        seconds = seconds_per_call([&] {
          f = fastsim(c, G, h.a, h.b, load, friction.static_coefficient, creep, forces_only).forces;
        });
        const FastsimResult r =
            fastsim(c, G, h.a, h.b, load, friction.static_coefficient, creep, fastsim_grid);
        f = r.forces;
        adhesion = r.adhesion_fraction;
        for (std::size_t e = 0; e < r.x.size(); ++e)
          field(theory, k, r.x[e], r.y[e],
                r.bound[e] / std::max(friction.static_coefficient, 1e-300), r.px[e], r.py[e],
                r.adhesion[e], std::nan(""), std::nan(""));
      } else {
        const auto start = std::chrono::steady_clock::now();
        TangentialSolution t;
        try {
          TangentialSettings settings;
          settings.leading_edge = patch.leading_edge;
          settings.row_longitudinal_slip = patch.row_longitudinal_slip;
          t = solve_steady_rolling(*patch.kernels, patch.normal.pressure, creep, friction, 1e-6,
                                   nullptr, settings);
        } catch (const std::invalid_argument& e) {
          throw_input_error(context.source(), context.path + "/Exact grid", e.what(),
                            "more elements");
        }
        seconds = normal_seconds +
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        f = t.forces;
        adhesion = t.adhesion_fraction;
        pmax = patch.normal.max_pressure;
        if (!t.converged) {
          status = "not unique or not converged";
          ++refused;
        }
        const ContactGrid& g = patch.kernels->grid();
        for (int e = 0; e < g.size(); ++e)
          if (patch.normal.pressure[e] > 0)
            field(theory, k, g.x(e % g.mx), g.y(e / g.mx), patch.normal.pressure[e], t.qx[e],
                  t.qy[e], t.adhesion[e], t.sx[e], t.sy[e]);
      }
      // Forces are NaN only where the theory has none (Polach's moment) or the case has no
      // unique steady state (its status says so); anything else non-finite is a failure.
      if (status == "ok" && !(std::isfinite(f.Fx) && std::isfinite(f.Fy)))
        throw RunError(context.path + ": theory '" + theory + "', case " + std::to_string(k) +
                       " gave non-finite creep forces");
      forces.write_row({theory, std::to_string(k), CsvWriter::format(creep.longitudinal),
                        CsvWriter::format(creep.lateral), CsvWriter::format(creep.spin),
                        CsvWriter::format(load), cell(f.Fx), cell(f.Fy), cell(f.Mz),
                        CsvWriter::format(h.a), CsvWriter::format(h.b), CsvWriter::format(pmax),
                        cell(adhesion), status, CsvWriter::format(seconds)});
    }
    progress.update(static_cast<double>(k + 1));
  }
  progress.finish();
  forces.flush();
  if (tractions)
    tractions->flush();
  const std::string section = "Step " + context.step_name + " (contact patch)";
  if (separation) {
    const ContactGrid& g = patch.kernels->grid();
    context.summary.add(section, "patch semi-axes from the pressure's moments, a", h.a, "m");
    context.summary.add(section, "patch semi-axes from the pressure's moments, b", h.b, "m");
    context.summary.add(section, "patch area", patch.normal.area, "m2");
    context.summary.add(section, "maximum pressure", h.pressure, "Pa");
    context.summary.add(section, "approach", h.approach, "m");
    context.summary.add(section, "grid across, from y", g.y0, "m");
    context.summary.add(section, "grid across, to y", g.y0 + g.my * g.dy, "m");
    context.summary.add(section, "grid refits", refits.refits);
  } else {
    context.summary.add(section, "Hertz a", h.a, "m");
    context.summary.add(section, "Hertz b", h.b, "m");
    context.summary.add(section, "Hertz maximum pressure", h.pressure, "Pa");
    context.summary.add(section, "Hertz approach", h.approach, "m");
  }
  context.summary.add(section, "cases", static_cast<double>(cases_.size()));
  if (exact)
    context.summary.add(section, "exact cases without a unique steady state", refused);
  if (p.get<bool>("Chart"))
    draw_chart(context, section, "contact_patch_chart.py",
               {context.output.staging_path(forces_file),
                fields ? context.output.staging_path(tractions_file) : std::string("-"),
                context.output.staging_path(context.step_name + "_creep_forces.png"),
                context.output.staging_path(context.step_name + "_tractions.png")});
}

}  // namespace railfe
