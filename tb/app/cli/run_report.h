// report.json and frames.csv of a run (docs/cli.md; schema
// docs/report-schema.json): the config used, the verdict and its overruns,
// the summary (sync, timing, accuracy, data path, simulation speed) and one
// row per sync period ("frames"). frames.csv holds exactly the same rows, its
// columns taken from the JSON rows by frame_csv_columns(), so the two agree by
// construction and a test checks it from the files.
//
// Everything but summary.sim (host wall time) is a function of the inputs and
// the seed: two runs give byte-identical reports apart from it.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/app/cli/run_setup.h"
#include "tb/platform/budget.h"
#include "tb/platform/platform.h"
#include "tb/platform/scoreboard.h"

namespace cli {

inline constexpr int report_schema_version = 1;

nlohmann::json build_report(const run_setup& setup, const platform::platform_top& top,
                            const platform::scoreboard_report& score,
                            const platform::budget_report& budget);

// frames.csv: (column name, JSON pointer into a frame row); a column per
// stage of the report's firmware.
std::vector<std::pair<std::string, std::string>> frame_csv_columns(const nlohmann::json& report);
// A header line, then one line per report["frames"] row; null or absent
// values are empty cells, booleans 1 / 0, numbers as in the JSON.
std::string frames_csv(const nlohmann::json& report);

// The stage names of the report's firmware, in its order (tool.firmware.stages).
std::vector<std::string> stage_names(const nlohmann::json& report);

}  // namespace cli
