// A physical group of the mesh read for a problem file's entry: a missing group is named by
// the entry's key.
#pragma once

#include "native/problem_file.h"

#include "base/errors.h"

#include <string>

namespace ffeti::native {

/// A physical group's nodes or segments, a missing group named by the problem file's key.
template <class Lookup>
auto from_group(const ProblemFile& problem, const std::string& key, Lookup lookup) {
  try {
    return lookup();
  } catch (const InputError& error) {
    throw InputError(problem.path + ": " + key + ": " + error.what());
  }
}

}  // namespace ffeti::native
