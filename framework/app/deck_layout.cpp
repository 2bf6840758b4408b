#include "framework/app/deck_layout.hpp"

#include "framework/base/error.hpp"
#include "framework/deck/validation.hpp"
#include "framework/mesh/mesh_parameters.hpp"

namespace railfe {

ParameterSpec output_parameters() {
  ParameterSpec spec("Where and what the run writes.");
  spec.text("Directory", "",
            "Results directory ('' = <deck name>_results in the current directory; the "
            "command-line option --output overrides it).");
  spec.flag("Exodus", true, "Write Exodus II results (ParaView) for each step.");
  spec.real("Progress interval", 5.0, "Seconds between progress lines of long phases.", "s",
            Range::positive());
  return spec;
}

namespace {

std::vector<Choice> module_choices(const ModuleRegistry& registry) {
  std::vector<Choice> choices;
  for (const auto& module : registry.modules())
    choices.push_back({module.name, module.summary});
  return choices;
}

ParameterSpec framework_parameters(const ModuleRegistry& registry) {
  ParameterSpec spec("The top level of a railfe deck.");
  spec.text("Title", "", "A title for the run summary and result files.");
  spec.sublist("Mesh", mesh_parameters(registry.mesh_generators()),
               "The mesh (needed by every step whose module works on a solid).", false);
  spec.sublist("Output", output_parameters(), "Results directory and formats.");
  for (const auto& section : registry.sections()) {
    spec.delegated_sublist(section.name, section.parameters(), section.summary, section.required);
  }
  ParameterSpec steps("The analysis steps, run in deck order.");
  spec.delegated_sublist("Steps", steps,
                         "The analysis steps, run in the order they appear; each is a sublist "
                         "naming its Module (see the module's parameters).",
                         true);
  return spec;
}

}  // namespace

ParameterSpec step_parameters(const ModuleDescriptor& module, const ModuleRegistry& registry) {
  ParameterSpec spec = module.parameters();
  spec.required_choice("Module", module_choices(registry), "The physics module of the step.");
  return spec;
}

void validate_deck(Deck& deck, const ModuleRegistry& registry) {
  auto& top = *deck.parameters;
  validate_and_complete(top, *framework_parameters(registry).list(), deck.source, "");
  for (const auto& section : registry.sections()) {
    if (top.isSublist(section.name)) {
      validate_and_complete(top.sublist(section.name), *section.parameters().list(), deck.source,
                            section.name);
    }
  }
  auto& steps = top.sublist("Steps");
  if (steps.numParams() == 0) {
    throw_input_error(deck.source, "Steps", "has no steps", "at least one step sublist");
  }
  for (auto it = steps.begin(); it != steps.end(); ++it) {
    const std::string name = steps.name(it);
    const std::string path = "Steps/" + name;
    if (!steps.isSublist(name)) {
      throw_input_error(deck.source, path, "is a parameter but must be a step sublist",
                        "a sublist with a Module parameter");
    }
    auto& step = steps.sublist(name);
    const auto names = registry.module_names();
    if (!step.isParameter("Module") || !step.isType<std::string>("Module")) {
      throw_input_error(deck.source, path + "/Module",
                        "missing required parameter (the step's physics module)",
                        quoted_list(names));
    }
    const auto module_name = step.get<std::string>("Module");
    const ModuleDescriptor* module = registry.find_module(module_name);
    if (module == nullptr) {
      std::string problem = "unknown module '" + module_name + "'";
      const std::string guess = closest_name(module_name, names);
      if (!guess.empty())
        problem += " (did you mean '" + guess + "'?)";
      throw_input_error(deck.source, path + "/Module", problem, quoted_list(names));
    }
    validate_and_complete(step, *step_parameters(*module, registry).list(), deck.source, path);
  }
}

bool describe_deck(std::ostream& out, const ModuleRegistry& registry, const std::string& only,
                   DescribeFormat format) {
  bool found = false;
  if (only.empty() || only == "framework") {
    describe_parameters(out, *framework_parameters(registry).list(), "",
                        "The top level of a railfe deck.", format);
    found = true;
  }
  for (const auto& section : registry.sections()) {
    if (!only.empty() && only != section.name)
      continue;
    describe_parameters(out, *section.parameters().list(), section.name, section.summary, format);
    found = true;
  }
  for (const auto& module : registry.modules()) {
    if (!only.empty() && only != module.name)
      continue;
    describe_parameters(out, *step_parameters(module, registry).list(),
                        "Steps/<" + module.name + " step>",
                        "A step with Module = '" + module.name + "': " + module.summary, format);
    found = true;
  }
  return found;
}

}  // namespace railfe
