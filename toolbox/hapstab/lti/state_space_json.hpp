// hapstab/lti/state_space_json.hpp -- a discrete-time state space from JSON (`passivity-level
// --ss FILE`), an untrusted input format (docs/security.md):
//   {"A": [[0.5]], "B": [[1]], "C": [[1]], "D": [[1]], "T": "1/100"}
// Entries are numbers or strings holding exact decimals/fractions ("1/3"), rounded to double;
// T is exact. Dimensions are at most limits::state_space_dim (numeric/limits.hpp) and must
// agree (StateSpace::validate). Every error is an InputError naming `where` and the key.
#pragma once

#include <string>
#include <string_view>

#include "hapstab/lti/state_space.hpp"

namespace hapstab {

StateSpace<double> state_space_from_json(std::string_view text, const std::string& where);
/// The same model at the exact values written (numbers at their doubles' exact values, strings
/// such as "3/5" exactly): what the certified passivity levels are about.
StateSpace<rational> state_space_from_json_exact(std::string_view text, const std::string& where);

}  // namespace hapstab
