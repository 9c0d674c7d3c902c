// hapstab/lmi/backend.cpp -- validation and DIMACS errors shared by both back-ends, and DSDP.
#include "hapstab/lmi/backend.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "hapstab/numeric/error.hpp"

extern "C" {
#include <dsdp/dsdp5.h>
}

namespace hapstab::lmi {

const char* to_string(Backend b) {
  switch (b) {
    case Backend::automatic: return "automatic";
    case Backend::dsdp: return "DSDP";
    case Backend::csdp: return "CSDP";
    case Backend::ipm: return "hapstab IPM";
  }
  return "?";
}

Backend parse_backend(const std::string& name) {
  if (name == "auto") return Backend::automatic;
  if (name == "dsdp") return Backend::dsdp;
  if (name == "csdp") return Backend::csdp;
  if (name == "ipm") return Backend::ipm;
  throw InputError("--backend must be auto, dsdp, csdp or ipm, got '" + name + "'");
}
const char* to_string(SolveStatus s) {
  switch (s) {
    case SolveStatus::optimal: return "optimal";
    case SolveStatus::infeasible: return "infeasible";
    case SolveStatus::unbounded: return "unbounded";
    case SolveStatus::numerical_trouble: return "numerical trouble";
  }
  return "numerical trouble";
}

std::mutex& sdp_mutex() {
  static std::mutex m;
  return m;
}

void validate(const StandardForm& sf) {
  if (sf.m <= 0) throw InputError("sdp: no decision variables");
  if (sf.b.size() != sf.m || !sf.b.allFinite()) throw InputError("sdp: objective vector has the wrong size or is not finite");
  if (sf.blocks.empty()) throw InputError("sdp: no constraint blocks");
  std::vector<int> used(static_cast<size_t>(sf.m), 0);
  for (size_t j = 0; j < sf.blocks.size(); ++j) {
    const auto& B = sf.blocks[j];
    const auto n = B.C.rows();
    const std::string w = "sdp block " + std::to_string(j + 1);
    if (n <= 0 || B.C.cols() != n) throw InputError(w + ": constant is not square");
    if (!B.C.allFinite() || (B.C - B.C.transpose()).cwiseAbs().maxCoeff() != 0.0)
      throw InputError(w + ": constant is not finite and exactly symmetric");
    for (const auto& t : B.terms) {
      if (t.var < 0 || t.var >= sf.m) throw InputError(w + ": variable index out of range");
      if (t.A.rows() != n || t.A.cols() != n) throw InputError(w + ": coefficient has the wrong size");
      bool ok = true;
      for (int o = 0; o < t.A.outerSize() && ok; ++o)
        for (Eigen::SparseMatrix<double>::InnerIterator it(t.A, o); it && ok; ++it)
          ok = std::isfinite(it.value()) && t.A.coeff(it.col(), it.row()) == it.value();
      if (!ok) throw InputError(w + ": coefficient is not finite and exactly symmetric");
      used[static_cast<size_t>(t.var)] = 1;
    }
  }
  for (int k = 0; k < sf.m; ++k)
    if (!used[static_cast<size_t>(k)]) throw InputError("sdp: variable " + std::to_string(k) + " appears in no block");
}

std::array<double, 6> dimacs_errors(const StandardForm& sf, const Eigen::VectorXd& y, const std::vector<Eigen::MatrixXd>& X) {
  std::array<double, 6> e{};
  if (y.size() != sf.m || X.size() != sf.blocks.size()) {
    e.fill(NAN);
    return e;
  }
  Eigen::VectorXd AX = Eigen::VectorXd::Zero(sf.m);
  double cmax = 0, trCX = 0, trXS = 0, minX = INFINITY, minS = INFINITY;
  for (size_t j = 0; j < sf.blocks.size(); ++j) {
    const auto& B = sf.blocks[j];
    Eigen::MatrixXd S = B.C;
    for (const auto& t : B.terms)
      for (int o = 0; o < t.A.outerSize(); ++o)
        for (Eigen::SparseMatrix<double>::InnerIterator it(t.A, o); it; ++it) {
          AX(t.var) += it.value() * X[j](it.row(), it.col());
          S(it.row(), it.col()) += y(t.var) * it.value();
        }
    cmax = std::max(cmax, B.C.cwiseAbs().maxCoeff());
    trCX += (B.C.cwiseProduct(X[j])).sum();
    trXS += (S.cwiseProduct(X[j])).sum();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ex(X[j], Eigen::EigenvaluesOnly), es(S, Eigen::EigenvaluesOnly);
    minX = std::min(minX, ex.eigenvalues()(0));
    minS = std::min(minS, es.eigenvalues()(0));
  }
  const double bmax = sf.b.cwiseAbs().maxCoeff();
  const double pobj = trCX, dobj = sf.b.dot(y);
  e[0] = (AX + sf.b).norm() / (1 + bmax);
  e[1] = std::max(0.0, -minX) / (1 + bmax);
  e[2] = 0;  // S is formed from y exactly: no dual residual
  e[3] = std::max(0.0, -minS) / (1 + cmax);
  e[4] = (pobj - dobj) / (1 + std::abs(pobj) + std::abs(dobj));
  e[5] = trXS / (1 + std::abs(pobj) + std::abs(dobj));
  return e;
}

// ---------------------------------------------------------------------------------------------
// DSDP: maximise b^T y s.t. C - sum A_i y_i >= 0, so its A_i are our -A_k. Data in packed
// lower-triangular storage, element (i, j), i >= j, at i(i+1)/2 + j.
namespace {

// Throws NumericalError naming the DSDP call that failed (the solver object is destroyed on
// the way out: DsdpRun::Handle).
void check(int info, const char* what) {
  if (info) throw NumericalError(std::string("DSDP: ") + what + " failed (code " + std::to_string(info) + ")");
}

// One DSDP solver object and every array it was given: DSDP keeps pointers into them until
// DSDPDestroy, so they live exactly as long.
class DsdpRun {
 public:
  DsdpRun(const StandardForm& sf, double ybound);
  int solve() { return DSDPSolve(dsdp_.p); }
  /// reason, type, iterations, y, the y box and the multipliers X after solve()
  void read(const StandardForm& sf, BackendResult& r, DSDPTerminationReason& reason, DSDPSolutionType& type,
            double& ylo, double& yhi);

