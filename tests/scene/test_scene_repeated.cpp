// Repeated blocks in scene files (docs/scene.md "Repeated blocks"; scene/reader.hpp table_copies,
// Reader::expand; scene.cpp expand_matrix): a table with count = n is its n copies, list
// parameters are indexed from 1 and summed exactly, an environment given by its diagonal and
// off-diagonal entries is the matrix written out; every wrong count or length is refused by name.
// The reference each time is the same scene written out by hand (no count, no list, full tf).
#include "hapstab_paths.hpp"  // HAPSTAB_SOURCE_DIR
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "hapstab/lti/realization.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/scene.hpp"
#include "scene/scene_text.hpp"

// Its own namespace: the module's tests compile in unity batches (tests/CMakeLists.txt),
// and other files of the batch define helpers of the same names.
namespace test_scene_repeated {

using namespace hapstab;
using hapstab::scene::parse_scene;
using scene_test::error_of;
using scene_test::replace;

namespace {

const std::string kHead = "[scene]\nT = \"1/100\"\n";

// Three devices, three operators, a 3 x 3 environment: compact ...
const std::string kCompact = kHead + R"TOML(
[parameters]
kc = ["500", "600", "7/2*200"]
w = ["1", "2", "3"]
[[device]]
count = 3
name = "d"
m = "w[i]/10"
b = "1.37"
[[operator]]
count = 3
name = "H"
dofs = "d[i]"
tf = "w[i]*(s + 1)/(s + 2)"
[environment]
domain = "s"
method = "backward_euler"
diagonal = "kc[i] + s - kc[i]^2/(s + sum(kc))"
off_diagonal = "-kc[i]*kc[j]/(s + sum(kc))"
)TOML";

// ... and written out.
std::string written() {
  const char* k[] = {"500", "600", "700"};
  std::ostringstream o;
  o << kHead;
  for (int i = 1; i <= 3; ++i) o << "[[device]]\nname = \"d[" << i << "]\"\nm = \"" << i << "/10\"\nb = \"1.37\"\n";
  for (int i = 1; i <= 3; ++i)
    o << "[[operator]]\nname = \"H[" << i << "]\"\ndofs = \"d[" << i << "]\"\ntf = \"" << i << "*(s + 1)/(s + 2)\"\n";
  o << "[environment]\ndomain = \"s\"\nmethod = \"backward_euler\"\ntf = [";
  for (int i = 0; i < 3; ++i) {
    o << (i ? ", [" : "[");
    for (int j = 0; j < 3; ++j)
      o << (j ? ", " : "") << "\"" << (i == j ? std::string(k[i]) + " + s - " + k[i] + "^2/(s + 1800)"
                                              : std::string("-") + k[i] + "*" + k[j] + "/(s + 1800)") << "\"";
    o << "]";
  }
  o << "]\n";
  return o.str();
}

bool same_tf(const StateSpace<rational>& a, const StateSpace<rational>& b) {
  const auto ta = ss2tf(a), tb = ss2tf(b);
  if (ta.outputs() != tb.outputs() || ta.inputs() != tb.inputs()) return false;
  for (size_t i = 0; i < ta.outputs(); ++i)
    for (size_t j = 0; j < ta.inputs(); ++j) {
      const auto x = ta(i, j), y = tb(i, j);
      if (!(x.num() * y.den() == y.num() * x.den())) return false;
    }
  return true;
}

}  // namespace

