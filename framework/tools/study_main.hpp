#pragma once
/// \file
/// The command line of the study tools (contact/tools, framework/tools): `TOOL MODE OUT.csv`, one
/// function per mode; and their clock.

#include <chrono>
#include <exception>
#include <iostream>
#include <map>
#include <string>

namespace railfe {

/// Seconds elapsed since \p start.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Runs the mode named by argv[1] with the output path argv[2]; prints the usage (status 2)
/// for anything else and the message (status 1) when the mode throws.
inline int run_study(int argc, char** argv, const std::string& tool,
                     const std::map<std::string, int (*)(const std::string&)>& modes) {
  const auto mode = argc == 3 ? modes.find(argv[1]) : modes.end();
  if (mode == modes.end()) {
    std::string names;
    for (const auto& [name, run] : modes)
      names += (names.empty() ? "" : "|") + name;
    std::cerr << "usage: " << tool << ' ' << names << " OUT.csv\n";
    return 2;
  }
  try {
    return mode->second(argv[2]);
  } catch (const std::exception& e) {
    std::cerr << e.what() << '\n';
    return 1;
  }
}

}  // namespace railfe
