// The unit tests' check of a refusal: `action` throws an InputError whose message contains
// `part` (the argument it names and what is wrong).
#pragma once

#include "base/errors.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace ffeti {

inline void expect_input_error(const std::function<void()>& action, const std::string& part) {
  try {
    action();
    ADD_FAILURE() << "no InputError, expected one containing '" << part << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

}  // namespace ffeti
