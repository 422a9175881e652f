// The message of the InputError a call throws, for tests of refusals.
#pragma once

#include "base/errors.h"

#include <functional>
#include <string>

namespace ffeti {

/// "(no InputError)" when `f` throws none.
inline std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace ffeti
