// Tests of the figure fixes of issue 41's second review that are not pictures: the machine line
// of a bench chart is read from a Google Benchmark JSON that holds Infinity (sampling_bench.json
// did, and the footer said "unreadable").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "cli/cli_run.hpp"
#include "cli/figure.hpp"
#include "hapstab/report/registration.hpp"

namespace fs = std::filesystem;

TEST(FigureReview, BenchTimingReadsAJsonWithInfinityAndNaN) {
  const fs::path d = hapstab_test::temp_path("figreview", "bench");
  fs::create_directories(d);
  std::ofstream(d / "sampling_bench.json")
      << R"({"context": {"date": "2026-11-27T10:00:00+00:00", "num_cpus": 2, "mhz_per_cpu": 2596, "load_avg": [1.5, 1, 1],
           "note": "a string with Infinity and NaN inside stays"},
           "benchmarks": [{"name": "form/eq35/double", "rel_err": Infinity, "digits": -Infinity, "ulps": NaN}]})";
  const auto v = hapstab::cli::bench_timing_vars("sampling", d);
  ASSERT_EQ(v.text.size(), 1u);
  EXPECT_EQ(v.text[0].second, "timed 2026-11-27 on 2 CPUs at 2596 MHz, load average 1.5") << v.text[0].second;
  fs::remove_all(d);
}

// reproduce draws (and docs/commands.md shows) the figures in this order: it must not depend on the
// path the compiler saw (absolute in a unity batch, relative when ccache's base_dir rewrites it).
TEST(FigureReview, FiguresAreOrderedByTheRegisteringFilesNameThenLine) {
  using hapstab::report::source_file_name;
  EXPECT_TRUE(hapstab::report::registered_before("../toolbox/cli/b.cpp", 1, "/abs/tree/toolbox/cli/c.cpp", 1));
  EXPECT_FALSE(hapstab::report::registered_before("/abs/tree/toolbox/cli/c.cpp", 1, "../toolbox/cli/b.cpp", 1));
  EXPECT_TRUE(hapstab::report::registered_before("/abs/c.cpp", 1, "c.cpp", 2));
  const auto& all = hapstab::cli::figures();
  ASSERT_GT(all.size(), 10u);
  std::map<std::string, std::string> path_of;  // a file's name -> its path: the names are unique
  for (size_t i = 0; i < all.size(); ++i) {
    const auto [it, fresh] = path_of.emplace(source_file_name(all[i].file), all[i].file);
    EXPECT_TRUE(fresh || it->second == all[i].file) << all[i].file << " and " << it->second << " share a name";
    if (i == 0) continue;
    EXPECT_TRUE(hapstab::report::registered_before(all[i - 1].file, all[i - 1].line, all[i].file, all[i].line))
        << all[i - 1].name << " before " << all[i].name;
  }
}
