// hapstab/lmi/program.cpp -- affine matrix expressions and the program object.
#include "hapstab/lmi/program.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "hapstab/lmi/sparse_ops.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::lmi {

namespace {
std::string dims(int r, int c) { return std::to_string(r) + "x" + std::to_string(c); }


SpMat dense_to_sparse(const MatrixXd& d) {
  SpMat s = d.sparseView(0.0, 0.0);  // keep every non-zero exactly
  s.makeCompressed();
  return s;
}

// a + b on the low-rank forms: bases side by side, b's pieces re-indexed; a variable keeps
// its pieces only when every operand that has its term has them
LowRank concat(const LowRank& a, const std::map<int, SpMat>& ta, const LowRank& b, const std::map<int, SpMat>& tb) {
  LowRank r;
  r.L.resize(std::max(a.L.rows(), b.L.rows()), a.L.cols() + b.L.cols());
  r.R.resize(std::max(a.R.rows(), b.R.rows()), a.R.cols() + b.R.cols());
  r.L << a.L, b.L;
  r.R << a.R, b.R;
  const int du = static_cast<int>(a.L.cols()), dv = static_cast<int>(a.R.cols());
  std::set<int> vars;
  for (const auto& [k, m] : ta) vars.insert(k);
  for (const auto& [k, m] : tb) vars.insert(k);
  for (int k : vars) {
    const bool in_a = ta.count(k) > 0, in_b = tb.count(k) > 0;
    if ((in_a && !a.factors.count(k)) || (in_b && !b.factors.count(k))) continue;
    std::vector<Factor> f;
    if (in_a) f = a.factors.at(k);
    if (in_b)
      for (const Factor& g : b.factors.at(k)) f.push_back({g.u + du, g.v + dv, g.s});
    r.factors.emplace(k, std::move(f));
  }
  // Long sums of small pieces could grow the bases without bound (and every later congruence
  // multiplies them): past 16 columns per row the form is dropped, the sparse terms stay.
  if (r.L.cols() + r.R.cols() > 16 * (r.L.rows() + r.R.rows()) + 256) {
    r.L.resize(r.L.rows(), 0);
    r.R.resize(r.R.rows(), 0);
    r.factors.clear();
  }
  return r;
}

// places `a` (rows x cols) at (r0, c0) of a rows_out x cols_out expression
LowRank embed(const LowRank& a, int r0, int c0, int rows_out, int cols_out) {
  LowRank r;
  r.L = MatrixXd::Zero(rows_out, a.L.cols());
  r.R = MatrixXd::Zero(cols_out, a.R.cols());
  // an empty factor has no data to offset (a block of it at r0 > 0 is pointer arithmetic on null)
  if (a.L.size() > 0) r.L.middleRows(r0, a.L.rows()) = a.L;
  if (a.R.size() > 0) r.R.middleRows(c0, a.R.rows()) = a.R;
  r.factors = a.factors;
  return r;
}
}  // namespace

Expr::Expr(const MatrixXd& constant) : rows_(static_cast<int>(constant.rows())), cols_(static_cast<int>(constant.cols())), c0_(constant) {
  lr_.L.resize(rows_, 0);
  lr_.R.resize(cols_, 0);
}

Expr::Expr(const MatrixVariable& v) : rows_(v.rows), cols_(v.cols), c0_(MatrixXd::Zero(v.rows, v.cols)) {
  std::map<int, std::vector<Eigen::Triplet<double>>> trip;
  for (int j = 0; j < v.cols; ++j)
    for (int i = 0; i < v.rows; ++i)
      if (int k = v.at(i, j); k >= 0) trip[k].emplace_back(i, j, 1.0);
  lr_.L = MatrixXd::Identity(rows_, rows_);
  lr_.R = MatrixXd::Identity(cols_, cols_);
  for (auto& [k, t] : trip) {
    SpMat m(rows_, cols_);
    m.setFromTriplets(t.begin(), t.end());
    terms_.emplace(k, std::move(m));
    auto& f = lr_.factors[k];
    for (const auto& e : t) f.push_back({static_cast<int>(e.row()), static_cast<int>(e.col()), e.value()});
  }
}

Expr Expr::zero(int rows, int cols) { return Expr(MatrixXd::Zero(rows, cols)); }
Expr Expr::identity(int n) { return Expr(MatrixXd::Identity(n, n)); }
Expr Expr::scalar(double c) { return Expr(MatrixXd::Constant(1, 1, c)); }

Expr Expr::invalid(std::string why) {
  Expr e;
  e.rows_ = e.cols_ = -1;
  e.error_ = std::move(why);
  return e;
}

