// fuzz-sources: toolbox/hapstab/scene/scene.cpp toolbox/hapstab/scene/reader.cpp toolbox/hapstab/lti/parse.cpp toolbox/hapstab/lti/tf.cpp toolbox/hapstab/lti/discretize.cpp toolbox/hapstab/lti/realization.cpp toolbox/hapstab/poly/polynomial.cpp toolbox/hapstab/poly/sturm.cpp toolbox/hapstab/poly/unit_circle.cpp toolbox/hapstab/numeric/decimal.cpp toolbox/hapstab/numeric/ball_expm.cpp toolbox/hapstab/sim/loop.cpp toolbox/hapstab/sim/simulator.cpp toolbox/hapstab/report/escape.cpp toolbox/hapstab/report/paths.cpp
// fuzz-seeds: examples tests/fuzz/seeds_scene
// fuzz-dict: tests/fuzz/scene.dict
// libFuzzer target: the scene loader (TOML -> scene, every section) on arbitrary text, with a
// scene folder that holds one small profile file. Any input must end in a Scene or an
// InputError -- never a crash, a hang, or another exception type.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "hapstab/numeric/error.hpp"
#include "hapstab/scene/scene.hpp"

namespace {
std::string scene_dir;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  scene_dir = (std::filesystem::temp_directory_path() / ("hapstab-fuzz-scene-" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(scene_dir);
  std::ofstream(scene_dir + "/p.csv") << "0,1\n0.001,2\n";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hapstab::scene::parse_scene(text, "fuzz.toml", {}, scene_dir);
  } catch (const hapstab::InputError&) {
  }
  return 0;
}
