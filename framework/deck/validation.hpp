#pragma once
/// \file
/// Validation of one deck level against a valid list, with one clear message per problem.

#include <string>

#include <Teuchos_ParameterList.hpp>

namespace railfe {

/// Checks \p given against \p valid and completes it in place. Throws InputError naming
/// \p source (the deck) and the parameter path (\p path + "/" + name) on the first problem:
/// unknown or misspelled name (with a suggestion), wrong type, value out of range or not among the
/// choices, missing required value. Sublists the spec owns are checked recursively; delegated
/// sublists are left for their owner. Afterwards every optional parameter is present (defaults
/// filled in) and integers given for real parameters are stored as doubles, so owners can read
/// values with get<double>() etc. without further checks.
void validate_and_complete(Teuchos::ParameterList& given, const Teuchos::ParameterList& valid,
                           const std::string& source, const std::string& path);

/// Joins a parameter path: join_path("Steps", "load") == "Steps/load"; join_path("", "Mesh") ==
/// "Mesh".
std::string join_path(const std::string& path, const std::string& name);

}  // namespace railfe
