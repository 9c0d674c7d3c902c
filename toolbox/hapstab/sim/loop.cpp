// Exact composition of a sampled-data haptic loop (see loop.hpp).
#include "hapstab/sim/loop.hpp"

#include <Eigen/LU>
#include <numeric>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/exact_matrix.hpp"
#include "hapstab/numeric/limits.hpp"

namespace hapstab::sim {

namespace {
using Q = rational;
using MQ = Mat<Q>;

std::string dims(const StateSpace<Q>& G) {
  return std::to_string(G.outputs()) + "x" + std::to_string(G.inputs()) + " with " + std::to_string(G.states()) +
         " states";
}

MQ zeros(Eigen::Index r, Eigen::Index c) { return MQ::Zero(r, c); }

// A B exactly, skipping the zero entries: the blocks of an N-DOF loop are mostly zero (one
// device, one operator per DOF), so this costs O(N^2) rational operations where the dense
// product costs O(N^3) (issue 33: 0.8 s of compose() at N = 64).
MQ sparse_product(const MQ& A, const MQ& B) {
  MQ C = MQ::Zero(A.rows(), B.cols());
  std::vector<std::vector<Eigen::Index>> rows(static_cast<size_t>(B.rows()));
  for (Eigen::Index l = 0; l < B.rows(); ++l)
    for (Eigen::Index k = 0; k < B.cols(); ++k)
      if (B(l, k) != 0) rows[size_t(l)].push_back(k);  // the non-zero columns of row l of B
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index l = 0; l < A.cols(); ++l) {
      if (A(i, l) == 0) continue;
      for (Eigen::Index k : rows[size_t(l)]) C(i, k) += A(i, l) * B(l, k);
    }
  return C;
}

}  // namespace

int LoopSpec::dofs() const {
  int n = 0;
  for (const auto& d : devices) n += int(d.dofs());
  return n;
}

