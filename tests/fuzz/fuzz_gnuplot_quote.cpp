// fuzz-modules: report
// fuzz-seeds: tests/fuzz/seeds_text
// fuzz-dict: tests/fuzz/escape.dict
// libFuzzer target: report::gnuplot::quote. The expression must read back, by gnuplot's rules
// (nothing is special inside single quotes; "'" is a quote; '.' concatenates), as
// text(input), and hold no line break (which would end the command).
// Also: is_clean_text(s) exactly when text(s) == s.
#include "fuzz_escape.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  const std::string full = hapstab::report::gnuplot::quote(in);
  // Pieces joined by '.': "'" (one quote), or '...' holding no quote, no line break, no NUL.
  std::string body;
  std::string_view q = full;
  for (bool first = true; !q.empty(); first = false) {
    if (!first) {
      FUZZ_CHECK(q.front() == '.', "pieces not joined by '.'", in, full);
      q.remove_prefix(1);
    }
    if (q.substr(0, 3) == "\"'\"") {
      body += '\'';
      q.remove_prefix(3);
      continue;
    }
    FUZZ_CHECK(!q.empty() && q.front() == '\'', "a piece is not a single-quoted literal", in, full);
    const size_t end = q.find('\'', 1);
    FUZZ_CHECK(end != std::string_view::npos, "unterminated literal", in, full);
    const std::string_view lit = q.substr(1, end - 1);
    FUZZ_CHECK(lit.find_first_of(std::string_view("\n\r\0", 3)) == std::string_view::npos,
               "line break or NUL inside a literal", in, full);
    FUZZ_CHECK(end + 1 == q.size() || q[end + 1] == '.', "two literals next to each other read as ''", in, full);
    body += lit;
    q.remove_prefix(end + 1);
  }
  const std::string t = hapstab::report::text(in);
  FUZZ_CHECK(body == t, "read back differs from text(input)", in, full);
  FUZZ_CHECK(hapstab::report::is_clean_text(in) == (t == in), "is_clean_text disagrees with text", in, t);
  FUZZ_CHECK(hapstab::report::is_clean_text(t), "text() output is not clean", in, t);
  return 0;
}
