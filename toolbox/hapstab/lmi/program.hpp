// hapstab/lmi/program.hpp -- LMI modelling: a program object in the spirit of Drake's
// MathematicalProgram. Decision variables (scalars, symmetric, full, diagonal, block-diagonal
// BD(m; m1..mN) square or not, scalar-times-identity blocks G(m; m1..mN) of paper 000),
// affine matrix expressions (const*var*const, transposes, sums, block assembly with dimension
// checks), constraints F > 0, F >= 0, linear (in)equalities on entries, and two objectives:
// linear minimisation and feasibility with the best margin (LMI Lab feasp's tmin).
//
// Strict inequalities are never a silent ">=":
//   * Margin objective (the default): maximise t subject to F_j >= t I for every STRICT LMI
//     (non-strict LMIs stay F >= 0), t <= margin_cap. The strict system is declared feasible
//     only when t* > Options::strict_threshold (default 1e-7, a hundred times the back-ends'
//     gap tolerance 1e-9, measured in the equilibrated coordinates of solve.hpp), and it is
//     `certified` only after the rational rounding passes the exact LDL^T test (certificate.hpp).
//   * Linear objective: each strict LMI is posed as F_j >= strict_threshold * I.
// A non-strict LMI that is singular along known vectors for every feasible point has no
// interior; use facial_reduce() (certificate.hpp) to impose the equalities and pose the rest.
//
// All data are doubles; the exact certificates use their exact binary values (no rounding).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace hapstab::lmi {

using MatrixXd = Eigen::MatrixXd;
using SpMat = Eigen::SparseMatrix<double>;

/// A matrix of decision variables: entry (i, j) is scalar variable index(i, j), or a structural
/// zero (-1). Symmetric variables share one scalar between (i, j) and (j, i).
struct MatrixVariable {
  std::string name;
  int rows = 0, cols = 0;
  std::vector<int> index;  ///< column-major, size rows*cols; -1 = structural zero
  int at(int i, int j) const { return index[static_cast<size_t>(j) * rows + i]; }
};

/// One rank-one piece s * u v^T of a term, u and v columns of a basis (LowRank).
struct Factor {
  int u, v;
  double s;
};

/// The terms F_k as sums of rank-one pieces over shared bases: F_k = sum over factors(k) of
/// s * L.col(u) * R.col(v)^T. A matrix variable starts with L = R = I and its unit pieces;
/// congruences multiply the bases (L <- A L), sums and block assembly concatenate them. A
/// Lyapunov term A^T E_ij A - E_ij keeps 4 pieces over the columns of [A^T, I], which the
/// interior-point method uses to form its Schur complement in O(pieces^2) per entry instead
/// of O(n^2) (lmi/ipm.cpp). A variable whose term lost the form (kron with a scalar
/// expression) has no entry in `factors`; the sparse term is always the reference.
struct LowRank {
  MatrixXd L, R;
  std::map<int, std::vector<Factor>> factors;
};

/// An affine matrix expression F0 + sum_k x_k F_k (F_k sparse).
///
/// A dimension mismatch in an operation does not throw where it happens (a C++ expression has
/// no name there): the result is an invalid Expr carrying the message (`ok()` false, the
/// first error wins through later operations), and the constraint or objective that receives
/// it throws InputError naming itself, the block (for blocks()) and the operation, e.g.
///   constraint '(16) first': block matrix: block (1,2): cannot add a 2x3 and a 2x2 matrix.
class Expr {
 public:
  Expr() = default;  ///< the empty expression: "unspecified" in a block list (see blocks())
  Expr(const MatrixXd& constant);  // NOLINT: constants convert implicitly
  Expr(const MatrixVariable& v);   // NOLINT
  static Expr zero(int rows, int cols);
  static Expr identity(int n);
  static Expr scalar(double c);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  bool empty() const { return rows_ == 0 && cols_ == 0; }
  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }  ///< why the expression is invalid
  const MatrixXd& constant() const { return c0_; }
  const std::map<int, SpMat>& terms() const { return terms_; }
  const LowRank& low_rank() const { return lr_; }

  Expr transpose() const;
  /// Value at the scalar variables x (double).
  MatrixXd value(const std::vector<double>& x) const;

  Expr& operator+=(const Expr& o);
  Expr& operator-=(const Expr& o);
  friend Expr operator+(Expr a, const Expr& b) { return a += b; }
  friend Expr operator-(Expr a, const Expr& b) { return a -= b; }
  // Hidden friends: found only when an Expr is an operand, so they never compete with
  // Eigen's own matrix products.
  friend Expr operator-(Expr a) { return scaled(std::move(a), -1.0); }
  friend Expr operator*(double s, Expr a) { return scaled(std::move(a), s); }
  friend Expr operator*(const MatrixXd& L, const Expr& a) { return left(L, a); }
  friend Expr operator*(const Expr& a, const MatrixXd& R) { return right(a, R); }
  /// M * s for a 1x1 expression s (a scalar variable times a constant matrix).
  friend Expr kron(const MatrixXd& M, const Expr& s) { return scalar_times(M, s); }

 private:
  static Expr scaled(Expr a, double s);
  static Expr scalar_times(const MatrixXd& M, const Expr& s);
  static Expr left(const MatrixXd& L, const Expr& a);
  static Expr right(const Expr& a, const MatrixXd& R);
  static Expr invalid(std::string why);
  friend Expr blocks(const std::vector<std::vector<Expr>>&, const std::string&);
  int rows_ = 0, cols_ = 0;  // -1 x -1 when invalid
  MatrixXd c0_;
  std::map<int, SpMat> terms_;
  LowRank lr_;
  std::string error_;
};

