// Tests of hapstab/study: SHA-256 against the FIPS 180-4 / NIST test vectors, exact axes (linear,
// log, random reproducible from integer draws), point enumeration, spec errors naming their key,
// record flattening and the record store (torn lines, duplicates, missing points).
#include <gtest/gtest.h>

#include <boost/multiprecision/gmp.hpp>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "hapstab/numeric/decimal.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/study/sha256.hpp"
#include "hapstab/study/spec.hpp"
#include "hapstab/study/table.hpp"
#include "hapstab/study/threads.hpp"

using namespace hapstab;
using namespace hapstab::study;
namespace fs = std::filesystem;

namespace {

fs::path unique_dir(const std::string& tag) {
  std::string t = (fs::temp_directory_path() / ("hapstab-study-" + tag + "-XXXXXX")).string();
  EXPECT_NE(::mkdtemp(t.data()), nullptr);
  return t;
}

std::string error_of(const std::string& spec) {
  try {
    parse_spec(spec, "s.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::string head = "command = \"bound\"\n[args]\nH = \"K\"\nT = \"1/1000\"\n[axes]\n";

}  // namespace

TEST(Sha256, NistVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // 55, 56 and 64 bytes: the padding edges (one block, two blocks).
  EXPECT_EQ(sha256_hex(std::string(55, 'a')), "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
  EXPECT_EQ(sha256_hex(std::string(56, 'a')), "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a");
  EXPECT_EQ(sha256_hex(std::string(64, 'a')), "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
}

TEST(Axes, LinearGridIsExact) {
  const Spec s = parse_spec(head + "K = { from = \"0\", to = \"40000\", points = 7 }\nB = { values = [\"1/2\", 3] }\n",
                            "s.toml");
  ASSERT_EQ(s.axes.size(), 2u);
  EXPECT_EQ(s.axes[0].name, "K");  // file order, not alphabetical
  EXPECT_EQ(s.axes[0].values,
            (std::vector<std::string>{"0", "20000/3", "40000/3", "20000", "80000/3", "100000/3", "40000"}));
  EXPECT_EQ(s.axes[1].values, (std::vector<std::string>{"1/2", "3"}));
  EXPECT_EQ(s.points, 14u);
  EXPECT_EQ(point_values(s, 0), (std::vector<std::string>{"0", "1/2"}));
  EXPECT_EQ(point_values(s, 13), (std::vector<std::string>{"40000", "3"}));  // the last axis varies fastest
  const auto args = point_args(s, 3, {"--json"});
  EXPECT_EQ(args, (std::vector<std::string>{"bound", "--H", "K", "--T", "1/1000", "--json", "--set", "K=20000/3",
                                            "--set", "B=3"}));
}

TEST(Axes, ConstantsAndUnits) {
  // [set]: --set NAME=VALUE at every point, before the axes; [units] for plots; the axis kinds
  const Spec s = parse_spec(head + "K = { from = \"1\", to = \"100\", points = 3, scale = \"log\" }\n"
                                   "B = { values = [\"0\", \"1/2\"] }\n[set]\nc = \"1/3\"\nd = 2\n[units]\nK = \"N/m\"\nbound = \"N s/m\"\n",
                            "s.toml");
  ASSERT_EQ(s.constants.size(), 2u);
  EXPECT_EQ(point_args(s, 1, {}), (std::vector<std::string>{"bound", "--H", "K", "--T", "1/1000", "--set", "c=1/3", "--set",
                                                            "d=2", "--set", "K=1", "--set", "B=1/2"}));
  EXPECT_EQ(unit_of(s, "K"), "N/m");
  EXPECT_EQ(unit_of(s, "bound"), "N s/m");
  EXPECT_EQ(unit_of(s, "B"), "");
  EXPECT_TRUE(s.axes[0].log && !s.axes[0].listed);
  EXPECT_TRUE(s.axes[1].listed && !s.axes[1].log);
  const std::string k = "K = { values = [\"1\"] }\n";
  EXPECT_NE(error_of(head + k + "[set]\nK = \"2\"\n").find("set.K: is an axis too"), std::string::npos);
  EXPECT_NE(error_of(head + k + "[set]\nc = 0.5\n").find("set.c"), std::string::npos);  // a TOML float: not exact
  EXPECT_NE(error_of(head + k + "[set]\nindex = \"1\"\n").find("set.index"), std::string::npos);
  EXPECT_NE(error_of(head + k + "[units]\nK = 3\n").find("units.K"), std::string::npos);
  EXPECT_NE(error_of(head + k + "[units]\nK = \"" + std::string(65, 'm') + "\"\n").find("units.K"), std::string::npos);
}

TEST(Axes, ExactTextOfDecimalsAndFractions) {
  EXPECT_EQ(exact_text(rational(1, 8)), "0.125");
  EXPECT_EQ(exact_text(rational(-3, 40)), "-0.075");
  EXPECT_EQ(exact_text(rational(1, 3)), "1/3");
  EXPECT_EQ(exact_text(rational(250)), "250");
  EXPECT_EQ(parse_rational(exact_text(rational(7, 1024))), rational(7, 1024));
}

TEST(Axes, LogScaleRoundedToStatedDigits) {
  const Spec s = parse_spec(head + "K = { from = \"1\", to = \"1000\", points = 4, scale = \"log\", digits = 3 }\n", "s");
  EXPECT_EQ(s.axes[0].values, (std::vector<std::string>{"1", "10", "100", "1000"}));
  const Spec t = parse_spec(head + "K = { from = \"1\", to = \"10\", points = 3, scale = \"log\", digits = 4 }\n", "s");
  EXPECT_EQ(t.axes[0].values, (std::vector<std::string>{"1", "3.162", "10"}));  // sqrt(10) = 3.16227...
}

TEST(Axes, RandomIsReproducibleFromIntegerDraws) {
  // splitmix64's published first output for seed 0 (Vigna's reference implementation).
  EXPECT_EQ(splitmix64(0, 0), 0xe220a8397b1dcdafULL);
  const std::string axis = "K = { random = 5, from = \"-1\", to = \"1\", seed = 42 }\n";
  const Spec a = parse_spec(head + axis, "s"), b = parse_spec(head + axis, "s");
  EXPECT_EQ(a.axes[0].values, b.axes[0].values);
  for (size_t k = 0; k < 5; ++k) {
    const rational v = parse_rational(a.axes[0].values[k]);
    EXPECT_GE(v, -1);
    EXPECT_LT(v, 1);
    const rational expect = rational(-1) + 2 * rational(integer(splitmix64(42, k) >> 11)) / rational(integer(1) << 53);
    EXPECT_EQ(v, expect);
  }
  EXPECT_NE(a.axes[0].values, parse_spec(head + "K = { random = 5, from = \"-1\", to = \"1\", seed = 43 }\n", "s").axes[0].values);
}

TEST(Spec, ErrorsNameTheKey) {
  EXPECT_NE(error_of("[axes]\nK = { values = [\"1\"] }\n").find("command"), std::string::npos);
  EXPECT_NE(error_of(head).find("axes"), std::string::npos);
  EXPECT_NE(error_of(head + "K = { values = [0.1] }\n").find("axes.K.values[0]"), std::string::npos);
  EXPECT_NE(error_of(head + "K = { values = [\"x\"] }\n").find("axes.K.values[0]"), std::string::npos);
  EXPECT_NE(error_of(head + "K = { from = \"0\", to = \"1\" }\n").find("axes.K.points"), std::string::npos);
  EXPECT_NE(error_of(head + "K = { from = \"0\", to = \"1\", points = 3, step = 1 }\n").find("axes.K.step"),
            std::string::npos);
  EXPECT_NE(error_of(head + "K = { from = \"0\", to = \"1\", points = 3, scale = \"log\" }\n").find("axes.K"),
            std::string::npos);
  EXPECT_NE(error_of(head + "index = { values = [\"1\"] }\n").find("axes.index"), std::string::npos);
  EXPECT_NE(error_of("command = \"bound\"\n[args]\ndigits = 1.5\n[axes]\nK = { values = [\"1\"] }\n").find("args.digits"),
            std::string::npos);
  EXPECT_NE(error_of(head + "K = { from = \"0\", to = \"1\", points = 100000 }\nB = { from = \"0\", to = \"1\", points = "
                            "100000 }\n").find("10^9"),
            std::string::npos);
  EXPECT_NE(error_of("command = \"bound\"\nextra = 1\n[axes]\nK = { values = [\"1\"] }\n").find("extra"), std::string::npos);
  EXPECT_NE(error_of("command = \n").find("s.toml:1"), std::string::npos);  // TOML syntax: file:line
}

TEST(Table, FlattenDropsTimingsAndSplitsEnclosures) {
  const nlohmann::json j = nlohmann::json::parse(
      R"({"bound":"5","enclosure":["4.9","5.1"],"seconds":{"total":1.5},"run_seconds":2,"d":{"b":"1","ok":true},"v":[1,2,3],"n":null,)"
      R"("w":0.1,"m":[[1,2],{"x":[true,false]},[]],"big":-12345678901234})");
  const FlatRecord r = flatten_record(record_line(3, {{"exit", 0}, {"json", j}}));
  const auto& f = r.cells;
  std::vector<std::string> keys;
  for (const auto& [k, v] : f) keys.push_back(k);
  EXPECT_EQ(keys, (std::vector<std::string>{"big", "bound", "d_b", "d_ok", "enclosure_lo", "enclosure_hi", "m_0_lo", "m_0_hi",
                                            "m_1_x_lo", "m_1_x_hi", "n", "v_0", "v_1", "v_2", "w"}));
  EXPECT_EQ(f[0].second, "-12345678901234");
  EXPECT_EQ(f[3].second, "true");
  EXPECT_EQ(f[4].second, "4.9");
  EXPECT_EQ(f[10].second, "");
  EXPECT_EQ(f[14].second, nlohmann::json(0.1).dump());  // a number reads as json::dump writes it
  EXPECT_EQ(r.exit, "0");
  EXPECT_EQ(r.error, "");
  const FlatRecord e = flatten_record(record_line(9, {{"exit", 2}, {"error", "--H: bad, \"quoted\""}}));
  EXPECT_TRUE(e.cells.empty());
  EXPECT_EQ(e.exit, "2");
  EXPECT_EQ(e.error, "--H: bad, \"quoted\"");
  // not records: no index, not JSON, not an object, no exit, a column twice, a torn line
  for (const char* bad : {"{\"exit\":0}", "1 [1,2]", "1 {\"json\":{}}", "1 {\"exit\":0,\"json\":{\"a\":1,\"a\":2}}",
                          "1 {\"exit\":0,\"json\":{\"a_b\":1,\"a\":{\"b\":2}}}", "1 {\"exit\":0,\"js", "1 nonsense"})
    EXPECT_THROW(flatten_record(bad), InputError) << bad;
}

// The reference: the record parsed by nlohmann into a tree and flattened as table.hpp says.
void reference_flatten(const nlohmann::json& j, const std::string& name, std::vector<std::pair<std::string, std::string>>& out) {
  const std::string pre = name.empty() ? "" : name + "_";
  const auto timing = [](const std::string& k) {
    return k == "seconds" || (k.size() > 8 && k.compare(k.size() - 8, 8, "_seconds") == 0);
  };
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!timing(it.key())) reference_flatten(it.value(), pre + it.key(), out);
  } else if (j.is_array()) {
    for (size_t i = 0; i < j.size(); ++i)
      reference_flatten(j[i], pre + (j.size() == 2 ? (i == 0 ? "lo" : "hi") : std::to_string(i)), out);
  } else {
    out.emplace_back(name.empty() ? "value" : name, j.is_null() ? "" : j.is_string() ? j.get<std::string>() : j.dump());
  }
}

nlohmann::json random_value(std::mt19937& g, int depth) {
  static const std::vector<std::string> keys{"a", "b", "bound", "enclosure", "seconds", "t_seconds", "x_y", "\u00e9t\u00e9", "k\"q"};
  static const std::vector<std::string> texts{"", "plain", "a,b", "say \"hi\"", "tab\there", "line\nbreak", "back\\slash",
                                              "\u00b5s \u03c9 \u2264 \U0001F600", std::string("nul\0in", 6), "\x7f"};
  switch (std::uniform_int_distribution<int>(0, depth > 3 ? 4 : 6)(g)) {
    case 0: return nullptr;
    case 1: return std::uniform_int_distribution<int>(0, 1)(g) == 1;
    case 2: return std::uniform_int_distribution<long long>(-(1LL << 62), 1LL << 62)(g);
    case 3: return std::ldexp(std::uniform_real_distribution<double>(-1, 1)(g), std::uniform_int_distribution<int>(-1070, 1020)(g));
    case 4: return texts[std::uniform_int_distribution<size_t>(0, texts.size() - 1)(g)];
    case 5: {
      nlohmann::json a = nlohmann::json::array();
      for (int n = std::uniform_int_distribution<int>(0, 4)(g); n > 0; --n) a.push_back(random_value(g, depth + 1));
      return a;
    }
    default: {
      nlohmann::json o = nlohmann::json::object();
      for (int n = std::uniform_int_distribution<int>(0, 4)(g); n > 0; --n)
        o[keys[std::uniform_int_distribution<size_t>(0, keys.size() - 1)(g)]] = random_value(g, depth + 1);
      return o;
    }
  }
}

// flatten_record reads its own JSON: on 3000 random records (nesting, escapes, UTF-8, NUL, every
// number shape dump writes) it gives the cells of the tree flattening, and on every truncation
// and byte mutation of them it either refuses (InputError) or agrees with nlohmann's parse.
TEST(Table, FlattenRecordEqualsTheTreeFlatteningAndRefusesWhatIsNotJson) {
  std::mt19937 g(2026);
  int refused = 0, mutated = 0;
  for (int n = 0; n < 3000; ++n) {
    nlohmann::json j = nlohmann::json::object();
    for (int k = std::uniform_int_distribution<int>(0, 5)(g); k > 0; --k) j["k" + std::to_string(k)] = random_value(g, 1);
    const nlohmann::json rec = {{"exit", 0}, {"json", j}};
    const std::string line = record_line(n, rec);
    std::vector<std::pair<std::string, std::string>> want;
    reference_flatten(j, "", want);
    std::vector<std::string> names;
    for (const auto& c : want) names.push_back(c.first);
    std::sort(names.begin(), names.end());
    const bool clash = std::adjacent_find(names.begin(), names.end()) != names.end();  // "x_y" against {"x": {"y"}}
    if (clash) {
      EXPECT_THROW(flatten_record(line), InputError) << line;
      continue;
    }
    const FlatRecord got = flatten_record(line);
    ASSERT_EQ(got.cells, want) << line;
    EXPECT_EQ(got.exit, "0");
    for (size_t cut = 2; cut + 1 < line.size(); cut += 7) EXPECT_THROW(flatten_record(line.substr(0, cut)), InputError);
    std::string m = line;  // one byte changed
    m[std::uniform_int_distribution<size_t>(2, m.size() - 1)(g)] = char(std::uniform_int_distribution<int>(0, 255)(g));
    const auto tree = nlohmann::json::parse(m.substr(m.find(' ') + 1), nullptr, false);
    const bool record = !tree.is_discarded() && tree.is_object() && tree.contains("exit");
    try {
      const FlatRecord r = flatten_record(m);
      ASSERT_TRUE(record) << "accepted what nlohmann refuses: " << m;
      ++mutated;
      if (tree.contains("json")) {
        std::vector<std::pair<std::string, std::string>> w;
        reference_flatten(tree["json"], "", w);
        std::vector<std::string> a, b;  // the same columns (in the text's order, where a tree sorts them)
        for (const auto& c : r.cells) a.push_back(c.first);
        for (const auto& c : w) b.push_back(c.first);
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        ASSERT_EQ(a, b) << m;
      }
    } catch (const InputError&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 1000);  // most mutations break the JSON
  EXPECT_GT(mutated, 100);   // and many do not
  // nesting: 60 levels are read; deeper is refused, however deep (no recursion, no quadratic paths)
  const auto nested = [](size_t n) {
    return "0 {\"exit\":0,\"json\":{\"a\":" + std::string(n, '[') + "1" + std::string(n, ']') + "}}";
  };
  std::string path = "a";
  for (int i = 0; i < 60; ++i) path += "_0";
  EXPECT_EQ(flatten_record(nested(60)).cells.at(0).first, path);
  for (size_t n : {64, 1000, 1000000}) EXPECT_THROW(flatten_record(nested(n)), InputError) << n;
}

TEST(Table, StoreIgnoresTornLineAndReportsDuplicatesAndMissing) {
  const fs::path dir = unique_dir("store");
  const PointRange r = PointRange::shard_of(10, 1, 3);  // indices 1, 4, 7
  ASSERT_EQ(r.count, 3u);
  {
    std::ofstream f(dir / "a.txt");
    f << record_line(4, {{"exit", 0}, {"json", {{"x", 1}}}}) << "\n" << record_line(1, {{"exit", 2}, {"error", "bad"}})
      << "\n7 {\"exit\":0,\"js";  // torn by a kill
  }
  RecordStore s(r);
  s.add_file(dir / "a.txt");
  EXPECT_EQ(s.present(), 2u);
  EXPECT_EQ(s.missing(5), (std::vector<uint64_t>{7}));
  EXPECT_EQ(flatten_record(s.line(1)).cells, (std::vector<std::pair<std::string, std::string>>{{"x", "1"}}));
  s.add_file(dir / "a.txt");
  EXPECT_EQ(s.duplicates(), (std::vector<uint64_t>{4, 1}));
  {
    std::ofstream f(dir / "b.txt");
    f << record_line(5, {{"exit", 0}}) << "\n";  // not in shard 1/3
  }
  RecordStore t(r);
  EXPECT_THROW(t.add_file(dir / "b.txt"), InputError);
  fs::remove_all(dir);
}

TEST(Table, WritesRowsInIndexOrderWithKeysRenamedOnClash) {
  const fs::path dir = unique_dir("table");
  const Spec s = parse_spec(head + "bound = { values = [\"1\", \"1/3\"] }\nK = { values = [\"7\"] }\n", "s.toml");
  {
    std::ofstream f(dir / "r.txt");  // index 1 first: the table is in index order all the same
    f << record_line(1, {{"exit", 2}, {"error", "bad, \"quoted\""}}) << "\n"
      << record_line(0, {{"exit", 0}, {"json", {{"bound", "0.5"}, {"enclosure", {"0.4", "0.6"}}, {"total_seconds", 3}}}}) << "\n";
  }
  RecordStore store(PointRange::shard_of(s.points, 0, 1));
  store.add_file(dir / "r.txt");
  const TableCounts c = write_table(s, store, dir);
  EXPECT_EQ(c.ok, 1u);
  EXPECT_EQ(c.failed, 1u);
  std::ifstream in(dir / "points.csv");
  const std::string csv((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(csv,
            "index,bound,K,json_bound,enclosure_lo,enclosure_hi,exit,error\n"
            "0,1,7,0.5,0.4,0.6,0,\n"
            "1,1/3,7,,,,2,\"bad, \"\"quoted\"\"\"\n");
  fs::remove_all(dir);
}

// A received shard is untrusted: a record's text that a spreadsheet would evaluate (= + - @, tab)
// reaches points.csv neutralised by report::csv::cell (issue 40), in every column the record
// fills (a JSON value, the exit code, the error), while numbers -- "-0.5", "-1/3", "-inf" -- stay
// numbers.
TEST(Table, FormulaCellsOfAReceivedShardAreNeutralised) {
  const fs::path dir = unique_dir("formula");
  const Spec s = parse_spec(head + "bound = { values = [\"1\", \"2\", \"3\"] }\n", "s.toml");
  {
    std::ofstream f(dir / "shard.txt");
    f << record_line(0, {{"exit", 0}, {"json", {{"note", "=HYPERLINK(\"http://x\",\"y\")"}, {"lo", "-0.5"}, {"hi", "-inf"}}}})
      << "\n"
      << record_line(1, {{"exit", "@SUM(A1)"}, {"json", {{"note", "+cmd"}, {"lo", "-1/3"}, {"hi", "\tx"}}}}) << "\n"
      << record_line(2, {{"exit", 2}, {"error", "-2+3+cmd|' /C calc'!A0"}}) << "\n";
  }
  RecordStore store(PointRange::shard_of(s.points, 0, 1));
  store.add_file(dir / "shard.txt");
  write_table(s, store, dir);
  std::ifstream in(dir / "points.csv");
  const std::string csv((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(csv,
            "index,bound,hi,lo,note,exit,error\n"  // the record's keys in JSON (sorted) order
            "0,1,-inf,-0.5,\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\",0,\n"
            "1,2,'\tx,-1/3,'+cmd,'@SUM(A1),\n"
            "2,3,,,,2,'-2+3+cmd|' /C calc'!A0\n");
  fs::remove_all(dir);
}

// ---- untrusted input ----------------------------------------------------------------------
// Sweep specs are untrusted (docs/security.md; issue 32): the number of points is counted from the
// axes' sizes before any value is generated, every exact value has a bounded size, exact values
// are written in time linear in their size, and a spec deeper than toml++ can take is refused
// before toml++ sees it.

// Two random axes of 10^7 values were generated in full (1.5 GB) before the product was checked.
TEST(SpecLimits, PointsAreCountedBeforeAnyValueIsGenerated) {
  const std::string msg = error_of(head + "K = { random = 10000000, from = \"0\", to = \"1\", seed = 1 }\n"
                                          "B = { random = 10000000, from = \"0\", to = \"1\", seed = 2 }\n");
  EXPECT_NE(msg.find("s.toml: axes.B: the axes up to this one make 100000000000000 points, more than the limit of "
                     "10^9 (nothing was generated)"),
            std::string::npos)
      << msg;
  // a values list, a linear and a random axis are counted alike
  EXPECT_NE(error_of(head + "K = { values = [\"1\", \"2\"] }\nB = { from = \"0\", to = \"1\", points = 10000000 }\n"
                            "C = { random = 100, from = \"0\", to = \"1\", seed = 1 }\n")
                .find("axes.C: the axes up to this one make 2000000000 points"),
            std::string::npos);
}

// "1e-200000" is 9 bytes of spec and 660,000 bits: a 150-byte spec parsed for more than 55 s.
TEST(SpecLimits, EveryExactValueHasABoundedSize) {
  for (const std::string& axis : {std::string("K = { from = \"0\", to = \"1e-200000\", points = 3 }"),
                                  std::string("K = { values = [\"1\", \"1e-200000\"] }"),
                                  std::string("K = { random = 3, from = \"1e200000\", to = \"1\", seed = 1 }")}) {
    const std::string msg = error_of(head + axis + "\n");
    EXPECT_NE(msg.find("s.toml: axes.K."), std::string::npos) << msg;
    EXPECT_NE(msg.find("bits of numerator and denominator, more than the limit of 1024"), std::string::npos) << msg;
  }
  // 300 digits pass
  const Spec s = parse_spec(head + "K = { from = \"0\", to = \"1e-300\", points = 3 }\n", "s.toml");
  EXPECT_EQ(s.axes[0].values[2], "0." + std::string(299, '0') + "1");
}

// exact_text finds the powers of 2 and 5 of the denominator by GMP's valuations and writes the
// decimal at once: the loops it replaces were quadratic in the size of the denominator.
TEST(SpecLimits, ExactTextOfLargeDenominators) {
  using boost::multiprecision::pow;
  const rational tiny(integer(3), pow(integer(10), 200000));  // 3e-200000
  const std::string t = exact_text(tiny);
  EXPECT_EQ(t.size(), 200002u);  // "0." and 200000 digits
  EXPECT_EQ(t.substr(0, 4), "0.00");
  EXPECT_EQ(t.back(), '3');
  EXPECT_EQ(exact_text(rational(integer(-7), pow(integer(2), 5000))).size(), 5003u);  // -0.<5000 digits>
  EXPECT_EQ(exact_text(rational(integer(1), pow(integer(5), 3) * pow(integer(2), 7))), "0.0000625");
  EXPECT_EQ(exact_text(rational(integer(1), pow(integer(5), 4000) * 3)).find('/'), 1u);  // not terminating: p/q
  EXPECT_EQ(exact_text(rational(-3, 40)), "-0.075");
}

TEST(SpecLimits, DeepTablesAreRefusedBeforeToml) {
  std::string deep = "a";
  for (int i = 0; i < 50000; ++i) deep += ".a";
  const std::string msg = error_of(head + "K = { values = [\"1\"] }\n[" + deep + "]\n");
  EXPECT_NE(msg.find("s.toml:7: a key or table nested 50001 levels deep"), std::string::npos) << msg;
}

// ---- run_threads (study/threads.hpp): Python's vectorised calls ---------------------------------


TEST(StudyThreads, EveryPointRunsOnceWhateverTheThreads) {
  constexpr uint64_t n = 100000;
  for (unsigned jobs : {1u, 2u, 3u, 8u}) {
    std::vector<std::atomic<int>> hits(n);
    EXPECT_TRUE(hapstab::study::run_threads(n, jobs, [&](uint64_t i) { hits[i].fetch_add(1); }));
    for (uint64_t i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 1) << "jobs " << jobs << " point " << i;
  }
  EXPECT_TRUE(hapstab::study::run_threads(0, 2, [](uint64_t) { FAIL(); }));
}

TEST(StudyThreads, PollStopsTheRunAndAnEscapingErrorIsRethrown) {
  std::atomic<uint64_t> ran{0};
  const bool finished = hapstab::study::run_threads(
      1000000, 2,
      [&](uint64_t) {
        ++ran;
        std::this_thread::sleep_for(std::chrono::microseconds(50));
      },
      [] { return true; }, 1);
  EXPECT_FALSE(finished);
  EXPECT_LT(ran.load(), 1000000u);  // stopped after the points in progress, not run to the end
  EXPECT_THROW(hapstab::study::run_threads(100, 2, [](uint64_t i) {
                 if (i == 50) throw std::runtime_error("point 50");
               }),
               std::runtime_error);
}
