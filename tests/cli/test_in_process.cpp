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
