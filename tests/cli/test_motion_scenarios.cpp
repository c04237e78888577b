// `--scenario spinning` and `--scenario fast` co-simulated: the scenes on
// which the reference firmware's box drifted before it followed the
// silhouette (docs/firmware.md, "Fast and spinning objects"). Checked: the
// ball is detected within 3 frames of the first motion, the tracker reports
// TRACK with a box and a 3D point for every pair after, in budget; from the
// third tracked pair on the box centre is within 3 px of the truth on
// average and 6 px in every pair, the depth within 1 %. Before, on 30
// periods: spinning mean 3.75 px, max 15.9 px, |depth| max 1.37 %; fast
// mean 15.7 px, max 90.0 px (the box left the ball after the bounce).
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "tests/cli/scenario_tracking.h"

namespace {

using nlohmann::json;

void expect_tracked_in_budget(const json& report, const char* scenario) {
    ASSERT_TRUE(report.is_object());
    EXPECT_EQ(report["verdict"], "within_budget");
    const json& accuracy = report["summary"]["accuracy"];
    ASSERT_FALSE(accuracy["detection_frame"].is_null()) << "never detected";
    const int detected = accuracy["detection_frame"].get<int>();
    EXPECT_LE(accuracy["detect_latency_frames"].get<int>(), 3);
    const scenario_test::tracking t =
        scenario_test::tracking_after_detection(report, detected, /*unbounded=*/2);
    ASSERT_GE(t.after, 20);
    EXPECT_EQ(t.scored, t.after) << "a pair without a box or a 3D point";
    EXPECT_LE(t.box_mean_px, 3.0);
    EXPECT_LE(t.box_max_px, 6.0);
    EXPECT_LE(t.depth_max_pct, 1.0);
    std::printf(
        "%s: %d pairs after the detection, box centre error mean %.2f px max %.2f px, "
        "|depth| max %.2f %%, processing max %.3f ms\n",
        scenario, t.after, t.box_mean_px, t.box_max_px, t.depth_max_pct,
        report["summary"]["timing"]["processing_ms_max"].get<double>());
}

TEST(MotionScenarios, SpinningBall) {
    const json report = scenario_test::run("spinning");
    expect_tracked_in_budget(report, "spinning");
    EXPECT_EQ(report["config"]["scenario"]["spin_rpm"], 300.0);
}

TEST(MotionScenarios, FastThrow) {
    const json report = scenario_test::run("fast");
    expect_tracked_in_budget(report, "fast");
    EXPECT_EQ(report["config"]["scenario"]["speed"], 2.0);
}

// Open (docs/firmware.md, "Open"; run with --gtest_also_run_disabled_tests):
// slow passes, 1 px per frame, co-simulated. The 320 px ball is tracked on
// its outline once it moved 4 px (box at most 15.7 px off, depth within
// 0.47 %) but detected 5 frames after its motion began, and a pair is
// dropped (over budget: after the keyed start's whole-frame SDRAM copy, the
// first TRACK pairs of a 322 px box take 20-23 ms of CPU while capture
// keeps the EMIF busy 23.7 of 24.5 ms). The 10 px ball, never detected before
// the strided detection (dsp/stride_history.h), is detected 12 frames
// after its motion began (the stride's two kept frames, then 4 px for its
// candidate), 13 pairs scored of the 20 asked, box 0.86 / 2.55 px from the
// third, |depth| 0.61 %.
TEST(MotionScenarios, DISABLED_SlowLargeBall) {
    const json report = scenario_test::run("large", "--set scenario.speed=0.2");
    EXPECT_EQ(report["config"]["scenario"]["speed"], 0.2);  // the option reached the run
    expect_tracked_in_budget(report, "large at 1 px per frame");
}

TEST(MotionScenarios, DISABLED_SlowSmallBall) {
    const json report = scenario_test::run("small", "--set scenario.speed=0.2");
    EXPECT_EQ(report["config"]["scenario"]["speed"], 0.2);  // the option reached the run
    expect_tracked_in_budget(report, "small at 1 px per frame");
}

// The spinning throw slowed to a fifth of its speed, its ball turning once
// a second about y: box mean 1.05 px, max 1.66 px from the third tracked
// pair, |depth| max 0.84 %.
TEST(MotionScenarios, SlowSpinningBallAboutY) {
    const json report = scenario_test::run(
        "spinning",
        "--set scenario.speed=0.2 --set scenario.spin_rpm=60 --set scenario.spin_axis=y");
    EXPECT_EQ(report["config"]["scenario"]["spin_axis"], "y");  // the option reached the run
    expect_tracked_in_budget(report, "spinning at 1 rev/s about y, a fifth of its speed");
}

// Open: the same about x (docs/firmware.md, "Open"): detected 6 frames
// after the motion began (19 pairs after it); from the third tracked pair
// box mean 1.23 px, max 2.82 px, but |depth| 1.17 % in one pair.
TEST(MotionScenarios, DISABLED_SlowSpinningBallAboutX) {
    const json report = scenario_test::run(
        "spinning",
        "--set scenario.speed=0.2 --set scenario.spin_rpm=60 --set scenario.spin_axis=x");
    EXPECT_EQ(report["config"]["scenario"]["spin_rpm"], 60.0);  // the option reached the run
    expect_tracked_in_budget(report, "spinning at 1 rev/s about x, a fifth of its speed");
}

}  // namespace
