// The plan of a sweep before anything runs (docs/sweep.md): the grid, every
// point's setup checked as `stereosim run` would check it (a bad point is
// bad input for the whole sweep), the closed form of each point, and which
// points are co-simulated (all, or with --screen those near the closed
// form's boundary plus a sample of the rest).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/app/cli/config_keys.h"
#include "tb/app/sweep/sweep_command.h"
#include "tb/app/sweep/sweep_grid.h"

namespace sweep {

inline constexpr size_t max_points_without_force = 10000;

struct sweep_plan {
    std::vector<grid_axis> axes;
    size_t total = 0;  // points in the whole grid
    int shard = 1, shards = 1;
    std::vector<cli::key_assignment> base;  // config file, --frames, --set
    std::vector<nlohmann::json> points;     // this shard's, with "simulate" and "closed_form"
    size_t host_runs = 0;                   // firmware runs on the host for the closed form
};

// Checks the options and every point; false + *error (one line) if any is
// bad. Fills everything but the points.
bool check_sweep(const sweep_options& options, sweep_plan* plan, std::string* error);

// This shard's points with their closed form and "simulate"; with --screen
// the closed form of the whole grid decides (the same points on any shard).
// Progress of the host runs on `log`.
void plan_points(const sweep_options& options, sweep_plan* plan, std::FILE* log);

// The header of sweep.json (everything but the points and the summary).
nlohmann::json sweep_header(const sweep_options& options, const sweep_plan& plan);

// The summary of a set of points: counts of within / over / failed /
// closed-form-only, and the points where the closed form disagrees.
nlohmann::json sweep_summary(const std::vector<nlohmann::json>& points);

}  // namespace sweep