namespace {

// ---- devices: block diagonal, force -> velocity ----
struct DeviceStack {
  MQ A, B, C;  ///< s_d' = A s_d + B F, v = C s_d
};

DeviceStack stack_devices(const LoopSpec& spec, int N, std::vector<std::optional<Q>>& mass) {
  Eigen::Index nd = 0;
  for (const auto& d : spec.devices) {
    d.G.validate(d.name);
    if (d.G.is_discrete()) throw InputError(d.name + ": a device must be continuous (T = 0)");
    if (d.G.inputs() != d.G.outputs())
      throw InputError(d.name + ": a device maps forces to velocities (square), got " + dims(d.G));
    if (!d.G.D.isZero()) throw InputError(d.name + ": a device must be strictly proper (D = 0: force cannot move it instantly)");
    nd += d.G.states();
  }
  DeviceStack st{zeros(nd, nd), zeros(nd, N), zeros(N, nd)};
  mass.assign(N, std::nullopt);
  Eigen::Index so = 0;
  int dof = 0;
  for (const auto& d : spec.devices) {
    auto n = d.G.states(), k = d.G.inputs();
    st.A.block(so, so, n, n) = d.G.A;
    st.B.block(so, dof, n, k) = d.G.B;
    st.C.block(dof, so, k, n) = d.G.C;
    if (d.mass)
      for (Eigen::Index i = 0; i < k && i < Eigen::Index(d.mass->size()); ++i) mass[dof + i] = (*d.mass)[i];
    so += n;
    dof += int(k);
  }
  return st;
}

// ---- operators: proper part Z (ports) and inertia Mo ----
struct OperatorStack {
  MQ A, B, C, D, M;  ///< s_o' = A s_o + B v, force C s_o + D v + M v' (on every DOF)
};

void check_operator(const OperatorBlock& o, int N) {
  o.Z.validate(o.name);
  if (o.Z.is_discrete()) throw InputError(o.name + ": an operator must be continuous (T = 0)");
  const auto p = Eigen::Index(o.ports.size());
  if (o.Z.inputs() != p || o.Z.outputs() != p)
    throw InputError(o.name + ": acts on " + std::to_string(p) + " DOF(s) but its impedance is " + dims(o.Z));
  for (int j : o.ports)
    if (j < 0 || j >= N)
      throw InputError(o.name + ": port DOF " + std::to_string(j) + " does not exist (the devices give " +
                       std::to_string(N) + " DOFs, numbered from 0)");
  if (!o.mass.empty() && Eigen::Index(o.mass.size()) != p)
    throw InputError(o.name + ": mass needs one entry per port (" + std::to_string(p) + ")");
  for (const auto& m : o.mass)
    if (m < 0) throw InputError(o.name + ": operator mass must be >= 0");
}

OperatorStack stack_operators(const LoopSpec& spec, int N) {
  Eigen::Index no = 0;
  for (const auto& o : spec.operators) {
    check_operator(o, N);
    no += o.Z.states();
  }
  OperatorStack st{zeros(no, no), zeros(no, N), zeros(N, no), zeros(N, N), zeros(N, N)};
  Eigen::Index so = 0;
  for (const auto& o : spec.operators) {
    const auto n = o.Z.states();
    if (n > 0) st.A.block(so, so, n, n) = o.Z.A;  // a static operator has no states: no block (an empty block of an empty matrix is UB)
    for (size_t a = 0; a < o.ports.size(); ++a) {
      const int ja = o.ports[a];
      if (n > 0) {
        st.B.block(so, ja, n, 1) += o.Z.B.col(Eigen::Index(a));
        st.C.block(ja, so, 1, n) += o.Z.C.row(Eigen::Index(a));
      }
      for (size_t b = 0; b < o.ports.size(); ++b) st.D(ja, o.ports[b]) += o.Z.D(Eigen::Index(a), Eigen::Index(b));
      if (!o.mass.empty()) st.M(ja, ja) += o.mass[a];
    }
    so += n;
  }
  return st;
}

// ---- plant: s = [s_d; x; s_o], in = [u; w] ----
// F = u + w - Co s_o - Do v  (v = Cd s_d); s_d' = K (Ad s_d + Bd F), K = (I + Bd Mo Cd)^{-1}.
StateSpace<Q> plant_of(const DeviceStack& dev, const OperatorStack& op, int N) {
  const MQ &Ad = dev.A, &Bd = dev.B, &Cd = dev.C;
  const MQ &Ao = op.A, &Bo = op.B, &Co = op.C, &Do = op.D, &Mo = op.M;
  const Eigen::Index nd = Ad.rows(), no = Ao.rows();
  const Eigen::Index n = nd + N + no;
  // K block by block over the connected components of I + Bd Mo Cd (exact: a matrix that is
  // block diagonal up to a permutation has the inverse of each block as its inverse's blocks)
  const MQ Kinv = MQ::Identity(nd, nd) + sparse_product(sparse_product(Bd, Mo), Cd);
  MQ K = zeros(nd, nd);
  for (const auto& c : components(Kinv)) {
    Eigen::FullPivLU<MQ> klu(Kinv(c, c));
    if (klu.rank() < Eigen::Index(c.size()))
      throw InputError("operator inertia makes the device dynamics singular (I + B M C not invertible)");
    K(c, c) = klu.inverse();
  }
  // F = [ -Do Cd, 0, -Co ] s + [I, I] in
  MQ Fs = zeros(N, n), Fi = zeros(N, 2 * N);
  Fs.block(0, 0, N, nd) = -sparse_product(Do, Cd);
  Fs.block(0, nd + N, N, no) = -Co;
  Fi.block(0, 0, N, N) = MQ::Identity(N, N);
  Fi.block(0, N, N, N) = MQ::Identity(N, N);
  MQ A = zeros(n, n), B = zeros(n, 2 * N);
  const MQ KBd = sparse_product(K, Bd);
  A.block(0, 0, nd, n) = sparse_product(KBd, Fs);
  A.block(0, 0, nd, nd) += sparse_product(K, Ad);
  B.block(0, 0, nd, 2 * N) = sparse_product(KBd, Fi);
  A.block(nd, 0, N, nd) = Cd;                 // x' = v
  A.block(nd + N, 0, no, nd) = sparse_product(Bo, Cd);  // s_o' = Ao s_o + Bo v
  A.block(nd + N, nd + N, no, no) += Ao;
  // outputs [x; v; f_h], f_h = -Mo v' + F - u  (the human port: operator + exogenous forces)
  MQ C = zeros(3 * N, n), D = zeros(3 * N, 2 * N);
  C.block(0, nd, N, N) = MQ::Identity(N, N);
  C.block(N, 0, N, nd) = Cd;
  const MQ vdot_s = sparse_product(Cd, A.topRows(nd)), vdot_i = sparse_product(Cd, B.topRows(nd));
  C.block(2 * N, 0, N, n) = Fs - sparse_product(Mo, vdot_s);
  D.block(2 * N, 0, N, 2 * N) = Fi - sparse_product(Mo, vdot_i);
  D.block(2 * N, 0, N, N) -= MQ::Identity(N, N);
  return StateSpace<Q>{A, B, C, D, 0};
}

// ---- controller: positions -> u, with E (impedance) and V (admittance) ----
void check_discrete(const StateSpace<Q>& G, const std::string& what, const Q& T, int N) {
  G.validate(what);
  if (!G.is_discrete()) throw InputError(what + ": must be a discrete block (z domain, T > 0)");
  if (G.T != T) throw InputError(what + ": sample period " + G.T.str() + " differs from the scene's T = " + T.str());
  if (G.inputs() != N || G.outputs() != N)
    throw InputError(what + ": must be " + std::to_string(N) + "x" + std::to_string(N) + " (one row/column per DOF), got " +
                     dims(G));
}

// E with the coupling V in parallel with the device (paper 000 (11)). Products and the solve
// through FLINT (numeric/exact_matrix.hpp): at 128 DOF, D_E is a dense 128 x 128 block and
// Eigen's rational products and LU cost tens of seconds per composition.
StateSpace<Q> coupled_controller(const StateSpace<Q>& E, const StateSpace<Q>& V, int N, const Q& T) {
  // u = -(Ce se + De (m + Cv sv + Dv u))  =>  (I + De Dv) u = -(Ce se + De Cv sv + De m)
  const MQ S = MQ::Identity(N, N) + exact_product(E.D, V.D);
  if (exact_rank(S) < N)
    throw InputError("environment/coupling: the algebraic loop through their feedthrough terms is singular "
                     "(det(I + D_E D_V) = 0)");
  const Eigen::Index ne = E.states(), nv = V.states();
  MQ rhs(N, ne + nv + N);  // S [Cu | Du] = -[Ce | De Cv | De]; empty blocks skipped (null data)
  if (ne > 0) rhs.leftCols(ne) = -E.C;
  if (nv > 0) rhs.middleCols(ne, nv) = -exact_product(E.D, V.C);
  rhs.rightCols(N) = -E.D;
  const MQ CuDu = exact_solve(S, rhs, "I + D_E D_V");
  const MQ Cu = CuDu.leftCols(ne + nv), Du = CuDu.rightCols(N);
  // x_e = m + Cv sv + Dv u ; se' = Ae se + Be x_e ; sv' = Av sv + Bv u
  MQ Xs = exact_product(V.D, Cu);
  if (nv > 0) Xs.rightCols(nv) += V.C;
  const MQ Xm = MQ::Identity(N, N) + exact_product(V.D, Du);
  MQ Ac = zeros(ne + nv, ne + nv), Bc = zeros(ne + nv, N);
  if (ne > 0) {
    Ac.topRows(ne) = exact_product(E.B, Xs);
    Ac.topLeftCorner(ne, ne) += E.A;
    Bc.topRows(ne) = exact_product(E.B, Xm);
  }
  if (nv > 0) {
    Ac.bottomRows(nv) = exact_product(V.B, Cu);
    Ac.bottomRightCorner(nv, nv) += V.A;
    Bc.bottomRows(nv) = exact_product(V.B, Du);
  }
  return StateSpace<Q>{Ac, Bc, Cu, Du, T};
}

StateSpace<Q> controller_of(const LoopSpec& spec, int N) {
  for (int j : spec.contact)
    if (j < 0 || j >= N) throw InputError("contact: DOF " + std::to_string(j) + " does not exist");
  if (!spec.environment) {
    if (spec.coupling) throw InputError("coupling: a coupling needs an environment");
    return StateSpace<Q>{zeros(0, 0), zeros(0, N), zeros(N, 0), zeros(N, N), spec.T};
  }
  const auto& E = *spec.environment;
  check_discrete(E, "environment", spec.T, N);
  if (!spec.coupling) return StateSpace<Q>{E.A, E.B, -E.C, -E.D, spec.T};
  const auto& V = *spec.coupling;
  check_discrete(V, "coupling", spec.T, N);
  return coupled_controller(E, V, N, spec.T);
}

}  // namespace

