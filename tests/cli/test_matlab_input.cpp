// MATLAB-shaped input and output: --num/--den (descending powers of z) and --mat FILE:VAR give
// exactly the H of the equivalent expression (same JSON from the commands), the doubles of a .mat
// file are taken at their exact binary value, bad .mat files and coefficient lists are refused
// with exit 2 naming the input, and `simulate --format mat` writes what MATLAB and scipy read.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/cli_run.hpp"
#include "cli/mat_fixture.hpp"

namespace fs = std::filesystem;
using hapstab_test::mat_cell;
using hapstab_test::mat_double;
using hapstab_test::mat_struct;
using hapstab_test::json_of;
using hapstab_test::run_cli;
using hapstab_test::write_mat_file;

namespace {

fs::path tmp(const std::string& name) { return hapstab_test::temp_path("matlab", name); }

void expect_bad(const std::string& args, const std::string& says) {
  const auto r = run_cli(args);
  EXPECT_EQ(r.code, 2) << args << "\n" << r.out;
  EXPECT_NE(r.out.find(says), std::string::npos) << args << "\n" << r.out;
}

// The backward-difference wall K + B (z-1)/(T z), K = 1000, B = 5, T = 1 ms: (6000 z - 5000)/z.
const std::string wall_expr = "bound --json --T 1/1000 --H \"K + B*(z-1)/(T*z)\" --set K=1000 --set B=5";

}  // namespace

TEST(NumDen, SameBoundAsTheExpression) {
  const auto expr = json_of(wall_expr);
  ASSERT_FALSE(expr.is_null());
  for (const std::string& nd : {"--num \"6000 -5000\" --den \"1 0\"", "--num \"[6000, -5000]\" --den \"[1 0]\"",
                                "--num 12000/2,-5e3 --den \"[ 1, 0 ]\"", "--num \"0 6000 -5000\" --den \"1,0\""}) {
    EXPECT_EQ(json_of("bound --json --T 1/1000 " + nd), expr) << nd;
  }
  // with a delay, and a common factor that cancels as in the expression
  EXPECT_EQ(json_of("bound --json --T 1/1000 --delay 2 --num \"0.3 0.3\" --den \"1 -0.5 0.1\""),
            json_of("bound --json --T 1/1000 --delay 2 --H \"0.3*(z+1)/(z^2-0.5*z+0.1)\""));
  EXPECT_EQ(json_of("bound --json --T 1/1000 --num \"1 -0.5\" --den \"1 -0.75 0.125\""),
            json_of("bound --json --T 1/1000 --H \"1/(z-0.25)\""));
}

TEST(NumDen, OtherCommandsTakeThem) {
  EXPECT_EQ(json_of("wedge --json --num \"0.3 0.3\" --den \"1 -0.5 0.1\""),
            json_of("wedge --json --H \"0.3*(z+1)/(z^2-0.5*z+0.1)\""));
  EXPECT_EQ(json_of("passivity-level --json --T 1/100 --num \"1 0.5\" --den \"1 -0.5\""),
            json_of("passivity-level --json --T 1/100 --H \"(z+0.5)/(z-0.5)\""));
}

TEST(NumDen, BadListsAreRefusedNamingTheOption) {
  const std::string b = "bound --T 1/1000 ";
  expect_bad(b + "--num \"1 -0.5\"", "--num needs --den");
  expect_bad(b + "--den \"1 -0.5\"", "--den needs --num");
  expect_bad(b + "--num \"[ ]\" --den 1", "--num: no coefficients");
  expect_bad(b + "--num 1 --den \"0 1 2\"", "--den: the leading coefficient (of z^2) is 0");
  expect_bad(b + "--num \"1 x\" --den 1", "--num: coefficient 2");
  expect_bad(b + "--num \"[1 2\" --den 1", "--num: '[' without a closing ']'");
  expect_bad(b + "--num 1 --den 1 --H 1", "only one of --H, --num/--den and --mat");
  expect_bad(b + "--num 1 --den 1 --set K=1", "--set names parameters of --H");
  std::string many;
  for (int i = 0; i < 202; ++i) many += "1 ";
  expect_bad(b + "--num 1 --den \"" + many + "\"", "--den: more than 201 coefficients (degree limit 200)");
  expect_bad(b + "--num \"1 0 0\" --den \"1 0\"", "not causal");
}

