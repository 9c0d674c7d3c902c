// cli/sweep_slurm.cpp -- `hapstab sweep slurm`: DIR/sweep.sbatch, an array job whose task k runs
// shard k/N into DIR/shards/k (with --resume, so a requeued task continues), and DIR/merge.sbatch,
// which merges them into DIR; --submit submits both, the merge after the array (afterany: a shard
// with failed points exits 1, and merge checks completeness itself).
#include <cctype>
#include <fstream>
#include <iostream>

#include "cli/command.hpp"
#include "cli/figure.hpp"
#include "cli/sweep_cli.hpp"
#include "hapstab/numeric/error.hpp"
#include "hapstab/report/process.hpp"
#include "hapstab/study/table.hpp"

namespace hapstab::cli::sweep {

namespace fs = std::filesystem;

namespace {

/// A word for bash in single quotes ('it'\''s').
std::string sh_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// #SBATCH lines are not read by a shell: their values must need no quoting.
std::string sbatch_value(const std::string& s, const std::string& option) {
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || std::string("/._-:+,=@").find(c) != std::string::npos))
      throw InputError(option + " '" + s + "': for Slurm it may hold letters, digits and / . _ - : + , = @ only");
  return s;
}

std::string header(const std::string& name, const std::string& log, const SlurmOptions& o, const fs::path& cwd) {
  std::string h = "#!/bin/bash\n# Written by hapstab sweep slurm.\n#SBATCH --job-name=" + name + "\n#SBATCH --output=" + log +
                  "\n#SBATCH --chdir=" + sbatch_value(cwd.string(), "the working folder") + "\n";
  if (!o.partition.empty()) h += "#SBATCH --partition=" + sbatch_value(o.partition, "--partition") + "\n";
  if (!o.time.empty()) h += "#SBATCH --time=" + sbatch_value(o.time, "--time") + "\n";
  return h;
}

/// The job id that `sbatch --parsable` printed ("123" or "123;cluster").
std::string submit(const std::vector<std::string>& argv) {
  const report::ProcessResult r = report::run_checked(argv, "sbatch");
  std::string id;
  for (char c : r.out) {
    if (!std::isdigit(static_cast<unsigned char>(c))) break;
    id += c;
  }
  if (id.empty()) throw NumericalError("sbatch printed no job id: " + r.out);
  return id;
}

}  // namespace

int slurm(const SlurmOptions& o) {
  const study::Spec spec = load_spec(o.spec);  // a bad spec fails here, not on the cluster
  const fs::path dir = fs::absolute(output_folder(o.out, "--out")).lexically_normal();
  const std::string d = sbatch_value(dir.string(), "--out");
  const fs::path cwd = fs::current_path();
  const std::string exe = sh_quote(self_exe().string());
  const std::string n = std::to_string(o.shards);
  fs::create_directories(dir / "logs");
  std::ifstream src(o.spec, std::ios::binary);
  study::write_atomically(dir / "spec.toml", std::string(std::istreambuf_iterator<char>(src), {}));

  std::string array = header("hapstab-sweep", d + "/logs/shard-%a.log", o, cwd);
  array += "#SBATCH --array=0-" + std::to_string(o.shards - 1) + "\n#SBATCH --cpus-per-task=" + std::to_string(o.cpus) +
           "\n# Task k runs shard k/" + n + " of the spec (sha256 " + spec.sha256 + ").\nset -eu\n";
  array += "exec " + exe + " sweep " + sh_quote(d + "/spec.toml") + " --out " + sh_quote(d + "/shards/") +
           "\"$SLURM_ARRAY_TASK_ID\" --shard \"$SLURM_ARRAY_TASK_ID\"/" + n +
           " --jobs \"${SLURM_CPUS_PER_TASK:-1}\" --resume --quiet\n";
  std::string merge = header("hapstab-merge", d + "/logs/merge.log", o, cwd) + "set -eu\nexec " + exe + " sweep merge";
  for (unsigned k = 0; k < o.shards; ++k) merge += " " + sh_quote(d + "/shards/" + std::to_string(k));
  merge += " --out " + sh_quote(d) + "\n";
  study::write_atomically(dir / "sweep.sbatch", array);
  study::write_atomically(dir / "merge.sbatch", merge);
  fs::permissions(dir / "sweep.sbatch", fs::perms::owner_exec, fs::perm_options::add);
  fs::permissions(dir / "merge.sbatch", fs::perms::owner_exec, fs::perm_options::add);
  std::cout << "wrote " << (dir / "sweep.sbatch").string() << " (" << spec.points << " points in " << n
            << " shards) and " << (dir / "merge.sbatch").string() << "\n";
  if (!o.submit) return exit_ok;
  const std::string array_id = submit({"sbatch", "--parsable", (dir / "sweep.sbatch").string()});
  const std::string merge_id =
      submit({"sbatch", "--parsable", "--dependency=afterany:" + array_id, (dir / "merge.sbatch").string()});
  std::cout << "array_job=" << array_id << "\nmerge_job=" << merge_id << "\n";
  return exit_ok;
}

}  // namespace hapstab::cli::sweep