 private:
  void push(int j, int var, int n, std::vector<std::pair<int, double>>& e);
  void add_dense(int j, int var, const Eigen::MatrixXd& M, double sign);
  void add_sparse(int j, int var, const Eigen::SparseMatrix<double>& M, double sign);

  struct Handle {  // destroyed also when the constructor throws
    DSDP p = nullptr;
    Handle() = default;
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() {
      if (p) DSDPDestroy(p);
    }
  };
  // declared before the handle: destroyed after it
  std::vector<std::vector<int>> idx_;
  std::vector<std::vector<double>> val_;
  Handle dsdp_;
  SDPCone cone_ = nullptr;
};

// The data (DSDP's A_i are our -A_k; the constant is variable 0), tolerances, iteration limit,
// and the box |y_k| <= ybound when ybound > 0 (else DSDP's default 1e7).
DsdpRun::DsdpRun(const StandardForm& sf, double ybound) {
  check(DSDPCreate(sf.m, &dsdp_.p), "DSDPCreate");
  for (int k = 0; k < sf.m; ++k) check(DSDPSetDualObjective(dsdp_.p, k + 1, sf.b(k)), "DSDPSetDualObjective");
  const int J = static_cast<int>(sf.blocks.size());
  check(DSDPCreateSDPCone(dsdp_.p, J, &cone_), "DSDPCreateSDPCone");
  idx_.reserve(1024);
  val_.reserve(1024);
  for (int j = 0; j < J; ++j) {
    const auto& B = sf.blocks[static_cast<size_t>(j)];
    check(SDPConeSetBlockSize(cone_, j, static_cast<int>(B.C.rows())), "SDPConeSetBlockSize");
    check(SDPConeSetSparsity(cone_, j, static_cast<int>(B.terms.size()) + 1), "SDPConeSetSparsity");
    add_dense(j, 0, B.C, 1.0);
    for (const auto& t : B.terms) add_sparse(j, t.var + 1, t.A, -1.0);
  }
  check(DSDPSetGapTolerance(dsdp_.p, 1e-9), "DSDPSetGapTolerance");
  check(DSDPSetMaxIts(dsdp_.p, 300), "DSDPSetMaxIts");
  if (ybound > 0) check(DSDPSetYBounds(dsdp_.p, -ybound, ybound), "DSDPSetYBounds");
  check(DSDPSetup(dsdp_.p), "DSDPSetup");
}

// Packed lower-triangular (index, value) pairs in increasing index order.
void DsdpRun::push(int j, int var, int n, std::vector<std::pair<int, double>>& e) {
  if (e.empty()) return;
  std::sort(e.begin(), e.end());
  std::vector<int> ii;
  std::vector<double> vv;
  ii.reserve(e.size());
  vv.reserve(e.size());
  for (const auto& [i, v] : e) {
    ii.push_back(i);
    vv.push_back(v);
  }
  idx_.push_back(std::move(ii));
  val_.push_back(std::move(vv));
  check(SDPConeSetASparseVecMat(cone_, j, var, n, 1.0, 0, idx_.back().data(), val_.back().data(),
                                static_cast<int>(idx_.back().size())),
        "SDPConeSetASparseVecMat");
}

void DsdpRun::add_dense(int j, int var, const Eigen::MatrixXd& M, double sign) {
  const int n = static_cast<int>(M.rows());
  std::vector<std::pair<int, double>> e;
  for (int i = 0; i < n; ++i)
    for (int c = 0; c <= i; ++c)
      if (M(i, c) != 0.0) e.emplace_back(i * (i + 1) / 2 + c, sign * M(i, c));
  push(j, var, n, e);
}

void DsdpRun::add_sparse(int j, int var, const Eigen::SparseMatrix<double>& M, double sign) {
  std::vector<std::pair<int, double>> e;
  e.reserve(static_cast<size_t>(M.nonZeros() / 2 + M.rows()));
  for (int o = 0; o < M.outerSize(); ++o)
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, o); it; ++it) {
      const int i = static_cast<int>(it.row()), c = static_cast<int>(it.col());
      if (i >= c && it.value() != 0.0) e.emplace_back(i * (i + 1) / 2 + c, sign * it.value());
    }
  push(j, var, static_cast<int>(M.rows()), e);
}