TEST(MatFile, EveryLayoutGivesTheSameH) {
  // (z - 0.5)/(z^2 - 0.75 z + 0.125): dyadic coefficients, so the doubles are the decimals
  const auto ref = json_of("bound --json --T 1/1000 --num \"1 -0.5\" --den \"1 -0.75 0.125\"");
  const std::vector<double> num{1, -0.5}, den{1, -0.75, 0.125};
  const auto f1 = tmp("nd.mat"), f2 = tmp("st.mat"), f3 = tmp("cell.mat"), f4 = tmp("rows.mat");
  write_mat_file(f1, {mat_double("num", 1, 2, num), mat_double("den", 3, 1, den)});  // row and column vectors
  write_mat_file(f2, {mat_struct("G", {{"num", mat_double("num", 1, 2, num)}, {"den", mat_double("den", 1, 3, den)}})});
  write_mat_file(f3, {mat_cell("G", {mat_double("", 1, 2, num), mat_double("", 1, 3, den)}),
                      mat_cell("n1", {mat_double("", 1, 2, num)})});
  write_mat_file(f4, {mat_double("G", 2, 3, {0, 1, 1, -0.75, -0.5, 0.125})});  // [0 1 -0.5; 1 -0.75 0.125]
  const std::string b = "bound --json --T 1/1000 --mat ";
  EXPECT_EQ(json_of(b + f1.string()), ref);
  EXPECT_EQ(json_of(b + f1.string() + ":num,den"), ref);
  EXPECT_EQ(json_of(b + f2.string() + ":G"), ref);
  EXPECT_EQ(json_of(b + f3.string() + ":G"), ref);
  EXPECT_EQ(json_of(b + f4.string() + ":G"), ref);
  write_mat_file(f3, {mat_cell("n1", {mat_double("", 1, 2, num)}), mat_double("d", 1, 3, den)});
  EXPECT_EQ(json_of(b + f3.string() + ":n1,d"), ref) << "a 1x1 cell holding the vector (tfdata without 'v')";
}

TEST(MatFile, DoublesAreTakenAtTheirExactBinaryValue) {
  // H = 0.1 (a constant): b* = T H/2 exactly; 0.1 in a .mat file is 3602879701896397/2^55
  const auto f = tmp("tenth.mat");
  write_mat_file(f, {mat_double("num", 1, 1, {0.1}), mat_double("den", 1, 1, {1})});
  const auto j = json_of("bound --json --T 1 --mat " + f.string());
  EXPECT_EQ(j["exact"], "3602879701896397/72057594037927936");  // 0.1 (binary: /2^55) / 2
  EXPECT_EQ(j, json_of("bound --json --T 1 --num 3602879701896397/36028797018963968 --den 1"));
}

