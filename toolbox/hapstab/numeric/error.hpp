// hapstab/numeric/error.hpp -- the error types every module throws, mapped by the CLI to
// exit codes (DESIGN.md, "Interfaces"): InputError -> 2 (bad input), NumericalError -> 3.
// Messages name the offending input; the CLI prints them without a stack.
#pragma once

#include <stdexcept>
#include <string>

namespace hapstab {

/// Bad input: malformed expression, T <= 0, an assumption of a theorem violated, ...
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A computation that could not reach a trustworthy answer (solver failure, precision
/// exhausted). Never used for "the property does not hold" (that is a result, exit 1).
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace hapstab