namespace {

// Encoders and Coulomb friction: DOFs in range, one of each per DOF, Delta > 0, f_c >= 0.
void check_sensors_and_friction(const LoopSpec& spec, int N) {
  std::vector<char> q(size_t(N), 0), f(size_t(N), 0);
  for (const Quantizer& e : spec.quantizers) {
    if (e.dof < 0 || e.dof >= N) throw InputError("encoder: DOF " + std::to_string(e.dof) + " does not exist");
    if (e.step <= 0) throw InputError("encoder on DOF " + std::to_string(e.dof) + ": quantum must be > 0, got " + e.step.str());
    if (q[size_t(e.dof)]++) throw InputError("encoder: DOF " + std::to_string(e.dof) + " has two");
  }
  for (const Coulomb& c : spec.coulomb) {
    if (c.dof < 0 || c.dof >= N) throw InputError("coulomb friction: DOF " + std::to_string(c.dof) + " does not exist");
    if (c.force < 0)
      throw InputError("coulomb friction on DOF " + std::to_string(c.dof) + ": f_c must be >= 0, got " + c.force.str());
    if (f[size_t(c.dof)]++) throw InputError("coulomb friction: DOF " + std::to_string(c.dof) + " has two");
  }
  for (int j : spec.passivity_controller)
    if (j < 0 || j >= N) throw InputError("passivity controller: DOF " + std::to_string(j) + " does not exist");
}

}  // namespace

