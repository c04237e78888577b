// End-to-end firmware test on rendered stereo sequences: the controller
// (dsp/controller.h) on raw Bayer pairs from the scene renderer, scored
// against the scene's closed-form ground truth (model/scene/sequence.h):
// detection delay after the first motion, box centre against the centre of
// the ball's image ellipse, X / Y against the ball's centre and depth
// against the mean depth of its VISIBLE surface (docs/design-brief.md, "Default rig").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "model/scene/sequence.h"
#include "tb/platform/scoring/error_metrics.h"
#include "tests/support/host/scenarios.h"
#include "tests/support/host/stereo_runner.h"

namespace {

// Thresholds (see each test for why).
constexpr int max_detection_delay = 3;            // frames after the first motion (the brief)
constexpr double max_depth_error_pct = 2.0;       // docs/design-brief.md: 2 % depth at 1-3 m
constexpr double max_box_error_diameters = 0.25;  // box centre within a quarter diameter
// X and Y against the ball's CENTRE: a quarter of the ball's 100 mm
// diameter, the box-centre criterion in space. Part of it is by design: the
// box centre is triangulated at the visible-surface depth, 2/3 r nearer than
// the centre, which scales X and Y by Z_visible / Z_centre (~4 mm at
// X = -0.3 m, Z = 2.6 m).
constexpr double max_xy_error_mm = 25.0;

double ball_diameter_px(const scene::ball_truth& truth) {
    return 2.0 * std::sqrt(truth.right.area_px / std::acos(-1.0));
}

struct run_result {
    std::vector<host::host_record> records;
    platform::run_summary summary;
};

run_result run(const scene::scenario& scenario, int frames) {
    host::stereo_runner runner(scenario, host::controller_config_for(scenario.scene.rig));
    run_result r;
    r.records = runner.run(0, frames);
    r.summary = platform::summarize(host::scored(r.records),
                                    platform::first_motion_frame(runner.sequence(), frames));
    return r;
}

void print_errors(const char* name, const run_result& r) {
    std::printf("%s: frame state  box_err_px (diam)  dX_mm   dY_mm   depth_err_%%  disp_err_px\n",
                name);
    for (const host::host_record& rec : r.records) {
        const platform::frame_errors e = platform::score_frame(rec);
        std::printf("%s: %5d %-6s", name, rec.index, dsp::tracker_state_name(rec.firmware.state));
        if (e.box_scored) {
            std::printf(" %6.2f (%5.1f)", e.box_centre_err_px, ball_diameter_px(rec.truth));
        } else {
            std::printf(" %14s", "-");
        }
        if (e.point_scored) {
            std::printf(" %+7.1f %+7.1f %+9.2f %+9.2f\n", e.err_x_mm, e.err_y_mm, e.depth_err_pct,
                        e.disparity_err_px);
        } else {
            std::printf(" %7s %7s %9s %9s\n", "-", "-", "-", "-");
        }
    }
    const platform::run_summary& s = r.summary;
    std::printf(
        "%s: first motion %d, detection %d, tracked %d, points %d, depth within 2%% %d, "
        "RMSE x %.1f y %.1f z %.1f mm, max |depth err| %.2f%%, box err mean %.2f max %.2f px\n",
        name, s.first_motion_frame, s.detection_frame, s.tracked_frames, s.point_scored_frames,
        s.depth_within_2pct, s.rmse_x_mm, s.rmse_y_mm, s.rmse_z_mm, s.max_abs_depth_err_pct,
        s.mean_box_centre_err_px, s.max_box_centre_err_px);
}

void record(const std::string& prefix, const platform::run_summary& s) {
    ::testing::Test::RecordProperty(prefix + "_detection_delay_frames",
                                    s.detection_frame - s.first_motion_frame);
    ::testing::Test::RecordProperty(prefix + "_depth_max_abs_err_pct_x100",
                                    static_cast<int>(std::lround(100 * s.max_abs_depth_err_pct)));
    ::testing::Test::RecordProperty(prefix + "_rmse_z_um", static_cast<int>(1000 * s.rmse_z_mm));
    ::testing::Test::RecordProperty(prefix + "_rmse_x_um", static_cast<int>(1000 * s.rmse_x_mm));
    ::testing::Test::RecordProperty(prefix + "_rmse_y_um", static_cast<int>(1000 * s.rmse_y_mm));
}

// The checks shared by every sequence in which the ball stays in view:
// detected within max_detection_delay frames of its first motion and never
// before it; from then on tracked in every frame, the box centre within a
// quarter of the ball's diameter of the ellipse centre and X, Y within
// max_xy_error_mm (after `settle` frames for the box to grow to the ball), a
// 3D point in every frame with depth within 2 % of the visible surface.
void expect_detected_and_tracked(const run_result& r, int settle) {
    const platform::run_summary& s = r.summary;
    ASSERT_GE(s.first_motion_frame, 3) << "the sequence must start with still frames";
    ASSERT_GE(s.detection_frame, 0) << "never detected";
    // Three-frame differencing needs a change on both sides of f(t-1): the
    // earliest possible detection is one frame after the first motion.
    EXPECT_GT(s.detection_frame, s.first_motion_frame);
    EXPECT_LE(s.detection_frame - s.first_motion_frame, max_detection_delay);

    for (const host::host_record& rec : r.records) {
        const platform::frame_errors e = platform::score_frame(rec);
        if (rec.index < s.detection_frame) {
            EXPECT_FALSE(rec.firmware.motion_found) << "frame " << rec.index;
            EXPECT_FALSE(rec.firmware.has_object) << "frame " << rec.index;
            continue;
        }
        ASSERT_TRUE(rec.truth.in_both_views) << "scenario leaves the view at " << rec.index;
        EXPECT_EQ(rec.firmware.state, dsp::tracker_state::track) << "frame " << rec.index;
        ASSERT_TRUE(e.box_scored) << "frame " << rec.index;
        ASSERT_TRUE(e.point_scored) << "no 3D point in frame " << rec.index;
        EXPECT_LE(std::fabs(e.depth_err_pct), max_depth_error_pct) << "frame " << rec.index;
        if (rec.index >= s.detection_frame + settle) {
            EXPECT_LE(e.box_centre_err_px, max_box_error_diameters * ball_diameter_px(rec.truth))
                << "frame " << rec.index;
            EXPECT_LE(std::fabs(e.err_x_mm), max_xy_error_mm) << "frame " << rec.index;
            EXPECT_LE(std::fabs(e.err_y_mm), max_xy_error_mm) << "frame " << rec.index;
        }
    }
}

}  // namespace

