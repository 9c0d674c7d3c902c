// fuzz-modules: scene
// fuzz-seeds: examples tests/fuzz/seeds_scene
// fuzz-dict: tests/fuzz/scene.dict
// fuzz-max-len: 131072
// libFuzzer target: the scene loader (TOML -> scene, every section) on arbitrary text, with a
// scene folder that holds one small profile file. Any input must end in a Scene or an
// InputError -- never a crash, a hang, or another exception type. And the depth check every
// TOML text passes before toml++ (report/toml_limits.hpp) never under-counts: when toml++ parses
// a text, no node of its tree is deeper than report::toml_depth says.
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <toml++/toml.h>
#include <utility>
#include <vector>

#include "hapstab/numeric/error.hpp"
#include "hapstab/numeric/limits.hpp"
#include "hapstab/report/toml_limits.hpp"
#include "hapstab/scene/scene.hpp"

namespace {
std::string scene_dir;

// The depth of toml++'s tree (a table's keys one deeper than it, an array's elements too),
// without recursion.
int tree_depth(const toml::table& root) {
  int deepest = 0;
  std::vector<std::pair<const toml::node*, int>> todo{{&root, 0}};
  while (!todo.empty()) {
    const auto [n, d] = todo.back();
    todo.pop_back();
    deepest = std::max(deepest, d);
    if (const auto* t = n->as_table())
      for (auto&& [k, v] : *t) todo.emplace_back(&v, d + 1);
    else if (const auto* a = n->as_array())
      for (const auto& v : *a) todo.emplace_back(&v, d + 1);
  }
  return deepest;
}
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  scene_dir = (std::filesystem::temp_directory_path() / ("hapstab-fuzz-scene-" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(scene_dir);
  std::ofstream(scene_dir + "/p.csv") << "0,1\n0.001,2\n";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const int scanned = hapstab::report::toml_depth(text).depth;
  if (scanned <= hapstab::limits::toml_depth) {
    try {
      if (tree_depth(toml::parse(text)) > scanned) std::abort();
    } catch (const toml::parse_error&) {
    }
  }
  try {
    (void)hapstab::scene::parse_scene(text, "fuzz.toml", {}, scene_dir);
  } catch (const hapstab::InputError&) {
  }
  return 0;
}
