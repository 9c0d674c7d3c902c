// fuzz-modules: study
// fuzz-seeds: tests/fuzz/seeds_spec
// fuzz-dict: tests/fuzz/spec.dict
// fuzz-max-len: 131072
// libFuzzer target: the sweep spec reader (study::parse_spec: TOML -> command, [args], [axes])
// on arbitrary text. Any input must end in a Spec within the limits of study/spec.hpp (points
// counted before any axis is generated, every exact value bounded) or an InputError -- never a
// crash, a hang, or another exception type.
#include <cstdint>
#include <string>

#include "hapstab/numeric/error.hpp"
#include "hapstab/study/spec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto spec = hapstab::study::parse_spec(text, "fuzz.toml");
    uint64_t points = 1;
    size_t bytes = 0;
    for (const auto& a : spec.axes) {
      points *= a.values.size();
      for (const auto& v : a.values) bytes += v.size();
    }
    if (spec.axes.empty() || points != spec.points || points > hapstab::study::max_points ||
        bytes > hapstab::study::max_values_bytes)
      std::abort();
  } catch (const hapstab::InputError&) {
  }
  return 0;
}