TEST(SceneRepeated, CountIsTheWrittenOutScene) {
  const auto c = parse_scene(kCompact, "c.toml"), w = parse_scene(written(), "w.toml");
  ASSERT_EQ(c.loop.devices.size(), 3u);
  ASSERT_EQ(c.loop.operators.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(c.loop.devices[i].name, "d[" + std::to_string(i + 1) + "]");
    EXPECT_EQ(c.loop.devices[i].name, w.loop.devices[i].name);
    EXPECT_EQ(c.loop.devices[i].G.A, w.loop.devices[i].G.A);
    EXPECT_EQ(c.loop.devices[i].G.B, w.loop.devices[i].G.B);
    EXPECT_EQ(c.loop.operators[i].name, w.loop.operators[i].name);
    EXPECT_EQ(c.loop.operators[i].ports, std::vector<int>{int(i)});
    EXPECT_TRUE(same_tf(c.loop.operators[i].Z, w.loop.operators[i].Z)) << i;
  }
  EXPECT_EQ(c.loop.devices[2].G.B(0, 0), rational(10, 3));  // 1/m with m = w[3]/10 = 3/10
  ASSERT_TRUE(c.loop.environment && w.loop.environment);
  EXPECT_TRUE(same_tf(*c.loop.environment, *w.loop.environment));
  EXPECT_EQ(c.loop.environment->D, w.loop.environment->D);
}

// A copy's name may be a pattern; later sections refer to copies by name; other tables keep their place.
TEST(SceneRepeated, NamesPatternsAndOrder) {
  const std::string text = kHead + R"TOML(
[[device]]
name = "first"
m = "1"
[[device]]
count = 2
name = "finger[i].pad"
m = "1"
[[device]]
name = "last"
m = "1"
[[operator]]
name = "all"
dofs = ["first", "finger[1].pad", "finger[2].pad", "last"]
tf = [["1", "0", "0", "0"], ["0", "1", "0", "0"], ["0", "0", "1", "0"], ["0", "0", "0", "1"]]
)TOML";
  const auto sc = parse_scene(text, "s.toml");
  ASSERT_EQ(sc.loop.devices.size(), 4u);
  EXPECT_EQ(sc.loop.devices[0].name, "first");
  EXPECT_EQ(sc.loop.devices[1].name, "finger[1].pad");
  EXPECT_EQ(sc.loop.devices[2].name, "finger[2].pad");
  EXPECT_EQ(sc.loop.devices[3].name, "last");
  EXPECT_EQ(sc.loop.operators[0].ports, (std::vector<int>{0, 1, 2, 3}));
}

TEST(SceneRepeated, ListParametersAreExact) {
  const auto sc = parse_scene(kHead + "[parameters]\na = \"1/3\"\nv = [\"a\", \"2*a\", \"1/7\"]\nt = \"sum(v) + v[2]\"\n"
                              "[[device]]\nname = \"d\"\nm = \"v[3]\"\n", "s.toml");
  EXPECT_EQ(sc.parameters.at("t"), rational(1) + rational(1, 7) + rational(2, 3));
  EXPECT_EQ(sc.loop.devices[0].G.B(0, 0), rational(7));  // 1/m, m = 1/7
  EXPECT_EQ(sc.parameters.count("v"), 0u);  // a list is not a scalar parameter
}

