// cli::run_in_process: a command run in the calling process gives the JSON the command prints,
// its errors as the exceptions main maps to exit codes, and each thread its own capture.
#include <gtest/gtest.h>

#include <mpfr.h>

#include <thread>

#include "cli/command.hpp"
#include "hapstab/numeric/error.hpp"

using hapstab::cli::run_in_process;

TEST(InProcess, ReturnsTheJsonTheCommandPrints) {
  const auto run = run_in_process({"bound", "--H", "K + B*(z-1)/(T*z)", "--T", "1/1000", "--set", "K=1000",
                                   "--set", "B=1", "--delay", "1", "--json"});
  EXPECT_EQ(run.code, 0);
  EXPECT_EQ(run.json.at("bound"), "1.625");
  EXPECT_EQ(run.json.at("exact"), "13/8");
  EXPECT_EQ(run.json.at("status"), "exact");
}

TEST(InProcess, BadInputThrowsWhatMainMapsToExitTwo) {
  try {
    run_in_process({"bound", "--H", "1/(z-2", "--T", "1/1000", "--json"});
    FAIL() << "no exception";
  } catch (const std::exception& e) {
    EXPECT_EQ(hapstab::cli::exit_code_for(e).code, hapstab::cli::exit_bad_input) << e.what();
  }
  EXPECT_THROW(run_in_process({"bound", "--no-such-option"}), CLI::ParseError);
  EXPECT_THROW(run_in_process({"no-such-command"}), CLI::ParseError);
}

TEST(InProcess, EachThreadCapturesItsOwnOutput) {
  // A thread that used MPFR frees MPFR's per-thread caches before it ends (MPFR's manual).
  std::string a, b;
  std::thread ta([&] {
    a = run_in_process({"r", "--T", "1/1000", "--omega", "100", "--json"}).json.at("im");
    mpfr_free_cache();
  });
  std::thread tb([&] {
    b = run_in_process({"r", "--T", "1/1000", "--omega", "200", "--json"}).json.at("im");
    mpfr_free_cache();
  });
  ta.join();
  tb.join();
  EXPECT_EQ(a, run_in_process({"r", "--T", "1/1000", "--omega", "100", "--json"}).json.at("im"));
  EXPECT_EQ(b, run_in_process({"r", "--T", "1/1000", "--omega", "200", "--json"}).json.at("im"));
  EXPECT_NE(a, b);
}

// A prepared parser run point after point gives each point the JSON of a fresh run, for every
// command a sweep can run (and an error at one point does not reach the next); a run naming other
// options than the first is refused.
TEST(InProcess, PreparedCommandEqualsFreshRunsPointAfterPoint) {
  using hapstab::cli::PreparedCommand;
  const std::string scene = std::string(HAPSTAB_SOURCE_DIR) + "/examples/multidof_case_i_nominal.toml";
  const std::vector<std::vector<std::vector<std::string>>> commands = {
      {{"bound", "--H", "K + B*(z-1)/(T*z)", "--T", "1/1000", "--delay", "1", "--json", "--set", "K=1000", "--set", "B=1"},
       {"bound", "--H", "K + B*(z-1)/(T*z)", "--T", "1/1000", "--delay", "1", "--json", "--set", "K=0", "--set", "B=1/3"},
       {"bound", "--H", "K + B*(z-1)/(T*z)", "--T", "1/1000", "--delay", "1", "--json", "--set", "K=20000", "--set", "B=0"}},
      {{"bound", "--H", "1/(z-c)", "--T", "1", "--method", "fast", "--json", "--set", "c=2"},  // unstable: an error
       {"bound", "--H", "1/(z-c)", "--T", "1", "--method", "fast", "--json", "--set", "c=1/2"}},
      {{"wedge", "--H", "K*(z-1)/z", "--T", "1/100", "--json", "--set", "K=3"},
       {"wedge", "--H", "K*(z-1)/z", "--T", "1/100", "--json", "--set", "K=1/7"}},
      {{"multidof", "analyze", "--scene", scene, "--json", "--set", "k=1000"},
       {"multidof", "analyze", "--scene", scene, "--json", "--set", "k=x"},  // bad value: an error
       {"multidof", "analyze", "--scene", scene, "--json", "--set", "k=3000"}},
  };
  const auto outcome = [](auto&& run) -> std::string {
    try {
      auto r = run();
      if (r.json.is_object()) r.json.erase("seconds");  // timings: the one thing that differs
      return std::to_string(r.code) + " " + r.json.dump();
    } catch (const std::exception& e) {
      return "exception " + std::to_string(hapstab::cli::exit_code_for(e).code) + ": " + e.what();
    }
  };
  for (const auto& points : commands) {
    PreparedCommand prepared(points.front().front());
    for (const auto& args : points)
      EXPECT_EQ(outcome([&] { return prepared.run(args); }), outcome([&] { return run_in_process(args); })) << args[0] << " " << args.back();
  }
  PreparedCommand prepared("r");
  prepared.run({"r", "--T", "1/1000", "--omega", "100", "--json"});
  EXPECT_THROW(prepared.run({"r", "--T", "1/1000", "--json"}), std::logic_error);
}
