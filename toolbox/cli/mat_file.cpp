// cli/mat_file.cpp -- see mat_file.hpp.
#include "cli/mat_file.hpp"

#include "cli/mat_level5.hpp"

#include <dlfcn.h>
#include <gmp.h>
#include <matio.h>

#include <cmath>
#include <cctype>
#include <cstring>
#include <fstream>
#include <memory>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/report/escape.hpp"

namespace hapstab::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t max_file_bytes = 64u << 20;
constexpr unsigned max_struct_fields = 64;

// matio is loaded when a .mat file is first read or written, not with the program: it brings 37
// shared libraries (HDF5, libcurl, GnuTLS, ...) whose loading and relocation were two thirds of
// every hapstab process's ~20 ms start-up. HAPSTAB_MATIO_SONAME is the library CMake found.
struct Matio {
  decltype(&::Mat_LogInitFunc) LogInitFunc;
  decltype(&::Mat_Open) Open;
  decltype(&::Mat_Close) Close;
  decltype(&::Mat_GetVersion) GetVersion;
  decltype(&::Mat_Rewind) Rewind;
  decltype(&::Mat_VarFree) VarFree;
  decltype(&::Mat_VarReadNextInfo) VarReadNextInfo;
  decltype(&::Mat_VarReadInfo) VarReadInfo;
  decltype(&::Mat_VarRead) VarRead;
  decltype(&::Mat_VarGetNumberOfFields) VarGetNumberOfFields;
  decltype(&::Mat_VarGetStructFieldByName) VarGetStructFieldByName;
  decltype(&::Mat_CreateVer) CreateVer;
  decltype(&::Mat_VarCreate) VarCreate;
  decltype(&::Mat_VarWrite) VarWrite;
};

// matio reports through a log function (by default to stderr); its last message joins our error.
thread_local std::string matio_message;
void matio_log(int, char* message) { matio_message = message ? message : ""; }

template <class F>
void bind_symbol(void* lib, F& f, const char* name) {
  f = reinterpret_cast<F>(::dlsym(lib, name));
  if (!f) throw InputError(std::string("reading or writing a .mat file: ") + HAPSTAB_MATIO_SONAME + " has no " + name);
}

const Matio& matio() {
  static const Matio api = [] {
    void* lib = ::dlopen(HAPSTAB_MATIO_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
      const char* why = ::dlerror();
      throw InputError(std::string("reading or writing a .mat file needs ") + HAPSTAB_MATIO_SONAME +
                       ", which could not be loaded (" + (why ? why : "no reason given") +
                       "); scripts/install-deps installs it");
    }
    restore_gmp_allocator();  // GnuTLS's constructor ran just now (mat_file.hpp)
    Matio m{};
    bind_symbol(lib, m.LogInitFunc, "Mat_LogInitFunc");
    bind_symbol(lib, m.Open, "Mat_Open");
    bind_symbol(lib, m.Close, "Mat_Close");
    bind_symbol(lib, m.GetVersion, "Mat_GetVersion");
    bind_symbol(lib, m.Rewind, "Mat_Rewind");
    bind_symbol(lib, m.VarFree, "Mat_VarFree");
    bind_symbol(lib, m.VarReadNextInfo, "Mat_VarReadNextInfo");
    bind_symbol(lib, m.VarReadInfo, "Mat_VarReadInfo");
    bind_symbol(lib, m.VarRead, "Mat_VarRead");
    bind_symbol(lib, m.VarGetNumberOfFields, "Mat_VarGetNumberOfFields");
    bind_symbol(lib, m.VarGetStructFieldByName, "Mat_VarGetStructFieldByName");
    bind_symbol(lib, m.CreateVer, "Mat_CreateVer");
    bind_symbol(lib, m.VarCreate, "Mat_VarCreate");
    bind_symbol(lib, m.VarWrite, "Mat_VarWrite");
    m.LogInitFunc("hapstab", &matio_log);
    return m;
  }();
  return api;
}

