// hapstab/report/escape.hpp -- one writer per output language. Every string that comes from
// input (a scene's names and description, a file name, an expectation, an error message that
// quotes input) reaches a gnuplot script, a CSV file, a LaTeX file, an HTML page or a Markdown
// report only through these functions; docs/security.md is the threat model they serve.
//
// The rules, each in one place:
//   text        control characters (C0 but tab, DEL, C1) and malformed UTF-8 become U+FFFD;
//               every other character, any script, passes.
//   gnuplot     single-quoted string literals, in which nothing is special (no backslash
//               escapes, no `command` substitution, no @macro), joined by '.' with "'" for
//               each quote: it's -> 'it'."'".'s' (gnuplot's own '' escape fails next to
//               another quote). A newline would end the command, so `text` runs first. Use
//               it for every string; never splice input into a command position.
//   CSV         RFC 4180: a cell holding , " CR LF or a leading/trailing space is quoted, "
//               doubled. A cell a spreadsheet would take as a formula (first character
//               = + - @ tab CR) is prefixed with ' unless it is a plain number
//               (characters 0-9 + - . / e E only, or [+-]inf, nan: "-1/2", "-3.5e-7", "-inf"
//               stay as they are). The sweep's points.csv and simulate's CSV use it (OWASP's
//               CSV-injection rule).
//   LaTeX       \ { } $ & # ^ _ ~ % (and < > |, misprinted in OT1) become their text-mode
//               commands, so no control sequence (\write18, \input, ^^5c...) can be formed
//               from input.
//   HTML        & < > " ' become entities; `attribute` is the same for a double-quoted
//               attribute value; `url_component` percent-encodes all but [A-Za-z0-9._~-].
//   Markdown    a table cell: | \ ` [ ] backslash-escaped, and < before a letter / ! ? and &
//               before a letter or # (no raw HTML, autolink or entity, no link, no broken row;
//               "b* < b" stays readable; emphasis marks are left, they only change how text looks);
//               `code` is a code span whose fence is longer than any backtick run inside.
// Lines written for file comments (`# ...` in a data file) go through `comment`.
#pragma once

#include <string>
#include <string_view>

namespace hapstab::report {

/// `s` with control characters (all C0 but tab; DEL; C1) and malformed UTF-8 replaced by U+FFFD.
/// keep_newlines: '\n' passes (for multi-line error messages on a terminal).
std::string text(std::string_view s, bool keep_newlines = false);

/// True when `s` is well-formed UTF-8 without control characters (tab allowed).
bool is_clean_text(std::string_view s);

/// One line for a '#'-comment of a data file or script: `text`, newlines and tabs to spaces.
std::string comment(std::string_view s);

namespace gnuplot {
/// A gnuplot string expression holding `text(s)`: 'it'."'".'s' for it's.
std::string quote(std::string_view s);
}  // namespace gnuplot

namespace csv {
/// One RFC 4180 cell holding `text(s)`, formula-neutralised (see above).
std::string cell(std::string_view s);
/// True when `s` would be read as a plain number (0-9 + - . / e E, at least one digit; or
/// [+-]inf, [+-]nan).
bool is_plain_number(std::string_view s);
}  // namespace csv

namespace latex {
/// `text(s)` as LaTeX text-mode material.
std::string escape(std::string_view s);
}  // namespace latex

namespace html {
/// `text(s)` as HTML character data.
std::string text(std::string_view s);
/// `text(s)` for a double-quoted attribute value.
std::string attribute(std::string_view s);
/// Percent-encoding of every byte outside [A-Za-z0-9._~-] (one path segment of a URL).
std::string url_component(std::string_view s);
}  // namespace html

namespace markdown {
/// `text(s)` for one cell of a GitHub-flavoured Markdown table (or a paragraph).
std::string cell(std::string_view s);
/// `text(s)` as a code span inside a table cell.
std::string code(std::string_view s);
}  // namespace markdown

}  // namespace hapstab::report
