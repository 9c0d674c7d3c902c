// python/core.cpp -- hapstab._core, the C++ half of the Python package: the module, its
// exceptions, the helpers every binding file shares (binding.hpp), and the forked-child runner
// kept for the calls where a child process still earns its cost (below).
//
// The functions are bindings of the library (bind_*.cpp): they take the library's types and
// return its results as Python objects and numpy arrays; long calls release the GIL, and the
// vectorised ones poll Ctrl-C between points.
//
// A long library computation (a simulation, multidof's LMIs and design) runs on a worker thread
// instead (run_interruptible): Ctrl-C asks it to stop at its next interruption point
// (numeric/interrupt.hpp: each LMI solve -- the SDP back-ends are serialised by a mutex, CSDP in
// a child process of its own --, IPM iteration, Riccati point, simulation block).
// A forked child remains for the sweep's worker processes and run() (the command line itself,
// the escape hatch), where Ctrl-C must stop a whole command at once. The parent waits on a
// pipe with the GIL released and checks for signals every 20 ms; Ctrl-C kills the child. The
// child leads a process group of its own, so that Ctrl-C kills everything it started with it
// (the sweep's worker processes: issue 49), whoever the SIGINT reached (a terminal's whole
// group, or Jupyter's interrupt, the kernel alone); it also dies with the interpreter
// (PR_SET_PDEATHSIG), and so do the sweep's workers with it. The child answers with one JSON document (the pipe's format, not a result format):
//   {"code": <exit code>, "json": <what the command printed or null>}   or
//   {"error": "<message>", "code": 2|3, "kind": "error"|"numerical failure"|"internal error"}
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <charconv>
#include <cerrno>
#include <chrono>
#include <future>
#include <cstring>
#include <iostream>
#include <limits>
#include <set>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/mat_file.hpp"
#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/interrupt.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/study/threads.hpp"
#include "python/binding.hpp"
#include "python/forked.hpp"

namespace hapstab::python {

StatusCode status_code(Status s) {
  switch (s) {
    case Status::exact: return code_exact;
    case Status::certified: return code_certified;
    case Status::numeric: return code_numeric;
    case Status::failed: return code_failed;
  }
  return code_failed;
}

rational exact_arg(const std::string& text, const std::string& what) { return parse_rational(text, what); }

std::optional<rational> exact_arg(const std::optional<std::string>& text, const std::string& what) {
  if (!text) return std::nullopt;
  return exact_arg(*text, what);
}

ParseOptions parse_options(char variable, const rational& T, std::map<std::string, rational> params,
                           HiddenPoles hidden_poles) {
  ParseOptions po;
  po.hidden_poles = hidden_poles;
  po.variable = variable;
  po.T = T;
  po.parameters = std::move(params);
  po.parameter_hint = "pass params={'{}': ...}";
  po.period_hint = "T=...";
  return po;
}

namespace {

py::object decimal_or_none(const std::optional<rational>& q, int digits, int dir) {
  if (!q) return py::none();
  return py::str(decimal_outward(*q, digits, dir));
}

}  // namespace

py::dict record(const std::optional<Enclosure<rational>>& e, const rational& mid, Status status,
                const std::string& method, const std::string& note, int digits) {
  py::dict d;
  const bool exact = status == Status::exact;
  d["value_exact"] = exact ? py::object(py::str(mid.str())) : py::object(py::none());
  d["mid"] = to_real<double>(mid);
  const rational lo = e ? e->lo : mid, hi = e ? e->hi : mid;
  d["lo"] = double_outward(lo, -1);
  d["hi"] = double_outward(hi, +1);
  d["lo_text"] = decimal_or_none(lo, digits, -1);
  d["hi_text"] = decimal_or_none(hi, digits, +1);
  d["status"] = to_string(status);
  d["method"] = method;
  d["note"] = note;
  return d;
}

py::dict record(const Certified<rational>& c, int digits) {
  return record(c.enclosure, c.value, c.status, c.method, c.note, digits);
}

py::dict record_infinite(Status status, const std::string& method, const std::string& note) {
  py::dict d;
  const double inf = std::numeric_limits<double>::infinity();
  d["value_exact"] = py::none();
  d["mid"] = inf;
  d["lo"] = inf;
  d["hi"] = inf;
  d["lo_text"] = "inf";
  d["hi_text"] = "inf";
  d["status"] = to_string(status);
  d["method"] = method;
  d["note"] = note;
  return d;
}

rational shortest_decimal(double x) {
  // std::to_chars without a precision: the shortest decimal that reads back as x (Python's repr)
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, x);
  if (res.ec != std::errc()) throw std::logic_error("shortest_decimal: to_chars failed");
  return parse_rational(std::string(buf, res.ptr), "a float");
}