Expr Expr::transpose() const {
  if (!ok()) return *this;
  Expr t;
  t.rows_ = cols_;
  t.cols_ = rows_;
  t.c0_ = c0_.transpose();
  for (const auto& [k, m] : terms_) t.terms_.emplace(k, SpMat(m.transpose()));
  t.lr_.L = lr_.R;
  t.lr_.R = lr_.L;
  for (const auto& [k, f] : lr_.factors) {
    auto& g = t.lr_.factors[k];
    for (const Factor& x : f) g.push_back({x.v, x.u, x.s});
  }
  return t;
}
Expr transpose(const Expr& e) { return e.transpose(); }

MatrixXd Expr::value(const std::vector<double>& x) const {
  if (!ok()) throw InputError("lmi expression: " + error_);
  MatrixXd v = c0_;
  for (const auto& [k, m] : terms_) {
    const double xk = x.at(static_cast<size_t>(k));
    for (int o = 0; o < m.outerSize(); ++o)
      for (SpMat::InnerIterator it(m, o); it; ++it) v(it.row(), it.col()) += xk * it.value();
  }
  return v;
}

Expr& Expr::operator+=(const Expr& o) {
  if (!ok()) return *this;
  if (!o.ok()) return *this = o;
  if (o.empty()) return *this;
  if (empty()) return *this = o;
  if (rows_ != o.rows_ || cols_ != o.cols_)
    return *this = invalid("cannot add a " + dims(rows_, cols_) + " and a " + dims(o.rows_, o.cols_) + " matrix");
  c0_ += o.c0_;
  lr_ = concat(lr_, terms_, o.lr_, o.terms_);
  for (const auto& [k, m] : o.terms_) {
    auto it = terms_.find(k);
    if (it == terms_.end()) terms_.emplace(k, m);
    else it->second += m;
  }
  return *this;
}
Expr& Expr::operator-=(const Expr& o) { return *this += -o; }
Expr Expr::scaled(Expr a, double s) {
  if (!a.ok()) return a;
  a.c0_ *= s;
  for (auto& [k, m] : a.terms_) m *= s;
  for (auto& [k, f] : a.lr_.factors)
    for (Factor& x : f) x.s *= s;
  return a;
}
Expr Expr::scalar_times(const MatrixXd& M, const Expr& s) {
  if (!s.ok()) return s;
  if (s.rows_ != 1 || s.cols_ != 1) return invalid("kron(M, s) needs a 1x1 s, got " + dims(s.rows_, s.cols_));
  Expr r;
  r.rows_ = static_cast<int>(M.rows());
  r.cols_ = static_cast<int>(M.cols());
  r.c0_ = s.c0_(0, 0) * M;
  r.lr_.L.resize(r.rows_, 0);  // the terms c_k M have no low-rank form here
  r.lr_.R.resize(r.cols_, 0);
  for (const auto& [k, m] : s.terms_) r.terms_.emplace(k, dense_to_sparse(MatrixXd(m.coeff(0, 0) * M)));
  return r;
}

Expr Expr::left(const MatrixXd& L, const Expr& a) {
  if (!a.ok()) return a;
  if (L.cols() != a.rows_)
    return invalid("cannot multiply a " + dims(static_cast<int>(L.rows()), static_cast<int>(L.cols())) +
                   " constant by a " + dims(a.rows_, a.cols_) + " expression");
  Expr r;
  r.rows_ = static_cast<int>(L.rows());
  r.cols_ = a.cols_;
  r.c0_ = L * a.c0_;
  for (const auto& [k, m] : a.terms_) r.terms_.emplace(k, dense_to_sparse(MatrixXd(L * m)));
  r.lr_.L = L * a.lr_.L;
  r.lr_.R = a.lr_.R;
  r.lr_.factors = a.lr_.factors;
  return r;
}
Expr Expr::right(const Expr& a, const MatrixXd& R) {
  if (!a.ok()) return a;
  if (a.cols_ != R.rows())
    return invalid("cannot multiply a " + dims(a.rows_, a.cols_) + " expression by a " +
                   dims(static_cast<int>(R.rows()), static_cast<int>(R.cols())) + " constant");
  Expr r;
  r.rows_ = a.rows_;
  r.cols_ = static_cast<int>(R.cols());
  r.c0_ = a.c0_ * R;
  for (const auto& [k, m] : a.terms_) r.terms_.emplace(k, dense_to_sparse(MatrixXd(m * R)));
  r.lr_.L = a.lr_.L;
  r.lr_.R = R.transpose() * a.lr_.R;
  r.lr_.factors = a.lr_.factors;
  return r;
}

