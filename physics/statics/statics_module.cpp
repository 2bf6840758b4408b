#include "physics/statics/statics_module.hpp"

#include "framework/solvers/linear_solver.hpp"
#include "physics/common/contact_settings.hpp"
#include "physics/common/solid_beam_ties.hpp"
#include "physics/common/solid_conditions.hpp"
#include "physics/elements/node_set_springs.hpp"
#include "physics/statics/statics_step.hpp"

namespace railfe {

namespace {

ParameterSpec statics_parameters() {
  ParameterSpec spec("Linear elastostatics of hex8 solids, with penalty contact between them.");
  add_solid_condition_parameters(spec);
  add_solid_beam_tie_parameters(spec);
  spec.sublist("Linear solver", linear_solver_parameters(), "How K u = f is solved.");
  ParameterSpec solid("Hex8 formulation of every solid block in this step.");
  solid.choice("Integration", "full",
               {{"full", "2x2x2 Gauss points, or the materials' Element (enhanced strain)"},
                {"one point",
                 "one point with Flanagan-Belytschko stiffness hourglass control, the explicit "
                 "module's default element at small strain: a preload for an explicit step with "
                 "the same Solid settings starts it in equilibrium"}},
               "Integration rule.");
  solid.real("Hourglass coefficient", 0.03,
             "kappa of the hourglass stiffness (as the explicit step's Solid list).", "",
             Range::closed(0, 1));
  solid.only_when("Integration", {"one point"}, {"Hourglass coefficient"});
  spec.sublist("Solid", solid, "Hex8 formulation.");
  spec.named_sublists("Springs", node_set_spring_parameters(),
                      "Node sets on springs to the ground (supports: pads, ballast) or to another "
                      "node set (a rail pad over a sleeper); their forces go to "
                      "<step>_springs.csv.");
  spec.named_sublists("Contact pairs", contact_pair_parameters(ContactUse::statics),
                      "Frictionless penalty contact between deformable bodies (a static preload).");
  spec.integer("Contact iterations", 30,
               "Most linear solves of the contact iterations (only with Contact pairs).",
               Range::closed(1, 1000));
  spec.real("Contact tolerance", 1e-8,
            "Out-of-balance force on the free DOFs, relative to the largest of the load, reaction "
            "and contact force norms, at which the contact iterations stop (only with Contact "
            "pairs).",
            "", Range::open_closed(0, 0.1));
  return spec;
}

}  // namespace

ModuleDescriptor statics_module() {
  ModuleDescriptor module;
  module.name = "statics";
  module.summary = "linear elastostatics: displacements, stresses and reactions under static loads";
  module.parameters = statics_parameters;
  module.create = [](const Teuchos::ParameterList& parameters) {
    return std::make_unique<StaticsStep>(parameters);
  };
  return module;
}

}  // namespace railfe