TEST(MatFile, StateSpaceForPassivityLevel) {
  const auto f = tmp("ss.mat"), g = tmp("ss_struct.mat"), js = tmp("ss.json");
  write_mat_file(f, {mat_double("A", 2, 2, {0.5, 0.25, 0, 0.25}), mat_double("B", 2, 1, {1, 0}),
                     mat_double("C", 1, 2, {1, 0.5}), mat_double("D", 1, 1, {1})});
  write_mat_file(g, {mat_struct("sys", {{"A", mat_double("A", 2, 2, {0.5, 0.25, 0, 0.25})}, {"B", mat_double("B", 2, 1, {1, 0})},
                                        {"C", mat_double("C", 1, 2, {1, 0.5})}, {"D", mat_double("D", 1, 1, {1})}})});
  std::ofstream(js) << R"({"A": [[0.5, 0], [0.25, 0.25]], "B": [[1], [0]], "C": [[1, 0.5]], "D": [[1]], "T": "1/100"})";
  const auto ref = json_of("passivity-level --json --ss " + js.string());
  EXPECT_EQ(json_of("passivity-level --json --T 1/100 --mat " + f.string()), ref);
  EXPECT_EQ(json_of("passivity-level --json --T 1/100 --mat " + g.string() + ":sys"), ref);
  expect_bad("passivity-level --mat " + f.string(), "--T is required");
  // a SISO state space is H = C (zI - A)^-1 B + D, exactly: 1 + (z - 0.125)/((z - 0.5)(z - 0.25))
  EXPECT_EQ(json_of("bound --json --T 1/100 --mat " + f.string()),
            json_of("bound --json --T 1/100 --H \"1 + (z-0.125)/((z-0.5)*(z-0.25))\""));
  write_mat_file(g, {mat_double("A", 1, 1, {0.5}), mat_double("B", 1, 2, {1, 1}), mat_double("C", 1, 1, {1}),
                     mat_double("D", 1, 2, {0, 0})});
  expect_bad("bound --T 1/100 --mat " + g.string(), "this command takes a SISO H");
  write_mat_file(f, {mat_double("A", 2, 2, {0.5, 0.25, 0, 0.25}), mat_double("B", 3, 1, {1, 0, 0}),
                     mat_double("C", 1, 2, {1, 0.5}), mat_double("D", 1, 1, {1})});
  expect_bad("passivity-level --T 1/100 --mat " + f.string(), "B must have 2 rows");
}

TEST(MatFile, BadFilesAreRefusedNamingTheVariable) {
  const std::string b = "bound --T 1/1000 --mat ";
  const auto f = tmp("bad.mat");
  expect_bad(b + tmp("absent.mat").string(), "cannot read");
  std::ofstream(f) << "not a mat file";
  expect_bad(b + f.string(), "not a MATLAB level-5 .mat file");
  {  // a v7.3 header (HDF5 follows)
    std::string h(128, ' ');
    h[124] = 0, h[125] = 2, h[126] = 'I', h[127] = 'M';
    std::ofstream(f, std::ios::binary) << h << std::string(512, '\0');
  }
  expect_bad(b + f.string(), "v7.3 (HDF5)");
  {  // a truncated level-5 file
    write_mat_file(f, {mat_double("num", 1, 200, std::vector<double>(200, 1.5)), mat_double("den", 1, 1, {1})});
    fs::resize_file(f, fs::file_size(f) - 40);
  }
  const auto r = run_cli("bound --T 1/1000 --mat " + f.string());
  EXPECT_EQ(r.code, 2) << r.out;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  write_mat_file(f, {mat_double("num", 1, 2, {1, nan}), mat_double("den", 1, 1, {1})});
  expect_bad(b + f.string(), ":num: entry 2 is NaN");
  write_mat_file(f, {mat_double("num", 1, 1, {inf}), mat_double("den", 1, 1, {1})});
  expect_bad(b + f.string(), ":num: entry 1 is Inf");
  write_mat_file(f, {mat_double("num", 2, 2, {1, 2, 3, 4}), mat_double("den", 1, 1, {1})});
  expect_bad(b + f.string(), ":num: 2x2; expected a vector");
  write_mat_file(f, {mat_double("num", 0, 0, {}), mat_double("den", 1, 1, {1})});
  expect_bad(b + f.string(), ":num: empty");
  write_mat_file(f, {mat_double("x", 1, 1, {1})});
  expect_bad(b + f.string(), "no variables num and den, nor A, B, C and D (found: x)");
  expect_bad(b + f.string() + ":y", ":y: no such variable");
  expect_bad(b + f.string() + ":x", "expected a struct, a cell {num, den} or a 2-row matrix");
  write_mat_file(f, {mat_struct("G", {{"num", mat_double("num", 1, 1, {1})}})});
  expect_bad(b + f.string() + ":G", "a struct without the fields num, den");
  {
    size_t dims[2] = {1, 2};
    int32_t ints[2] = {1, 2};
    double re[2] = {1, 2}, im[2] = {0, 1};
    mat_complex_split_t z{re, im};
    char text[3] = {'a', 'b', 'c'};
    size_t cdims[2] = {1, 3}, d3[3] = {1, 1, 2};
    double two[2] = {1, 1};
    write_mat_file(f, {Mat_VarCreate("i", MAT_C_INT32, MAT_T_INT32, 2, dims, ints, 0),
                       Mat_VarCreate("z", MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims, &z, MAT_F_COMPLEX),
                       Mat_VarCreate("c", MAT_C_CHAR, MAT_T_UINT8, 2, cdims, text, 0),
                       Mat_VarCreate("t", MAT_C_DOUBLE, MAT_T_DOUBLE, 3, d3, two, 0), mat_double("den", 1, 1, {1})});
  }
  expect_bad(b + f.string() + ":i,den", ":i: of a class other than double");
  expect_bad(b + f.string() + ":z,den", ":z: complex");
  expect_bad(b + f.string() + ":c,den", ":c: text");
  expect_bad(b + f.string() + ":t,den", ":t: has 3 dimensions");
}

