// Error type of the core: bad input, with a message naming the argument and the fix.
#pragma once

#include <stdexcept>
#include <string>

namespace ffeti {

/// Thrown for input that cannot define a valid problem (sizes, symmetry, kernels,
/// unrestrained bodies). Messages name the argument as the FreeFEM functions call it,
/// e.g. "K[3]" for the stiffness matrix of subdomain 3. Non-convergence is never thrown:
/// it is a SolveStatus in the result.
class InputError : public std::invalid_argument {
 public:
  explicit InputError(const std::string& message) : std::invalid_argument(message) {}
};

}  // namespace ffeti
