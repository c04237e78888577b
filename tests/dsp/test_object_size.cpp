// Objects of any size (issue 17, part 2): the firmware on rendered pairs
// (host runner, no hardware) with one textured ball 10 px to half the image
// (320 px) wide on scene::pass_path, scored against the renderer's
// closed-form truth (the ellipse centre, the visible surface's mean depth).
//
// Bounds (the issue's): detected within 3 frames of its first motion, box
// centre within 5 px of the truth on average over the tracked frames, depth
// within 1 % in every tracked frame. Measured (depth error, max): 0.37,
// 0.59, 0.46, 0.50, 0.60, 0.71, 0.61 % for 10 ... 320 px with the box on
// the silhouette (dsp/box_refit.h); 0.78, 0.34, 0.35, 0.39, 0.42, 0.72,
// 0.88 % with the box of before.
//
// Above 96 px the depth is the mean of the object's tiles
// (dsp/object_depth.h). With the core's single match instead, the errors
// at 160 / 240 / 320 px were 1.11 / 1.05 / 1.30 %: the core's mean surface
// on a sphere lies nearer than the whole visible surface's. The tile count
// (16 a side) and the gate were chosen on these seven sizes and a held-out
// 300 px ball at 2.0 m (1.03 % with 12 tiles a side, 0.65 % with 16); then
// checked on five more sizes not used to choose (180 px at 1.3 m, 260 at
// 1.8, 310 at 1.6, 100 at 1.2, 150 at 2.8: 0.66, 0.84, 0.79, 0.41, 0.32 %)
// and in co-simulation (tests/cli/test_object_size_scenarios.cpp).
//
// On the firmware before the object box and the block extent (motion_blocks)
// this test failed: 20 px 1.66 % depth, 80 px 30.7 px mean box error, 160 px
// and larger never detected.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "tb/platform/scoring/error_metrics.h"
#include "tests/support/host/scenarios.h"
#include "tests/support/host/stereo_runner.h"

namespace {

constexpr int max_detection_delay = 3;         // frames after the first motion (issue 17)
constexpr double max_mean_box_error_px = 5.0;  // box centre, mean over the tracked frames
constexpr double max_depth_error_pct = 1.0;    // every tracked frame

struct size_case {
    double diameter_px;
    double depth_m;
};

void PrintTo(const size_case& c, std::ostream* os) {
    *os << c.diameter_px << " px at " << c.depth_m << " m";
}

struct size_result {
    platform::run_summary summary;
    double max_abs_depth_pct = 0.0;
    int points = 0;
    int tracked_after_detection = 0;
    int frames_after_detection = 0;
};

size_result run_case(const size_case& c) {
    const scene::stereo_rig rig;
    const double radius_m = host::ball_radius_for_width(c.diameter_px, c.depth_m, rig.focal_px());
    const scene::scenario scenario = host::pass_scenario(c.depth_m, radius_m);
    host::stereo_runner runner(scenario, host::controller_config_for(scenario.scene.rig));
    const std::vector<host::host_record> records = runner.run(0, scenario.frame_count);
    size_result r;
    r.summary =
        platform::summarize(host::scored(records),
                            platform::first_motion_frame(runner.sequence(), scenario.frame_count));
    for (const host::host_record& rec : records) {
        if (r.summary.detection_frame < 0 || rec.index < r.summary.detection_frame) continue;
        ++r.frames_after_detection;
        r.tracked_after_detection += rec.firmware.state == dsp::tracker_state::track;
        const platform::frame_errors e = platform::score_frame(rec);
        if (!e.point_scored) continue;
        ++r.points;
        r.max_abs_depth_pct = std::max(r.max_abs_depth_pct, std::fabs(e.depth_err_pct));
    }
    const platform::run_summary& s = r.summary;
    std::printf(
        "%3.0f px at %.1f m: first motion %d, detected %d, tracked %d of %d, box centre "
        "error mean %.2f max %.2f px, |depth error| max %.2f %% over %d points\n",
        c.diameter_px, c.depth_m, s.first_motion_frame, s.detection_frame,
        r.tracked_after_detection, r.frames_after_detection, s.mean_box_centre_err_px,
        s.max_box_centre_err_px, r.max_abs_depth_pct, r.points);
    const std::string key = "ball_" + std::to_string(static_cast<int>(c.diameter_px)) + "px";
    ::testing::Test::RecordProperty(key + "_box_err_mean_x100",
                                    static_cast<int>(std::lround(100 * s.mean_box_centre_err_px)));
    ::testing::Test::RecordProperty(key + "_depth_err_max_x100",
                                    static_cast<int>(std::lround(100 * r.max_abs_depth_pct)));
    return r;
}

}  // namespace

// One test per size (each its own ctest: under ASan the seven together
// outran the dsp label's 120 s).
class ObjectSize : public ::testing::TestWithParam<size_case> {};

TEST_P(ObjectSize, DetectedAndTrackedWithinTheBounds) {
    const size_case c = GetParam();
    const size_result r = run_case(c);
    const platform::run_summary& s = r.summary;
    ASSERT_GE(s.first_motion_frame, 3);
    ASSERT_GE(s.detection_frame, 0) << "never detected";
    EXPECT_GT(s.detection_frame, s.first_motion_frame);
    EXPECT_LE(s.detection_frame - s.first_motion_frame, max_detection_delay);
    // Tracked, with a 3D point, in every frame from the detection on.
    EXPECT_EQ(r.tracked_after_detection, r.frames_after_detection);
    EXPECT_EQ(r.points, r.frames_after_detection);
    EXPECT_LE(s.mean_box_centre_err_px, max_mean_box_error_px);
    EXPECT_LE(r.max_abs_depth_pct, max_depth_error_pct);
}

// 10 px to half the image width (320 px), each at a depth inside 1-3 m.
INSTANTIATE_TEST_SUITE_P(TenPixelsToHalfTheImageWidth, ObjectSize,
                         ::testing::Values(size_case{10, 2.6}, size_case{20, 2.2},
                                           size_case{40, 2.0}, size_case{80, 1.8},
                                           size_case{160, 1.6}, size_case{240, 1.5},
                                           size_case{320, 1.4}),
                         [](const ::testing::TestParamInfo<size_case>& info) {
                             return std::to_string(static_cast<int>(info.param.diameter_px)) + "px";
                         });