Columns Columns::from_python(const std::vector<std::string>& names, const py::list& columns) {
  Columns c;
  c.names = names;
  if (columns.size() != names.size()) throw std::logic_error("Columns: names and columns differ in number");
  for (size_t k = 0; k < names.size(); ++k) {
    std::vector<rational> v;
    const py::handle col = columns[k];
    const std::string what = "params['" + names[k] + "']";
    if (py::isinstance<py::array>(col)) {
      const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(col);
      const auto r = a.unchecked<1>();
      v.reserve(size_t(r.shape(0)));
      for (py::ssize_t i = 0; i < r.shape(0); ++i) {
        if (!std::isfinite(r(i)))
          throw InputError(what + "[" + std::to_string(i) + "]: " + std::to_string(r(i)) + " is not a finite number");
        v.push_back(shortest_decimal(r(i)));
      }
    } else {
      const auto texts = col.cast<std::vector<std::string>>();
      v.reserve(texts.size());
      for (size_t i = 0; i < texts.size(); ++i) v.push_back(exact_arg(texts[i], what + "[" + std::to_string(i) + "]"));
    }
    if (k == 0) c.points = v.size();
    else if (v.size() != c.points) throw std::logic_error("Columns: columns of different lengths");
    c.values.push_back(std::move(v));
  }
  return c;
}

std::map<std::string, rational> Columns::at(const std::map<std::string, rational>& fixed, size_t i) const {
  std::map<std::string, rational> p = fixed;
  for (size_t k = 0; k < names.size(); ++k) p[names[k]] = values[k][i];
  return p;
}

