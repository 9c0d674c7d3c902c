// python/core.cpp -- hapstab._core, the one C++ entry of the Python package: runs a hapstab
// command (hapstab::cli::run_in_process, the command's own code, so the numbers are the CLI's
// by construction) and hands back its exit code and JSON.
//
// Each call runs in a forked child process; the parent waits on a pipe with the GIL released and
// checks for signals every 20 ms, so Ctrl-C (KeyboardInterrupt) stops a long computation at once:
// the child is killed, since C++ code (FLINT, the SDP solvers) cannot be interrupted from inside.
// A crash in the child cannot take the interpreter down either. The cost is a fork per call
// (a few milliseconds; README "Python"). The child answers with one JSON document:
//   {"code": <exit code>, "json": <what the command printed or null>}   or
//   {"error": "<message>", "code": 2|3, "kind": "error"|"numerical failure"|"internal error"}
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <nlohmann/json.hpp>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <string>
#include <vector>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/mat_file.hpp"

namespace py = pybind11;

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

/// The child's whole life: run the command, write the answer, leave without running any of the
/// parent's exit handlers (Python's, stdio buffers it inherited).
[[noreturn]] void child_main(const std::vector<std::string>& args, int fd) {
  ::signal(SIGINT, SIG_DFL);  // Ctrl-C in a terminal reaches the child too: let it end it
  nlohmann::json answer;
  try {
    auto run = hapstab::cli::run_in_process(args);
    answer = {{"code", run.code}, {"json", std::move(run.json)}};
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

/// Runs `hapstab args...` in a forked child; returns the child's answer (JSON text). Raises
/// KeyboardInterrupt (or whatever a signal handler raises) after killing the child.
std::string run_forked(const std::vector<std::string>& args) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("hapstab: pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("hapstab: fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    hapstab::cli::restore_gmp_allocator();  // cli/mat_file.hpp: GnuTLS, loaded with matio, zeroes every GMP block
    child_main(args, fds[1]);
  }
  ::close(fds[1]);
  std::string data;
  char buf[1 << 16];
  auto reap = [pid](bool kill_first) {
    if (kill_first) ::kill(pid, SIGKILL);
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

PYBIND11_MODULE(_core, m) {
  m.doc() = "hapstab's C++ core: runs a hapstab command and returns its exit code and JSON";
  m.attr("__version__") = HAPSTAB_VERSION;
  static py::exception<std::exception> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<std::exception> numerical_error(m, "NumericalError", PyExc_RuntimeError);
  m.def(
      "run",
      [](const std::vector<std::string>& args) -> py::tuple {
        const auto answer = nlohmann::json::parse(run_forked(args));
        if (answer.contains("error")) {
          const std::string msg = answer["error"].get<std::string>();
          const int code = answer["code"].get<int>();
          const std::string kind = answer["kind"].get<std::string>();
          if (code == hapstab::cli::exit_bad_input) input_error(msg.c_str());
          else if (kind == "numerical failure") numerical_error(msg.c_str());
          else PyErr_SetString(PyExc_RuntimeError, ("hapstab internal error: " + msg).c_str());
          throw py::error_already_set();
        }
        const auto& j = answer["json"];
        return py::make_tuple(answer["code"].get<int>(), j.is_null() ? py::object(py::none()) : py::object(py::str(j.dump())));
      },
      py::arg("args"),
      "Runs `hapstab args...` (no program name) in a child process; returns (exit code, JSON text or None).\n"
      "Raises InputError (exit 2), NumericalError (exit 3), KeyboardInterrupt on Ctrl-C.");
  m.def(
      "examples_dir", [] { return hapstab::cli::examples_dir().string(); },
      "The folder of hapstab's example scenes (the source tree's examples/, or the installed share/hapstab/examples).");
}
