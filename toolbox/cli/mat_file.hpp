// cli/mat_file.hpp -- MATLAB .mat files (level 5, what `save -v7` and `save -v6` write; read and
// written through matio): a model read from one (`--mat FILE:VAR`), and the simulator's samples
// written to one (`simulate --format mat`).
//
// A .mat file is untrusted binary input (docs/security.md). Before matio parses it: at most
// 64 MB, and a level-5 header (v7.3 files are HDF5 containers and v4 files have no header:
// both refused, "save with -v7"). Every variable used is checked for class (real double only:
// no complex, sparse, integer, logical, char), rank 2, dimensions (limits.hpp) and finite
// entries before its data is used, and every failure is an InputError naming FILE:VAR.
//
// Doubles are taken at their exact binary value (0.1 in the file is 3602879701896397/2^55,
// not 1/10): the analyses are exact for the model the file holds. Write exact decimals with
// --num/--den when 1/10 is meant.
//
// What `--mat FILE[:SPEC]` finds (first match):
//   FILE:NUM,DEN   two vectors, the numerator and denominator in descending powers of z
//   FILE:VAR       VAR a struct with fields num, den (vectors) or A, B, C, D (matrices);
//                  a 1x2 cell {num, den}; or a 2-row matrix [num; den]
//   FILE           variables named num and den, else A, B, C and D
// A vector may also be a 1x1 cell holding the vector (MATLAB's tfdata without 'v'). A SISO
// state space is turned into H(z) exactly by the commands that take a transfer function.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hapstab/lti/state_space.hpp"
#include "hapstab/numeric/scalar.hpp"

namespace hapstab::cli {

/// A model from a .mat file: a transfer function (coefficients in descending powers, exact
/// values of the doubles) or a state space (T = 0: the sample period comes from --T).
struct MatModel {
  std::string where;  ///< "--mat FILE:VAR" for messages
  std::optional<std::pair<std::vector<rational>, std::vector<rational>>> tf;  ///< num, den
  std::optional<StateSpace<double>> ss;
};

/// `spec` split into the file and ":VAR" / ":NUM,DEN" (empty when `spec` names the file alone):
/// FILE:SPEC when what follows the last ':' is one or two MATLAB names, else FILE alone.
std::pair<std::string, std::string> split_mat_spec(const std::string& spec);

/// Reads `spec` ("FILE", "FILE:VAR" or "FILE:NUM,DEN") of option `option` ("--mat").
MatModel read_mat_model(const std::string& spec, const std::string& option);

/// One real double matrix to write: rows x cols, `data` column-major (MATLAB's order).
struct MatMatrix {
  std::string name;
  std::size_t rows = 0, cols = 0;
  std::vector<double> data;
};

/// Writes the matrices to `file` as a level-5 .mat file, zlib-compressed (what MATLAB's
/// `save -v7` writes; scipy.io.loadmat and MATLAB read it). NumericalError when it cannot.
void write_mat(const std::filesystem::path& file, const std::vector<MatMatrix>& vars);

/// matio brings GnuTLS (matio -> HDF5 -> libcurl -> GnuTLS), and GnuTLS's library constructor
/// makes GMP zero every block it frees (mp_set_memory_functions with a zeroising free). That cost
/// a quarter of the instructions of an exact computation in every process that loaded matio.
/// hapstab holds no secrets. matio is loaded (dlopen) only when a .mat file is first read or
/// written, which calls this right after; main() and the Python module's worker call it too, for
/// a program that links matio itself (the tests). When GMP's free function is GnuTLS's, GMP gets
/// its own malloc-based functions back (GnuTLS's are malloc's too, so a block allocated before the
/// call is freed correctly after it); any other is left.
void restore_gmp_allocator();

}  // namespace hapstab::cli
