// Tests of the figure fixes of issue 41's second review that are not pictures: the machine line
// of a bench chart is read from a Google Benchmark JSON that holds Infinity (sampling_bench.json
// did, and the footer said "unreadable").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_run.hpp"
#include "cli/figure.hpp"

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