ParsedExpression parsed(const std::string& expr, const std::string& what, char variable, const rational& T,
                        const std::map<std::string, rational>& fixed, const Columns& cols, HiddenPoles hidden_poles) {
  try {
    return ParsedExpression(expr, parse_options(variable, T, fixed, hidden_poles), {cols.names.begin(), cols.names.end()});
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
}

void check_names(const std::string& expr, const std::string& what, char variable,
                 const std::map<std::string, rational>& fixed, const Columns& cols) {
  std::set<std::string> known{std::string(1, variable), "T"};
  for (const auto& [k, v] : fixed) known.insert(k);
  known.insert(cols.names.begin(), cols.names.end());
  for (const std::string& name : names_in(expr))
    if (!known.count(name)) {
      std::string list;
      for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(what + ": unknown name '" + name + "' (known: " + list + "; pass params={'" + name + "': ...})");
    }
}

void run_points(size_t n, unsigned jobs, const std::function<void(uint64_t)>& fn) {
  bool interrupted = false;
  {
    py::gil_scoped_release nogil;
    const bool finished = study::run_threads(n, jobs, fn, [&] {
      py::gil_scoped_acquire gil;
      if (PyErr_CheckSignals() != 0) return interrupted = true;
      return false;
    });
    (void)finished;
  }
  if (interrupted) throw py::error_already_set();  // KeyboardInterrupt (or what the handler raised)
}

std::string point_error(const std::exception& e) {
  if (dynamic_cast<const InputError*>(&e)) return e.what();
  if (dynamic_cast<const NumericalError*>(&e)) return std::string("numerical failure: ") + e.what();
  return std::string("internal error: ") + e.what();
}

void run_interruptible(const std::function<void()>& work) {
  std::atomic<bool> stop{false};
  auto task = std::async(std::launch::async, [&] {
    InterruptScope scope(stop);
    work();
  });
  bool interrupted = false;
  {
    py::gil_scoped_release nogil;
    while (task.wait_for(std::chrono::milliseconds(20)) != std::future_status::ready) {
      bool signalled;
      {
        py::gil_scoped_acquire gil;
        signalled = PyErr_CheckSignals() != 0;  // the exception stays set for this thread
      }
      if (signalled) {
        interrupted = stop = true;
        task.wait();  // until the work reaches its next interruption point
        break;
      }
    }
  }
  if (interrupted) {
    try {
      task.get();
    } catch (...) {  // Interrupted, or whatever the work raised meanwhile: Ctrl-C is the answer
    }
    throw py::error_already_set();
  }
  task.get();
}

PointColumns::PointColumns(size_t n)
    : value(n, std::numeric_limits<double>::quiet_NaN()), lo(value), hi(value), status(n, code_failed), exact(n),
      lo_exact(n), hi_exact(n), error(n) {}

void PointColumns::enclose(size_t i, const rational& a, const rational& b, int digits) {
  lo[i] = double_outward(a, -1);
  hi[i] = double_outward(b, +1);
  value[i] = to_real<double>((a + b) / 2);
  lo_exact[i] = decimal_outward(a, digits, -1);
  hi_exact[i] = decimal_outward(b, digits, +1);
}

py::dict PointColumns::dict() const {
  py::dict d;
  d["value"] = doubles(value);
  d["lo"] = doubles(lo);
  d["hi"] = doubles(hi);
  d["status"] = codes(status);
  d["exact"] = strings(exact);
  d["lo_exact"] = strings(lo_exact);
  d["hi_exact"] = strings(hi_exact);
  d["error"] = strings(error);
  return d;
}

py::array_t<double> doubles(const std::vector<double>& v) {
  py::array_t<double> a(py::ssize_t(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::array_t<int8_t> codes(const std::vector<int8_t>& v) {
  py::array_t<int8_t> a(py::ssize_t(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::array strings(const std::vector<std::optional<std::string>>& v) {
  py::list l;
  for (const auto& s : v) l.append(s ? py::object(py::str(*s)) : py::object(py::none()));
  return py::module_::import("numpy").attr("array")(l, py::arg("dtype") = "object");
}

// ---- the forked child ------------------------------------------------------------------------

namespace {

void write_all(int fd, const std::string& s) {
  size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent has gone: nothing left to tell
    done += size_t(n);
  }
}

/// The child's whole life: run `work`, write the answer, leave without running any of the
/// parent's exit handlers (Python's, stdio buffers it inherited).
[[noreturn]] void child_main(const std::function<nlohmann::json()>& work, int fd) {
  ::signal(SIGINT, SIG_DFL);  // Ctrl-C in a terminal reaches the child too: let it end it
  nlohmann::json answer;
  try {
    answer = work();
  } catch (const std::exception& e) {
    const auto exit = hapstab::cli::exit_code_for(e);
    answer = {{"error", e.what()}, {"code", int(exit.code)}, {"kind", exit.kind}};
  } catch (...) {
    answer = {{"error", "unknown exception"}, {"code", 3}, {"kind", "internal error"}};
  }
  std::cout.flush();
  std::cerr.flush();
  write_all(fd, answer.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  ::close(fd);
  ::_exit(0);
}

std::string describe_status(int status) {
  if (WIFSIGNALED(status)) return std::string("killed by signal ") + ::strsignal(WTERMSIG(status));
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  return "status " + std::to_string(status);
}

std::string run_forked_text(const std::function<nlohmann::json()>& work) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("hapstab: pipe: ") + std::strerror(errno));
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("hapstab: fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::setpgid(0, 0);  // its own process group (the parent sets it too: whichever runs first)
    // and it dies with the interpreter (a Jupyter kernel restarted with SIGKILL): the calling thread
    // waits for the child, so the thread that forked it outlives it unless the process dies
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(4);
    ::close(fds[0]);
    hapstab::cli::restore_gmp_allocator();  // cli/mat_file.hpp: GnuTLS, loaded with matio, zeroes every GMP block
    child_main(work, fds[1]);
  }
  ::setpgid(pid, pid);  // the child's own call, made here too: the group exists before either goes on
  ::close(fds[1]);
  std::string data;
  char buf[1 << 16];
  auto reap = [pid](bool kill_first) {
    if (kill_first) {  // the child and whatever it started (its group), before the child is reaped and
      ::kill(-pid, SIGKILL);  // its pid could name another group
      ::kill(pid, SIGKILL);
    }
    int status = 0;
    py::gil_scoped_release nogil;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return status;
  };
  for (;;) {
    pollfd p{fds[0], POLLIN, 0};
    int ready;
    {
      py::gil_scoped_release nogil;
      ready = ::poll(&p, 1, 20);
    }
    if (ready > 0) {
      const ssize_t n = ::read(fds[0], buf, sizeof buf);
      if (n > 0) data.append(buf, size_t(n));
      else if (n == 0) break;  // the child closed its end: the answer is complete
      else if (errno != EINTR && errno != EAGAIN) break;
    } else if (ready < 0 && errno != EINTR) {
      const int err = errno;
      ::close(fds[0]);
      reap(true);
      throw std::runtime_error(std::string("hapstab: poll: ") + std::strerror(err));
    }
    if (PyErr_CheckSignals() != 0) {  // Ctrl-C: a Python exception is set
      ::close(fds[0]);
      reap(true);
      throw py::error_already_set();
    }
  }
  ::close(fds[0]);
  const int status = reap(false);
  // Ctrl-C in a terminal reaches the whole process group: the child may have died of it first
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  if (data.empty() || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("hapstab: the computation ended abnormally (" + describe_status(status) + ")");
  return data;
}

}  // namespace

nlohmann::json run_forked(const std::function<nlohmann::json()>& work) {
  auto answer = nlohmann::json::parse(run_forked_text(work));
  if (answer.contains("error")) {
    const std::string msg = answer["error"].get<std::string>();
    const int code = answer["code"].get<int>();
    const std::string kind = answer["kind"].get<std::string>();
    if (code == hapstab::cli::exit_bad_input) throw InputError(msg);
    if (kind == "numerical failure") throw NumericalError(msg);
    throw std::runtime_error("hapstab internal error: " + msg);
  }
  return answer;
}

}  // namespace hapstab::python

PYBIND11_MODULE(_core, m) {
  using namespace hapstab::python;
  m.doc() = "hapstab's C++ core: bindings of the library (transfer functions, b*, r(jw), stability, passivity levels, "
            "scenes); see the package hapstab";
  m.attr("__version__") = HAPSTAB_VERSION;
  // the command line's limit on delay= (numeric/limits.hpp): the long-delay paths take up to it
  m.attr("CRITERION_DELAY") = hapstab::limits::criterion_delay;
  py::register_exception<hapstab::InputError>(m, "InputError", PyExc_ValueError);
  py::register_exception<hapstab::NumericalError>(m, "NumericalError", PyExc_RuntimeError);
  register_types(m);
  register_passivity(m);
  register_stability(m);
  register_scene(m);
  register_multidof(m);
  m.def(
      "names_in",
      [](const std::string& text) { return hapstab::names_in(text); }, py::arg("text"),
      "The names an expression refers to (parameters, T, the variable), by the parser's own lexer.");
  m.def(
      "run",
      [](const std::vector<std::string>& args) -> py::tuple {
        const auto answer = run_forked([&] {
          auto run = hapstab::cli::run_in_process(args);
          return nlohmann::json{{"code", run.code}, {"json", std::move(run.json)}};
        });
        const auto& j = answer["json"];
        return py::make_tuple(answer["code"].get<int>(), j.is_null() ? py::object(py::none()) : py::object(py::str(j.dump())));
      },
      py::arg("args"),
      "Runs `hapstab args...` (the command line, no program name) in a child process; returns (exit code, JSON text "
      "or None). Raises InputError (exit 2), NumericalError (exit 3), KeyboardInterrupt on Ctrl-C.");
  m.def(
      "examples_dir", [] { return hapstab::cli::examples_dir().string(); },
      "The folder of hapstab's example scenes (the source tree's examples/, or the installed share/hapstab/examples).");
}
