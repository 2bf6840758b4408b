#pragma once
/// \file
/// Prints a valid-parameter list for people: plain text for `railfe --describe`, Markdown for the
/// deck reference in docs/.

#include <ostream>
#include <string>

#include <Teuchos_ParameterList.hpp>

namespace railfe {

/// Output style of describe_parameters().
enum class DescribeFormat { text, markdown };

/// Writes every parameter of \p valid (recursively) with type, default, allowed values, units
/// and doc string. \p path is the list's place in the deck ("" for the top level), \p title the
/// heading printed above it.
void describe_parameters(std::ostream& out, const Teuchos::ParameterList& valid,
                         const std::string& path, const std::string& title, DescribeFormat format);

}  // namespace railfe