// The firmware tests' default scenario: default rig, 5 cm ball still for 6
// frames, then thrown and bouncing at 2.6 m -> 1.6 m, up to ~15 px per frame.
TEST(RenderedSequence, DefaultScenarioDetectsTracksAndMeasuresDepth) {
    const scene::scenario scenario = scene::default_scenario(6);
    const run_result r = run(scenario, scenario.frame_count);
    print_errors("default", r);
    record("default", r.summary);
    EXPECT_EQ(r.summary.first_motion_frame, 6);
    expect_detected_and_tracked(r, /*settle=*/0);
    EXPECT_EQ(r.summary.depth_within_2pct, r.summary.point_scored_frames);
}

// Both ends of the 1-3 m range: the ball circling at 1 m (80 px image) and
// at 3 m (27 px image), 8 px per frame. At 1 m the first detected zone is a
// part of the ball (21 px of 80), so the box gets 6 frames to grow to it.
TEST(RenderedSequence, NearAndFarEndsOfTheDepthRange) {
    for (const double depth_m : {1.0, 3.0}) {
        const scene::scenario scenario = host::circling_scenario(depth_m);
        const run_result r = run(scenario, scenario.frame_count);
        const std::string name = depth_m < 2.0 ? "near_1m" : "far_3m";
        print_errors(name.c_str(), r);
        record(name, r.summary);
        SCOPED_TRACE(name);
        expect_detected_and_tracked(r, /*settle=*/6);
    }
}