TEST(MatFile, AHeaderClaimingHugeArraysIsAnInputError) {
  // Found by libFuzzer: 284 bytes whose array header made matio ask calloc for 206 GB. The
  // structure check (cli/mat_level5.hpp) refuses it before matio reads anything.
  static const unsigned char bytes[] = {
      0x4d, 0x41, 0x54, 0x4c, 0x41, 0x42, 0x20, 0x35, 0x2e, 0x30, 0x20, 0x4d, 0x41, 0x54, 0x2d, 0x66, 0x69, 0x6c,
      0x65, 0x20, 0x50, 0x6c, 0x61, 0x74, 0x66, 0x6f, 0x72, 0x6d, 0x3a, 0x20, 0x70, 0x6f, 0x73, 0x69, 0x78, 0x2c,
      0x20, 0x43, 0x72, 0x65, 0x61, 0x74, 0x65, 0x64, 0x20, 0x6f, 0x6e, 0x3a, 0x20, 0x57, 0x65, 0x64, 0x20, 0x4e,
      0x6f, 0x76, 0x20, 0x32, 0x35, 0x20, 0x30, 0x33, 0x3a, 0x30, 0x23, 0x3a, 0x30, 0x31, 0x20, 0x32, 0x30, 0x32,
      0x36, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x09, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01,
      0x49, 0x4d, 0x0e, 0x00, 0x00, 0x00, 0xb0, 0x00, 0x00, 0x00, 0x06, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0xf9, 0xff,
      0xff, 0xff, 0x06, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00,
      0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x09, 0x00,
      0x00, 0x00, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xf0, 0x3f, 0x0e, 0x00, 0x00, 0x00,
      0x40, 0x00, 0x00, 0x00, 0x06, 0x72, 0x6d, 0x3a, 0x20, 0x70, 0x6f, 0x73, 0x69, 0x78, 0x2c, 0x20, 0x43, 0x72,
      0x65, 0x61, 0x74, 0x65, 0x64, 0x20, 0x6f, 0x6e, 0x3a, 0x20, 0x57, 0x65, 0x64, 0x20, 0x4e, 0x6f, 0x76, 0x20,
      0x32, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x09, 0x00, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00,
      0x00, 0x00, 0x00, 0x00, 0xf0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xe0, 0xbf};
  const auto f = tmp("huge_dims.mat");
  std::ofstream(f, std::ios::binary).write(reinterpret_cast<const char*>(bytes), sizeof bytes);
  for (const std::string spec : {"", ":G", ":num,den"}) {
    const auto r = run_cli("bound --T 1 --mat " + f.string() + spec);
    EXPECT_EQ(r.code, 2) << spec << "\n" << r.out;
    EXPECT_NE(r.out.find("--mat " + f.string() + ": not a valid .mat file: an element declares 176 bytes, 148 are left"),
              std::string::npos) << r.out;
  }
}

