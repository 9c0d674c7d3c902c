// cli/mat_level5.hpp -- the structure of a MATLAB level-5 .mat file, checked before matio
// reads it (cli/mat_file.cpp; docs/security.md).
//
// matio trusts the sizes a file declares: a 284-byte file whose cell claims 2^34 elements made
// it calloc 206 GB (found by tests/fuzz/fuzz_mat.cpp). This walk reads the file's data
// elements as the MAT-File Format (MathWorks, "MAT-File Level 5") defines them -- an 8-byte tag
// (type, byte count; the "small data element" packs both into 4 bytes), a miMATRIX holding
// array flags, dimensions, a name and, by class, numeric data, cell elements or struct fields,
// and miCOMPRESSED holding one zlib-deflated element -- and refuses, with an InputError naming
// the variable, every element that
//   - runs past the end of its parent (or of the file),
//   - declares more elements than its bytes can hold (a cell or struct element needs at least
//     an 8-byte tag; a numeric array at most max_elements entries),
//   - nests deeper than max_depth, has more than max_dims dimensions or a product of
//     dimensions that overflows,
//   - inflates to more than max_inflated_bytes (a zip bomb), or is of a class hapstab cannot
//     hold (objects, function handles, opaque classes).
// What passes can still be refused later (class, shape, NaN: mat_file.cpp), but matio's
// allocations are then bounded by the file's own size and these limits.
#pragma once

#include <string>

namespace hapstab::cli {

/// Throws InputError (naming `where` and the variable) unless every variable of the level-5
/// file `bytes` (header included) has a consistent, bounded structure.
void check_level5_structure(const std::string& bytes, const std::string& where);

}  // namespace hapstab::cli
