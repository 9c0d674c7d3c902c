// fuzz-modules: report
// fuzz-seeds: tests/fuzz/seeds_text
// fuzz-dict: tests/fuzz/escape.dict
// libFuzzer target: report::csv::cell. The cell must parse by RFC 4180 as one field (quoted:
// "" is a quote, nothing after the closing quote; unquoted: no , " CR LF) whose value is
// text(input), prefixed with ' exactly when a spreadsheet would read a formula (= + - @ tab
// first, and not a plain number).
#include "fuzz_escape.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hapstab::report;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  const std::string c = csv::cell(in);
  std::string value;
  if (!c.empty() && c.front() == '"') {
    FUZZ_CHECK(c.size() >= 2 && c.back() == '"', "unterminated quoted cell", in, c);
    for (size_t i = 1; i + 1 < c.size(); ++i) {
      if (c[i] == '"') {
        FUZZ_CHECK(i + 2 < c.size() && c[i + 1] == '"', "a lone quote inside a quoted cell", in, c);
        ++i;
      }
      value += c[i];
    }
  } else {
    FUZZ_CHECK(c.find_first_of(",\"\r\n") == std::string::npos, "unquoted cell holds a separator", in, c);
    value = c;
  }
  std::string want = text(in);
  if (!want.empty() && std::string_view("=+-@\t").find(want[0]) != std::string_view::npos && !csv::is_plain_number(want))
    want = "'" + want;
  FUZZ_CHECK(value == want, "parsed cell differs from the neutralised text", in, c);
  if (!value.empty() && std::string_view("=+-@\t\r").find(value[0]) != std::string_view::npos)
    FUZZ_CHECK(csv::is_plain_number(value), "a formula reaches the spreadsheet", in, c);
  return 0;
}
