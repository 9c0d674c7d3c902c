// hapstab/lmi/standard_form.hpp -- internal to lmi/: steps (1)-(3) of solve()'s pipeline
// (solve.hpp), a Program turned into the back-ends' StandardForm (backend.hpp), and back.
//
//   collect_blocks      the LMIs, then every entry of a linear inequality as a 1x1 block;
//   eliminate           (1) the linear equalities, EXACTLY: rational Gauss-Jordan on the doubles'
//                       exact values gives x = x0 + N z, so a rounded z satisfies them exactly;
//                       inconsistent equalities are an exact infeasibility certificate;
//   reduce_program      (2) every posed block as G0 + sum_k z_k G_k, the objective as c'z + c0;
//                       the variables that some posed block uses get solver indices y;
//   equilibrate         (3) block rows by a diagonal congruence D G D, variables by s_k, all
//                       powers of two: exact, and a congruence keeps definiteness, so the
//                       verdict is that of the data as given in exact arithmetic;
//   build_standard_form the margin variable t, the cap block, and the SdpBlocks;
//   map_back            the back-end's y to z (x = x0 + N z), margin, objective, eigenvalues
//                       and multipliers in the original coordinates.
//
// The exact certificates (solve.cpp) read the same Reduction: the rounded z, the exact
// reduced coefficients (exact_reduced) of the Farkas check.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "hapstab/lmi/backend.hpp"
#include "hapstab/lmi/certificate.hpp"
#include "hapstab/lmi/program.hpp"

namespace hapstab::lmi {

struct Options;
class SolveResult;

/// One constraint block as the solver poses it.
struct Block {
  std::string name;
  Expr F;          ///< original-space expression (symmetrised on use)
  bool strict;
  bool posed;
  bool exact;      ///< part of the exact certificate
  int lmi = -1;    ///< index into prog.lmis(), -1 for a linear inequality entry
};

/// x = x0 + N z, exact; `identity` when there are no equalities (N = I, x0 = 0).
struct Affine {
  bool identity = true;
  int nz = 0;
  std::vector<rational> x0;
  MatQ N;
  Eigen::VectorXd x0d;
  Eigen::MatrixXd Nd;
};

/// Reduced block data in double: G0 + sum_k z_k G_k (symmetrised). The coefficients stay sparse:
/// at m = 32 DOF a dense copy per variable and block is hundreds of MB.
struct Reduced {
  Eigen::MatrixXd G0;
  std::map<int, SpMat> G;
  Eigen::MatrixXd basis;                       ///< G[k] = sum over factors[k] of s b_u b_v^T
  std::map<int, std::vector<Factor>> factors;  ///< (symmetrised; see LowRank in program.hpp)
};

/// The program in the solver's coordinates, and what maps the solution back.
struct Reduction {
  std::vector<Block> blocks;    ///< LMIs, then the entries of linear inequalities
  Affine af;                    ///< (1) x = x0 + N z
  std::vector<int> posed;       ///< indices into blocks of the posed ones
  std::vector<Reduced> red;     ///< (2) per posed block
  Eigen::VectorXd cz;           ///< objective c'z + cconst (minimize; else zero)
  double cconst = 0;
  std::vector<int> ymap;        ///< y index -> z index (the variables some posed block uses)
  std::vector<int> zmap;        ///< z index -> y index, -1 when unused
  std::vector<Eigen::VectorXd> D;  ///< (3) row scaling per posed block (powers of two)
  Eigen::VectorXd s;               ///< (3) variable scaling (powers of two)
  bool any_strict = false;      ///< some posed block is strict
  bool use_t = false;           ///< the margin variable t is y(t_index)
  int t_index = -1;
  StandardForm sf;
};

/// The LMIs, then the entries of the linear inequalities; throws InputError when none is posed.
std::vector<Block> collect_blocks(const Program& prog);

/// Exact Gauss-Jordan: reduced row echelon form of the first n columns of `rows` (each of
/// n + 1 entries: coefficients | right-hand side), the rows of zero pivot search left in place;
/// `names` (when given) follow their rows. Returns the pivot column of each leading row.
std::vector<int> row_reduce(std::vector<std::vector<rational>>& rows, int n, std::vector<std::string>* names = nullptr);

/// Gauss-Jordan elimination of the linear equalities in exact arithmetic. Returns false when
/// they are inconsistent (sets `why`).
bool eliminate(const Program& prog, Affine& af, std::string& why);

/// (2): rd.posed, rd.red, rd.cz, rd.cconst, rd.ymap, rd.zmap from rd.blocks and rd.af. Returns
/// false when the objective depends on a variable that no posed constraint bounds.
bool reduce_program(const Program& prog, Reduction& rd);

/// (3): rd.D and rd.s, ones when !scale.
void equilibrate(Reduction& rd, bool scale);

/// rd.sf (and rd.use_t, rd.t_index) from the reduced, equilibrated data; throws InputError when
/// no decision variable appears in a posed constraint.
void build_standard_form(const Program& prog, const Options& opt, Reduction& rd);

/// The back-end's answer in the original coordinates: res.status, detail, dimacs, iterations,
/// x, margin, objective, min_eigenvalue, multipliers. Returns z (unscaled, x = x0 + N z).
Eigen::VectorXd map_back(const Program& prog, const Reduction& rd, const BackendResult& br, SolveResult& res);

/// Smallest eigenvalue of the strict posed blocks at z (equilibrated, without the t term and
/// the strict_threshold shift); +inf when there is none.
double strict_margin_at(const Reduction& rd, const Eigen::VectorXd& z);

/// Exact reduced coefficient (for the Farkas check): G_k = sum_i N_ik F_i, G_0 = F_0 + sum x0_i F_i.
MatQ exact_reduced(const Expr& F, const Affine& af, int k /* -1: constant */);

/// The exact x = x0 + N z.
std::vector<rational> exact_point(const Affine& af, std::vector<rational> zq, int n);

}  // namespace hapstab::lmi
