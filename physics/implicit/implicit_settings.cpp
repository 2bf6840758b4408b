#include "physics/implicit/implicit_settings.hpp"

#include <cmath>

#include "framework/base/error.hpp"
#include "framework/deck/expression.hpp"

namespace railfe {

namespace {

ParameterSpec newton_parameters() {
  ParameterSpec spec(
      "When a step's Newton iteration has converged: both the residual and the increment test "
      "hold (docs/theory.md, \"HHT-α with Newton iterations\"). A linear model takes one solve "
      "per step and is checked the same way.");
  spec.real("Residual tolerance", 1e-8,
            "||R|| at most this times the largest force term of the balance.", "",
            Range::open_closed(0, 0.1));
  spec.real("Residual floor", 1e-10, "Absolute floor of the residual test.", "N",
            Range::positive());
  spec.real("Increment tolerance", 1e-8,
            "The last correction of u at most this times the step's displacement increment.", "",
            Range::open_closed(0, 0.1));
  spec.real("Increment floor", 1e-14, "Absolute floor of the increment test.", "m",
            Range::positive());
  spec.integer("Maximum iterations", 20, "Newton corrections allowed per step.",
               Range::closed(1, 1000));
  spec.integer("Maximum halvings", 10,
               "Times a step that fails to converge may be halved (each cut is reported) before "
               "the run stops with exit status 2.",
               Range::closed(0, 30));
  return spec;
}

ParameterSpec output_parameters() {
  ParameterSpec spec("What the step writes.");
  spec.integer("History interval", 1, "Steps between rows of <step>_histories.csv.",
               Range::at_least(1));
  spec.integer("Energy interval", 10, "Steps between rows of <step>_energy.csv.",
               Range::at_least(1));
  spec.real("Exodus interval", 0.0,
            "Simulated time between Exodus snapshots (0 = only the first and last).", "s",
            Range::non_negative());
  ParameterSpec history(
      "The mean of one kinematic component over a node set, every History "
      "interval; its peak and period go to <step>_measurements.csv.");
  history.required_text("Node set", "The nodes averaged.");
  history.choice("Quantity", "displacement",
                 {{"displacement", "m (rad for rotations)"},
                  {"velocity", "m/s (rad/s)"},
                  {"acceleration", "m/s^2 (rad/s^2)"}},
                 "What is recorded.");
  history.choice("Component", "x",
                 {{"x", "translation x"},
                  {"y", "translation y"},
                  {"z", "translation z"},
                  {"rx", "rotation about x (6-DOF nodes)"},
                  {"ry", "rotation about y (6-DOF nodes)"},
                  {"rz", "rotation about z (6-DOF nodes)"}},
                 "Which component.");
  history.real("Period reference", 0.0,
               "Value about which the period of an oscillation is measured (upward crossings).");
  spec.named_sublists("Histories", history, "Node-set histories.");
  return spec;
}

}  // namespace

void add_implicit_parameters(ParameterSpec& spec) {
  spec.required_real("End time", "Simulated duration.", "s", Range::positive());
  spec.required_real("Time step", "Δt (halved where Newton fails, then grown back).", "s",
                     Range::positive());
  spec.choice("Scheme", "HHT-alpha",
              {{"HHT-alpha",
                "Hilber-Hughes-Taylor: beta = (1-alpha)^2/4, gamma = (1-2 alpha)/2; alpha = 0 is "
                "the average-acceleration (trapezoidal) rule"},
               {"Newmark", "Newmark with the Beta and Gamma given (alpha = 0)"}},
              "The integrator (sign convention: docs/theory.md).");
  spec.real("Alpha", 0.0,
            "HHT alpha in [-1/3, 0]: numerical damping of high frequencies, spectral radius "
            "(1+alpha)/(1-alpha) at infinite step.",
            "", Range::closed(-1.0 / 3.0, 0));
  spec.real("Beta", 0.25, "Newmark beta (> 0; beta = 0 is the explicit module's scheme).", "",
            Range::open_closed(0, 1));
  spec.real("Gamma", 0.5, "Newmark gamma (>= 1/2).", "", Range::closed(0.5, 1.5));
  spec.only_when("Scheme", {"HHT-alpha"}, {"Alpha"});
  spec.only_when("Scheme", {"Newmark"}, {"Beta", "Gamma"});
  ParameterSpec rayleigh("Rayleigh damping C = a M + b K.");
  rayleigh.real("Mass coefficient", 0.0, "a.", "1/s", Range::non_negative());
  rayleigh.real("Stiffness coefficient", 0.0, "b.", "s", Range::non_negative());
  spec.sublist("Rayleigh damping", rayleigh, "Proportional damping.");
  spec.sublist("Newton", newton_parameters(), "Convergence of each step.");
  spec.choice("Mass", "consistent",
              {{"consistent", "the elements' consistent mass"}, {"lumped", "row sums (diagonal)"}},
              "Mass matrix.");
  spec.text("Start from", "",
            "A previous statics step whose displacements start this one (its loads should be "
            "this step's loads at t = 0, so that it starts in balance), or ''.");
  spec.text("Load function", "1",
            "Scale of the step's Gravity, Nodal forces and Surface loads as a function of time t "
            "(s), e.g. 'min(t/0.01, 1)' for a ramp (Moving loads have their own Function).");
  ParameterSpec initial("Initial velocity v = V on a node set.");
  initial.text("Node set", "", "The nodes ('' = every node).");
  initial.real_array("Translation", {0, 0, 0}, "V.", "m/s", 3);
  spec.named_sublists("Initial velocity", initial,
                      "Initial velocity fields (applied in order; later ones win).");
  spec.sublist("Output", output_parameters(), "What the step writes.");
}

ImplicitSettings read_implicit_settings(const Teuchos::ParameterList& step, const std::string& deck,
                                        const std::string& path) {
  ImplicitSettings settings;
  settings.end_time = step.get<double>("End time");
  settings.time_step = step.get<double>("Time step");
  if (settings.time_step > settings.end_time)
    throw_input_error(deck, path + "/Time step",
                      "is longer than the End time " + std::to_string(settings.end_time) + " s",
                      "a step no longer than End time");
  if (settings.end_time / settings.time_step > 1e8)
    throw_input_error(deck, path + "/Time step", "needs more than 1e8 steps to reach End time",
                      "a longer step or a shorter End time");
  if (step.get<std::string>("Scheme") == "HHT-alpha") {
    settings.scheme = NewmarkScheme::hht(step.get<double>("Alpha"));
  } else {
    settings.scheme = NewmarkScheme::newmark(step.get<double>("Beta"), step.get<double>("Gamma"));
  }
  const auto& rayleigh = step.sublist("Rayleigh damping");
  settings.rayleigh.mass = rayleigh.get<double>("Mass coefficient");
  settings.rayleigh.stiffness = rayleigh.get<double>("Stiffness coefficient");
  const auto& newton = step.sublist("Newton");
  settings.newton.residual_relative = newton.get<double>("Residual tolerance");
  settings.newton.residual_absolute = newton.get<double>("Residual floor");
  settings.newton.increment_relative = newton.get<double>("Increment tolerance");
  settings.newton.increment_absolute = newton.get<double>("Increment floor");
  settings.newton.max_iterations = newton.get<int>("Maximum iterations");
  settings.cut_back.max_halvings = newton.get<int>("Maximum halvings");
  settings.lumped_mass = step.get<std::string>("Mass") == "lumped";
  settings.start_from = step.get<std::string>("Start from");
  settings.load_function = step.get<std::string>("Load function");
  Expression(settings.load_function, deck, path + "/Load function");  // refuses a bad one now
  const auto& initial = step.sublist("Initial velocity");
  for (auto it = initial.begin(); it != initial.end(); ++it) {
    const auto& list = initial.sublist(initial.name(it));
    ImplicitInitialVelocity velocity;
    velocity.node_set = list.get<std::string>("Node set");
    const auto values = list.get<Teuchos::Array<double>>("Translation");
    for (int d = 0; d < 3; ++d)
      velocity.translation[d] = values[d];
    settings.initial_velocities.push_back(velocity);
  }
  const auto& output = step.sublist("Output");
  settings.history_interval = output.get<int>("History interval");
  settings.energy_interval = output.get<int>("Energy interval");
  settings.exodus_interval = output.get<double>("Exodus interval");
  const auto& histories = output.sublist("Histories");
  for (auto it = histories.begin(); it != histories.end(); ++it) {
    const auto& list = histories.sublist(histories.name(it));
    ImplicitHistory history;
    history.name = histories.name(it);
    history.node_set = list.get<std::string>("Node set");
    const std::string quantity = list.get<std::string>("Quantity");
    history.quantity = quantity == "displacement" ? 0 : quantity == "velocity" ? 1 : 2;
    const std::string component = list.get<std::string>("Component");
    const std::vector<std::string> names{"x", "y", "z", "rx", "ry", "rz"};
    for (int c = 0; c < 6; ++c)
      if (component == names[c])
        history.component = c;
    history.period_reference = list.get<double>("Period reference");
    settings.histories.push_back(history);
  }
  return settings;
}

}  // namespace railfe
