// cli/python_examples.hpp -- the Python examples (examples/python/*.py, issue 18) as figures of
// `hapstab reproduce`'s report: each runs with the package built next to this hapstab
// (build/python/hapstab) and /usr/bin/python3, headless (MPLBACKEND=Agg), writing into the
// report's figures/; every PNG it prints becomes a figure entry of the paper "python". Where the
// package was not built (an install without it, HAPSTAB_PYTHON=OFF) they are "not reproduced on
// this build", like the bench charts without their programs.
#pragma once

#include <filesystem>
#include <vector>

#include "cli/reproduce.hpp"

namespace hapstab::cli {

std::vector<FigureEntry> run_python_examples(const std::filesystem::path& figures_dir, bool quiet);

}  // namespace hapstab::cli