// A list said once with `repeat` is the list written out; a compact matrix over classes of DOFs
// (entries parsed once per class pair, Reader::compact_block) realises exactly what the matrix
// written out does (tf2ss column by column: the same A, B, C, D entry for entry).
TEST(SceneRepeated, RepeatedListsAndClassesAreTheWrittenOutScene) {
  const std::string body = R"TOML(
[[device]]
count = 6
name = "d"
m = "1/10"
b = "1"
[environment]
domain = "s"
method = "backward_euler"
diagonal = "kc[i] + s - kc[i]^2/(s + sum(kc))"
off_diagonal = "-kc[i]*kc[j]/(s + 1/2*kc[j] + sum(kc))"
)TOML";
  const auto rep = parse_scene(kHead + "[parameters]\nkc = { repeat = [\"500\", \"3/2\", \"500\"], times = 2 }\n" + body, "r.toml");
  const auto listed = parse_scene(kHead + "[parameters]\nkc = [\"500\", \"3/2\", \"500\", \"500\", \"3/2\", \"500\"]\n" + body, "l.toml");
  std::ostringstream o;  // the same matrix written out entry by entry, the values in place
  const char* k[] = {"500", "3/2", "500", "500", "3/2", "500"};
  o << kHead << body.substr(0, body.find("diagonal")) << "tf = [";
  for (int i = 0; i < 6; ++i) {
    o << (i ? ", [" : "[");
    for (int j = 0; j < 6; ++j)
      o << (j ? ", " : "") << "\""
        << (i == j ? std::string(k[i]) + " + s - (" + k[i] + ")^2/(s + 2003)"
                   : "-(" + std::string(k[i]) + ")*(" + k[j] + ")/(s + 1/2*(" + k[j] + ") + 2003)")
        << "\"";
    o << "]";
  }
  o << "]\n";
  const auto out = parse_scene(o.str(), "w.toml");
  for (const auto* sc : {&listed, &out}) {
    ASSERT_TRUE(rep.loop.environment && sc->loop.environment);
    EXPECT_EQ(rep.loop.environment->A, sc->loop.environment->A);
    EXPECT_EQ(rep.loop.environment->B, sc->loop.environment->B);
    EXPECT_EQ(rep.loop.environment->C, sc->loop.environment->C);
    EXPECT_EQ(rep.loop.environment->D, sc->loop.environment->D);
  }
  EXPECT_EQ(rep.lists.at("kc"), listed.lists.at("kc"));
  // wrong repeated lists, by name
  const auto bad = [&](const std::string& list, const std::string& what) {
    const std::string e = error_of(kHead + "[parameters]\nkc = " + list + "\n" + body);
    EXPECT_NE(e.find(what), std::string::npos) << list << ": " << e;
  };
  bad("{ repeat = [\"1\", \"2\"], times = 0 }", "parameters.kc.times: missing or not a whole number >= 1");
  bad("{ repeat = [\"1\", \"2\"] }", "parameters.kc.times: missing or not a whole number >= 1");
  bad("{ repeat = [\"1\", \"2\"], times = 2 }", "'kc[i]' indexes the list parameter kc of 4 values");
  bad("{ repeat = [\"1\", \"2\"], times = 3, each = 1 }", "parameters.kc.each: not a key of a repeated list");
  bad("{ repeat = [\"1\", \"x\"], times = 3 }", "parameters.kc.repeat[2]");
  bad("{ repeat = [\"1\", \"2\"], times = 3000 }", "more than the limit of 4096 values");
  bad("{ times = 3 }", "parameters.kc.repeat: missing or not an array");
  // blocks = K: K diagonal blocks, entries between them 0 (the matrix written out with "0" there)
  const std::string two = kHead + "[parameters]\nkc = [\"1\", \"2\", \"3\", \"4\"]\n[[device]]\ncount = 4\nname = \"d\"\nm = \"1\"\n"
                          "[environment]\ndiagonal = \"kc[i]\"\noff_diagonal = \"-kc[i]*kc[j]/10\"\n";
  const auto blocked = parse_scene(two + "blocks = 2\n", "b.toml");
  ASSERT_TRUE(blocked.loop.environment);
  const MatQ& D = blocked.loop.environment->D;
  EXPECT_EQ(D(0, 1), rational(-2, 10));
  EXPECT_EQ(D(2, 3), rational(-12, 10));
  EXPECT_EQ(D(0, 2), rational(0));
  EXPECT_EQ(D(3, 1), rational(0));
  EXPECT_EQ(D(1, 1), rational(2));
  for (const char* k : {"3", "0", "\"2\"", "5"}) {
    const std::string e = error_of(two + "blocks = " + k + "\n");
    EXPECT_NE(e.find("environment.blocks: expected a whole number K >= 1 that divides the 4 DOFs"), std::string::npos) << k << ": " << e;
  }
  const std::string lone = error_of(kHead + "[[device]]\nname = \"d\"\nm = \"1\"\n[environment]\ntf = \"1\"\nblocks = 1\n");
  EXPECT_NE(lone.find("environment.blocks: only with diagonal"), std::string::npos) << lone;
}