std::string matio_said() { return matio_message.empty() ? "" : " (matio: " + report::text(matio_message) + ")"; }

struct MatCloser {
  void operator()(mat_t* m) const { matio().Close(m); }
};
struct VarFreer {
  void operator()(matvar_t* v) const { matio().VarFree(v); }
};
using MatPtr = std::unique_ptr<mat_t, MatCloser>;
using VarPtr = std::unique_ptr<matvar_t, VarFreer>;

// Level 5 header: 116 bytes text, 8 subsystem offset, version 0x0100, endian "IM" (or "MI").
void check_header(const std::string& file, const std::string& where) {
  std::error_code ec;
  const auto size = fs::file_size(file, ec);
  if (ec) throw InputError(where + ": cannot read '" + report::text(file) + "': " + ec.message());
  if (size > max_file_bytes)
    throw InputError(where + ": " + std::to_string(size) + " bytes, more than the limit of 64 MB");
  unsigned char h[128];
  std::ifstream in(file, std::ios::binary);
  if (!in || !in.read(reinterpret_cast<char*>(h), sizeof h))
    throw InputError(where + ": not a MATLAB level-5 .mat file (shorter than its 128-byte header)");
  int version = -1;
  if (h[126] == 'I' && h[127] == 'M') version = h[124] | h[125] << 8;
  if (h[126] == 'M' && h[127] == 'I') version = h[124] << 8 | h[125];
  if (version == 0x0200)
    throw InputError(where + ": a v7.3 (HDF5) .mat file, which hapstab does not read; save it with -v7");
  if (version != 0x0100) throw InputError(where + ": not a MATLAB level-5 .mat file (save it with -v7)");
  in.seekg(0);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) throw InputError(where + ": cannot read it whole");
  check_level5_structure(bytes, where);  // matio trusts the sizes a file declares: check them first
}

class MatReader {
 public:
  MatReader(std::string file, std::string where) : file_(std::move(file)), where_(std::move(where)) {
    matio();
    check_header(file_, where_);
    matio_message.clear();
    mat_.reset(matio().Open(file_.c_str(), MAT_ACC_RDONLY));
    if (!mat_) throw InputError(where_ + ": matio cannot open it" + matio_said());
    if (matio().GetVersion(mat_.get()) != MAT_FT_MAT5) throw InputError(where_ + ": not a level-5 .mat file (save it with -v7)");
  }

  /// The names of the file's variables (at most 1000).
  std::vector<std::string> names() {
    std::vector<std::string> out;
    matio().Rewind(mat_.get());
    while (out.size() < 1000) {
      VarPtr v(matio().VarReadNextInfo(mat_.get()));
      if (!v) break;
      if (v->name) out.emplace_back(v->name);
    }
    return out;
  }
  bool has(const std::string& name) {
    for (const auto& n : names())
      if (n == name) return true;
    return false;
  }

  /// Variable `name`, its class and sizes checked on the header before the data is read.
  VarPtr read(const std::string& name) {
    matio_message.clear();
    matio().Rewind(mat_.get());
    VarPtr info(matio().VarReadInfo(mat_.get(), name.c_str()));
    if (!info) throw InputError(where_of(name) + ": no such variable" + matio_said());
    check_shape(info.get(), where_of(name), 0);
    matio().Rewind(mat_.get());
    VarPtr v(matio().VarRead(mat_.get(), name.c_str()));
    if (!v) throw InputError(where_of(name) + ": matio cannot read it" + matio_said());
    check_shape(v.get(), where_of(name), 0);
    return v;
  }

  /// "--mat FILE:VAR", how messages name a variable
  std::string where_of(const std::string& var) const { return where_ + ":" + report::text(var); }
  const std::string& where() const { return where_; }