// Level-5 bytes by hand (little-endian), for structures matio cannot be asked to write.
std::string u32(std::uint32_t v) { return {char(v), char(v >> 8), char(v >> 16), char(v >> 24)}; }
std::string element(std::uint32_t type, const std::string& data) {
  std::string e = u32(type) + u32(std::uint32_t(data.size())) + data;
  return e + std::string((8 - e.size() % 8) % 8, '\0');
}
// A miMATRIX of class `cls` named "G" with dimensions `dims`, followed by `payload`.
std::string matrix(unsigned cls, std::vector<std::uint32_t> dims, const std::string& payload) {
  std::string d;
  for (auto x : dims) d += u32(x);
  return element(14, element(6, u32(cls) + u32(0)) + element(5, d) + element(1, "G") + payload);
}
std::string level5(const std::string& variables) {
  std::string h = "MATLAB 5.0 MAT-file, written by hand for a test";
  h.resize(124, ' ');
  return h + std::string("\x00\x01IM", 4) + variables;
}

TEST(MatFile, StructureBeyondWhatTheBytesHoldIsRefusedBeforeMatio) {
  const std::string doubles = element(9, std::string(16, '\0'));
  const std::vector<std::pair<std::string, std::string>> cases = {
      // a 65536 x 65536 cell in 0 bytes: each entry needs at least a tag
      {level5(matrix(1, {65536, 65536}, "")), "4294967296 cell entries in 0 bytes"},
      // a 2^24 + 1 entry double array
      {level5(matrix(6, {4097, 4097}, element(9, ""))), "16785409 entries (at most 16777216)"},
      // a 1 x 2 double array whose data holds 2 doubles' bytes as singles (4 entries)
      {level5(matrix(6, {1, 2}, element(7, std::string(16, '\0')))), "numeric data of 16 bytes for 2 entries"},
      // dimensions that overflow size_t
      {level5(matrix(6, {0x7fffffff, 0x7fffffff, 0x7fffffff}, doubles)), "dimensions whose product overflows"},
      // a cell nested 40 deep
      {[&doubles] {
         std::string m = matrix(6, {1, 2}, doubles);
         for (int k = 0; k < 40; ++k) m = matrix(1, {1, 1}, m);
         return level5(m);
       }(),
       "nested more than 16 deep"},
      // a compressed element whose data is not zlib
      {level5(u32(15) + u32(8) + "notzlib!"), "compressed data is corrupt"},
      // a function handle
      {level5(matrix(16, {1, 1}, "")), "of class 16"},
      {level5(std::string(8, '\0').replace(0, 1, 1, '\x01')), "an element of type 1 where a variable"},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const auto f = tmp("structure_" + std::to_string(k) + ".mat");
    std::ofstream(f, std::ios::binary) << cases[k].first;
    const auto r = run_cli("bound --T 1 --mat " + f.string());
    EXPECT_EQ(r.code, 2) << k << "\n" << r.out;
    EXPECT_NE(r.out.find("not a valid .mat file"), std::string::npos) << k << "\n" << r.out;
    EXPECT_NE(r.out.find(cases[k].second), std::string::npos) << k << "\n" << r.out;
  }
  // the hand-written bytes are a valid file when the sizes agree: G = [1 0; 2 1] = [num; den]
  std::string nd;
  for (double v : {1.0, 2.0, 0.0, 1.0}) nd += std::string(reinterpret_cast<const char*>(&v), 8);  // column-major
  const auto f = tmp("structure_ok.mat");
  std::ofstream(f, std::ios::binary) << level5(matrix(6, {2, 2}, element(9, nd)));
  const auto r = run_cli("bound --T 1 --json --mat " + f.string() + ":G");
  EXPECT_EQ(r.code, 0) << r.out;
  EXPECT_EQ(r.out, run_cli("bound --T 1 --json --H \"z/(2*z + 1)\"").out);
}

