// fuzz-modules: report
// fuzz-seeds: tests/fuzz/seeds_text
// fuzz-dict: tests/fuzz/escape.dict
// libFuzzer target: report::latex::escape. Outside the commands the escape writes itself, no
// character that LaTeX treats specially may remain (so no \write18, \input, ^^5c, $...$, {, #
// can be formed), and undoing those commands gives text(input) with tabs as spaces.
#include "fuzz_escape.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hapstab::report;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  const std::string e = latex::escape(in);
  static const std::pair<const char*, const char*> table[] = {
      {"\\textbackslash{}", "\\"}, {"\\textasciicircum{}", "^"}, {"\\textasciitilde{}", "~"}, {"\\textless{}", "<"},
      {"\\textgreater{}", ">"},    {"\\textbar{}", "|"},         {"\\{", "{"},  {"\\}", "}"}, {"\\$", "$"},
      {"\\&", "&"},                {"\\#", "#"},                 {"\\_", "_"},  {"\\%", "%"}};
  std::string back;
  fuzz::unescape(e, table, back);
  FUZZ_CHECK(back == fuzz::tabs_to_spaces(text(in)), "unescaped LaTeX differs from text(input)", in, e);
  // With the escape's own commands removed, nothing special is left.
  std::string rest;
  static const std::pair<const char*, const char*> drop[] = {
      {"\\textbackslash{}", ""}, {"\\textasciicircum{}", ""}, {"\\textasciitilde{}", ""}, {"\\textless{}", ""},
      {"\\textgreater{}", ""},   {"\\textbar{}", ""},         {"\\{", ""}, {"\\}", ""}, {"\\$", ""},
      {"\\&", ""},               {"\\#", ""},                 {"\\_", ""}, {"\\%", ""}};
  fuzz::unescape(e, drop, rest);
  FUZZ_CHECK(rest.find_first_of("\\{}$&#^_~%\n\r\t") == std::string::npos, "a LaTeX special character survived", in, e);
  return 0;
}