 private:
  // The classes and sizes a model can have: doubles up to state_space_dim x state_space_dim or
  // a vector of degree + 1, 1x1 structs of such fields, 1x1/1x2/2x1 cells of such vectors.
  void check_shape(const matvar_t* v, const std::string& where, int depth) const {
    if (depth > 2) throw InputError(where + ": nested more than two levels deep");
    if (v->rank != 2 || !v->dims) throw InputError(where + ": has " + std::to_string(v->rank) + " dimensions, expected a matrix");
    const std::size_t r = v->dims[0], c = v->dims[1];
    const auto dim = static_cast<std::size_t>(limits::state_space_dim);
    const auto len = static_cast<std::size_t>(limits::model_degree) + 1;
    const std::string size = std::to_string(r) + "x" + std::to_string(c);
    switch (v->class_type) {
      case MAT_C_DOUBLE:
        if (v->isComplex) throw InputError(where + ": complex; expected real doubles");
        if (v->isLogical) throw InputError(where + ": logical; expected real doubles");
        if ((r > dim || c > dim) && !((r <= 2 && c <= len) || (c <= 2 && r <= len)))
          throw InputError(where + ": " + size + ", beyond the limits of " + std::to_string(dim) + "x" + std::to_string(dim) +
                           " (a matrix) or " + std::to_string(len) + " entries (a coefficient vector)");
        return;
      case MAT_C_STRUCT: {
        if (r != 1 || c != 1) throw InputError(where + ": a " + size + " struct array; expected a 1x1 struct");
        const unsigned n = matio().VarGetNumberOfFields(const_cast<matvar_t*>(v));
        if (n > max_struct_fields) throw InputError(where + ": a struct with " + std::to_string(n) + " fields (more than 64)");
        auto** fields = static_cast<matvar_t**>(v->data);
        for (unsigned i = 0; fields && i < n; ++i)
          if (fields[i]) check_shape(fields[i], where + "." + report::text(fields[i]->name ? fields[i]->name : "?"), depth + 1);
        return;
      }
      case MAT_C_CELL: {
        if (r * c > 2) throw InputError(where + ": a " + size + " cell; expected {num, den} or {vector}");
        auto** cells = static_cast<matvar_t**>(v->data);
        for (std::size_t i = 0; cells && i < r * c; ++i)
          if (cells[i]) check_shape(cells[i], where + "{" + std::to_string(i + 1) + "}", depth + 1);
        return;
      }
      case MAT_C_SPARSE: throw InputError(where + ": a sparse matrix; save it with full(...)");
      case MAT_C_CHAR: throw InputError(where + ": text; expected real doubles");
      default: throw InputError(where + ": of a class other than double (integer, single, object, ...); use double(...)");
    }
  }

  std::string file_, where_;
  MatPtr mat_;
};

// A real double matrix's entries (column-major), checked; a 1x1 cell is unwrapped.
struct Dense {
  std::size_t rows = 0, cols = 0;
  const double* data = nullptr;
  double at(std::size_t i, std::size_t j) const { return data[j * rows + i]; }
};

Dense dense(const matvar_t* v, const std::string& where) {
  if (v->class_type == MAT_C_CELL && v->dims[0] * v->dims[1] == 1 && v->data)
    return dense(static_cast<matvar_t**>(v->data)[0], where);
  if (v->class_type != MAT_C_DOUBLE) throw InputError(where + ": expected a real double matrix");
  Dense d{v->dims[0], v->dims[1], static_cast<const double*>(v->data)};
  const std::size_t n = d.rows * d.cols;
  if (n > 0 && (!d.data || v->data_type != MAT_T_DOUBLE || v->nbytes < n * sizeof(double)))
    throw InputError(where + ": its data could not be read as doubles");
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isfinite(d.data[k]))
      throw InputError(where + ": entry " + std::to_string(k + 1) + " is " + (std::isnan(d.data[k]) ? "NaN" : "Inf"));
  return d;
}

std::vector<rational> coefficients(const Dense& d, const std::string& where) {
  if (d.rows * d.cols == 0) throw InputError(where + ": empty; expected a coefficient vector");
  if (d.rows != 1 && d.cols != 1)
    throw InputError(where + ": " + std::to_string(d.rows) + "x" + std::to_string(d.cols) + "; expected a vector");
  std::vector<rational> c;
  for (std::size_t k = 0; k < d.rows * d.cols; ++k) c.push_back(exact_rational(d.data[k]));
  return c;
}