Expr blocks(const std::vector<std::vector<Expr>>& b, const std::string& where) {
  const size_t R = b.size();
  if (R == 0) return Expr::invalid(where + ": empty block list");
  const size_t C = b[0].size();
  for (size_t i = 0; i < R; ++i)
    if (b[i].size() != C)
      return Expr::invalid(where + ": block row " + std::to_string(i + 1) + " has " + std::to_string(b[i].size()) +
                           " blocks, row 1 has " + std::to_string(C));
  const bool square = R == C;
  auto given = [&](size_t i, size_t j) -> const Expr* {
    if (!b[i][j].empty()) return &b[i][j];
    return nullptr;
  };
  // Row heights and column widths from the given blocks (mirrors count for the lower part).
  std::vector<int> h(R, -1), w(C, -1);
  auto name = [&](size_t i, size_t j) { return "block (" + std::to_string(i + 1) + "," + std::to_string(j + 1) + ")"; };
  for (size_t i = 0; i < R; ++i)
    for (size_t j = 0; j < C; ++j)
      if (!b[i][j].ok()) return Expr::invalid(where + ": " + name(i, j) + ": " + b[i][j].error());
  std::string bad;  // the first mismatch
  auto setdim = [&](std::vector<int>& v, size_t idx, int d, size_t i, size_t j, const char* what) {
    if (v[idx] < 0) v[idx] = d;
    else if (v[idx] != d && bad.empty())
      bad = where + ": " + name(i, j) + " has " + std::to_string(d) + " " + what + ", but block " +
            (std::string(what) == "rows" ? "row " : "column ") + std::to_string(idx + 1) + " has " + std::to_string(v[idx]);
  };
  for (size_t i = 0; i < R; ++i)
    for (size_t j = 0; j < C; ++j)
      if (auto e = given(i, j)) {
        setdim(h, i, e->rows(), i, j, "rows");
        setdim(w, j, e->cols(), i, j, "columns");
      }
  if (square)
    for (size_t i = 0; i < R; ++i)
      for (size_t j = 0; j < C; ++j)
        if (!given(i, j) && i > j && given(j, i)) {
          setdim(h, i, given(j, i)->cols(), i, j, "rows");
          setdim(w, j, given(j, i)->rows(), i, j, "columns");
        }
  if (!bad.empty()) return Expr::invalid(bad);
  for (size_t i = 0; i < R; ++i)
    if (h[i] < 0) return Expr::invalid(where + ": the height of block row " + std::to_string(i + 1) + " is not determined");
  for (size_t j = 0; j < C; ++j)
    if (w[j] < 0) return Expr::invalid(where + ": the width of block column " + std::to_string(j + 1) + " is not determined");
  Expr out;
  out.rows_ = 0;
  for (int x : h) out.rows_ += x;
  out.cols_ = 0;
  for (int x : w) out.cols_ += x;
  out.c0_ = MatrixXd::Zero(out.rows_, out.cols_);
  out.lr_.L.resize(out.rows_, 0);
  out.lr_.R.resize(out.cols_, 0);
  std::map<int, SpMat> seen;  // the variables met so far (for concat's bookkeeping)
  std::map<int, std::vector<Eigen::Triplet<double>>> trip;
  int r0 = 0;
  for (size_t i = 0; i < R; ++i) {
    int cc0 = 0;
    for (size_t j = 0; j < C; ++j) {
      Expr blk;
      if (auto e = given(i, j)) blk = *e;
      else if (square && i > j && given(j, i)) blk = given(j, i)->transpose();
      if (!blk.empty()) {
        out.c0_.block(r0, cc0, h[i], w[j]) = blk.c0_;
        out.lr_ = concat(out.lr_, seen, embed(blk.lr_, r0, cc0, out.rows_, out.cols_), blk.terms_);
        for (const auto& [k, m] : blk.terms_) seen.emplace(k, SpMat());
        for (const auto& [k, m] : blk.terms_)
          for (int o = 0; o < m.outerSize(); ++o)
            for (SpMat::InnerIterator it(m, o); it; ++it)
              trip[k].emplace_back(r0 + static_cast<int>(it.row()), cc0 + static_cast<int>(it.col()), it.value());
      }
      cc0 += w[j];
    }
    r0 += h[i];
  }
  for (auto& [k, t] : trip) {
    SpMat m(out.rows_, out.cols_);
    m.setFromTriplets(t.begin(), t.end());
    out.terms_.emplace(k, std::move(m));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
int Program::add_scalar(const std::string& name) {
  scalar_names_.push_back(name);
  return static_cast<int>(scalar_names_.size()) - 1;
}

MatrixVariable Program::new_scalar(const std::string& name) { return {name, 1, 1, {add_scalar(name)}}; }

MatrixVariable Program::new_symmetric(int n, const std::string& name) {
  if (n <= 0) throw InputError("variable '" + name + "': size must be positive");
  MatrixVariable v{name, n, n, std::vector<int>(static_cast<size_t>(n) * n, -1)};
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i) {
      int k = add_scalar(name + "(" + std::to_string(i) + "," + std::to_string(j) + ")");
      v.index[static_cast<size_t>(j) * n + i] = k;
      v.index[static_cast<size_t>(i) * n + j] = k;
    }
  return v;
}

MatrixVariable Program::new_full(int rows, int cols, const std::string& name) {
  if (rows <= 0 || cols <= 0) throw InputError("variable '" + name + "': sizes must be positive");
  MatrixVariable v{name, rows, cols, std::vector<int>(static_cast<size_t>(rows) * cols, -1)};
  for (int j = 0; j < cols; ++j)
    for (int i = 0; i < rows; ++i)
      v.index[static_cast<size_t>(j) * rows + i] = add_scalar(name + "(" + std::to_string(i) + "," + std::to_string(j) + ")");
  return v;
}

MatrixVariable Program::new_diagonal(int n, const std::string& name) {
  if (n <= 0) throw InputError("variable '" + name + "': size must be positive");
  MatrixVariable v{name, n, n, std::vector<int>(static_cast<size_t>(n) * n, -1)};
  for (int i = 0; i < n; ++i) v.index[static_cast<size_t>(i) * n + i] = add_scalar(name + "(" + std::to_string(i) + ")");
  return v;
}

// The order of a block-diagonal variable with blocks of these sizes (each positive, at least one).
static int total_block_size(const std::vector<int>& sizes, const std::string& name) {
  int n = 0;
  for (int s : sizes) {
    if (s <= 0) throw InputError("variable '" + name + "': block sizes must be positive");
    n += s;
  }
  if (n == 0) throw InputError("variable '" + name + "': no blocks");
  return n;
}

MatrixVariable Program::new_block_diagonal(const std::vector<int>& sizes, const std::string& name, bool symmetric) {
  const int n = total_block_size(sizes, name);
  MatrixVariable v{name, n, n, std::vector<int>(static_cast<size_t>(n) * n, -1)};
  int o = 0, b = 0;
  for (int s : sizes) {
    ++b;
    for (int j = 0; j < s; ++j)
      for (int i = symmetric ? j : 0; i < s; ++i) {
        int k = add_scalar(name + "[" + std::to_string(b) + "](" + std::to_string(i) + "," + std::to_string(j) + ")");
        v.index[static_cast<size_t>(o + j) * n + o + i] = k;
        if (symmetric) v.index[static_cast<size_t>(o + i) * n + o + j] = k;
      }
    o += s;
  }
  return v;
}

MatrixVariable Program::new_block_diagonal(const std::vector<std::pair<int, int>>& sizes, const std::string& name) {
  int R = 0, C = 0;
  for (auto [r, c] : sizes) {
    if (r <= 0 || c <= 0) throw InputError("variable '" + name + "': block sizes must be positive");
    R += r;
    C += c;
  }
  if (R == 0) throw InputError("variable '" + name + "': no blocks");
  MatrixVariable v{name, R, C, std::vector<int>(static_cast<size_t>(R) * C, -1)};
  int ro = 0, co = 0, b = 0;
  for (auto [r, c] : sizes) {
    ++b;
    for (int j = 0; j < c; ++j)
      for (int i = 0; i < r; ++i)
        v.index[static_cast<size_t>(co + j) * R + ro + i] =
            add_scalar(name + "[" + std::to_string(b) + "](" + std::to_string(i) + "," + std::to_string(j) + ")");
    ro += r;
    co += c;
  }
  return v;
}

MatrixVariable Program::new_scalar_identity_blocks(const std::vector<int>& sizes, const std::string& name) {
  const int n = total_block_size(sizes, name);
  MatrixVariable v{name, n, n, std::vector<int>(static_cast<size_t>(n) * n, -1)};
  int o = 0, b = 0;
  for (int s : sizes) {
    int k = add_scalar(name + "[" + std::to_string(++b) + "]");
    for (int i = 0; i < s; ++i) v.index[static_cast<size_t>(o + i) * n + o + i] = k;
    o += s;
  }
  return v;
}

void Program::check_name(const std::string& name) const {
  if (name.empty()) throw InputError("lmi program: every constraint needs a name");
  for (const auto& c : lmis_)
    if (c.name == name) throw InputError("lmi program: constraint name '" + name + "' is used twice");
  for (const auto& c : linear_)
    if (c.name == name) throw InputError("lmi program: constraint name '" + name + "' is used twice");
}

namespace {
void check_vars(const Expr& F, int nvars, const std::string& where) {
  for (const auto& [k, m] : F.terms())
    if (k < 0 || k >= nvars) throw InputError(where + ": uses a variable that does not belong to this program");
  auto finite = [](const MatrixXd& m) { return m.allFinite(); };
  if (!finite(F.constant())) throw InputError(where + ": a constant is not finite (NaN or Inf)");
  for (const auto& [k, m] : F.terms())
    for (Eigen::Index i = 0; i < m.nonZeros(); ++i)
      if (!std::isfinite(m.valuePtr()[i])) throw InputError(where + ": a coefficient is not finite (NaN or Inf)");
}
}  // namespace

int Program::add_lmi(const std::string& name, const Expr& F, Strictness s) {
  check_name(name);
  const std::string where = "constraint '" + name + "'";
  if (!F.ok()) throw InputError(where + ": " + F.error());
  if (F.empty()) throw InputError(where + ": empty matrix");
  if (F.rows() != F.cols()) throw InputError(where + ": the matrix is " + dims(F.rows(), F.cols()) + ", not square");
  check_vars(F, num_scalars(), where);
  // Symmetry of the constant and of every coefficient (relative tolerance 1e-12 on the largest
  // entry: assembled expressions are exactly symmetric; this catches a wrong sign or block).
  auto asym = [&](const MatrixXd& m, const std::string& what) {
    double scale = m.cwiseAbs().maxCoeff();
    double err = (m - m.transpose()).cwiseAbs().maxCoeff();
    if (err > 1e-12 * scale)
      throw InputError(where + ": the matrix is not symmetric (" + what + ", asymmetry " + std::to_string(err) + ")");
  };
  asym(F.constant(), "constant part");
  for (const auto& [k, m] : F.terms()) {  // sparse: only the stored entries are compared
    const double scale = max_abs(m);
    const double err = max_abs(SpMat(m - SpMat(m.transpose())));
    if (err > 1e-12 * scale)
      throw InputError(where + ": the matrix is not symmetric (coefficient of " + scalar_names_[static_cast<size_t>(k)] +
                       ", asymmetry " + std::to_string(err) + ")");
  }
  // Store the exactly symmetrised expression (the upper triangle is what the back-ends read).
  lmis_.push_back({name, F, s});
  return static_cast<int>(lmis_.size()) - 1;
}

int Program::add_lmi(const std::string& name, const std::vector<std::vector<Expr>>& b, Strictness s) {
  check_name(name);
  return add_lmi(name, blocks(b), s);
}

void Program::add_linear(const std::string& name, const Expr& lhs, const MatrixXd& rhs, bool equality) {
  check_name(name);
  const std::string where = "constraint '" + name + "'";
  if (!lhs.ok()) throw InputError(where + ": " + lhs.error());
  if (lhs.empty() || lhs.rows() != rhs.rows() || lhs.cols() != rhs.cols())
    throw InputError(where + ": left side is " + dims(lhs.rows(), lhs.cols()) + ", right side is " +
                     dims(static_cast<int>(rhs.rows()), static_cast<int>(rhs.cols())));
  check_vars(lhs, num_scalars(), where);
  if (!rhs.allFinite()) throw InputError(where + ": right side is not finite");
  linear_.push_back({name, lhs, rhs, equality});
}

void Program::add_linear_equality(const std::string& name, const Expr& lhs, const MatrixXd& rhs) {
  add_linear(name, lhs, rhs, true);
}

void Program::add_linear_inequality(const std::string& name, const Expr& lhs, const MatrixXd& rhs) {
  add_linear(name, lhs, rhs, false);
}

void Program::set_margin_objective(double cap) {
  if (!(cap > 0) || !std::isfinite(cap)) throw InputError("margin objective: the cap on t must be positive and finite");
  objective_ = ObjectiveKind::margin;
  cap_ = cap;
  cost_ = Expr();
}

void Program::set_minimize(const Expr& c) {
  if (!c.ok()) throw InputError("objective: " + c.error());
  if (c.rows() != 1 || c.cols() != 1) throw InputError("objective: must be a 1x1 expression");
  check_vars(c, num_scalars(), "objective");
  objective_ = ObjectiveKind::minimize;
  cost_ = c;
}

void Program::replace_lmi(int i, LmiConstraint c) { lmis_.at(static_cast<size_t>(i)) = std::move(c); }

}  // namespace hapstab::lmi
