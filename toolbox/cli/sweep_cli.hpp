// cli/sweep_cli.hpp -- the parts of `hapstab sweep` (cmd_sweep.cpp registers the command):
// checking a spec against the command registry, running it, merging shards, writing Slurm
// scripts and drawing a map. The library half (spec, records, workers) is hapstab/study.
#pragma once

#include <string>
#include <vector>

#include "hapstab/study/spec.hpp"

namespace hapstab::cli::sweep {

/// Reads and parses a spec and checks it against the registry: the command exists, takes --set
/// and --json, and has every [args] key as an option (InputError naming the key otherwise).
study::Spec load_spec(const std::string& path);

struct RunOptions {
  std::string spec, out, shard = "0/1";
  unsigned jobs = 0;  ///< 0: the CPUs this process may use
  bool resume = false, quiet = false;
};
int run(const RunOptions& o);
/// run() on a spec given as text (o.spec unused): `name` calls the spec in messages ("spec: args.T:
/// ...") and its folder resolves the files [args] name (none: the working folder). Python's
/// hapstab.sweep with a dict or TOML text, which has no file.
int run_text(const std::string& text, const std::string& name, const RunOptions& o);

int merge(const std::vector<std::string>& dirs, const std::string& out, bool quiet);

struct SlurmOptions {
  std::string spec, out, partition, time;
  unsigned shards = 0, cpus = 1;
  bool submit = false;
};
int slurm(const SlurmOptions& o);

struct PlotOptions {
  std::string dir, x, y, z, format = "png";
  bool contour = false;
};
int plot(const PlotOptions& o);

}  // namespace hapstab::cli::sweep
