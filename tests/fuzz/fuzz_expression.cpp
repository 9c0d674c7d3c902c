// fuzz-modules: lti
// fuzz-seeds: tests/fuzz/seeds_expression
// fuzz-dict: tests/fuzz/expression.dict
// fuzz-max-len: 131072
// libFuzzer target: the exact expression parser behind --H, a scene's tf, a --batch line, and
// the number reader behind --T, --set values and every exact decimal. The first byte picks the
// options (variable s / z / inferred, T given or not, a parameter K defined or not); the rest is
// the text. Any input must end in a result or an InputError -- never a crash, a hang, another
// exception type, or a result beyond the limits of numeric/limits.hpp.
#include <cstdint>
#include <string>

#include "hapstab/lti/parse.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const unsigned char mode = data[0];
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  hapstab::ParseOptions o;
  o.variable = (mode & 3) == 1 ? 's' : (mode & 3) == 2 ? 'z' : 0;
  if (mode & 4) o.T = hapstab::rational(1, 1000);
  if (mode & 8) o.parameters["K"] = hapstab::rational(20000);
  if (mode & 16) o.parameters["B_1"] = hapstab::rational(-5, 3);
  try {
    const auto tf = hapstab::parse_tf(text, o);
    if (tf.H.num().degree() > hapstab::limits::model_degree || tf.H.den().degree() > hapstab::limits::model_degree) std::abort();
  } catch (const hapstab::InputError&) {
  }
  try {
    (void)hapstab::parse_rational(text, "--T");
  } catch (const hapstab::InputError&) {
  }
  return 0;
}
