// hapstab/lmi/backend_csdp.cpp -- CSDP 6 through easy_sdp, isolated in a forked child (see
// backend.hpp for why). CSDP: primal max tr(C' X) s.t. tr(A'_k X) = a_k, X >= 0; dual
// min a^T y s.t. sum y_k A'_k - C' = Z >= 0. With C' = -C, A'_k = A_k, a = -b its dual is our
// standard form (Z = S(y)) and its X is our multiplier. Return codes (CSDP manual):
// 0 optimal, 1 primal infeasible (our LMI problem unbounded), 2 dual infeasible (our LMI
// infeasible; X is a ray with tr(A_k X) = 0, tr(C' X) = 1), 3 partial success, 4+ failures.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "hapstab/lmi/backend.hpp"
#include "hapstab/numeric/error.hpp"

extern "C" {
#include <csdp/declarations.h>
}

namespace hapstab::lmi {

namespace {

bool write_all(int fd, const void* p, size_t n) {
  const char* c = static_cast<const char*>(p);
  while (n) {
    ssize_t w = ::write(fd, c, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    c += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}
// Reads n bytes, waiting at most until `deadline`; false on EOF, error or timeout (*timed_out).
using Clock = std::chrono::steady_clock;
bool read_all(int fd, void* p, size_t n, Clock::time_point deadline, bool* timed_out) {
  char* c = static_cast<char*>(p);
  while (n) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      *timed_out = true;
      return false;
    }
    pollfd pfd{fd, POLLIN, 0};
    const int pr = ::poll(&pfd, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
    if (pr < 0 && errno == EINTR) continue;
    if (pr < 0) return false;
    if (pr == 0) continue;  // re-check the deadline
    ssize_t r = ::read(fd, c, n);
    if (r < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    if (r == 0) return false;
    c += r;
    n -= static_cast<size_t>(r);
  }
  return true;
}

// CSDP's default parameters (CSDP 6 user's guide) with printlevel 0; read by initparams in
// this order.
const char* kParams =
    "axtol=1.0e-8\natytol=1.0e-8\nobjtol=1.0e-8\npinftol=1.0e8\ndinftol=1.0e8\nmaxiter=100\n"
    "minstepfrac=0.90\nmaxstepfrac=0.97\nminstepp=1.0e-8\nminstepd=1.0e-8\nusexzgap=1\ntweakgap=0\n"
    "affine=0\nprintlevel=0\nperturbobj=1\nfastmode=0\n";

// Runs in the child, in the private folder `dir` that holds our param.csdp: builds CSDP's
// structures, solves, streams (code, pobj, dobj, y, X) to fd.
[[noreturn]] void child(const StandardForm& sf, int fd, const char* dir) {
  int devnull = ::open("/dev/null", O_WRONLY);
  if (devnull >= 0) {
    ::dup2(devnull, STDOUT_FILENO);
    ::dup2(devnull, STDERR_FILENO);
  }
  if (::chdir(dir) != 0) ::_exit(90);
  const int J = static_cast<int>(sf.blocks.size());
  const int k = sf.m;
  struct blockmatrix C;
  C.nblocks = J;
  C.blocks = static_cast<blockrec*>(std::calloc(static_cast<size_t>(J + 1), sizeof(blockrec)));
  int n = 0;
  for (int j = 1; j <= J; ++j) {
    const auto& B = sf.blocks[static_cast<size_t>(j - 1)];
    const int s = static_cast<int>(B.C.rows());
    n += s;
    C.blocks[j].blockcategory = MATRIX;
    C.blocks[j].blocksize = s;
    C.blocks[j].data.mat = static_cast<double*>(std::malloc(sizeof(double) * static_cast<size_t>(s) * s));
    for (int c = 1; c <= s; ++c)
      for (int i = 1; i <= s; ++i) C.blocks[j].data.mat[ijtok(i, c, s)] = -B.C(i - 1, c - 1);
  }
  double* a = static_cast<double*>(std::malloc(sizeof(double) * static_cast<size_t>(k + 1)));
  for (int i = 1; i <= k; ++i) a[i] = -sf.b(i - 1);
  auto* constraints = static_cast<constraintmatrix*>(std::calloc(static_cast<size_t>(k + 1), sizeof(constraintmatrix)));
  // Build each constraint's block list in decreasing block order by prepending, so that the
  // final list is in increasing block order.
  for (int j = J; j >= 1; --j) {
    const auto& B = sf.blocks[static_cast<size_t>(j - 1)];
    const int s = static_cast<int>(B.C.rows());
    for (const auto& t : B.terms) {
      int cnt = 0;  // upper triangle (row <= column), column by column
      for (int c = 0; c < s; ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(t.A, c); it; ++it) cnt += it.row() <= c && it.value() != 0.0;
      if (cnt == 0) continue;
      auto* sb = static_cast<sparseblock*>(std::calloc(1, sizeof(sparseblock)));
      sb->blocknum = j;
      sb->blocksize = s;
      sb->constraintnum = t.var + 1;
      sb->numentries = cnt;
      sb->issparse = 1;
      sb->entries = static_cast<double*>(std::malloc(sizeof(double) * static_cast<size_t>(cnt + 1)));
      sb->iindices = static_cast<int*>(std::malloc(sizeof(int) * static_cast<size_t>(cnt + 1)));
      sb->jindices = static_cast<int*>(std::malloc(sizeof(int) * static_cast<size_t>(cnt + 1)));
      int e = 0;
      for (int c = 0; c < s; ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(t.A, c); it; ++it)
          if (it.row() <= c && it.value() != 0.0) {
            ++e;
            sb->iindices[e] = static_cast<int>(it.row()) + 1;
            sb->jindices[e] = c + 1;
            sb->entries[e] = it.value();
          }
      sb->next = constraints[t.var + 1].blocks;
      constraints[t.var + 1].blocks = sb;
    }
  }
  struct blockmatrix X, Z;
  double* y = nullptr;
  double pobj = 0, dobj = 0;
  initsoln(n, k, C, a, constraints, &X, &y, &Z);
  int code = easy_sdp(n, k, C, a, constraints, 0.0, &X, &y, &Z, &pobj, &dobj);
  bool ok = write_all(fd, &code, sizeof code) && write_all(fd, &pobj, sizeof pobj) && write_all(fd, &dobj, sizeof dobj);
  for (int i = 1; i <= k && ok; ++i) ok = write_all(fd, &y[i], sizeof(double));
  for (int j = 1; j <= J && ok; ++j) {
    const int s = X.blocks[j].blocksize;
    ok = write_all(fd, X.blocks[j].data.mat, sizeof(double) * static_cast<size_t>(s) * s);
  }
  ::_exit(ok ? 0 : 92);
}

}  // namespace

BackendResult solve_csdp(const StandardForm& sf, double time_limit) {
  validate(sf);
  if (!(time_limit > 0)) throw InputError("CSDP: the time limit must be positive");
  std::lock_guard<std::mutex> lock(sdp_mutex());
  // The parent owns the private folder, so it is removed even when the child is killed.
  // ($TMPDIR, else /tmp)
  const char* tmp = std::getenv("TMPDIR");
  std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/hapstab-csdp-XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  char* dir = buf.data();
  if (!::mkdtemp(dir)) throw NumericalError("CSDP: cannot create a private folder in " + templ.substr(0, templ.rfind('/')));
  const std::string param = std::string(dir) + "/param.csdp";
  auto cleanup = [&] {
    ::unlink(param.c_str());
    ::rmdir(dir);
  };
  if (FILE* f = std::fopen(param.c_str(), "w")) {
    std::fputs(kParams, f);
    std::fclose(f);
  } else {
    cleanup();
    throw NumericalError("CSDP: cannot write " + param);
  }
  int fds[2];
  if (::pipe(fds) != 0) {
    cleanup();
    throw NumericalError("CSDP: cannot create a pipe");
  }
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    cleanup();
    throw NumericalError("CSDP: cannot fork the solver process");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(sf, fds[1], dir);
  }
  ::close(fds[1]);
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(time_limit));
  bool timed_out = false;
  BackendResult r;
  r.iterations = -1;  // easy_sdp does not return its iteration count
  int code = -1;
  double pobj = 0, dobj = 0;
  auto get = [&](void* p, size_t bytes) { return read_all(fds[0], p, bytes, deadline, &timed_out); };
  bool ok = get(&code, sizeof code) && get(&pobj, sizeof pobj) && get(&dobj, sizeof dobj);
  r.y.resize(sf.m);
  for (int i = 0; i < sf.m && ok; ++i) ok = get(&r.y(i), sizeof(double));
  r.X.resize(sf.blocks.size());
  for (size_t j = 0; j < sf.blocks.size() && ok; ++j) {
    const auto s = sf.blocks[j].C.rows();
    r.X[j].resize(s, s);  // column-major, as CSDP's Fortran layout
    ok = get(r.X[j].data(), sizeof(double) * static_cast<size_t>(s * s));
  }
  ::close(fds[0]);
  // easy_sdp can loop without end (seen: the OSP-level LMI of (z^2+1)/(z^2-0.25), whose
  // zeros lie on the unit circle): past the deadline the child is killed.
  if (timed_out) ::kill(pid, SIGKILL);
  int wstatus = 0;
  while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
  }
  cleanup();
  if (!ok || !WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0) {
    r.status = SolveStatus::numerical_trouble;
    r.detail = timed_out ? std::string(kCsdpTimedOut) + " of " +
                               std::to_string(static_cast<int>(std::ceil(time_limit))) + " s and was stopped"
                         : "CSDP process ended without a result (" +
                               (WIFEXITED(wstatus) ? "exit code " + std::to_string(WEXITSTATUS(wstatus))
                                                   : "signal " + std::to_string(WTERMSIG(wstatus))) +
                               ")";
    r.y.setZero();
    for (size_t j = 0; j < sf.blocks.size(); ++j) r.X[j] = Eigen::MatrixXd::Zero(sf.blocks[j].C.rows(), sf.blocks[j].C.rows());
    r.dimacs.fill(NAN);
    return r;
  }
  r.primal_objective = sf.b.dot(r.y);
  double trCX = 0;
  for (size_t j = 0; j < sf.blocks.size(); ++j) trCX += sf.blocks[j].C.cwiseProduct(r.X[j]).sum();
  r.dual_objective = trCX;
  r.detail = "CSDP return code " + std::to_string(code);
  switch (code) {
    case 0: r.status = SolveStatus::optimal; break;
    case 3:  // "partial success": solved to reduced accuracy; the certificate decides
      r.status = SolveStatus::optimal;
      r.detail += " (partial success: reduced accuracy)";
      break;
    case 1: r.status = SolveStatus::unbounded; break;
    case 2: r.status = SolveStatus::infeasible; break;
    default: r.status = SolveStatus::numerical_trouble; break;
  }
  r.dimacs = dimacs_errors(sf, r.y, r.X);
  return r;
}

}  // namespace hapstab::lmi
