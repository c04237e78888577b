// Runs the co-simulated points of a sweep: each an independent
// `stereosim run --quiet ... --out DIR/points/NNNNNN/out` child process
// (posix_spawn), `jobs` at a time, with a progress line (points done, over,
// failed, elapsed, ETA) on `log`.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sweep {

struct run_request {
    std::string binary;                  // the stereosim to spawn
    std::string config_file;             // --config, may be empty
    std::vector<std::string> base_sets;  // the user's --set KEY=VALUE, before the point's keys
    std::string out_dir;                 // the sweep's folder (points/ inside it)
    int jobs = 2;
    bool keep_runs = false;  // keep DIR/points/NNNNNN (report.json, frames.csv, ...)
};

// Runs every point of `points` whose "simulate" is true and that has not
// run yet (a resumed sweep's); fills its figures (read_point_report),
// "exit_code", "wall_s", or "error". Returns the number of points that failed
// to run (no report.json: exit 2 or 3, a signal). On SIGINT or SIGTERM it
// stops the points under way and returns; *interrupted = the signal (else 0),
// the points it did not finish keep no "ran".
int run_points(const run_request& request, std::vector<nlohmann::json>& points, std::FILE* log,
               int* interrupted = nullptr);

// This program's path (/proc/self/exe).
std::string this_program();

}  // namespace sweep
