#pragma once
/// \file
/// The top level of a deck and its validation, level by level: the framework checks the top
/// level, Mesh and Output; each registered section's owner checks its section; each step is
/// checked against the spec of the module it names.

#include <ostream>
#include <string>

#include "framework/app/registry.hpp"
#include "framework/deck/deck.hpp"
#include "framework/deck/describe.hpp"

namespace railfe {

/// Valid parameters of the Output section.
ParameterSpec output_parameters();

/// Valid parameters of a step that uses \p module (its spec plus "Module").
ParameterSpec step_parameters(const ModuleDescriptor& module, const ModuleRegistry& registry);

/// Validates \p deck completely and fills in defaults (deterministic, so every rank reaches
/// the same verdict). Throws InputError naming the deck and the parameter path.
void validate_deck(Deck& deck, const ModuleRegistry& registry);

/// Prints the valid parameters of the framework, every section and every module; or, when
/// \p only is not empty, of the module or section of that name ("framework" for the top level).
/// Returns false if \p only names nothing known.
bool describe_deck(std::ostream& out, const ModuleRegistry& registry, const std::string& only,
                   DescribeFormat format);

}  // namespace railfe
