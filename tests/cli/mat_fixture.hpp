// tests/cli/mat_fixture.hpp -- writing MATLAB .mat test inputs with matio (what MATLAB's
// `save -v7` writes), and reading a variable back: for the tests of --mat and simulate --format mat.
#pragma once

#include <matio.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace hapstab_test {

/// A real double rows x cols matrix, `v` column-major; caller owns it (Mat_VarFree).
inline matvar_t* mat_double(const char* name, size_t rows, size_t cols, const std::vector<double>& v) {
  size_t dims[2] = {rows, cols};
  return Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(v.data()), 0);
}

/// A 1x1 struct with the given fields (takes ownership of them).
inline matvar_t* mat_struct(const char* name, std::initializer_list<std::pair<const char*, matvar_t*>> fields) {
  std::vector<const char*> names;
  for (const auto& f : fields) names.push_back(f.first);
  size_t dims[2] = {1, 1};
  matvar_t* s = Mat_VarCreateStruct(name, 2, dims, names.data(), unsigned(names.size()));
  for (const auto& f : fields) Mat_VarSetStructFieldByName(s, f.first, 0, f.second);
  return s;
}

/// A 1 x n cell (takes ownership of the entries).
inline matvar_t* mat_cell(const char* name, std::initializer_list<matvar_t*> entries) {
  size_t dims[2] = {1, entries.size()};
  std::vector<matvar_t*> cells(entries);  // the pointer array is copied, the entries are owned
  return Mat_VarCreate(name, MAT_C_CELL, MAT_T_CELL, 2, dims, cells.data(), 0);
}

/// Writes the variables (and frees them) to `file` as a compressed level-5 file.
inline void write_mat_file(const std::filesystem::path& file, std::initializer_list<matvar_t*> vars) {
  mat_t* m = Mat_CreateVer(file.c_str(), nullptr, MAT_FT_MAT5);
  for (matvar_t* v : vars) {
    Mat_VarWrite(m, v, MAT_COMPRESSION_ZLIB);
    Mat_VarFree(v);
  }
  Mat_Close(m);
}

/// Variable `name` of `file`: its dimensions and doubles (empty when absent or not double).
struct MatRead {
  size_t rows = 0, cols = 0;
  std::vector<double> data;
  bool found = false;
};
inline MatRead read_mat_variable(const std::filesystem::path& file, const char* name) {
  MatRead r;
  mat_t* m = Mat_Open(file.c_str(), MAT_ACC_RDONLY);
  if (!m) return r;
  if (matvar_t* v = Mat_VarRead(m, name)) {
    if (v->class_type == MAT_C_DOUBLE && v->rank == 2 && !v->isComplex) {
      r.found = true;
      r.rows = v->dims[0], r.cols = v->dims[1];
      const double* d = static_cast<const double*>(v->data);
      r.data.assign(d, d + r.rows * r.cols);
    }
    Mat_VarFree(v);
  }
  Mat_Close(m);
  return r;
}

}  // namespace hapstab_test
