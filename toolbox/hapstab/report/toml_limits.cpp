// The depth check of TOML text before parsing (see toml_limits.hpp).
#include "hapstab/report/toml_limits.hpp"

#include <algorithm>
#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::report {

namespace {

class DepthScan {
 public:
  explicit DepthScan(std::string_view text) : s_(text) {}

  TomlDepth run() {
    bool line_start = true;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '\n') {
        ++line_, ++i_;
        if (stack_.empty()) line_start = true;
        continue;
      }
      if (c == ' ' || c == '\t' || c == '\r') {
        ++i_;
        continue;
      }
      if (c == '#') {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
        continue;
      }
      if (line_start) {  // a [header], [[header]] or key = value
        line_start = false;
        if (c == '[') {
          const bool array_of_tables = i_ + 1 < s_.size() && s_[i_ + 1] == '[';
          i_ += array_of_tables ? 2 : 1;
          // Each component may pass through an array of tables ([[a]] then [a.b]: a, its last
          // element, b), at most as many as the [[...]] headers before: counted as if it did.
          const int parts = key_components(']');
          table_ = parts + std::min(parts, arrays_) + (array_of_tables ? 1 : 0);
          if (array_of_tables) ++arrays_;
          check(table_);
          while (i_ < s_.size() && s_[i_] == ']') ++i_;
        } else {
          value_ = table_ + key_components('=');
          check(value_);
        }
        continue;
      }
      if (want_key_) {  // after '{' or ',' inside an inline table
        want_key_ = false;
        if (c == '}') {
          close();
          continue;
        }
        value_ = stack_.back().depth + key_components('=');
        check(value_);
        continue;
      }
      switch (c) {
        case '"':
        case '\'':
          skip_string();
          break;
        case '[':  // an array at depth value_, its elements one deeper
          stack_.push_back({'[', value_});
          check(++value_);
          ++i_;
          break;
        case '{':
          stack_.push_back({'{', value_});
          want_key_ = true;
          ++i_;
          break;
        case ']':
        case '}':
          close();
          break;
        case ',':
          if (!stack_.empty() && stack_.back().kind == '{') want_key_ = true;
          ++i_;
          break;
        default:
          ++i_;
      }
    }
    return deepest_;
  }

 private:
  struct Open {
    char kind;  ///< '[' an array, '{' an inline table
    int depth;  ///< the depth of the array or table itself
  };

  void close() {
    ++i_;
    if (!stack_.empty()) stack_.pop_back();
    if (!stack_.empty() && stack_.back().kind == '[') value_ = stack_.back().depth + 1;
  }

  void check(int depth) {
    if (depth <= deepest_.depth) return;
    // the line of the first node beyond the limit (the header, not a key under it), else the deepest
    const bool first_over = depth > limits::toml_depth && deepest_.depth <= limits::toml_depth;
    deepest_.line = first_over || deepest_.depth <= limits::toml_depth ? line_ : deepest_.line;
    deepest_.depth = depth;
  }

  /// The components of a (dotted) key starting at i_, up to `end` ('=' or ']'), a newline or the
  /// end of the text; quoted components may hold dots and the end character.
  int key_components(char end) {
    int parts = 1;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '"' || c == '\'') {
        skip_string();
      } else if (c == '.') {
        ++parts, ++i_;
      } else if (c == end || c == '\n') {
        if (c == end) ++i_;
        break;
      } else {
        ++i_;
      }
    }
    return parts;
  }

  /// Skips a basic or literal string, one-line or multi-line, starting at its quote.
  void skip_string() {
    const char q = s_[i_];
    const bool multi = i_ + 2 < s_.size() && s_[i_ + 1] == q && s_[i_ + 2] == q;
    i_ += multi ? 3 : 1;
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == '\\' && q == '"') {
        if (i_ + 1 < s_.size() && s_[i_ + 1] == '\n') ++line_;
        i_ += 2;
        continue;
      }
      if (c == '\n') {
        if (!multi) return;  // an unterminated string: toml++ says so
        ++line_;
      }
      ++i_;
      if (c == q) {
        if (!multi) return;
        if (i_ + 1 < s_.size() && s_[i_] == q && s_[i_ + 1] == q) {  // """ ends it; up to two more quotes belong to it
          i_ += 2;
          for (int extra = 0; extra < 2 && i_ < s_.size() && s_[i_] == q; ++extra) ++i_;
          return;
        }
      }
    }
  }

  std::string_view s_;
  TomlDepth deepest_;
  std::size_t i_ = 0;
  long line_ = 1;
  int table_ = 0;   ///< depth of the current [header]'s table
  int arrays_ = 0;  ///< [[header]]s so far
  int value_ = 0;  ///< depth of the value about to be read
  bool want_key_ = false;
  std::vector<Open> stack_;
};

}  // namespace

TomlDepth toml_depth(std::string_view text) { return DepthScan(text).run(); }

void check_toml_depth(std::string_view text, const std::string& file) {
  const TomlDepth d = toml_depth(text);
  if (d.depth > limits::toml_depth)
    throw InputError(file + ":" + std::to_string(d.line) + ": a key or table nested " + std::to_string(d.depth) +
                     " levels deep (table header, dotted key, arrays and inline tables together), more than the "
                     "limit of " + std::to_string(limits::toml_depth));
}

}  // namespace hapstab::report