void DsdpRun::read(const StandardForm& sf, BackendResult& r, DSDPTerminationReason& reason, DSDPSolutionType& type,
                   double& ylo, double& yhi) {
  DSDPStopReason(dsdp_.p, &reason);
  DSDPGetSolutionType(dsdp_.p, &type);
  DSDPGetIts(dsdp_.p, &r.iterations);
  r.y.resize(sf.m);
  DSDPGetY(dsdp_.p, r.y.data(), sf.m);
  DSDPGetYBounds(dsdp_.p, &ylo, &yhi);
  int xinfo = DSDPComputeX(dsdp_.p);
  const int J = static_cast<int>(sf.blocks.size());
  r.X.resize(static_cast<size_t>(J));
  for (int j = 0; j < J; ++j) {
    const int n = static_cast<int>(sf.blocks[static_cast<size_t>(j)].C.rows());
    Eigen::MatrixXd X = Eigen::MatrixXd::Zero(n, n);
    double* xx = nullptr;
    int nn = 0;
    if (!xinfo && !SDPConeGetXArray(cone_, j, &xx, &nn) && nn == n * (n + 1) / 2)
      for (int i = 0; i < n; ++i)
        for (int c = 0; c <= i; ++c) X(i, c) = X(c, i) = xx[i * (i + 1) / 2 + c];
    r.X[static_cast<size_t>(j)] = X;
  }
}

// DSDP's return code, stop reason and solution type in our status words.
void classify(int info, DSDPTerminationReason reason, DSDPSolutionType type, BackendResult& r) {
  r.detail = "DSDP stop reason " + std::to_string(static_cast<int>(reason)) + ", solution type " +
             std::to_string(static_cast<int>(type));
  if (info) {
    r.status = SolveStatus::numerical_trouble;
    r.detail += ", DSDPSolve returned " + std::to_string(info);
  } else if (type == DSDP_INFEASIBLE) {
    r.status = SolveStatus::infeasible;
  } else if (type == DSDP_UNBOUNDED) {
    r.status = SolveStatus::unbounded;
  } else if (reason == DSDP_CONVERGED && type == DSDP_PDFEASIBLE) {
    r.status = SolveStatus::optimal;
  } else {
    r.status = SolveStatus::numerical_trouble;
  }
}

