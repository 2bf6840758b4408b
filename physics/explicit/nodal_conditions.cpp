#include "physics/explicit/nodal_conditions.hpp"

#include <regex>

#include "framework/assembly/dof_map.hpp"
#include "framework/mesh/partition.hpp"
#include "physics/common/solid_assembly.hpp"

namespace railfe {

namespace {

// Spacing of the central differences that give the initial velocity and acceleration of
// prescribed motion: short against the time scales decks resolve (a 1 % error needs a period
// of 0.1 ms), long enough that round-off in the second difference stays below 1e-4.
constexpr double kDerivativeStep = 1e-6;

}  // namespace

bool depends_on_position(const std::string& text) {
  static const std::regex variable("(^|[^A-Za-z0-9_])[xyz]($|[^A-Za-z0-9_])");
  return std::regex_search(text, variable);
}

TimedLoads::TimedLoads(const ExplicitSettings& settings, const MaterialTable& materials,
                       const DofMap& dofs, const std::string& deck, const std::string& path) {
  for (const TimedLoad& timed : settings.loads) {
    SolidConditions single;
    if (!timed.node_set.empty()) {
      single.nodal_forces.push_back({timed.name, timed.node_set, timed.total_force});
    } else {
      SurfaceLoad surface;
      surface.name = timed.name;
      surface.side_set = timed.side_set;
      surface.traction = timed.traction;
      surface.pressure = timed.pressure;
      if (timed.surface_total)
        surface.total_force = timed.total_force;
      single.surface_loads.push_back(surface);
    }
    TpetraVector forces(dofs.owned_map());
    assemble_solid_loads(single, materials, dofs, forces);
    const auto data = forces.getData();
    Load load{{}, {}, Expression(timed.function, deck, path + "/" + timed.name + "/Function")};
    for (LocalIndex k = 0; k < dofs.n_owned_dofs(); ++k) {
      if (data[k] != 0) {
        load.dofs.push_back(k);
        load.values.push_back(data[k]);
      }
    }
    loads_.push_back(std::move(load));
  }
}

void TimedLoads::add(double time, double* forces) const {
  for (const Load& load : loads_) {
    const double scale = load.function(0, 0, 0, time);
    for (std::size_t i = 0; i < load.dofs.size(); ++i)
      forces[load.dofs[i]] += scale * load.values[i];
  }
}

PrescribedMotions::PrescribedMotions(
    const ExplicitSettings& settings, LocalIndex n_owned_nodes,
    const std::vector<std::vector<LocalIndex>>& owned_nodes_of_motion, const double* coordinates,
    const std::string& deck, const std::string& path)
    : motions_(settings.motions),
      flags_(3 * static_cast<std::size_t>(n_owned_nodes), 0),
      coordinates_(coordinates) {
  std::vector<int> motion_of_dof(flags_.size(), -1);
  for (std::size_t m = 0; m < motions_.size(); ++m) {
    functions_.emplace_back(motions_[m].function, deck,
                            path + "/Prescribed motion/" + motions_[m].name + "/Function");
    uniform_.push_back(!depends_on_position(motions_[m].function));
    for (LocalIndex node : owned_nodes_of_motion[m])
      for (int component : motions_[m].components)
        motion_of_dof[3 * node + component] = static_cast<int>(m);
  }
  for (auto& values : values_at_)
    values.resize(motions_.size());
  for (std::size_t k = 0; k < motion_of_dof.size(); ++k) {
    if (motion_of_dof[k] >= 0) {
      dofs_.push_back({static_cast<LocalIndex>(k), motion_of_dof[k]});
      flags_[k] = 1;
    }
  }
}

double PrescribedMotions::value(const PrescribedDof& entry, double time, int motion) const {
  const double* x = coordinates_ + 3 * (entry.dof / 3);
  return functions_[motion](x[0], x[1], x[2], time);
}

double PrescribedMotions::value(const PrescribedDof& entry, double time) const {
  return value(entry, time, entry.motion);
}

void PrescribedMotions::apply(double time, double dt, double* u, double* du, double* v,
                              double* a) const {
  // Derivatives by central differences of the known function, centred on this time: the
  // spacing is the step (consistent with central difference) or, at the start, a short one.
  const double h = dt > 0 ? dt : kDerivativeStep;
  std::vector<double>* at = values_at_;
  for (std::size_t m = 0; m < motions_.size(); ++m) {
    if (uniform_[m]) {
      for (int i = 0; i < 3; ++i)
        at[i][m] = functions_[m](0, 0, 0, time + (i - 1) * h);
    }
  }
  for (const PrescribedDof& entry : dofs_) {
    const int m = entry.motion;
    double f[3];
    for (int i = 0; i < 3; ++i)
      f[i] = uniform_[m] ? at[i][m] : value(entry, time + (i - 1) * h);
    const LocalIndex k = entry.dof;
    const double u_old = u[k] - du[k];
    if (motions_[m].velocity) {
      // Trapezoidal displacement from the velocities at both ends of the step.
      if (dt > 0)
        u[k] = u_old + 0.5 * dt * (value(entry, time - dt, m) + f[1]);
      v[k] = f[1];
      a[k] = (f[2] - f[0]) / (2 * h);
    } else {
      u[k] = f[1];
      v[k] = (f[2] - f[0]) / (2 * h);
      a[k] = (f[2] - 2 * f[1] + f[0]) / (h * h);
    }
    if (dt > 0)
      du[k] = u[k] - u_old;
  }
}

}  // namespace railfe
