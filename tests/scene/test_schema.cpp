// The scene schema (scene/schema.hpp, issue 29): every section and key declared once; unknown
// names at any depth refused with file:line and the nearest valid name; values of the wrong
// TOML form refused instead of silently defaulted; each command refuses what it does not model;
// docs/scene.md is the generated text; every scene the project ships still loads.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/scene.hpp"
#include "hapstab/scene/schema.hpp"

using namespace hapstab;
namespace fs = std::filesystem;

namespace {

const std::string kDir = std::string(HAPSTAB_SOURCE_DIR) + "/tests/scene/data/";

std::string read(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string load_error(const std::string& path) {
  try {
    scene::load_scene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string error_of(const std::string& text) {
  try {
    scene::parse_scene(text, "s.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string command_error(const std::string& path, const std::string& command) {
  const auto sc = scene::load_scene(path);
  try {
    scene::check_command(sc.root, path, command);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replace_first(std::string s, const std::string& a, const std::string& b) {
  const auto p = s.find(a);
  EXPECT_NE(p, std::string::npos) << a;
  return p == std::string::npos ? s : s.replace(p, a.size(), b);
}

// The one-DOF wall of issue 29 (the scene files' common part, without their comment line).
const std::string kWall = [] {
  const std::string s = read(kDir + "multidof_ops.toml");
  const auto from = s.find("[scene]");
  return s.substr(from, s.find("\n[multidof]") + 1 - from);
}();

}  // namespace

// The situations of issue 29: a misspelled name changed nothing and said nothing.
TEST(SceneSchema, MisspelledNamesAreRefusedWithLineAndNearestName) {
  struct Case {
    std::string file, message;
  };
  const std::vector<Case> cases = {
      {"misspelled_delays.toml", "misspelled_delays.toml:31: unknown section [delays]; did you mean [delay]?"},
      {"misspelled_passivity_controler.toml",
       "misspelled_passivity_controler.toml:31: unknown section [passivity_controler]; did you mean [passivity_controller]?"},
      {"bias_wall_contacts.toml", "bias_wall_contacts.toml:41: unknown section [contacts]; did you mean [contact]?"},
      {"multidof_ops.toml", "multidof_ops.toml:32: unknown key multidof.ops; did you mean multidof.osp?"},
      {"multidof_misspelled_subtable.toml",
       "multidof_misspelled_subtable.toml:34: unknown section [multidof.coupl]; did you mean [multidof.coupling]?"},
      {"misspelled_input_field.toml", "misspelled_input_field.toml:27: unknown key input[0].tme; did you mean input[0].time?"},
  };
  for (const auto& c : cases) {
    const std::string msg = load_error(kDir + c.file);
    EXPECT_NE(msg.find(c.message), std::string::npos) << c.file << ": " << msg;
  }
}

TEST(SceneSchema, UnknownNamesAtEveryDepth) {
  struct Case {
    std::string add, message;
  };
  const std::vector<Case> cases = {
      {"[[devices]]\nm = \"1\"\n", "unknown section [[devices]]; did you mean [[device]]?"},
      {"[reproduce]\nsimulate = { diverged_typo = false }\n",
       "unknown key reproduce.simulate.diverged_typo; did you mean reproduce.simulate.diverged?"},
      {"[reproduce]\nanalyse = { feasible = true }\n", "unknown key reproduce.analyse; did you mean reproduce.analyze?"},
      {"[reproduce]\nanalyze = { feasable = true }\n", "unknown key reproduce.analyze.feasable; did you mean reproduce.analyze.feasible?"},
      {"[coupling]\ntf = \"1/1000\"\nmethd = \"tustin\"\n", "unknown key coupling.methd; did you mean coupling.method?"},
      {"[wedge]\nx = 1\n", "unknown section [wedge]"},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(kWall + c.add);
    EXPECT_NE(msg.find(c.message), std::string::npos) << c.add << ": " << msg;
    EXPECT_EQ(msg.rfind("s.toml:", 0), 0u) << msg;  // file:line first
  }
  // a key of the wrong input type; a block's ss; a key at top level
  EXPECT_NE(error_of(kWall + "[[input]]\ntype = \"bias\"\nforce = \"1\"\nmagnitude = \"1\"\n")
                .find("unknown key input[1].magnitude for type = \"bias\""),
            std::string::npos);
  const std::string ss = error_of(replace_first(kWall, "b = \"2\"", "ss = { A = [], B = [], C = [], D = [[\"2\"]], E = [] }"));
  EXPECT_NE(ss.find("unknown key operator[0].ss.E"), std::string::npos) << ss;
  const std::string top = error_of("T = \"1/1000\"\n" + kWall);
  EXPECT_NE(top.find("s.toml:1: unknown top-level key T; keys belong in a section (T is a key of [scene])"),
            std::string::npos)
      << top;
}

// Values a reader took with a default when their form was wrong are refused.
TEST(SceneSchema, ValuesOfTheWrongFormAreRefused) {
  struct Case {
    std::string add, message;
  };
  const std::vector<Case> cases = {
      {"[multidof]\nqv_block_diagonal = \"true\"\n", "multidof.qv_block_diagonal: expected true or false, got a string"},
      {"[multidof]\nosp = \"16\"\n", "multidof.osp: expected a list of exact numbers"},
      {"[multidof]\nperturb_C = \"1\"\n", "multidof.perturb_C: expected a matrix"},
      {"[multidof.coupling]\nmbar = 1\n", "multidof.coupling.mbar: expected a list of integers, got an integer"},
      {"[reproduce]\npaper = 1\n", "reproduce.paper: expected a string, got an integer"},
      {"[reproduce]\nsimulate = { diverged = [] }\n", "reproduce.simulate.diverged: expected true/false"},
  };
  for (const auto& c : cases) {
    const std::string msg = error_of(kWall + c.add);
    EXPECT_NE(msg.find(c.message), std::string::npos) << c.add << ": " << msg;
  }
  // [simulate] energy = "no" was read as the default (true)
  const std::string e = error_of(replace_first(kWall, "duration = \"1/2\"", "duration = \"1/2\"\nenergy = \"no\""));
  EXPECT_NE(e.find("simulate.energy: expected true or false, got a string"), std::string::npos) << e;
  const std::string p = error_of(replace_first(kWall, "b = \"2\"", "b = \"2\"\npassive = \"false\""));
  EXPECT_NE(p.find("operator[0].passive: expected true or false"), std::string::npos) << p;
}

// [multidof] as the schema's typed values (scene::multidof_values, read by multidof analyze|design):
// exact numbers mean what they mean for every other key (a fraction, a decimal, an integer, an
// expression of T and the parameters), and a value that is none is refused naming the entry.
TEST(SceneSchema, MultidofValuesAreTyped) {
  const auto values = [](const std::string& add) { return scene::multidof_values(scene::parse_scene(kWall + add, "s.toml")); };
  const auto none = values("");
  EXPECT_FALSE(none.osp || none.perturb_C);
  EXPECT_FALSE(none.qv_block_diagonal);
  EXPECT_TRUE(none.mbar.empty() && none.nbar.empty());
  const auto v = values(
      "[multidof]\nosp = [\"137/100\"]\nperturb_C = [[\"1/2\", 3], [\"-0.25\", \"B/K\"]]\nqv_block_diagonal = true\n"
      "[multidof.coupling]\nmbar = [1]\nnbar = [2]\n");
  ASSERT_TRUE(v.osp && v.perturb_C);
  EXPECT_EQ(*v.osp, std::vector<rational>{rational(137, 100)});
  const std::vector<std::vector<rational>> pc{{rational(1, 2), rational(3)}, {rational(-1, 4), rational(1, 4000)}};
  EXPECT_EQ(*v.perturb_C, pc);  // rows as written (the caller checks N x N); B/K = 5/20000 from [parameters]
  EXPECT_TRUE(v.qv_block_diagonal);
  EXPECT_EQ(v.mbar, std::vector<int>{1});
  EXPECT_EQ(v.nbar, std::vector<int>{2});
  EXPECT_EQ(*values("[multidof]\nosp = [\"2*T*K\"]\n").osp, std::vector<rational>{rational(40)});  // T = 1/1000
  const auto error = [&](const std::string& add) {
    try {
      values(add);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  struct Case {
    std::string add, message;
  };
  const std::vector<Case> cases = {
      {"[multidof]\nosp = [\"1\", \"abc\"]\n", "s.toml: multidof.osp[1]: "},
      {"[multidof]\nosp = [\"s + 1\"]\n", "s.toml: multidof.osp[0]: 's + 1' must be a constant"},
      {"[multidof]\nperturb_C = [[\"1\"], [\"1/0\"]]\n", "s.toml: multidof.perturb_C[1][0]: "},
      {"[multidof.coupling]\nnbar = [1, 2000000]\n", "s.toml: multidof.coupling.nbar[1]: 2000000 is out of range"},
  };
  for (const auto& c : cases) {
    const std::string msg = error(c.add);
    EXPECT_EQ(msg.rfind(c.message, 0), 0u) << c.add << ": " << msg;
  }
}

// Each command refuses, by name, a part of the scene it does not model, and names the command that does.
TEST(SceneSchema, CommandsRefuseWhatTheyDoNotModel) {
  const std::string contact = command_error(kDir + "multidof_contact.toml", "multidof analyze");
  EXPECT_NE(contact.find("multidof_contact.toml:31: multidof analyze does not model [contact] (a unilateral wall"),
            std::string::npos)
      << contact;
  EXPECT_NE(contact.find("`hapstab simulate` does"), std::string::npos) << contact;
  EXPECT_NE(command_error(kDir + "multidof_contact.toml", "multidof design").find("multidof design does not model [contact]"),
            std::string::npos);
  EXPECT_EQ(command_error(kDir + "multidof_contact.toml", "simulate"), "");
  // friction, quantization and the passivity controller are the simulator's only
  const std::string dev = "m = \"1/10\"\nb = \"16\"";
  for (const auto& [add, part] : std::vector<std::pair<std::string, std::string>>{
           {dev + "\ncoulomb = \"1/10\"", "[[device]] coulomb"},
           {dev + "\nquantum = \"1/4096\"", "[[device]] quantum, quantizer"}}) {
    const std::string text = replace_first(kWall, dev, add);
    const auto sc = scene::parse_scene(text, "s.toml");
    for (const char* cmd : {"multidof analyze", "multidof design"}) {
      try {
        scene::check_command(sc.root, "s.toml", cmd);
        ADD_FAILURE() << cmd << " took " << part;
      } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(std::string(cmd) + " does not model " + part), std::string::npos) << e.what();
      }
    }
    EXPECT_NO_THROW(scene::check_command(sc.root, "s.toml", "simulate"));
  }
  const auto pc = scene::parse_scene(kWall + "[passivity_controller]\ndofs = [\"haptic\"]\n", "s.toml");
  EXPECT_THROW(scene::check_command(pc.root, "s.toml", "multidof analyze"), InputError);
  // Sec. VI's perturbed environment: the simulator would run the unperturbed one
  const std::string perturbed = std::string(HAPSTAB_SOURCE_DIR) + "/examples/multidof_case_i_perturbed.toml";
  const std::string sim = command_error(perturbed, "simulate");
  EXPECT_NE(sim.find("simulate does not model multidof.perturb_C"), std::string::npos) << sim;
  EXPECT_NE(sim.find("`hapstab multidof analyze` and `hapstab multidof design` do"), std::string::npos) << sim;
  EXPECT_EQ(command_error(perturbed, "multidof analyze"), "");
  // sections that configure another command, and excitations, are not part of multidof's model
  EXPECT_EQ(command_error(std::string(HAPSTAB_SOURCE_DIR) + "/examples/multidof_case_ii_nominal.toml", "multidof analyze"), "");
}

// Every scene the project ships loads, and every command it is run with models all of it.
TEST(SceneSchema, ShippedScenesLoad) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(std::string(HAPSTAB_SOURCE_DIR) + "/examples")) {
    if (e.path().extension() != ".toml") continue;
    ++n;
    const auto sc = scene::load_scene(e.path().string());
    if (sc.root.contains("multidof"))
      for (const char* cmd : {"multidof analyze", "multidof design"}) EXPECT_NO_THROW(scene::check_command(sc.root, e.path().string(), cmd));
    else
      EXPECT_NO_THROW(scene::check_command(sc.root, e.path().string(), "simulate")) << e.path();
  }
  EXPECT_GE(n, 10);
  // the fuzzer's seed (its profile file is not there: names and types only)
  const std::string seed = std::string(HAPSTAB_SOURCE_DIR) + "/tests/fuzz/seeds_scene/profile.toml";
  EXPECT_NO_THROW(scene::check_schema(toml::parse_file(seed), seed));
}

TEST(SceneSchema, EditDistanceCountsTranspositionsOnce) {
  EXPECT_EQ(scene::edit_distance("ops", "osp"), 1u);
  EXPECT_EQ(scene::edit_distance("contacts", "contact"), 1u);
  EXPECT_EQ(scene::edit_distance("", "abc"), 3u);
  EXPECT_EQ(scene::edit_distance("kitten", "sitting"), 3u);
}

// docs/scene.md is generated from the schema; HAPSTAB_WRITE_DOCS=1 rewrites it.
TEST(SceneSchema, DocsSceneMdIsGenerated) {
  const fs::path doc = fs::path(HAPSTAB_SOURCE_DIR) / "docs" / "scene.md";
  const std::string text = scene::schema_markdown();
  if (std::getenv("HAPSTAB_WRITE_DOCS")) std::ofstream(doc) << text;
  EXPECT_EQ(read(doc), text) << "docs/scene.md is not the generated text; regenerate with HAPSTAB_WRITE_DOCS=1 "
                                "build/tests/test_scene --gtest_filter=SceneSchema.DocsSceneMdIsGenerated";
  for (const char* section : {"[contact]", "[[input]]", "[multidof.coupling]", "What each command models", "**refused**"})
    EXPECT_NE(text.find(section), std::string::npos) << section;
}
