#include "tb/app/cli/slurm_job.h"

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <regex>

namespace cli {

namespace {

namespace fs = std::filesystem;

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace

void add_slurm_options(CLI::App* app, slurm_options* o) {
    app->add_flag("--emit-slurm", o->emit,
                  "write OUT/job.sbatch, a Slurm job array of --slurm-tasks shards, and print the "
                  "sbatch command (docs/cluster.md); nothing is run");
    app->add_option("--slurm-tasks", o->tasks, "array tasks (shards), default 4");
    app->add_option("--slurm-cpus", o->cpus, "CPUs per task, also its --jobs (default 2)");
    app->add_option("--slurm-mem-per-cpu", o->mem_per_cpu, "memory per CPU (default 1G)");
    app->add_option("--slurm-time", o->time_limit, "time limit per task, e.g. 02:00:00");
    app->add_option("--slurm-partition", o->partition, "partition (default: the cluster's)");
}

bool check_slurm_options(const slurm_options& o, std::string* error) {
    if (o.tasks < 1 || o.tasks > 100000) {
        *error = "--slurm-tasks: out of range 1..100000";
        return false;
    }
    if (o.cpus < 1 || o.cpus > 256) {
        *error = "--slurm-cpus: out of range 1..256";
        return false;
    }
    if (!std::regex_match(o.mem_per_cpu, std::regex("[0-9]+[KMGT]?"))) {
        *error =
            "--slurm-mem-per-cpu: expected a size such as 1G or 512M, got '" + o.mem_per_cpu + "'";
        return false;
    }
    if (!o.time_limit.empty() &&
        !std::regex_match(o.time_limit, std::regex("([0-9]+-)?[0-9]+(:[0-9]{2}){0,2}"))) {
        *error = "--slurm-time: expected [D-]HH[:MM[:SS]], got '" + o.time_limit + "'";
        return false;
    }
    if (!std::regex_match(o.partition, std::regex("[A-Za-z0-9_.-]*"))) {
        *error = "--slurm-partition: unexpected characters in '" + o.partition + "'";
        return false;
    }
    return true;
}

std::string write_slurm_array(const slurm_options& o, const std::string& job_name,
                              const std::vector<std::string>& command, const std::string& out_dir,
                              std::string* error) {
    const std::string dir = absolute_path(out_dir);
    std::error_code ec;
    fs::create_directories(dir + "/logs", ec);
    if (ec) {
        *error = "cannot create " + dir + "/logs: " + ec.message();
        return {};
    }
    const std::string path = dir + "/job.sbatch";
    std::ofstream out(path);
    out << "#!/bin/bash\n"
        << "#SBATCH --job-name=" << job_name << "\n"
        << "#SBATCH --array=1-" << o.tasks << "\n"
        << "#SBATCH --ntasks=1\n"
        << "#SBATCH --cpus-per-task=" << o.cpus << "\n"
        << "#SBATCH --mem-per-cpu=" << o.mem_per_cpu << "\n";
    if (!o.time_limit.empty()) out << "#SBATCH --time=" << o.time_limit << "\n";
    if (!o.partition.empty()) out << "#SBATCH --partition=" << o.partition << "\n";
    out << "#SBATCH --output=" << dir << "/logs/task-%a.log\n"
        << "# Written by stereosim --emit-slurm (docs/cluster.md). Task N runs shard N of "
        << o.tasks << " into\n# " << dir << "/shard-N; when every task is done:\n"
        << "#   stereosim merge " << dir << "/shard-* --out " << dir << "\n"
        << "set -euo pipefail\n"
        << "task=${SLURM_ARRAY_TASK_ID:?run this script with sbatch}\n"
        << "exec";
    for (const std::string& word : command) out << " " << shell_quote(word);
    out << " --jobs " << o.cpus << " --shard \"$task/" << o.tasks << "\" --out "
        << shell_quote(dir + "/shard-") << "\"$task\"\n";
    out.close();
    if (!out) {
        *error = "cannot write " + path;
        return {};
    }
    return "sbatch " + shell_quote(path);
}

std::string absolute_path(const std::string& path) {
    std::error_code ec;
    const fs::path p = fs::absolute(path, ec);
    std::string abs = ec ? path : p.lexically_normal().string();
    while (abs.size() > 1 && abs.back() == '/') abs.pop_back();
    return abs;
}

}  // namespace cli
