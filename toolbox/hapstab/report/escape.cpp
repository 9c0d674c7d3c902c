#include "hapstab/report/escape.hpp"

#include <cctype>

#include <algorithm>
#include <cstdint>

namespace hapstab::report {

namespace {

constexpr const char* kReplacement = "\xEF\xBF\xBD";  // U+FFFD

// Length of the well-formed UTF-8 sequence at s[i] and its code point; 0 when malformed
// (overlong forms, surrogates, > U+10FFFF, truncated or stray continuation bytes).
size_t utf8_at(std::string_view s, size_t i, uint32_t& cp) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const unsigned char c = b(0);
  if (c < 0x80) {
    cp = c;
    return 1;
  }
  size_t n;
  uint32_t min;
  if ((c & 0xE0) == 0xC0) n = 2, cp = c & 0x1F, min = 0x80;
  else if ((c & 0xF0) == 0xE0) n = 3, cp = c & 0x0F, min = 0x800;
  else if ((c & 0xF8) == 0xF0) n = 4, cp = c & 0x07, min = 0x10000;
  else return 0;
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((b(k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (b(k) & 0x3F);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

// C0 but tab, DEL, C1, and the bidirectional embeddings, overrides and isolates (U+202A-E,
// U+2066-9), which can make displayed text read differently from its bytes.
bool is_control(uint32_t cp) {
  return (cp < 0x20 && cp != '\t') || (cp >= 0x7F && cp <= 0x9F) || (cp >= 0x202A && cp <= 0x202E) ||
         (cp >= 0x2066 && cp <= 0x2069);
}

// Applies `each(ch)` to every character of text(s) that is ASCII, and appends the others whole.
template <class F>
std::string map_text(std::string_view s, F each, bool keep_newlines = false) {
  std::string o;
  o.reserve(s.size() + 8);
  for (size_t i = 0; i < s.size();) {
    uint32_t cp = 0;
    const size_t n = utf8_at(s, i, cp);
    if (n == 0) {
      o += kReplacement;
      ++i;
      continue;
    }
    if (is_control(cp) && !(keep_newlines && cp == '\n')) o += kReplacement;
    else if (n == 1) each(o, s[i]);
    else o.append(s.data() + i, n);
    i += n;
  }
  return o;
}

void plain(std::string& o, char c) { o += c; }

// One ASCII character and what it becomes in the target language.
struct Substitution {
  char c;
  const char* with;
};

// map_text with a table: each listed character becomes its replacement, the others stay.
template <size_t K>
std::string substitute(std::string_view s, const Substitution (&table)[K]) {
  return map_text(s, [&](std::string& o, char c) {
    for (const auto& r : table)
      if (r.c == c) {
        o += r.with;
        return;
      }
    o += c;
  });
}

}  // namespace

std::string text(std::string_view s, bool keep_newlines) { return map_text(s, plain, keep_newlines); }

bool is_clean_text(std::string_view s) {
  for (size_t i = 0; i < s.size();) {
    uint32_t cp = 0;
    const size_t n = utf8_at(s, i, cp);
    if (n == 0 || is_control(cp)) return false;
    i += n;
  }
  return true;
}

std::string comment(std::string_view s) {
  static constexpr Substitution table[] = {{'\t', " "}};
  return substitute(s, table);
}

namespace gnuplot {
std::string quote(std::string_view s) {
  // gnuplot's scanner reads '' inside a literal as a quote only where no other quote is next
  // to it ('a''''b' and a literal starting with '' fail), so each quote is its own piece "'"
  // and the runs between them are plain single-quoted literals, joined by '.'.
  std::string o, run;
  const auto piece = [&](const std::string& p) { o += (o.empty() ? "" : ".") + p; };
  for (char c : text(s)) {
    if (c != '\'') {
      run += c;
      continue;
    }
    if (!run.empty()) piece("'" + run + "'");
    run.clear();
    piece("\"'\"");
  }
  if (!run.empty() || o.empty()) piece("'" + run + "'");
  return o;
}
}  // namespace gnuplot

namespace csv {
bool is_plain_number(std::string_view s) {
  // the non-finite values the commands print ("inf", "-inf", "nan"): numbers, and no formula
  // (a spreadsheet reads -inf as the name inf, which a CSV cannot define)
  const std::string_view unsigned_part = !s.empty() && (s[0] == '+' || s[0] == '-') ? s.substr(1) : s;
  if (unsigned_part == "inf" || unsigned_part == "nan") return true;
  bool digit = false;
  for (char c : s) {
    if (c >= '0' && c <= '9') digit = true;
    else if (c != '+' && c != '-' && c != '.' && c != '/' && c != 'e' && c != 'E') return false;
  }
  return digit;
}

std::string cell(std::string_view s) {
  std::string t = text(s);
  if (!t.empty() && (t[0] == '=' || t[0] == '+' || t[0] == '-' || t[0] == '@' || t[0] == '\t' || t[0] == '\r') && !is_plain_number(t))
    t.insert(t.begin(), '\'');
  const bool quote = t.find_first_of(",\"\r\n") != std::string::npos || (!t.empty() && (t.front() == ' ' || t.back() == ' '));
  if (!quote) return t;
  std::string o = "\"";
  for (char c : t) o += c == '"' ? std::string("\"\"") : std::string(1, c);
  return o + "\"";
}
}  // namespace csv

namespace latex {
std::string escape(std::string_view s) {
  static constexpr Substitution table[] = {
      {'\\', "\\textbackslash{}"}, {'{', "\\{"}, {'}', "\\}"}, {'$', "\\$"}, {'&', "\\&"}, {'#', "\\#"},
      {'^', "\\textasciicircum{}"}, {'_', "\\_"}, {'~', "\\textasciitilde{}"}, {'%', "\\%"},
      // in the default OT1 encoding < > | print as other glyphs
      {'<', "\\textless{}"}, {'>', "\\textgreater{}"}, {'|', "\\textbar{}"}, {'\t', " "}};
  return substitute(s, table);
}
}  // namespace latex

namespace html {
std::string text(std::string_view s) {
  static constexpr Substitution table[] = {{'&', "&amp;"}, {'<', "&lt;"}, {'>', "&gt;"}, {'"', "&quot;"}, {'\'', "&#39;"}};
  return substitute(s, table);
}

std::string attribute(std::string_view s) {
  std::string o = text(s);
  std::string r;
  for (char c : o) r += c == '`' ? std::string("&#96;") : std::string(1, c);  // old IE read ` as a quote
  return r;
}

std::string url_component(std::string_view s) {
  static const char* hex = "0123456789ABCDEF";
  std::string o;
  for (unsigned char c : s) {
    if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '~' ||
        c == '-')
      o += static_cast<char>(c);
    else
      o += '%', o += hex[c >> 4], o += hex[c & 15];
  }
  return o;
}
}  // namespace html

namespace markdown {
std::string cell(std::string_view s) {
  const std::string t = text(s);  // control characters, newlines, malformed UTF-8 -> U+FFFD
  std::string o;
  o.reserve(t.size());
  for (size_t i = 0; i < t.size(); ++i) {
    const char c = t[i], next = i + 1 < t.size() ? t[i + 1] : '\0';
    const bool letter = std::isalpha(static_cast<unsigned char>(next)) != 0;
    switch (c) {
      case '|': o += "\\|"; break;
      case '\\': o += "\\\\"; break;
      case '`': o += "\\`"; break;
      case '[': o += "\\["; break;
      case ']': o += "\\]"; break;
      case '\t': o += ' '; break;
      // '<' opens raw HTML or an autolink only before a letter, '/', '!' or '?', and '&' an entity
      // only before a letter or '#': those get CommonMark's backslash escape; the others stay as
      // they are, so "b* < b" and "K <= 2b/T" read the same in the file and on the page
      case '<': o += letter || next == '/' || next == '!' || next == '?' ? "\\<" : "<"; break;
      case '&': o += letter || next == '#' ? "\\&" : "&"; break;
      default: o += c;
    }
  }
  return o;
}

std::string code(std::string_view s) {
  // In a GFM table the pipe must be escaped even inside a code span; control characters and
  // newlines are already gone through map_text.
  size_t run = 0, longest = 0;
  std::string body = map_text(s, [&](std::string& o, char c) {
    run = c == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
    if (c == '|') o += "\\|";
    else o += c == '\t' ? ' ' : c;
  });
  if (body.empty()) return "` `";  // `` is no code span
  const std::string fence(longest + 1, '`');
  const bool pad = !body.empty() && (body.front() == '`' || body.back() == '`');
  return fence + (pad ? " " : "") + body + (pad ? " " : "") + fence;
}
}  // namespace markdown

}  // namespace hapstab::report