// One DSDP run; ybound > 0 replaces DSDP's default box |y_k| <= 1e7; *box: the box used.
BackendResult dsdp_once(const StandardForm& sf, double ybound, double* box) {
  BackendResult r;
  int info = 0;
  DSDPTerminationReason reason = CONTINUE_ITERATING;
  DSDPSolutionType type = DSDP_PDUNKNOWN;
  double ylo = -INFINITY, yhi = INFINITY;
  {
    DsdpRun run(sf, ybound);
    info = run.solve();
    run.read(sf, r, reason, type, ylo, yhi);
  }
  r.primal_objective = sf.b.dot(r.y);
  double trCX = 0;
  for (size_t j = 0; j < sf.blocks.size(); ++j) trCX += sf.blocks[j].C.cwiseProduct(r.X[j]).sum();
  r.dual_objective = trCX;
  classify(info, reason, type, r);
  r.dimacs = dimacs_errors(sf, r.y, r.X);
  *box = std::min(-ylo, yhi);
  // DSDP often ends on "short steps" (-2) next to the optimum. Accept the point as optimal when
  // our own DIMACS measures say so (primal/dual infeasibility and relative gap <= 1e-6); the
  // exact certificate remains the judge of feasibility.
  if (r.status == SolveStatus::numerical_trouble && !info && reason == DSDP_SMALL_STEPS && type == DSDP_PDFEASIBLE &&
      std::abs(r.dimacs[0]) <= 1e-6 && r.dimacs[1] <= 1e-6 && r.dimacs[3] <= 1e-6 && std::abs(r.dimacs[4]) <= 1e-6) {
    r.status = SolveStatus::optimal;
    r.detail += " (short steps; accepted on DIMACS errors <= 1e-6)";
  }
  return r;
}

}  // namespace

// DSDP keeps every y_k in a box (default |y_k| <= 1e7) and on an unbounded program stops
// "converged" on it: min -x s.t. x >= 1 gave x = 1e7, optimal. A y on the box where S(y) >= 0
// holds and whose objective is of the box's magnitude is re-solved with the box at 1e10; the
// program is called unbounded when the objective grows with the box (by 100x or more). A y on
// the box with a modest objective is a normal solution of a program whose feasible set is
// unbounded (a homogeneous Lyapunov LMI with the margin objective; badly scaled data as given).
BackendResult solve_dsdp(const StandardForm& sf) {
  validate(sf);
  std::lock_guard<std::mutex> lock(sdp_mutex());
  double box = 0;
  BackendResult r = dsdp_once(sf, 0, &box);
  auto on_box = [&](const BackendResult& q, double bx) {
    const double obj = std::abs(sf.b.dot(q.y)), bmax = sf.b.cwiseAbs().maxCoeff();
    // S(y) >= 0 at the box (DIMACS err4): an infeasible program also drifts to the box, but
    // through points that violate the LMIs
    return q.status != SolveStatus::infeasible && std::isfinite(bx) && q.y.allFinite() &&
           q.y.cwiseAbs().maxCoeff() >= 0.5 * bx && obj >= 1e-3 * bx * bmax && q.dimacs[3] <= 1e-6;
  };
  if (!on_box(r, box)) return r;
  BackendResult w = dsdp_once(sf, 1e10, &box);
  if (w.dimacs[3] <= 1e-6 && std::abs(sf.b.dot(w.y)) >= 100 * std::abs(sf.b.dot(r.y))) {
    w.status = SolveStatus::unbounded;
    w.detail += "; the objective follows DSDP's variable box (b'y = " + std::to_string(sf.b.dot(r.y)) +
                " at |y| <= 1e7, " + std::to_string(sf.b.dot(w.y)) + " at 1e10): unbounded";
    return w;
  }
  w.detail = "y reached DSDP's box 1e7, re-solved with 1e10: " + w.detail;
  return w;
}

}  // namespace hapstab::lmi
