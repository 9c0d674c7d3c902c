// fuzz-modules: lti report
// fuzz-sources: toolbox/cli/mat_file.cpp toolbox/cli/mat_level5.cpp
// fuzz-seeds: tests/fuzz/seeds_mat
// fuzz-libs: -lmatio -lz
// libFuzzer target: the --mat reader (cli/mat_file.hpp, cli/mat_level5.hpp). Any bytes must end
// in a model within numeric/limits.hpp or an InputError, through every way --mat names variables;
// matio must never be asked for memory the file's own size does not justify (-rss_limit_mb).
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "cli/mat_file.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // matio reads files: one per process (libFuzzer runs inputs one after another in a process)
  static const std::string file = "/tmp/hapstab_fuzz_mat_" + std::to_string(::getpid()) + ".mat";
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  for (const char* spec : {"", ":G", ":num,den"}) {
    try {
      const auto m = hapstab::cli::read_mat_model(file + spec, "--mat");
      if (!m.tf && !m.ss) std::abort();
      if (m.ss && (m.ss->A.rows() > hapstab::limits::state_space_dim || m.ss->A.cols() > hapstab::limits::state_space_dim))
        std::abort();
      if (m.tf && (m.tf->first.size() > size_t(hapstab::limits::model_degree) + 1 || m.tf->second.size() > size_t(hapstab::limits::model_degree) + 1))
        std::abort();
    } catch (const hapstab::InputError&) {
    }
  }
  return 0;
}