Mat<double> matrix(const Dense& d, const std::string& where) {
  const auto dim = static_cast<std::size_t>(limits::state_space_dim);
  if (d.rows > dim || d.cols > dim)
    throw InputError(where + ": " + std::to_string(d.rows) + "x" + std::to_string(d.cols) + ", more than the limit of " +
                     std::to_string(dim) + " rows or columns");
  Mat<double> M(static_cast<Eigen::Index>(d.rows), static_cast<Eigen::Index>(d.cols));
  for (std::size_t i = 0; i < d.rows; ++i)
    for (std::size_t j = 0; j < d.cols; ++j) M(Eigen::Index(i), Eigen::Index(j)) = d.at(i, j);
  return M;
}

const matvar_t* field(const matvar_t* s, const char* name) {
  return matio().VarGetStructFieldByName(const_cast<matvar_t*>(s), name, 0);
}

// VAR alone: a struct {num, den} or {A, B, C, D}, a cell {num, den}, or a 2-row [num; den].
void model_of_variable(MatModel& m, const matvar_t* v) {
  const std::string& w = m.where;
  if (v->class_type == MAT_C_STRUCT) {
    if (field(v, "num") && field(v, "den")) {
      m.tf = {coefficients(dense(field(v, "num"), w + ".num"), w + ".num"),
              coefficients(dense(field(v, "den"), w + ".den"), w + ".den")};
      return;
    }
    if (field(v, "A") && field(v, "B") && field(v, "C") && field(v, "D")) {
      StateSpace<double> s;
      s.A = matrix(dense(field(v, "A"), w + ".A"), w + ".A");
      s.B = matrix(dense(field(v, "B"), w + ".B"), w + ".B");
      s.C = matrix(dense(field(v, "C"), w + ".C"), w + ".C");
      s.D = matrix(dense(field(v, "D"), w + ".D"), w + ".D");
      m.ss = std::move(s);
      return;
    }
    throw InputError(w + ": a struct without the fields num, den or A, B, C, D");
  }
  if (v->class_type == MAT_C_CELL) {
    if (v->dims[0] * v->dims[1] != 2 || !v->data) throw InputError(w + ": expected a cell {num, den}");
    auto** c = static_cast<matvar_t**>(v->data);
    if (!c[0] || !c[1]) throw InputError(w + ": a cell with an unreadable entry");
    m.tf = {coefficients(dense(c[0], w + "{1}"), w + "{1}"), coefficients(dense(c[1], w + "{2}"), w + "{2}")};
    return;
  }
  const Dense d = dense(v, w);
  if (d.rows != 2) throw InputError(w + ": " + std::to_string(d.rows) + "x" + std::to_string(d.cols) +
                                    "; expected a struct, a cell {num, den} or a 2-row matrix [num; den]");
  std::vector<rational> num, den;
  for (std::size_t j = 0; j < d.cols; ++j) num.push_back(exact_rational(d.at(0, j))), den.push_back(exact_rational(d.at(1, j)));
  if (d.cols == 0) throw InputError(w + ": empty");
  m.tf = {num, den};
}

