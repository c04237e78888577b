// `--scenario spinning` and `--scenario fast` co-simulated: the scenes on
// which the reference firmware's box drifted before it followed the
// silhouette (docs/firmware.md, "Fast and spinning objects"). Checked: the
// ball is detected within 3 frames of the first motion (a slow one: within
// the frames the design waits for, below), the tracker reports
// TRACK with a box and a 3D point for every pair after, in budget; from the
// third tracked pair on the box centre is within 3 px of the truth on
// average and 6 px in every pair, the depth within 1 %. Before, on 30
// periods: spinning mean 3.75 px, max 15.9 px, |depth| max 1.37 %; fast
// mean 15.7 px, max 90.0 px (the box left the ball after the bounce).
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "dsp/key_frame.h"
#include "dsp/stride_history.h"
#include "tests/cli/scenario_tracking.h"

namespace {

using nlohmann::json;

// Detected within 3 frames of the first motion: three-frame differencing
// (paper eq. 2-4) needs f(t-2), f(t-1) and f(t).
constexpr int fast_latency_frames = 3;
// A slow object's detection is a candidate until it moved
// key_frame::min_shift px from its key (its whole outline in Dif(key, t),
// dsp/controller_detect.cpp confirm_slow_object): at 1 px per frame that many
// frames more.
constexpr int slow_latency_frames = fast_latency_frames + dsp::key_frame::min_shift;
// One too slow and small for one pair's differences is seen by the strided
// detection (dsp/stride_history.h) once two frames a stride apart are kept
// after it moved, then confirmed as above.
constexpr int strided_latency_frames = slow_latency_frames + 2 * dsp::stride_history::stride;

void expect_tracked_in_budget(const json& report, const char* scenario,
                              int latency_frames = fast_latency_frames) {
    ASSERT_TRUE(report.is_object());
    EXPECT_EQ(report["verdict"], "within_budget");
    const json& accuracy = report["summary"]["accuracy"];
    ASSERT_FALSE(accuracy["detection_frame"].is_null()) << "never detected";
    const int detected = accuracy["detection_frame"].get<int>();
    EXPECT_LE(accuracy["detect_latency_frames"].get<int>(), latency_frames);
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

// Slow passes, 1 px per frame, co-simulated for 40 periods (a slow
// detection waits for its object to move; 20 pairs are judged after it).
// The 320 px ball: before its size was held against one pair's silhouette
// while keyed and its key held a ring (dsp/key_frame.h), the sensors' noise
// made that silhouette 31 px short across the motion in its second tracked
// pair, the key was re-taken on it and the box stood 10-15 px off (mean
// 10.09 px); and reading and re-writing the key's whole 370 x 367 px region
// dropped a pair (EMIF busy 24.44 of 24.5 ms while tracked). The 10 px
// ball was never detected before the strided detection
// (dsp/stride_history.h).
TEST(MotionScenarios, SlowLargeBall) {
    const json report = scenario_test::run("large", "--set scenario.speed=0.2", 40);
    EXPECT_EQ(report["config"]["scenario"]["speed"], 0.2);  // the option reached the run
    expect_tracked_in_budget(report, "large at 1 px per frame", slow_latency_frames);
}

TEST(MotionScenarios, SlowSmallBall) {
    const json report = scenario_test::run("small", "--set scenario.speed=0.2", 40);
    EXPECT_EQ(report["config"]["scenario"]["speed"], 0.2);  // the option reached the run
    expect_tracked_in_budget(report, "small at 1 px per frame", strided_latency_frames);
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

// The same about x, detected 6 frames after the motion began: |depth|
// 0.76-1.17 % in pairs 22-30 (of 29) while the stereo core was the box less
// an eighth each side (its corners on the background), 0.60 % at most since
// a seventh.
TEST(MotionScenarios, SlowSpinningBallAboutX) {
    const json report = scenario_test::run(
        "spinning",
        "--set scenario.speed=0.2 --set scenario.spin_rpm=60 --set scenario.spin_axis=x", 40);
    EXPECT_EQ(report["config"]["scenario"]["spin_rpm"], 60.0);  // the option reached the run
    expect_tracked_in_budget(report, "spinning at 1 rev/s about x, a fifth of its speed",
                             slow_latency_frames);
}

// A 120 mm ball (73 px) passing at 3 px per frame, between a slow
// object's step and a moving one's, spinning once a second about y. Its SAD
// pattern reads it still and it is keyed; from pair 20 the key's pattern,
// come round with the spin, read 0 px and held the box while the ball went
// on (9.07 px mean, 33.67 px max, |depth| 3.07 %, seed 3), until a
// displacement that falls back towards the key dropped the key
// (docs/firmware.md, "A key's displacement that falls back").
TEST(MotionScenarios, SpinningPassBetweenSlowAndMoving) {
    const json report = scenario_test::run(
        "default",
        "--seed 3 --set scenario.path=pass --set scenario.speed=0.6 --set scenario.spin_rpm=60 "
        "--set scenario.spin_axis=y --set scenario.ball_radius_mm=120");
    EXPECT_EQ(report["config"]["scenario"]["ball_radius_mm"], 120.0);  // the options reached it
    expect_tracked_in_budget(report, "120 mm pass at 3 px per frame spinning 1 rev/s about y");
}

// The same ball circling at 3 px per frame: its key of the outline took the
// hull across the motion, which held where the ball was at the key while it
// drifted 1 px a pair across, and the box fell behind from pair 13 (3.70 px
// mean, 8.10 px max, seed 3) until the hull was trimmed by that drift
// (docs/firmware.md, "A key of the outline drifting across the motion"):
// 1.98 / 3.98 px.
TEST(MotionScenarios, SpinningCircleDriftingAcross) {
    const json report = scenario_test::run(
        "default",
        "--seed 3 --set scenario.path=circle --set scenario.speed=0.375 "
        "--set scenario.spin_rpm=60 --set scenario.spin_axis=y --set scenario.ball_radius_mm=120");
    EXPECT_EQ(report["config"]["scenario"]["path"], "circle");  // the options reached it
    expect_tracked_in_budget(report, "120 mm circle at 3 px per frame spinning 1 rev/s about y");
}

}  // namespace