TEST(SimulateMat, SamplesAndFineGridAsMatrices) {
  const auto out = tmp("sim");
  const auto r = run_cli("simulate --quiet --format csv,mat --scene " + std::string(HAPSTAB_SOURCE_DIR) +
                         "/examples/002_bias_wall.toml --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.out;
  const auto t = hapstab_test::read_mat_variable(out / "samples.mat", "t");
  const auto x = hapstab_test::read_mat_variable(out / "samples.mat", "x");
  const auto ft = hapstab_test::read_mat_variable(out / "samples.mat", "fine_t");
  const auto fx = hapstab_test::read_mat_variable(out / "samples.mat", "fine_x");
  const auto T = hapstab_test::read_mat_variable(out / "samples.mat", "T");
  ASSERT_TRUE(t.found && x.found && ft.found && fx.found && T.found);
  EXPECT_EQ(t.cols, 1u);
  EXPECT_EQ(x.rows, t.rows);
  EXPECT_GE(x.cols, 1u);
  EXPECT_EQ(fx.rows, ft.rows);
  EXPECT_GT(ft.rows, t.rows / 10);
  // the same numbers as samples.csv (17 digits: the doubles round-trip), whatever its header rows
  std::ifstream csv(out / "samples.csv");
  std::string line;
  size_t row = 0, checked = 0;
  while (std::getline(csv, line) && row < t.rows) {
    if (line.empty() || !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-')) continue;
    std::stringstream ss(line);
    std::string t_s, x_s;
    std::getline(ss, t_s, ',');
    std::getline(ss, x_s, ',');
    EXPECT_EQ(std::stod(t_s), t.data[row]) << row;
    EXPECT_EQ(std::stod(x_s), x.data[row]) << row;  // column 0 = DOF 0
    ++row, ++checked;
  }
  EXPECT_EQ(checked, t.rows);
  expect_bad("simulate --format xls --scene " + std::string(HAPSTAB_SOURCE_DIR) + "/examples/002_bias_wall.toml --out " +
                 tmp("sim2").string(), "--format: expected csv, mat or csv,mat");
}

// scipy is a dependency (scripts/install-deps: python3-scipy): its absence fails the test
// rather than skipping it, so that the check runs in CI.
TEST(SimulateMat, ScipyReadsIt) {
  ASSERT_TRUE(fs::exists("/usr/bin/python3")) << "no /usr/bin/python3 (scripts/install-deps installs python3)";
  const auto out = tmp("sim_scipy");
  ASSERT_EQ(run_cli("simulate --quiet --format mat --scene " + std::string(HAPSTAB_SOURCE_DIR) +
                    "/examples/002_bias_wall.toml --out " + out.string())
                .code,
            0);
  EXPECT_FALSE(fs::exists(out / "samples.csv"));
  const std::string py = "/usr/bin/python3 -c \"import scipy.io as s; m = s.loadmat('" + (out / "samples.mat").string() +
                         "'); print(m['t'].shape[0] == m['x'].shape[0], m['x'].dtype, m['fine_x'].shape[0] == m['fine_t'].shape[0])\"";
  FILE* p = popen((py + " 2>&1").c_str(), "r");
  ASSERT_NE(p, nullptr);
  char buf[512] = {0};
  const size_t n = fread(buf, 1, sizeof buf - 1, p);
  const int st = pclose(p);
  const std::string got(buf, n);
  ASSERT_EQ(got.find("No module named 'scipy'"), std::string::npos) << "scipy is missing: scripts/install-deps installs python3-scipy";
  EXPECT_EQ(WEXITSTATUS(st), 0) << got;
  EXPECT_EQ(got, "True float64 True\n");
}
