#pragma once

#include <functional>
#include <string>

#include "evaluator/core/input_error.h"

namespace slamsweep::testing {

/// The message of the InputError `action` throws, or "(no InputError)" when it throws none.
inline std::string ErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const evaluator::InputError& error) {
    return error.what();
  }
  return "(no InputError)";
}

}  // namespace slamsweep::testing