TEST(SceneRepeated, WrongCountsAreRefusedByName) {
  const std::string dev = "[[device]]\nname = \"d\"\nm = \"1\"\n";
  struct Case {
    std::string count, expected;
  };
  for (const auto& c : std::vector<Case>{
           {"count = 0", "s.toml: device[0].count: 0 copies: a repeated table needs count >= 1"},
           {"count = -3", "s.toml: device[0].count: -3 copies: a repeated table needs count >= 1"},
           {"count = 2.5", "s.toml: device[0].count: expected a whole number of copies (a TOML integer such as 128), got a float"},
           {"count = 4.0", "got a float"},
           {"count = \"4\"", "got a string"},
           {"count = 4097", "s.toml: device[0].count: 4097 copies, more than the limit of 4096"}}) {
    const std::string msg = error_of(kHead + dev + c.count + "\n");
    EXPECT_NE(msg.find(c.expected), std::string::npos) << c.count << ": " << msg;
  }
  const std::string unnamed = error_of(kHead + "[[device]]\ncount = 2\nm = \"1\"\n");
  EXPECT_NE(unnamed.find("s.toml: device[0].name: a table with count needs a name"), std::string::npos) << unnamed;
  const std::string op = error_of(kHead + dev + "[[operator]]\ncount = 0\nname = \"H\"\nm = \"1\"\n");
  EXPECT_NE(op.find("s.toml: operator[0].count: 0 copies"), std::string::npos) << op;
  const std::string input = error_of(kHead + dev + "[[input]]\ntype = \"bias\"\ncount = 2\nforce = \"1\"\n");
  EXPECT_NE(input.find("unknown key input[0].count"), std::string::npos) << input;  // inputs are not repeated
}

