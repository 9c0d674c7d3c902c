// fuzz-modules: lti
// fuzz-seeds: tests/fuzz/seeds_state_space
// fuzz-dict: tests/fuzz/state_space.dict
// libFuzzer target: the --ss JSON reader of `hapstab passivity-level` (lti/state_space_json.hpp).
// Any text must end in a validated state space within limits::state_space_dim or an InputError.
#include <cstdint>
#include <string>

#include "hapstab/lti/state_space_json.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto s = hapstab::state_space_from_json(text, "--ss fuzz.json");
    if (s.A.rows() > hapstab::limits::state_space_dim || !(s.T > 0)) std::abort();
  } catch (const hapstab::InputError&) {
  }
  return 0;
}
