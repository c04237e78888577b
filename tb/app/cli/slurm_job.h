// A Slurm job array for a sweep or a campaign (docs/cluster.md): task N of M
// runs the same command with `--shard N/M --out DIR/shard-N`, so that the
// shards can be merged (`stereosim merge DIR/shard-* --out DIR`). Shards are
// deterministic (point or run index modulo M), so a task lands on the same
// points on any node.
#pragma once

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace cli {

struct slurm_options {
    bool emit = false;               // --emit-slurm
    int tasks = 4;                   // --slurm-tasks: array size M
    int cpus = 2;                    // --slurm-cpus: CPUs per task (and the task's --jobs)
    std::string mem_per_cpu = "1G";  // --slurm-mem-per-cpu
    std::string time_limit;          // --slurm-time, e.g. 02:00:00; empty: the partition's
    std::string partition;           // --slurm-partition; empty: the cluster's default
};

// Adds --emit-slurm and the --slurm-* options to a subcommand.
void add_slurm_options(CLI::App* app, slurm_options* options);

// One line on *error if the options are out of range.
bool check_slurm_options(const slurm_options& options, std::string* error);

// Writes OUT/job.sbatch (OUT made if missing, OUT/logs for the tasks' logs)
// for `command` (absolute program path first; the task adds --jobs, --shard
// and --out); returns the sbatch command line to print, or "" with *error.
std::string write_slurm_array(const slurm_options& options, const std::string& job_name,
                              const std::vector<std::string>& command, const std::string& out_dir,
                              std::string* error);

// An absolute path for a file or folder named on the command line.
std::string absolute_path(const std::string& path);

}  // namespace cli
