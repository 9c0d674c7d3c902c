// fuzz-sources: toolbox/cli/batch_line.cpp
// fuzz-seeds: tests/fuzz/seeds_batch
// fuzz-dict: tests/fuzz/escape.dict
// libFuzzer target: the --batch line splitter (cli/batch_line.hpp). Any line ends in words or an
// InputError; a word holds no separator unless the line quoted it, and the words together hold
// every non-separator, non-quote character of an unquoted line, in order.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "cli/batch_line.hpp"
#include "hapstab/numeric/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string line(reinterpret_cast<const char*>(data), size);
  try {
    const auto words = hapstab::cli::split_batch_line(line);
    if (line.find_first_of("'\"") == std::string::npos) {
      std::string joined, expected;
      for (const auto& w : words) {
        if (w.empty() || w.find_first_of(" \t") != std::string::npos) std::abort();
        joined += w;
      }
      for (char c : line)
        if (c != ' ' && c != '\t') expected += c;
      if (joined != expected) std::abort();
    }
  } catch (const hapstab::InputError&) {
    if (line.find_first_of("'\"") == std::string::npos) std::abort();  // only quotes can be unterminated
  }
  return 0;
}
