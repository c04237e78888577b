// `--scenario spinning` and `--scenario fast` co-simulated: the scenes on
// which the reference firmware's box drifts (docs/firmware.md, "Tracking").
// What holds today and is checked: the ball is detected within 3 frames of
// the first motion and the tracker reports TRACK for every pair after, in
// budget. The box and depth errors are printed, not bounded: measured on
// 30 periods, spinning: box centre error mean 3.75 px, max 15.9 px, |depth|
// max 1.37 %; fast: mean 15.7 px, max 90.0 px (the box leaves the ball
// after the bounce and finds it again). A firmware that keeps its box on the
// object tightens these into bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/shell.h"

namespace {

using nlohmann::json;

json run(const std::string& dir, const std::string& scenario) {
    const auto r =
        testsupport::run_command(std::string(STEREOSIM_BINARY) + " run --quiet --frames 30 " +
                                 "--scenario " + scenario + " --out " + dir);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(dir + "/report.json");
    return json::parse(in, nullptr, false);
}

void expect_tracked_in_budget(const json& report, const char* scenario) {
    ASSERT_TRUE(report.is_object());
    EXPECT_EQ(report["verdict"], "within_budget");
    const json& accuracy = report["summary"]["accuracy"];
    ASSERT_FALSE(accuracy["detection_frame"].is_null()) << "never detected";
    const int detected = accuracy["detection_frame"].get<int>();
    EXPECT_LE(accuracy["detect_latency_frames"].get<int>(), 3);
    int after = 0, scored = 0;
    double box_sum = 0.0, box_max = 0.0, depth_max = 0.0;
    for (const json& f : report["frames"]) {
        if (f["pair"].is_null() || !f["pair"]["processed"].get<bool>()) continue;
        if (f["pair"]["scene_frame"].get<int>() < detected) continue;
        ++after;
        EXPECT_EQ(f["tracker_state"], "TRACK") << f["frame"];
        const json& e = f["errors"];
        if (e["box_centre_px"].is_null() || e["depth_pct"].is_null()) continue;
        ++scored;
        box_sum += e["box_centre_px"].get<double>();
        box_max = std::max(box_max, e["box_centre_px"].get<double>());
        depth_max = std::max(depth_max, std::fabs(e["depth_pct"].get<double>()));
    }
    ASSERT_GE(after, 20);
    EXPECT_EQ(scored, after) << "a pair without a box or a 3D point";
    std::printf(
        "%s: %d pairs after the detection, box centre error mean %.2f px max %.2f px, "
        "|depth| max %.2f %%, processing max %.3f ms\n",
        scenario, after, box_sum / scored, box_max, depth_max,
        report["summary"]["timing"]["processing_ms_max"].get<double>());
}

TEST(MotionScenarios, SpinningBall) {
    const json report = run(testsupport::temp_dir("spinning"), "spinning");
    expect_tracked_in_budget(report, "spinning");
    EXPECT_EQ(report["config"]["scenario"]["spin_rpm"], 300.0);
}

TEST(MotionScenarios, FastThrow) {
    const json report = run(testsupport::temp_dir("fast"), "fast");
    expect_tracked_in_budget(report, "fast");
}

}  // namespace
