// hapstab/report/registration.hpp -- the order of static registrations (proofs, figures): by the
// name of the file that registers them, then by line, whatever order the linker ran them in.
//
// The name, not the path: __FILE__ is the path the compiler was given, absolute for a file of a
// unity batch, relative to the tree for a lone file whose command line ccache's base_dir rewrote;
// '.' sorts before '/', so ordering by path once drew CI's figures in another order than the docs
// show (stop 58). The files that register must therefore have distinct names (tested).
#pragma once

#include <cstring>

namespace hapstab::report {

/// The last component of a __FILE__ path.
inline const char* source_file_name(const char* path) {
  const char* slash = std::strrchr(path, '/');
  return slash ? slash + 1 : path;
}

/// Whether a registration at (file_a, line_a) comes before one at (file_b, line_b).
inline bool registered_before(const char* file_a, int line_a, const char* file_b, int line_b) {
  const int c = std::strcmp(source_file_name(file_a), source_file_name(file_b));
  return c < 0 || (c == 0 && line_a < line_b);
}

}  // namespace hapstab::report
