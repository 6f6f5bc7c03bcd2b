#pragma once
// The message of the InputError that `f` throws, or "no InputError".
#include <functional>
#include <string>

#include "wearscale/core/errors.hpp"

inline std::string input_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const wearscale::InputError& e) {
    return e.what();
  }
  return "no InputError";
}
