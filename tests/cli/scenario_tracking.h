// A built-in scenario co-simulated as a user would run it (`stereosim run
// --frames 30 --scenario NAME`, or more frames), and what its report.json says of the
// tracking from the detection on: the scenario tests' shared reading.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/shell.h"

namespace scenario_test {

// `options`: more of the command line, e.g. "--set scenario.speed=0.2".
// `frames`: sync periods simulated.
inline nlohmann::json run(const std::string& scenario, const std::string& options = "",
                          int frames = 30) {
    const std::string dir = testsupport::temp_dir(scenario);
    const auto r = testsupport::run_command(
        std::string(STEREOSIM_BINARY) + " run --quiet --frames " + std::to_string(frames) +
        " --scenario " + scenario + " " + options + " --out " + dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(dir + "/report.json");
    return nlohmann::json::parse(in, nullptr, false);
}

// Pairs processed from the detection frame on; each must say TRACK (checked).
// The errors are of the pairs after the first `unbounded` (the firmware's
// first boxes start from the detection's object(t-1)).
struct tracking {
    int after = 0;    // pairs from the detection on
    int scored = 0;   // of them, with a box and a 3D point scored
    int bounded = 0;  // of those, after the first `unbounded`: the errors below
    double box_mean_px = 0.0, box_max_px = 0.0, depth_max_pct = 0.0;
};

inline tracking tracking_after_detection(const nlohmann::json& report, int detected,
                                         int unbounded = 0) {
    tracking t;
    double box_sum = 0.0;
    for (const nlohmann::json& f : report["frames"]) {
        if (f["pair"].is_null() || !f["pair"]["processed"].get<bool>()) continue;
        if (f["pair"]["scene_frame"].get<int>() < detected) continue;
        ++t.after;
        EXPECT_EQ(f["tracker_state"], "TRACK") << f["frame"];
        const nlohmann::json& e = f["errors"];
        if (e["box_centre_px"].is_null() || e["depth_pct"].is_null()) continue;
        if (++t.scored <= unbounded) continue;
        ++t.bounded;
        box_sum += e["box_centre_px"].get<double>();
        t.box_max_px = std::max(t.box_max_px, e["box_centre_px"].get<double>());
        t.depth_max_pct = std::max(t.depth_max_pct, std::fabs(e["depth_pct"].get<double>()));
    }
    t.box_mean_px = t.bounded > 0 ? box_sum / t.bounded : 0.0;
    return t;
}

}  // namespace scenario_test
