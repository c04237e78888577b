// The platform's report (docs/platform.md, "Report"): run speed, sync and
// data path, the firmware's track against the truth, per-stage times, the
// budget per period and its verdict, the closed-form figures beside the
// measured ones.
#pragma once

#include <cstdio>

#include "tb/platform/budget.h"
#include "tb/platform/closed_form.h"
#include "tb/platform/platform.h"
#include "tb/platform/scoreboard.h"

namespace platform {

struct run_figures {
    double sim_s = 0.0;
    double wall_s = 0.0;
    double island_wall_s = 0.0;
    double firmware_wall_s = 0.0;
    double sim_per_wall() const { return wall_s > 0.0 ? sim_s / wall_s : 0.0; }
    double firmware_share() const { return wall_s > 0.0 ? firmware_wall_s / wall_s : 0.0; }
};
run_figures figures_of(const platform_top& top);

// The closed-form capture figures for this configuration: the CECTL the
// firmware programmed, the frames where it reported them (reported_placement).
capture_figures capture_closed_form(const platform_top& top);

void print_report(std::FILE* out, const platform_top& top, const scoreboard_report& score,
                  const budget_report& budget, bool per_pair = true);

}  // namespace platform
