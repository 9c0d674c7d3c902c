// fuzz-modules: report
// fuzz-seeds: tests/fuzz/seeds_text
// fuzz-dict: tests/fuzz/escape.dict
// libFuzzer target: report::html and report::markdown. HTML text and attributes hold no
// < > " ' (attributes no `) and decode to text(input); URL segments hold only unreserved
// characters and %XX and decode to the input bytes; a Markdown cell has no unescaped | ` [ ] \,
// no raw < before a letter / ! ? (HTML, autolink) and no raw & before a letter or # (entity),
// and decodes (CommonMark backslash escapes) to text(input) with tabs as spaces; a code span's
// fence is longer than any backtick run inside it.
#include "fuzz_escape.hpp"

#include <cctype>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace hapstab::report;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  const std::string t = text(in);
  static const std::pair<const char*, const char*> entities[] = {
      {"&amp;", "&"}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&#96;", "`"}};
  std::string back;
  const std::string h = html::text(in), a = html::attribute(in);
  FUZZ_CHECK(h.find_first_of("<>\"'") == std::string::npos, "HTML text holds markup", in, h);
  FUZZ_CHECK(a.find_first_of("<>\"'`") == std::string::npos, "HTML attribute can be left", in, a);
  fuzz::unescape(h, entities, back);
  FUZZ_CHECK(back == t, "HTML text decodes to something else", in, h);
  fuzz::unescape(a, entities, back);
  FUZZ_CHECK(back == t, "HTML attribute decodes to something else", in, a);

  const std::string u = html::url_component(in);
  std::string decoded;
  for (size_t i = 0; i < u.size(); ++i) {
    const char c = u[i];
    if (c == '%') {
      FUZZ_CHECK(i + 2 < u.size(), "truncated %XX", in, u);
      decoded += static_cast<char>(std::strtol(std::string(u.substr(i + 1, 2)).c_str(), nullptr, 16));
      i += 2;
    } else {
      FUZZ_CHECK((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
                     c == '~' || c == '-',
                 "a reserved character in a URL segment", in, u);
      decoded += c;
    }
  }
  FUZZ_CHECK(decoded == in, "URL segment decodes to something else", in, u);

  const std::string m = markdown::cell(in);
  std::string md_back;
  for (size_t i = 0; i < m.size(); ++i) {
    const char c = m[i], next = i + 1 < m.size() ? m[i + 1] : '\0';
    if (c == '\\') {
      FUZZ_CHECK(next != '\0' && std::string_view("|\\`[]<&").find(next) != std::string_view::npos,
                 "a backslash that escapes nothing", in, m);
      md_back += m[++i];
      continue;
    }
    FUZZ_CHECK(std::string_view("|`[]").find(c) == std::string_view::npos, "an unescaped | ` [ ] in a cell", in, m);
    const bool letter = std::isalpha(static_cast<unsigned char>(next)) != 0;
    FUZZ_CHECK(c != '<' || !(letter || next == '/' || next == '!' || next == '?'), "a raw < that opens HTML", in, m);
    FUZZ_CHECK(c != '&' || !(letter || next == '#'), "a raw & that opens an entity", in, m);
    md_back += c;
  }
  FUZZ_CHECK(md_back == fuzz::tabs_to_spaces(t), "Markdown cell decodes to something else", in, m);

  const std::string k = markdown::code(in);
  size_t fence = 0;
  while (fence < k.size() && k[fence] == '`') ++fence;
  FUZZ_CHECK(fence >= 1 && k.size() >= 2 * fence, "code span without fences", in, k);
  const std::string_view inner(k.data() + fence, k.size() - 2 * fence);
  size_t run = 0;
  for (char c : inner) {
    run = c == '`' ? run + 1 : 0;
    FUZZ_CHECK(run < fence, "a backtick run as long as the fence closes the span early", in, k);
  }
  return 0;
}