bool is_name(const std::string& s) {
  if (s.empty() || s.size() > 63 || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  for (char ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') return false;
  return true;
}

}  // namespace

std::pair<std::string, std::string> split_mat_spec(const std::string& spec) {
  // FILE:SPEC when what follows the last ':' is one or two MATLAB names, else FILE alone
  const auto colon = spec.rfind(':');
  if (colon != std::string::npos) {
    const std::string tail = spec.substr(colon + 1);
    const auto comma = tail.find(',');
    const std::string a = tail.substr(0, comma), b = comma == std::string::npos ? "" : tail.substr(comma + 1);
    if (is_name(a) && (comma == std::string::npos || is_name(b))) return {spec.substr(0, colon), spec.substr(colon)};
  }
  return {spec, ""};
}

MatModel read_mat_model(const std::string& spec, const std::string& option) {
  const auto [file, tail] = split_mat_spec(spec);
  std::string var1, var2;
  if (!tail.empty()) {
    const auto comma = tail.find(',');
    var1 = tail.substr(1, comma == std::string::npos ? std::string::npos : comma - 1);
    var2 = comma == std::string::npos ? "" : tail.substr(comma + 1);
  }
  if (file.empty()) throw InputError(option + ": expected FILE, FILE:VAR or FILE:NUM,DEN");
  MatReader r(file, option + " " + report::text(file));
  MatModel m;
  if (!var2.empty()) {
    m.where = r.where_of(var1 + "," + var2);
    m.tf = {coefficients(dense(r.read(var1).get(), r.where_of(var1)), r.where_of(var1)),
            coefficients(dense(r.read(var2).get(), r.where_of(var2)), r.where_of(var2))};
    return m;
  }
  if (!var1.empty()) {
    m.where = r.where_of(var1);
    model_of_variable(m, r.read(var1).get());
    return m;
  }
  m.where = r.where();
  if (r.has("num") && r.has("den")) {
    m.tf = {coefficients(dense(r.read("num").get(), r.where_of("num")), r.where_of("num")),
            coefficients(dense(r.read("den").get(), r.where_of("den")), r.where_of("den"))};
    return m;
  }
  if (r.has("A") && r.has("B") && r.has("C") && r.has("D")) {
    StateSpace<double> s;
    s.A = matrix(dense(r.read("A").get(), r.where_of("A")), r.where_of("A"));
    s.B = matrix(dense(r.read("B").get(), r.where_of("B")), r.where_of("B"));
    s.C = matrix(dense(r.read("C").get(), r.where_of("C")), r.where_of("C"));
    s.D = matrix(dense(r.read("D").get(), r.where_of("D")), r.where_of("D"));
    m.ss = std::move(s);
    return m;
  }
  std::string found;
  const auto names = r.names();
  for (std::size_t i = 0; i < names.size() && i < 10; ++i) found += (i ? ", " : "") + report::text(names[i]);
  throw InputError(option + " " + report::text(file) + ": no variables num and den, nor A, B, C and D (found: " +
                   (found.empty() ? "none" : found) + "); name them with FILE:VAR or FILE:NUM,DEN");
}

void write_mat(const fs::path& file, const std::vector<MatMatrix>& vars) {
  matio();
  matio_message.clear();
  MatPtr mat(matio().CreateVer(file.c_str(), nullptr, MAT_FT_MAT5));
  if (!mat) throw NumericalError("cannot create " + report::text(file.string()) + matio_said());
  for (const auto& m : vars) {
    std::size_t dims[2] = {m.rows, m.cols};
    // matio does not write through the pointer (MAT_F_DONT_COPY_DATA: it is only read)
    VarPtr v(matio().VarCreate(m.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, const_cast<double*>(m.data.data()),
                           MAT_F_DONT_COPY_DATA));
    if (!v || matio().VarWrite(mat.get(), v.get(), MAT_COMPRESSION_ZLIB) != 0)
      throw NumericalError("cannot write variable " + m.name + " to " + report::text(file.string()) + matio_said());
  }
  if (matio().Close(mat.release()) != 0) throw NumericalError("cannot close " + report::text(file.string()) + matio_said());
}

void restore_gmp_allocator() {
  void* (*alloc)(size_t) = nullptr;
  void* (*realloc)(void*, size_t, size_t) = nullptr;
  void (*free)(void*, size_t) = nullptr;
  mp_get_memory_functions(&alloc, &realloc, &free);
  // only GnuTLS's: functions another library set (a Python extension's, say) are left alone
  Dl_info where{};
  if (dladdr(reinterpret_cast<void*>(free), &where) != 0 && where.dli_fname && std::strstr(where.dli_fname, "libgnutls"))
    mp_set_memory_functions(nullptr, nullptr, nullptr);
}

}  // namespace hapstab::cli
