// What a sweep writes into its folder (docs/sweep.md), from sweep.json's
// content alone, so that `stereosim merge` writes exactly what the
// unsharded sweep does: sweep.json, sweep.csv (a row per point),
// frontier.csv (per combination of the other keys, the smallest value of
// the first key that fits) and fitmap.png (gnuplot: the slack over the first
// two keys, the verdict marked, a panel per combination of further keys).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sweep {

// The sweep's header: "grid" [{key, values}], "base" (config file, sets),
// "frames", "shard", "screen", "jobs", "wall_s"; "points" sorted by index.
// Writes every file; false + *error if one cannot be written (fitmap.png
// without gnuplot is a warning on *warning, not an error).
bool write_sweep_files(const std::string& dir, const nlohmann::json& sweep, std::string* error,
                       std::string* warning);

// The point's figure a map or frontier uses: the co-simulation's verdict and
// margin when it ran (minimum slack per period if it fits, minus its largest
// overrun if not), else the closed form's verdict and slack (24.5 ms minus
// the binding figure); "source" says which.
struct point_outcome {
    bool known = false;
    bool judged = true;  // false: the run was too short for a stage to run (never fits)
    bool fits = false;
    double slack_ms = 0.0;
    const char* source = "";  // "cosim" or "closed_form"
};
point_outcome outcome_of(const nlohmann::json& point);

}  // namespace sweep
