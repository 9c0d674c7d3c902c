#include "hapstab/multidof/structure.hpp"

#include "hapstab/lmi/certificate.hpp"
#include "hapstab/numeric/error.hpp"

namespace hapstab::multidof {

int Structure::m() const {
  int s = 0;
  for (const auto& o : operators) s += o.dof;
  return s;
}

std::vector<int> Structure::operator_sizes() const {
  std::vector<int> v;
  for (const auto& o : operators) v.push_back(o.dof);
  return v;
}

std::vector<int> Structure::device_sizes() const {
  std::vector<int> v;
  for (const auto& o : operators)
    for (const auto& d : o.devices) v.push_back(d.dof);
  return v;
}

void Structure::validate() const {
  if (operators.empty()) throw InputError("structure: no operator given (N must be >= 1)");
  for (size_t i = 0; i < operators.size(); ++i) {
    const auto& o = operators[i];
    const std::string on = "operator " + std::to_string(i + 1) + (o.name.empty() ? "" : " '" + o.name + "'");
    if (o.dof < 1) throw InputError(on + ": dof must be >= 1, got " + std::to_string(o.dof));
    if (o.devices.empty()) throw InputError(on + ": uses no device (M_i must be >= 1)");
    int sum = 0;
    for (size_t j = 0; j < o.devices.size(); ++j) {
      const auto& d = o.devices[j];
      const std::string dn = on + ", device " + std::to_string(j + 1) + (d.name.empty() ? "" : " '" + d.name + "'");
      if (d.dof < 1) throw InputError(dn + ": dof must be >= 1, got " + std::to_string(d.dof));
      if (d.osp.rows() != d.dof || d.osp.cols() != d.dof)
        throw InputError(dn + ": OSP level must be " + std::to_string(d.dof) + "x" + std::to_string(d.dof) + ", got " +
                         std::to_string(d.osp.rows()) + "x" + std::to_string(d.osp.cols()));
      if (d.osp != d.osp.transpose()) throw InputError(dn + ": OSP level is not symmetric");
      if (!lmi::exact_definiteness(d.osp).pd)
        throw InputError(dn + ": OSP level is not positive definite (Assumption 1(a) needs Delta_d > 0)");
      sum += d.dof;
    }
    if (sum != o.dof)
      throw InputError(on + ": block sizes do not add up: m_i = " + std::to_string(o.dof) +
                       " but its devices have " + std::to_string(sum) + " DOF in total");
  }
}

MatQ Structure::delta_D() const {
  const int n = m();
  MatQ D = MatQ::Zero(n, n);
  int off = 0;
  for (const auto& o : operators)
    for (const auto& d : o.devices) {
      D.block(off, off, d.dof, d.dof) = d.osp;
      off += d.dof;
    }
  return D;
}


MatQ Structure::K(const rational& T) const {
  if (T <= 0) throw InputError("structure: sample period T must be > 0 for K = (T/2) Delta_D^-1");
  return (T / 2) * inverse(delta_D(), "Delta_D");
}

MatQ inverse(const MatQ& Ain, const std::string& what) {
  MatQ A = Ain;
  const Eigen::Index n = A.rows();
  if (A.cols() != n) throw InputError(what + " is not square");
  MatQ I = MatQ::Identity(n, n);
  for (Eigen::Index c = 0; c < n; ++c) {
    Eigen::Index p = c;
    while (p < n && A(p, c) == 0) ++p;
    if (p == n) throw InputError(what + " is singular");
    A.row(c).swap(A.row(p));
    I.row(c).swap(I.row(p));
    const rational piv = A(c, c);
    A.row(c) /= piv;
    I.row(c) /= piv;
    for (Eigen::Index r = 0; r < n; ++r)
      if (r != c && A(r, c) != 0) {
        const rational f = A(r, c);
        A.row(r) -= f * A.row(c);
        I.row(r) -= f * I.row(c);
      }
  }
  return I;
}

Device device(std::string name, int dof, const rational& delta) {
  return Device{std::move(name), dof, delta * MatQ::Identity(dof, dof)};
}

int CouplingStructure::m() const {
  int s = 0;
  for (int x : mbar) s += x;
  return s;
}
int CouplingStructure::n() const {
  int s = 0;
  for (int x : nbar) s += x;
  return s;
}

void CouplingStructure::validate(int mtot) const {
  if (mbar.empty()) throw InputError("coupling structure: no block given (N-bar must be >= 1)");
  if (mbar.size() != nbar.size())
    throw InputError("coupling structure: " + std::to_string(mbar.size()) + " block sizes m-bar but " +
                     std::to_string(nbar.size()) + " state dimensions n-bar");
  for (size_t i = 0; i < mbar.size(); ++i) {
    if (mbar[i] < 1) throw InputError("coupling block " + std::to_string(i + 1) + ": m-bar must be >= 1");
    if (nbar[i] < 0) throw InputError("coupling block " + std::to_string(i + 1) + ": n-bar must be >= 0");
  }
  if (m() != mtot)
    throw InputError("coupling structure: block sizes do not add up: sum of m-bar_i = " + std::to_string(m()) +
                     " but the environment has m = " + std::to_string(mtot) + " DOF");
}

std::vector<int> common_refinement(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> cuts;
  auto ends = [](const std::vector<int>& p) {
    std::vector<int> e;
    int s = 0;
    for (int x : p) e.push_back(s += x);
    return e;
  };
  auto ea = ends(a), eb = ends(b);
  if (ea.empty() || eb.empty() || ea.back() != eb.back())
    throw InputError("common_refinement: partitions of different sizes");
  std::vector<int> all;
  size_t i = 0, j = 0;
  while (i < ea.size() || j < eb.size()) {
    int x;
    if (j >= eb.size() || (i < ea.size() && ea[i] < eb[j])) x = ea[i++];
    else if (i >= ea.size() || eb[j] < ea[i]) x = eb[j++];
    else { x = ea[i]; ++i; ++j; }
    all.push_back(x);
  }
  std::vector<int> sizes;
  int prev = 0;
  for (int x : all) {
    sizes.push_back(x - prev);
    prev = x;
  }
  return sizes;
}

}  // namespace hapstab::multidof
