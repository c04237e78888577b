// `--scenario small` and `--scenario large` (issue 17, part 2) co-simulated:
// a ball 10 px wide and one half the image wide (320 px) on the same slow
// pass, through the sensors, the card, the bus and the firmware on the C6416
// model. Bounds, the (scored against the renderer's truth): detected
// within 3 frames of the first motion, tracked with a 3D point in every pair
// from then on, box centre within 5 px on average, depth within 1 % in every
// pair, and within the 24.5 ms budget, every stage included. 30 periods, as
// tests/dsp/test_object_size.cpp. Measured with the box on the silhouette
// (dsp/box_refit.h): small: box error mean 1.00 px, |depth| max 0.74 %,
// largest pair 7.6 ms; large: 1.12 px, 0.94 % (the large ball's depth is
// its tiles' mean, dsp/object_depth.h), 22.1 ms (track 6.0 ms, stereo_sad
// 9.1 ms: the tiles add 4.9 ms). With the box of before: small 1.17 px,
// 0.84 %, 7.5 ms; large 2.53 px, 0.91 % (per pair -0.55 % to +0.91 %; the
// core's single match gave 0.44 % here but 1.30 % on the host runs),
// 21.5 ms.
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>

#include "tests/cli/scenario_tracking.h"

namespace {

using nlohmann::json;

void expect_tracked_within_bounds(const json& report, double max_depth_pct) {
    ASSERT_TRUE(report.is_object());
    EXPECT_EQ(report["verdict"], "within_budget");
    EXPECT_TRUE(report["overruns"].empty());
    const json& accuracy = report["summary"]["accuracy"];
    ASSERT_FALSE(accuracy["detection_frame"].is_null()) << "never detected";
    const int detected = accuracy["detection_frame"].get<int>();
    EXPECT_EQ(accuracy["first_motion_frame"], 3);
    EXPECT_GE(accuracy["detect_latency_frames"].get<int>(), 1);
    EXPECT_LE(accuracy["detect_latency_frames"].get<int>(), 3);

    const scenario_test::tracking t = scenario_test::tracking_after_detection(report, detected);
    ASSERT_GE(t.after, 20);
    EXPECT_EQ(t.scored, t.after) << "a pair without a box or a 3D point";
    EXPECT_LE(t.box_mean_px, 5.0);
    EXPECT_LE(t.depth_max_pct, max_depth_pct);
    EXPECT_LT(report["summary"]["timing"]["processing_ms_max"].get<double>(), 24.5);
    std::printf(
        "%d pairs after the detection, box centre error mean %.2f px, |depth| max %.2f %%, "
        "processing max %.3f ms, track max %.3f ms, stereo_sad max %.3f ms\n",
        t.after, t.box_mean_px, t.depth_max_pct,
        report["summary"]["timing"]["processing_ms_max"].get<double>(),
        report["summary"]["timing"]["stage_ms"]["track"]["max"].get<double>(),
        report["summary"]["timing"]["stage_ms"]["stereo_sad"]["max"].get<double>());
}

TEST(ObjectSizeScenarios, SmallBallTenPixelsWide) {
    const json report = scenario_test::run("small");
    expect_tracked_within_bounds(report, 1.0);
    EXPECT_EQ(report["config"]["scenario"]["ball_radius_mm"], 16.5);
}

TEST(ObjectSizeScenarios, LargeBallHalfTheImageWide) {
    const json report = scenario_test::run("large");
    expect_tracked_within_bounds(report, 1.0);
    EXPECT_EQ(report["config"]["scenario"]["ball_radius_mm"], 278.0);
}

}  // namespace
