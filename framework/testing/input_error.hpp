#pragma once
/// \file
/// Test helper: the message of the InputError an action throws.

#include <functional>
#include <string>

#include "framework/base/error.hpp"

namespace railfe {

/// Runs \p action and returns the message of the InputError it throws, or "" if it throws none
/// (other exceptions propagate, so a wrong kind of failure fails the test).
inline std::string input_error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

}  // namespace railfe
