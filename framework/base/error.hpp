#pragma once
/// \file
/// Error types. railfe separates mistakes in what the user gave it (InputError: a deck, a mesh
/// file, a command-line option) from failures found while computing (RunError: a solver that did
/// not converge, an energy blow-up). Both carry a complete, user-facing message; the executable
/// prints it once and exits non-zero.

#include <stdexcept>
#include <string>
#include <vector>

namespace railfe {

/// A problem with user input. The message names the source (deck or file), the parameter path,
/// what was wrong and what is allowed.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A failure while computing that the user must know about (never a silently wrong answer).
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Formats the one-line message every input error uses:
/// "<source>: <path>: <problem>[; allowed: <allowed>]". Empty parts are left out.
std::string format_input_message(const std::string& source, const std::string& path,
                                 const std::string& problem, const std::string& allowed = "");

/// Throws InputError with format_input_message(source, path, problem, allowed).
[[noreturn]] void throw_input_error(const std::string& source, const std::string& path,
                                    const std::string& problem, const std::string& allowed = "");

/// Returns the candidate closest to \p name by edit distance (ignoring case), or "" when none is
/// close enough to be a plausible misspelling.
std::string closest_name(const std::string& name, const std::vector<std::string>& candidates);

/// The part of a multi-line library message that says what went wrong: its last non-empty line
/// (Trilinos messages open with file:line headers and "Throw test that evaluated to true").
std::string essential_line(const std::string& message);

/// Joins names as "'a', 'b', 'c'" for messages; long lists are shortened with a count.
std::string quoted_list(const std::vector<std::string>& names, std::size_t max_shown = 12);

}  // namespace railfe