Expr transpose(const Expr& e);

/// Block assembly [[A, B], [C, D]]. An empty Expr() below the diagonal of a square layout
/// means "the transpose of its mirror block"; an empty Expr() elsewhere is a zero block whose
/// size is taken from its row and column. A mismatch, or an invalid block, gives an invalid
/// Expr whose message names `where` and the block (row, column) (see Expr).
Expr blocks(const std::vector<std::vector<Expr>>& b, const std::string& where = "block matrix");

enum class Strictness { strict, nonstrict };

struct LmiConstraint {
  std::string name;
  Expr F;  ///< constrained F > 0 (strict) or F >= 0 (nonstrict); symmetric
  Strictness strictness;
  bool posed = true;       ///< false: not given to the solver, only checked exactly (facial_reduce)
  bool auxiliary = false;  ///< true: given to the solver but not part of the exact certificate
};

struct LinearConstraint {
  std::string name;
  Expr lhs;      ///< entrywise lhs == rhs (equality) or lhs >= rhs (inequality)
  MatrixXd rhs;
  bool equality;
};

enum class ObjectiveKind { margin, minimize };

class Program {
 public:
  // ---- decision variables ----
  MatrixVariable new_scalar(const std::string& name);
  MatrixVariable new_symmetric(int n, const std::string& name);
  MatrixVariable new_full(int rows, int cols, const std::string& name);
  MatrixVariable new_diagonal(int n, const std::string& name);
  /// BD(m; m1..mN): square blocks, symmetric (symmetric = true) or full.
  MatrixVariable new_block_diagonal(const std::vector<int>& sizes, const std::string& name, bool symmetric = true);
  /// BD(m1 x n1, ..., mN x nN): non-square full blocks.
  MatrixVariable new_block_diagonal(const std::vector<std::pair<int, int>>& sizes, const std::string& name);
  /// G(m; m1..mN) = blockdiag(g1 I_m1, ..., gN I_mN).
  MatrixVariable new_scalar_identity_blocks(const std::vector<int>& sizes, const std::string& name);

  // ---- constraints (each with a user-given name that every error message repeats) ----
  /// F > 0 (strict) or F >= 0. F must be square and symmetric (checked, tolerance 1e-12
  /// relative to its largest entry); throws InputError naming the constraint.
  int add_lmi(const std::string& name, const Expr& F, Strictness s = Strictness::strict);
  int add_lmi(const std::string& name, const std::vector<std::vector<Expr>>& b, Strictness s = Strictness::strict);
  void add_linear_equality(const std::string& name, const Expr& lhs, const MatrixXd& rhs);
  void add_linear_inequality(const std::string& name, const Expr& lhs, const MatrixXd& rhs);  ///< lhs >= rhs

  // ---- objectives ----
  /// Maximise t s.t. strict F_j >= t I, t <= cap (the default objective, cap = 1).
  void set_margin_objective(double cap = 1.0);
  /// Minimise the 1x1 expression c (strict LMIs become F >= strict_threshold I).
  void set_minimize(const Expr& c);

  // ---- inspection ----
  int num_scalars() const { return static_cast<int>(scalar_names_.size()); }
  const std::string& scalar_name(int k) const { return scalar_names_[static_cast<size_t>(k)]; }
  const std::vector<LmiConstraint>& lmis() const { return lmis_; }
  const std::vector<LinearConstraint>& linear() const { return linear_; }
  ObjectiveKind objective_kind() const { return objective_; }
  const Expr& objective() const { return cost_; }
  double margin_cap() const { return cap_; }
  /// Replaces LMI i (used by facial_reduce).
  void replace_lmi(int i, LmiConstraint c);

 private:
  int add_scalar(const std::string& name);
  void add_linear(const std::string& name, const Expr& lhs, const MatrixXd& rhs, bool equality);
  void check_name(const std::string& name) const;
  std::vector<std::string> scalar_names_;
  std::vector<LmiConstraint> lmis_;
  std::vector<LinearConstraint> linear_;
  ObjectiveKind objective_ = ObjectiveKind::margin;
  Expr cost_;
  double cap_ = 1.0;
};

}  // namespace hapstab::lmi