std::vector<std::vector<Eigen::Index>> components(const Mat<rational>& A) {
  const Eigen::Index n = A.rows();
  std::vector<Eigen::Index> root(static_cast<size_t>(n));
  std::iota(root.begin(), root.end(), Eigen::Index(0));
  auto find = [&](Eigen::Index i) {
    while (root[size_t(i)] != i) i = root[size_t(i)] = root[size_t(root[size_t(i)])];
    return i;
  };
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < n; ++k)
      if (A(i, k) != 0) {
        const Eigen::Index a = find(i), b = find(k);
        if (a != b) root[size_t(std::max(a, b))] = std::min(a, b);
      }
  std::vector<std::vector<Eigen::Index>> comps;
  std::vector<long> slot(static_cast<size_t>(n), -1);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index r = find(i);
    if (slot[size_t(r)] < 0) {
      slot[size_t(r)] = long(comps.size());
      comps.emplace_back();
    }
    comps[size_t(slot[size_t(r)])].push_back(i);
  }
  return comps;
}

ComposedLoop compose(const LoopSpec& spec) {
  if (spec.T <= 0) throw InputError("sample period T must be > 0, got " + spec.T.str());
  if (spec.delay < 0) throw InputError("delay must be >= 0, got " + spec.delay.str());
  // checked before anything converts t_d / T to an integer (1e30 s wrapped to a negative count)
  if (spec.delay > spec.T * limits::delay_samples)
    throw InputError("delay: " + to_decimal(spec.delay / spec.T, 6) + " sample periods (t_d / T), more than the limit of " +
                     std::to_string(limits::delay_samples));
  // every time the simulator turns into a sample index (t / T) is checked first (limits.hpp)
  for (const Bias& b : spec.biases)
    if (b.start < 0 || b.start > spec.T * limits::run_steps)
      throw InputError("bias start: " + to_decimal(b.start, 6) + " s is outside [0, " + std::to_string(limits::run_steps) +
                       " T] (the longest run)");
  for (const Impulse& im : spec.impulses)
    if (im.time < 0 || im.time > spec.T * limits::run_steps)
      throw InputError("impulse time: " + to_decimal(im.time, 6) + " s is outside [0, " + std::to_string(limits::run_steps) +
                       " T] (the longest run)");
  const int N = spec.dofs();
  if (N == 0) throw InputError("the loop has no device (at least one device is needed)");
  check_sensors_and_friction(spec, N);
  ComposedLoop L;
  L.N = N;
  L.T = spec.T;
  const DeviceStack dev = stack_devices(spec, N, L.mass);
  const OperatorStack op = stack_operators(spec, N);
  L.plant = plant_of(dev, op, N);
  L.position_state.resize(N);
  for (int j = 0; j < N; ++j) L.position_state[j] = int(dev.A.rows() + j);
  L.controller = controller_of(spec, N);
  return L;
}

}  // namespace hapstab::sim
