#pragma once
/// \file
/// Readers of the MiniProf and two-column text profile formats (see profile_file.hpp), and the
/// number parsing all profile readers share. The points come back as listed, unchecked.

#include <istream>
#include <optional>
#include <string>

#include "contact/geometry/profile_file.hpp"

namespace railfe {

/// \p token as a finite number, or nothing.
std::optional<double> profile_number(const std::string& token);

/// Reads a MiniProf .ban (rail) or .whl (wheel) file from \p in; \p path is for messages.
ProfileFile read_miniprof(std::istream& in, const std::string& path, ProfileType type);

/// Reads "y z" lines in mm from \p in; \p path is for messages.
ProfileFile read_two_columns(std::istream& in, const std::string& path);

}  // namespace railfe