TEST(SceneRepeated, WrongLengthsAndIndicesAreRefusedByName) {
  const std::string longer = error_of(replace(kCompact, "w = [\"1\", \"2\", \"3\"]", "w = [\"1\", \"2\", \"3\", \"4\"]"));
  EXPECT_NE(longer.find("s.toml: device[0]: 'w[i]' indexes the list parameter w of 4 values by a copy number, but count = 3"),
            std::string::npos) << longer;
  const std::string shorter = error_of(replace(kCompact, "kc = [\"500\", \"600\", \"7/2*200\"]", "kc = [\"500\", \"600\"]"));
  EXPECT_NE(shorter.find("s.toml: environment.diagonal: 'kc[i]' indexes the list parameter kc of 2 values by a row or "
                         "column, but the matrix is 3 x 3"), std::string::npos) << shorter;
  const std::string beyond = error_of(kHead + "[parameters]\nv = [\"1\", \"2\"]\n[[device]]\nname = \"d\"\nm = \"v[3]\"\n");
  EXPECT_NE(beyond.find("s.toml: device[0].m: 'v[3]': the list parameter v has 2 values, numbered v[1] .. v[2]"),
            std::string::npos) << beyond;
  const std::string zero = error_of(kHead + "[parameters]\nv = [\"1\", \"2\"]\n[[device]]\nname = \"d\"\nm = \"v[0]\"\n");
  EXPECT_NE(zero.find("'v[0]': the list parameter v has 2 values"), std::string::npos) << zero;
  const std::string bare = error_of(kHead + "[parameters]\nv = [\"1\", \"2\"]\n[[device]]\nname = \"d\"\nm = \"v\"\n");
  EXPECT_NE(bare.find("s.toml: device[0].m: 'v' is a list parameter: write v[k]"), std::string::npos) << bare;
  const std::string outside = error_of(kHead + "[parameters]\nv = [\"1\"]\n[[device]]\nname = \"d\"\nm = \"v[i]\"\n");
  EXPECT_NE(outside.find("s.toml: device[0].m: 'v[i]': [i] is a copy's number, meaningful only in a table with count"),
            std::string::npos) << outside;
  const std::string scalar = error_of(kHead + "[parameters]\nv = \"1\"\n[[device]]\nname = \"d\"\nm = \"v[1]\"\n");
  EXPECT_NE(scalar.find("'v[1]': v is not a list parameter"), std::string::npos) << scalar;
  const std::string empty = error_of(kHead + "[parameters]\nv = []\n[[device]]\nname = \"d\"\nm = \"1\"\n");
  EXPECT_NE(empty.find("s.toml: parameters.v: an empty list"), std::string::npos) << empty;
  const std::string bad = error_of(kHead + "[parameters]\nv = [\"1\", \"x\"]\n[[device]]\nname = \"d\"\nm = \"1\"\n");
  EXPECT_NE(bad.find("s.toml: parameters.v[2]"), std::string::npos) << bad;
  try {
    parse_scene(kCompact, "s.toml", {{"kc", rational(1)}});
    ADD_FAILURE() << "--set of a list accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("parameters.kc: --set gives one value, but kc is a list parameter"), std::string::npos)
        << e.what();
  }
  const std::string both = error_of(replace(kCompact, "method = \"backward_euler\"", "method = \"backward_euler\"\ntf = \"1\""));
  EXPECT_NE(both.find("s.toml: environment.diagonal: give either diagonal (and off_diagonal) or tf/ss, not both"),
            std::string::npos) << both;
  // a 3 KB scene may not stand for a matrix larger than the exact realisation may hold
  const std::string huge = error_of(kHead + "[[device]]\ncount = 4096\nname = \"d\"\nm = \"1\"\n[environment]\n"
                                    "diagonal = \"1/z\"\noff_diagonal = \"1 + 1 + 1 + 1\"\n");
  EXPECT_NE(huge.find("s.toml: environment.diagonal: realised column by column, the 4096 x 4096 matrix has 4096 states and "
                      "4096 inputs, more than the limit of 4096 states and inputs together"), std::string::npos) << huge;
  const auto spaced = parse_scene(kHead + "[parameters]\nv = [\"1\", \"2\"]\n[[device]]\nname = \"d\"\nm = \"sum( v )\"\n", "s.toml");
  EXPECT_EQ(spaced.loop.devices[0].G.B(0, 0), rational(1, 3));
  const std::string column = error_of(replace(kCompact, "diagonal = \"kc[i] + s", "diagonal = \"kc[j] + s"));
  EXPECT_NE(column.find("environment.diagonal: [j] (the column) is [i] on the diagonal"), std::string::npos) << column;
}

// docs/scene.md shows a compact scene: it parses, and it is the matrix it says.
TEST(SceneRepeated, DocsExampleParses) {
  std::ifstream in(std::filesystem::path(HAPSTAB_SOURCE_DIR) / "docs" / "scene.md");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  const size_t at = doc.find("## Repeated blocks");
  ASSERT_NE(at, std::string::npos);
  const size_t from = doc.find("```toml\n", at), to = doc.find("```\n", from + 8);
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  const auto sc = parse_scene(doc.substr(from + 8, to - from - 8), "docs/scene.md");
  ASSERT_EQ(sc.loop.devices.size(), 4u);
  EXPECT_EQ(sc.loop.devices[3].name, "d[4]");
  EXPECT_EQ(sc.loop.operators[3].ports, std::vector<int>{3});
  ASSERT_TRUE(sc.loop.environment);
  EXPECT_EQ(sc.loop.environment->inputs(), 4);
  // E at z = 1 (s = 0): diag(kc) - kc kc^T / (k + sum kc) = diag(kc) - kc kc^T / 3600
  const auto E = ss2tf(*sc.loop.environment);
  const rational kc[] = {500, 600, 700, 800};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const auto& e = E(size_t(i), size_t(j));
      const rational at1 = e.num()(rational(1)) / e.den()(rational(1));
      EXPECT_EQ(at1, (i == j ? kc[i] : rational(0)) - kc[i] * kc[j] / 3600) << i << "," << j;
    }
}

}  // namespace test_scene_repeated
