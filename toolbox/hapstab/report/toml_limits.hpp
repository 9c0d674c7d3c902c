// hapstab/report/toml_limits.hpp -- the check every TOML text passes before toml++ parses it
// (scenes, sweep specs, the [reproduce] sections `hapstab reproduce` reads; docs/security.md).
//
// toml++ builds a table per component of a dotted key and recurses over them: a header
// [a.a.a...] of 50,000 components (100 KB) overflowed the stack inside the parser. Its own caps
// cover nested arrays and inline tables, not dotted keys. This check is a linear scan of the text
// (strings, comments, headers, keys, arrays and inline tables recognised as TOML 1.0 writes them)
// that computes the depth of every node the parse would create -- header components, plus the
// dotted-key components of a key, plus one level per enclosing array and inline table -- and
// refuses a text where any node is deeper than limits::toml_depth. It never reads more than the
// text, uses no recursion, and leaves every other error to toml++.
#pragma once

#include <string>
#include <string_view>

namespace hapstab::report {

/// The deepest node a TOML text would make (a table's depth is its number of key components
/// from the root; an array's elements are one deeper than the array), and the line where the
/// first node deeper than limits::toml_depth starts (else where the deepest starts). Never less than the depth of the tree toml++ builds from the text (tests/fuzz/
/// fuzz_scene.cpp checks this); 0 for a text without keys.
struct TomlDepth {
  int depth = 0;
  long line = 0;
};
TomlDepth toml_depth(std::string_view text);

/// Throws InputError "FILE:LINE: ... nested N levels deep ..., more than the limit of
/// limits::toml_depth" when a node of the TOML text would be deeper than the limit.
void check_toml_depth(std::string_view text, const std::string& file);

}  // namespace hapstab::report
