// The box stays on a fast, large or spinning object: the firmware on
// rendered pairs (host runner, no hardware) scored against the renderer's
// closed-form truth (the ball's ellipse centre, its visible surface's mean
// depth), on the procedural background and on a real photograph mapped on
// the background plane.
//
// Bounds, over the pairs from the detection on while the ball is wholly in
// both views: from the third tracked pair on (the first two start from the
// detection's object(t-1), dsp/controller.h), box centre within 3 px of the
// truth on average and 6 px in every pair; |depth error| within 1 % in
// every pair; every pair from the detection on tracked, with a 3D point;
// the processing of every pair within the 24.5 ms frame period at 600 MHz.
// The cases span balls 10 px to half the image wide, motions up to 30 px
// per frame (a pass at 6 times its speed) and the throw's bounce, spins of
// 1 to 10 revolutions per second about each axis; slow passes and circles
// of 1 to 2 px per frame (suite Slow: the key frame, dsp/key_frame.h), and
// slow passes spinning at 0.5 to 3 rev/s (suite SlowSpinning); slow small
// balls entering the view from its edge (round 18); fast balls whose shaded
// rim the differences miss over teddy (suite ShadedRim) and passes
// leftwards (round 20); a fast throw's apex 4 m away (ThrowApex) and large
// balls thrown at half speed (LargeSlowThrow).
//
// The firmware before the silhouette refit (the box moved by the SAD
// pattern and pulled towards object(t-1)) failed 11 of the first 12 cases
// as first written (the two largest balls then at 30 and 20 px per frame,
// scored also while leaving the view): e.g. 40 px at 30 px per frame, mean
// 117 px (the search window lost the ball at the detection); 100 px at
// 10 rev/s, max 11.9 px. The held-out cases were run once, on the rules
// as they stand then: the first five before one image's brightness gain was
// given to both (one of them, 1.21 % in depth, showed that flaw), the next
// three after.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "model/scene/ball_paths.h"
#include "tb/platform/scoring/error_metrics.h"
#include "tests/support/data_path.h"
#include "tests/support/host/box_judge.h"
#include "tests/support/host/scenarios.h"
#include "tests/support/host/stereo_runner.h"
#include "tests/support/photo_texture.h"

namespace {

using host::frame_period_ms;
using host::max_box_error_px;
using host::max_depth_error_pct;
using host::max_mean_box_error_px;
using host::max_side_error;
using host::min_judged_pairs;
using host::min_side_error_px;
using host::untracked_start_pairs;

enum class path_kind {
    pass,
    pass_left,
    thrown,
    circle,
    circle_back,
    enter,
    recede,
    approach,
    rebound,
    orbit_near,
    orbit_far
};
enum class backdrop { procedural, cones, kodim23, kodim19, teddy, tsukuba, venus, aloe };

struct motion_case {
    const char* name;
    double diameter_px;  // at the path's depth (pass) or at its start (throw)
    double depth_m;
    path_kind path;
    double speed;  // the path's time scale (ball_paths.h): pass and enter 5, circle 8 px per frame
                   // x speed
    double spin_rps;  // revolutions per second
    char spin_axis;   // x, y or z
    backdrop background;
    int frames;
    double principal_dx_left_px = 0.0;  // the left camera's principal point off the centre
    double depth_speed_m_s = 0.0;       // rebound: towards the wall, before the bounce
};

void PrintTo(const motion_case& c, std::ostream* os) {
    *os << c.name;
}

std::string case_name(const ::testing::TestParamInfo<motion_case>& info) {
    return info.param.name;
}

// A real photograph mapped on the background plane at 5 m: the Middlebury
// 2003 "cones" and "teddy" and 2001 "tsukuba" and "venus" left views
// (../shared/data/middlebury_2001_2003), cluttered scenes, the 2006 "aloe"
// left view (../shared/data/middlebury_2006_aloe), a fine-textured plant, or
// Kodak kodim23 and kodim19 (../shared/data/kodak_demosaic_gt).
std::shared_ptr<const scene::texture_image> photograph(backdrop which) {
    const char* file = which == backdrop::cones     ? "middlebury_2001_2003/cones/im2.png"
                       : which == backdrop::teddy   ? "middlebury_2001_2003/teddy/im2.png"
                       : which == backdrop::tsukuba ? "middlebury_2001_2003/tsukuba/im3.png"
                       : which == backdrop::venus   ? "middlebury_2001_2003/venus/im2.png"
                       : which == backdrop::aloe    ? "middlebury_2006_aloe/aloeL.jpg"
                       : which == backdrop::kodim19 ? "kodak_demosaic_gt/kodim19.png"
                                                    : "kodak_demosaic_gt/kodim23.png";
    return testsupport::load_photo_texture(test_support::data_path(file));
}

// The pass's height and velocity (5 px per frame right at speed 1), from
// where the ball's left 12 px are outside the right view's left edge: it
// enters the view.
scene::trajectory entering_path(const motion_case& c, const scene::stereo_rig& rig,
                                double start_s) {
    const double centre_px = -0.5 * (rig.width - 1) + 0.5 * c.diameter_px - 12.0;
    const scene::vec3 from{centre_px / rig.focal_px() * c.depth_m, -0.02 * c.depth_m, c.depth_m};
    const scene::vec3 velocity{0.26 * c.depth_m * c.speed, 0.02 * c.depth_m * c.speed, 0.0};
    return scene::trajectory::line(from, velocity, start_s);
}

// The pass mirrored: from as far right of the centre, leftwards.
scene::trajectory leftward_pass(const motion_case& c, double start_s) {
    const double d = c.depth_m;
    return scene::trajectory::line({0.08 * d, -0.02 * d, d},
                                   {-0.26 * d * c.speed, 0.02 * d * c.speed, 0.0}, start_s);
}

// The pass, the ball also going away from the rig (recede: its depth 1.6
// times the start's after 24 frames) or towards it (approach: 0.65 times),
// so its image shrinks or grows by 1.5-2.5 px a frame at 100 px.
scene::trajectory depth_path(const motion_case& c, double start_s) {
    const double d = c.depth_m;
    const double z_rate = c.path == path_kind::recede ? 1.0 : -0.6;  // depths per second
    return scene::trajectory::line({-0.08 * d, -0.02 * d, d},
                                   {0.26 * d * c.speed, 0.02 * d * c.speed, z_rate * d}, start_s);
}

// The circle of scene::circling_path from its other side (its rightmost
// point): it goes down drifting leftwards, where the circle drifts right.
scene::trajectory circle_from_right(const motion_case& c, double start_s) {
    const double d = c.depth_m, radius = 0.15 * d;
    return scene::trajectory::circle({0.0, 0.0, d}, radius, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0},
                                     0.41 * d * c.speed / radius, 0.0, start_s);
}

// The pass, the ball also thrown away from the rig at depth_speed_m_s
// against the background's wall, from which it bounces back at 0.75 of
// that speed: its depth turns within one frame.
scene::trajectory rebound_path(const motion_case& c, double radius_m, double wall_z_m,
                               double start_s) {
    const double d = c.depth_m;
    return scene::trajectory::rebound({-0.08 * d, -0.02 * d, d},
                                      {0.26 * d * c.speed, 0.02 * d * c.speed, c.depth_speed_m_s},
                                      wall_z_m - radius_m, 0.75, start_s);
}

// A horizontal circle (a ball swung on a string): 0.2 depths in radius,
// from 45 degrees before its nearest point (orbit_near) or its farthest
// (orbit_far), so its depth turns smoothly mid-run, at 5 px per frame x
// speed across the image where it turns.
scene::trajectory orbit_path(const motion_case& c, double start_s) {
    const double d = c.depth_m, pi = std::acos(-1.0);
    const double phase = c.path == path_kind::orbit_near ? 1.25 * pi : 0.25 * pi;
    return scene::trajectory::circle({0.0, -0.02 * d, d}, 0.2 * d, {1.0, 0.0, 0.0}, {0.0, 0.0, 1.0},
                                     1.3 * c.speed, phase, start_s);
}

scene::scenario scenario_of(const motion_case& c) {
    scene::scenario s;
    s.scene.rig.principal_dx_left = c.principal_dx_left_px;
    const scene::stereo_rig& rig = s.scene.rig;
    const double wall_z_m = 5.0;
    if (c.background != backdrop::procedural) {
        s.scene.background =
            scene::background_desc::image_plane(photograph(c.background), rig, wall_z_m);
    } else {
        s.scene.background =
            scene::background_desc::procedural_plane(scene::procedural_texture_params{}, wall_z_m);
    }
    const double start = scene::motion_start_s(3, s.frame_period_s);
    scene::ball_desc ball;
    ball.radius_m = host::ball_radius_for_width(c.diameter_px, c.depth_m, rig.focal_px());
    ball.spin_rad_s = c.spin_rps * 2.0 * std::acos(-1.0);
    ball.spin_axis = c.spin_axis == 'x'   ? scene::vec3{1.0, 0.0, 0.0}
                     : c.spin_axis == 'y' ? scene::vec3{0.0, 1.0, 0.0}
                                          : scene::vec3{0.0, 0.0, 1.0};
    ball.path = c.path == path_kind::enter       ? entering_path(c, rig, start)
                : c.path == path_kind::pass      ? scene::pass_path(c.depth_m, c.speed, start)
                : c.path == path_kind::pass_left ? leftward_pass(c, start)
                : c.path == path_kind::recede || c.path == path_kind::approach
                    ? depth_path(c, start)
                : c.path == path_kind::circle      ? scene::circling_path(c.depth_m, c.speed, start)
                : c.path == path_kind::circle_back ? circle_from_right(c, start)
                : c.path == path_kind::rebound     ? rebound_path(c, ball.radius_m, wall_z_m, start)
                : c.path == path_kind::orbit_near || c.path == path_kind::orbit_far
                    ? orbit_path(c, start)
                    : scene::thrown_ball_path(c.depth_m, ball.radius_m, c.speed, start);
    s.scene.balls.push_back(ball);
    s.frame_count = c.frames;
    return s;
}

struct motion_result {
    int detection = -1;
    int after_detection = 0, tracked = 0, points = 0;
    double processing_max_ms = 0.0;
    double motion_max_px = 0.0;  // the truth's largest move between two frames
    host::box_errors judged;     // the scored pairs
};

motion_result run_case(const motion_case& c, host::stereo_runner& runner) {
    const std::vector<host::host_record> records = runner.run(0, c.frames);
    motion_result r;
    r.detection = platform::summarize(host::scored(records),
                                      platform::first_motion_frame(runner.sequence(), c.frames))
                      .detection_frame;
    std::string per_pair;  // box centre error (dx, dy) of each tracked pair
    for (const host::host_record& rec : records) {
        if (rec.index > 0) {
            const scene::sphere_image now = runner.sequence().truth(rec.index).front().right;
            const scene::sphere_image before = runner.sequence().truth(rec.index - 1).front().right;
            r.motion_max_px = std::max(r.motion_max_px,
                                       std::hypot(now.ellipse_centre.x - before.ellipse_centre.x,
                                                  now.ellipse_centre.y - before.ellipse_centre.y));
        }
        if (r.detection < 0 || rec.index < r.detection) continue;
        // Only while the ball is wholly in both views, clear of their
        // outermost pixels and in front of the background plane: a fast pass
        // leaves the left view first, and stereo then rightly gives no point.
        const scene::ball_truth truth = runner.sequence().truth(rec.index).front();
        if (!truth.in_both_views) continue;
        ++r.after_detection;
        r.processing_max_ms = std::max(r.processing_max_ms, host::processing_ms(rec));
        if (rec.firmware.state != dsp::tracker_state::track) {
            // The state, and where the ball was: a pair the track dropped.
            const dsp::box at = truth.right.pixel_box;
            char text[96];
            std::snprintf(text, sizeof text, " %d:%s(ball %d,%d %dx%d)", rec.index,
                          dsp::tracker_state_name(rec.firmware.state), at.x, at.y, at.width,
                          at.height);
            per_pair += text;
            continue;
        }
        ++r.tracked;
        const platform::frame_errors e = platform::score_frame(rec);
        r.points += e.point_scored;
        char text[64];
        std::snprintf(text, sizeof text, " %d:(%.1f,%.1f)%.2f%%", rec.index, e.box_centre_dx_px,
                      e.box_centre_dy_px, e.depth_err_pct);
        per_pair += text;
        if (r.tracked > untracked_start_pairs && e.box_scored && e.point_scored)
            r.judged.score(rec, e);
    }
    const host::box_errors& j = r.judged;
    std::printf(
        "%s: motion up to %.1f px/frame, detected %d, tracked %d of %d, box centre error mean "
        "%.2f max %.2f px over %d pairs, |depth| max %.2f %%, processing max %.2f ms\n",
        c.name, r.motion_max_px, r.detection, r.tracked, r.after_detection, j.box_mean_px(),
        j.box_max_px, j.scored, j.depth_max_pct, r.processing_max_ms);
    std::printf("  pair:(box dx,dy px)depth:%s\n", per_pair.c_str());
    std::printf("  box sides off by up to %.1f %%, pair:(w,h px):%s\n", j.side_max_pct,
                j.sides.c_str());
    return r;
}

// The pairs a case can judge, from its scene's truth alone: those with the
// ball wholly in both views from the first frame three-frame differencing
// can detect it in (two differences with motion: the frame after the first
// one that moved), less the start pairs not judged. Fewer than the judge
// asks for is a defect of the case, not of the firmware.
int judgeable_pairs(const motion_case& c, const scene::sequence& sequence) {
    const int first_motion = platform::first_motion_frame(sequence, c.frames);
    if (first_motion < 0) return 0;
    int in_view = 0;
    for (int n = first_motion + 1; n < c.frames; ++n)
        in_view += sequence.truth(n).front().in_both_views;
    return std::max(0, in_view - untracked_start_pairs);
}

class BoxOnMotion : public ::testing::TestWithParam<motion_case> {};

TEST_P(BoxOnMotion, StaysOnTheObject) {
    const motion_case c = GetParam();
    if (c.background != backdrop::procedural) {
        ASSERT_NE(photograph(c.background), nullptr);
    }
    const scene::scenario scenario = scenario_of(c);
    host::stereo_runner runner(scenario, host::controller_config_for(scenario.scene.rig));
    const int judgeable = judgeable_pairs(c, runner.sequence());
    ASSERT_GE(judgeable, min_judged_pairs) << "three-frame differencing can judge no more than "
                                           << judgeable << " pairs (a defect of the case)";
    const motion_result r = run_case(c, runner);
    ASSERT_GE(r.detection, 0) << "never detected";
    EXPECT_EQ(r.tracked, r.after_detection) << "a pair after the detection not in TRACK";
    EXPECT_EQ(r.points, r.tracked) << "a tracked pair without a 3D point";
    ASSERT_GE(r.judged.scored, min_judged_pairs);
    EXPECT_LE(r.judged.box_mean_px(), max_mean_box_error_px);
    EXPECT_LE(r.judged.box_max_px, max_box_error_px);
    EXPECT_LE(r.judged.side_over_px, 0.0)
        << "a box side off the object's by more than " << 100 * max_side_error << " % ("
        << min_side_error_px << " px)";
    EXPECT_LE(r.judged.depth_max_pct, max_depth_error_pct);
    EXPECT_LE(r.processing_max_ms, frame_period_ms);
}

constexpr path_kind pass = path_kind::pass;
constexpr path_kind pass_left = path_kind::pass_left;
constexpr path_kind thrown = path_kind::thrown;
constexpr path_kind circle = path_kind::circle;
constexpr path_kind circle_back = path_kind::circle_back;
constexpr path_kind enter = path_kind::enter;
constexpr path_kind recede = path_kind::recede;
constexpr path_kind approach = path_kind::approach;
constexpr path_kind rebound = path_kind::rebound;
constexpr path_kind orbit_near = path_kind::orbit_near;
constexpr path_kind orbit_far = path_kind::orbit_far;
constexpr backdrop procedural = backdrop::procedural;
constexpr backdrop photo = backdrop::cones;
constexpr backdrop photo2 = backdrop::kodim23;
constexpr backdrop photo3 = backdrop::kodim19;
constexpr backdrop photo4 = backdrop::teddy;
constexpr backdrop tsukuba = backdrop::tsukuba;
constexpr backdrop venus = backdrop::venus;
constexpr backdrop aloe = backdrop::aloe;

INSTANTIATE_TEST_SUITE_P(
    FastLargeSpinning, BoxOnMotion,
    ::testing::Values(
        // Fast: a pass at 6 times its speed, 30 px per frame.
        motion_case{"pass10px_30pxpf", 10, 2.6, pass, 6.0, 0.0, 'x', procedural, 16},
        motion_case{"pass40px_30pxpf", 40, 2.0, pass, 6.0, 0.0, 'x', procedural, 14},
        motion_case{"pass160px_20pxpf", 160, 1.6, pass, 4.0, 0.0, 'x', procedural, 14},
        motion_case{"pass320px_15pxpf", 320, 1.4, pass, 3.0, 0.0, 'x', procedural, 16},
        motion_case{"pass80px_30pxpf_photo", 80, 1.8, pass, 6.0, 5.0, 'y', photo, 13},
        // The throw and its bounce (up to 23 px per frame), spinning.
        motion_case{"throw60px_1rps_x", 60, 2.6, thrown, 1.0, 1.0, 'x', procedural, 30},
        motion_case{"throw60px_5rps_x", 60, 2.6, thrown, 1.0, 5.0, 'x', procedural, 30},
        motion_case{"throw100px_10rps_y", 100, 2.6, thrown, 1.0, 10.0, 'y', procedural, 30},
        motion_case{"throw90px_5rps_z", 90, 2.6, thrown, 1.0, 5.0, 'z', procedural, 30},
        motion_case{"throw60px_10rps_x_photo", 60, 2.6, thrown, 1.0, 10.0, 'x', photo, 30},
        motion_case{"throw100px_5rps_x_photo", 100, 2.6, thrown, 1.0, 5.0, 'x', photo, 30},
        motion_case{"throw33px_photo", 33, 2.6, thrown, 1.0, 0.0, 'x', photo, 30},
        // Held out: not run while the refit's rules were chosen on the cases
        // above, run once after, on another photograph (Kodak kodim23).
        motion_case{"heldout_pass25px_25pxpf", 25, 2.4, pass, 5.0, 0.0, 'x', procedural, 16},
        // 1.21 % in depth with a gain per image, 0.52 % with one gain.
        motion_case{"heldout_pass120px_25pxpf_photo2", 120, 1.7, pass, 5.0, 3.0, 'z', photo2, 13},
        motion_case{"heldout_throw75px_7rps_y_photo2", 75, 2.6, thrown, 1.0, 7.0, 'y', photo2, 30},
        motion_case{"heldout_throw150px_2rps_z", 150, 2.6, thrown, 1.0, 2.0, 'z', procedural, 30},
        motion_case{"heldout_throw45px_8rps_x", 45, 2.6, thrown, 1.0, 8.0, 'x', procedural, 30},
        // Held out from the one-gain change (run once after it; Kodak kodim19
        // and Middlebury "teddy", backgrounds no rule was chosen on).
        motion_case{"heldout2_pass200px_20pxpf_photo3", 200, 1.5, pass, 4.0, 4.0, 'y', photo3, 14},
        // Open (depth 1.02, 1.07, 1.41 %) until the outline-masked tiles.
        motion_case{"heldout2_throw110px_6rps_z_photo4", 110, 2.6, thrown, 1.0, 6.0, 'z', photo4,
                    30},
        motion_case{"open_throw110px_6rps_z_photo2", 110, 2.6, thrown, 1.0, 6.0, 'z', photo2, 30},
        motion_case{"open_throw110px_photo2", 110, 2.6, thrown, 1.0, 0.0, 'x', photo2, 30}),
    case_name);

// Slow objects, 2 px per frame and less: the thin differences of one pair
// miss the outline along the motion, and the box's size and place across
// it come from a key frame (dsp/key_frame.h); a slow detection is started
// only once its object moved key_frame::min_shift px, on Dif(key, t)'s
// outline (dsp/controller_detect.cpp, start_track), as one pair's detection may
// hold a crescent of it. The first case was an open case (mean 4.20, max
// 7.81 px before the key frame).
INSTANTIATE_TEST_SUITE_P(
    Slow, BoxOnMotion,
    ::testing::Values(
        motion_case{"pass60px_1pxpf", 60, 2.6, pass, 0.2, 0.0, 'x', procedural, 30},
        // Held out in round 3 and failed there (9.62 px in one pair, the
        // silhouette overruling the key); passes since the key is kept.
        motion_case{"pass30px_1pxpf", 30, 2.6, pass, 0.2, 0.0, 'x', procedural, 30},
        // Held out: written before the key frame's rules were run on them,
        // run once after (circling at its leftmost point: mostly vertical).
        // Five of those ten failed; the rules that a key is taken only on a
        // box a silhouette confirms and is not overruled by one pair's
        // silhouette came after that.
        motion_case{"heldout3_pass200px_1pxpf", 200, 1.5, pass, 0.2, 0.0, 'x', procedural, 30},
        motion_case{"heldout3_pass110px_2pxpf", 110, 2.6, pass, 0.4, 0.0, 'x', procedural, 30},
        motion_case{"heldout3_circle80px_1pxpf_photo2", 80, 2.6, circle, 0.125, 0.0, 'x', photo2,
                    30},
        motion_case{"heldout3_circle50px_2pxpf", 50, 2.6, circle, 0.25, 0.0, 'x', procedural, 30},
        motion_case{"heldout3_pass60px_1pxpf_3rps_z", 60, 2.6, pass, 0.2, 3.0, 'z', procedural, 30},
        // Held out from the key frame's final rules: written before, run
        // once after. Four of six passed.
        motion_case{"heldout4_pass45px_1pxpf_photo2", 45, 2.6, pass, 0.2, 0.0, 'x', photo2, 30},
        motion_case{"heldout4_circle120px_1pxpf", 120, 2.6, circle, 0.125, 0.0, 'x', procedural,
                    30},
        motion_case{"heldout4_pass90px_1pxpf_2rps_y", 90, 2.6, pass, 0.2, 2.0, 'y', procedural, 30},
        motion_case{"heldout4_pass20px_2pxpf_photo2", 20, 2.6, pass, 0.4, 0.0, 'x', photo2, 30},
        // Open until the slow detection was keyed (its rules were chosen on
        // these): a crescent or a piece detected (box means before: 3.80,
        // 10.84, 6.81, 35.19, 19.20 px).
        motion_case{"heldout3_pass110px_1pxpf_photo", 110, 2.6, pass, 0.2, 0.0, 'x', photo, 30},
        motion_case{"heldout4_pass150px_1_5pxpf_photo", 150, 2.6, pass, 0.3, 0.0, 'x', photo, 30},
        motion_case{"heldout4_circle70px_1_5pxpf_photo4", 70, 2.6, circle, 0.1875, 0.0, 'x', photo4,
                    30},
        motion_case{"heldout5_pass130px_1pxpf_photo", 130, 2.6, pass, 0.2, 0.0, 'x', photo, 30},
        motion_case{"heldout5_circle90px_1pxpf_photo3", 90, 2.6, circle, 0.125, 0.0, 'x', photo3,
                    30},
        // Held out, round 6: three photographs no rule was chosen on
        // (tsukuba, venus, aloe), written before the keyed slow detection
        // ran on them, run once after: five of eight pass (three open
        // below). The firmware before it passed the same five.
        motion_case{"heldout6_pass140px_1_5pxpf_tsukuba", 140, 2.6, pass, 0.3, 0.0, 'x', tsukuba,
                    30},
        motion_case{"heldout6_pass70px_1pxpf_venus", 70, 2.6, pass, 0.2, 0.0, 'x', venus, 30},
        motion_case{"heldout6_pass90px_2pxpf_aloe", 90, 2.6, pass, 0.4, 0.0, 'x', aloe, 30},
        motion_case{"heldout6_pass120px_1pxpf_2rps_y_aloe", 120, 2.6, pass, 0.2, 2.0, 'y', aloe,
                    30},
        motion_case{"heldout6_pass50px_1pxpf_photo4", 50, 2.6, pass, 0.2, 0.0, 'x', photo4, 30},
        // Held out, round 7: new sizes, paths and a spin over the cluttered
        // photographs of the open cases, written after the rules were final,
        // run once: three of six pass (three open below); the firmware
        // before passed one (box means before 2.06, 4.23, 52.33 px).
        motion_case{"heldout7_pass90px_1pxpf_photo", 90, 2.6, pass, 0.2, 0.0, 'x', photo, 30},
        motion_case{"heldout7_pass70px_1pxpf_photo3", 70, 2.6, pass, 0.2, 0.0, 'x', photo3, 30},
        motion_case{"heldout7_circle120px_1pxpf_photo", 120, 2.6, circle, 0.125, 0.0, 'x', photo,
                    30},
        // Open on depth (1.13-1.80 %) until the outline-masked tiles.
        motion_case{"open_pass110px_1pxpf_photo2", 110, 2.6, pass, 0.2, 0.0, 'x', photo2, 30},
        motion_case{"heldout3_pass110px_1pxpf_photo4", 110, 2.6, pass, 0.2, 0.0, 'x', photo4, 30},
        motion_case{"heldout3_pass110px_1pxpf_photo3", 110, 2.6, pass, 0.2, 0.0, 'x', photo3, 30},
        motion_case{"heldout5_pass100px_1pxpf_photo4", 100, 2.6, pass, 0.2, 0.0, 'x', photo4, 30},
        motion_case{"heldout6_pass110px_1pxpf_tsukuba", 110, 2.6, pass, 0.2, 0.0, 'x', tsukuba, 30},
        motion_case{"heldout6_circle100px_1pxpf_aloe", 100, 2.6, circle, 0.125, 0.0, 'x', aloe, 30},
        motion_case{"heldout7_pass130px_1_5pxpf_photo4", 130, 2.6, pass, 0.3, 0.0, 'x', photo4, 30},
        // Half the image wide at 1 px per frame: passes with the rules
        // before and since a keyed box is not shrunk by one pair's
        // silhouette (0.85 / 1.71 px both: the host runner has no sensor
        // noise; the co-simulated MotionScenarios.SlowLargeBall needed them).
        motion_case{"pass320px_1pxpf", 320, 1.4, pass, 0.2, 0.0, 'x', procedural, 30},
        // Round 7's 160 px ball about z over kodim19, open until a box held
        // where the difference is shorter than the ball and a key's
        // displacement bounded by Dif(key, t) (dsp/box_refit.h).
        motion_case{"heldout7_pass160px_1pxpf_1rps_z_photo3", 160, 2.6, pass, 0.2, 1.0, 'z', photo3,
                    30}),
    case_name);

// Held out from the outline-masked tiles (dsp/object_depth.h): written and
// committed before that rule ran on them, run once after.
INSTANTIATE_TEST_SUITE_P(
    HeldOutOutline, BoxOnMotion,
    ::testing::Values(
        motion_case{"heldout8_pass105px_1pxpf_photo2", 105, 2.2, pass, 0.2, 0.0, 'x', photo2, 30},
        motion_case{"heldout8_throw125px_4rps_y_aloe", 125, 2.6, thrown, 1.0, 4.0, 'y', aloe, 30},
        motion_case{"heldout8_pass180px_1_5pxpf_venus", 180, 1.8, pass, 0.3, 0.0, 'x', venus, 30},
        motion_case{"heldout8_circle115px_1pxpf_tsukuba", 115, 2.6, circle, 0.125, 0.0, 'x',
                    tsukuba, 30},
        motion_case{"heldout8_pass100px_12pxpf_2rps_x_photo3", 100, 2.0, pass, 2.4, 2.0, 'x',
                    photo3, 16},
        motion_case{"heldout8_pass240px_1pxpf_photo", 240, 1.5, pass, 0.2, 0.0, 'x', photo, 30},
        // Open (1.67 / 6.50 px) until a size measured short across the
        // motion was no longer taken (dsp/box_refit.h, across_motion;
        // traced for it).
        motion_case{"heldout8_throw140px_3rps_x_photo4", 140, 2.6, thrown, 1.0, 3.0, 'x', photo4,
                    30}),
    case_name);

// Slow and spinning: a grid of 40, 80 and 140 px balls passing at 1 px per
// frame, spinning at 0.5 to 3 rev/s about each axis (a ball rolled or
// tossed gently), written and run once on the firmware as it was; the 25
// that passed then are here, the 11 that failed in DISABLED_Open. The last
// four here failed until the key read its displacement from Dif(key, t) once
// its pattern turned (dsp/box_refit.h, difference_shift): development cases
// of that rule since. The three 140 px balls about y after them failed until
// a key of the outline (dsp/controller_key.cpp, follow_outline_key; 1 rev/s was
// traced for it): their texture outran them, no key was taken and the
// silhouette missed their poles. The last two failed until a detection's box
// may grow to both differences' common part (dsp/controller_track.cpp,
// follow_object; 1 rev/s about x was traced for it) and the axis across the
// motion of a key of the outline was judged afresh each pair.
INSTANTIATE_TEST_SUITE_P(
    SlowSpinning, BoxOnMotion,
    ::testing::Values(
        motion_case{"spin40px_1pxpf_0_5rps_x", 40, 2.6, pass, 0.2, 0.5, 'x', procedural, 30},
        motion_case{"spin40px_1pxpf_1rps_x", 40, 2.6, pass, 0.2, 1.0, 'x', procedural, 30},
        motion_case{"spin40px_1pxpf_2rps_x", 40, 2.6, pass, 0.2, 2.0, 'x', procedural, 30},
        motion_case{"spin40px_1pxpf_3rps_x", 40, 2.6, pass, 0.2, 3.0, 'x', procedural, 30},
        motion_case{"spin40px_1pxpf_1rps_y", 40, 2.6, pass, 0.2, 1.0, 'y', procedural, 30},
        motion_case{"spin40px_1pxpf_2rps_y", 40, 2.6, pass, 0.2, 2.0, 'y', procedural, 30},
        motion_case{"spin40px_1pxpf_3rps_y", 40, 2.6, pass, 0.2, 3.0, 'y', procedural, 30},
        motion_case{"spin40px_1pxpf_0_5rps_z", 40, 2.6, pass, 0.2, 0.5, 'z', procedural, 30},
        motion_case{"spin40px_1pxpf_1rps_z", 40, 2.6, pass, 0.2, 1.0, 'z', procedural, 30},
        motion_case{"spin40px_1pxpf_2rps_z", 40, 2.6, pass, 0.2, 2.0, 'z', procedural, 30},
        motion_case{"spin40px_1pxpf_3rps_z", 40, 2.6, pass, 0.2, 3.0, 'z', procedural, 30},
        motion_case{"spin80px_1pxpf_0_5rps_x", 80, 2.6, pass, 0.2, 0.5, 'x', procedural, 30},
        motion_case{"spin80px_1pxpf_1rps_x", 80, 2.6, pass, 0.2, 1.0, 'x', procedural, 30},
        motion_case{"spin80px_1pxpf_2rps_x", 80, 2.6, pass, 0.2, 2.0, 'x', procedural, 30},
        motion_case{"spin80px_1pxpf_3rps_x", 80, 2.6, pass, 0.2, 3.0, 'x', procedural, 30},
        motion_case{"spin80px_1pxpf_2rps_y", 80, 2.6, pass, 0.2, 2.0, 'y', procedural, 30},
        motion_case{"spin80px_1pxpf_3rps_y", 80, 2.6, pass, 0.2, 3.0, 'y', procedural, 30},
        motion_case{"spin80px_1pxpf_0_5rps_z", 80, 2.6, pass, 0.2, 0.5, 'z', procedural, 30},
        motion_case{"spin80px_1pxpf_1rps_z", 80, 2.6, pass, 0.2, 1.0, 'z', procedural, 30},
        motion_case{"spin80px_1pxpf_2rps_z", 80, 2.6, pass, 0.2, 2.0, 'z', procedural, 30},
        motion_case{"spin80px_1pxpf_3rps_z", 80, 2.6, pass, 0.2, 3.0, 'z', procedural, 30},
        motion_case{"spin140px_1pxpf_2rps_x", 140, 2.6, pass, 0.2, 2.0, 'x', procedural, 30},
        motion_case{"spin140px_1pxpf_3rps_x", 140, 2.6, pass, 0.2, 3.0, 'x', procedural, 30},
        motion_case{"spin140px_1pxpf_2rps_z", 140, 2.6, pass, 0.2, 2.0, 'z', procedural, 30},
        motion_case{"spin140px_1pxpf_3rps_z", 140, 2.6, pass, 0.2, 3.0, 'z', procedural, 30},
        motion_case{"spin40px_1pxpf_0_5rps_y", 40, 2.6, pass, 0.2, 0.5, 'y', procedural, 30},
        motion_case{"spin80px_1pxpf_0_5rps_y", 80, 2.6, pass, 0.2, 0.5, 'y', procedural, 30},
        motion_case{"spin80px_1pxpf_1rps_y", 80, 2.6, pass, 0.2, 1.0, 'y', procedural, 30},
        motion_case{"spin140px_1pxpf_0_5rps_z", 140, 2.6, pass, 0.2, 0.5, 'z', procedural, 30},
        motion_case{"spin140px_1pxpf_1rps_y", 140, 2.6, pass, 0.2, 1.0, 'y', procedural, 30},
        motion_case{"spin140px_1pxpf_2rps_y", 140, 2.6, pass, 0.2, 2.0, 'y', procedural, 30},
        motion_case{"spin140px_1pxpf_3rps_y", 140, 2.6, pass, 0.2, 3.0, 'y', procedural, 30},
        motion_case{"spin140px_1pxpf_1rps_x", 140, 2.6, pass, 0.2, 1.0, 'x', procedural, 30},
        motion_case{"spin140px_1pxpf_0_5rps_y", 140, 2.6, pass, 0.2, 0.5, 'y', procedural, 30},
        // Since a box held where the difference is shorter than the ball and
        // a key's displacement bounded by Dif(key, t) (dsp/box_refit.h,
        // follow_axis, bounded_shift).
        motion_case{"spin140px_1pxpf_1rps_z", 140, 2.6, pass, 0.2, 1.0, 'z', procedural, 30},
        // Since a key's bounded axis is taken from Dif(key, t) only where that
        // holds the key's box (bounded_shift): before, 2.33 / 9.75 px, a key's
        // first pair shrank the box to the partial difference.
        motion_case{"spin140px_1pxpf_0_5rps_x", 140, 2.6, pass, 0.2, 0.5, 'x', procedural, 30}),
    case_name);

// Held out, round 9: slow spinning balls on other sizes, rates, paths and
// backgrounds than the SlowSpinning grid, written and committed before any
// rule for slow spinning balls was tried, run once on a rule tried and not
// kept (docs/firmware.md, "Open") and on the firmware then: six passed on
// both. The 100 px ball over venus (last here) passes since the key reads
// Dif(key, t) once its pattern turned (a development case of that rule);
// the 160 px ball over kodim19 (last) since a key's box short on both sides
// of Dif(key, t) is grown by it (dsp/box_refit.h, outline_key_axis).
INSTANTIATE_TEST_SUITE_P(HeldOutSpinning, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout9_spin60px_1pxpf_1_5rps_y_aloe", 60,
                                                       2.6, pass, 0.2, 1.5, 'y', aloe, 30},
                                           motion_case{"heldout9_spin110px_1pxpf_0_5rps_x_photo2",
                                                       110, 2.6, pass, 0.2, 0.5, 'x', photo2, 30},
                                           motion_case{"heldout9_spin50px_1pxpf_2_5rps_z_tsukuba",
                                                       50, 2.6, pass, 0.2, 2.5, 'z', tsukuba, 30},
                                           motion_case{"heldout9_circle90px_1pxpf_1rps_y", 90, 2.6,
                                                       circle, 0.125, 1.0, 'y', procedural, 30},
                                           motion_case{"heldout9_spin120px_1_5pxpf_1rps_x", 120,
                                                       2.6, pass, 0.3, 1.0, 'x', procedural, 30},
                                           motion_case{"heldout9_spin70px_1pxpf_0_7rps_y_photo", 70,
                                                       2.6, pass, 0.2, 0.7, 'y', photo, 30},
                                           motion_case{"heldout9_spin100px_2pxpf_1rps_y_venus", 100,
                                                       2.6, pass, 0.4, 1.0, 'y', venus, 30},
                                           motion_case{"heldout9_spin160px_1pxpf_2rps_y_photo3",
                                                       160, 2.2, pass, 0.2, 2.0, 'y', photo3, 30}),
                         case_name);

// Held out, round 10: slow spinning balls on sizes, rates, axes and
// backgrounds neither the grid nor round 9 has, written and committed
// before a variant of the round outline (docs/firmware.md, "Open") was
// tried; run once on the firmware: 5 of 8 pass. The 130 px ball over cones
// (box 43 px ahead of it) was then traced and the rule for a part of the
// object (dsp/box_refit.h, is_part) made from it: no longer held out. The
// last two here pass since the key reads Dif(key, t) once its pattern turned
// (development cases of that rule), which moved the 130 px ball's last pair
// to 6.21 px; it passes again with a key of the outline (last here).
INSTANTIATE_TEST_SUITE_P(HeldOutSpinning10, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout10_spin75px_1pxpf_1_2rps_y_photo4",
                                                       75, 2.6, pass, 0.2, 1.2, 'y', photo4, 30},
                                           motion_case{"heldout10_spin45px_1pxpf_0_7rps_z_photo2",
                                                       45, 2.6, pass, 0.2, 0.7, 'z', photo2, 30},
                                           motion_case{"heldout10_spin150px_1pxpf_1_5rps_x_aloe",
                                                       150, 2.4, pass, 0.2, 1.5, 'x', aloe, 30},
                                           motion_case{"heldout10_spin60px_2pxpf_0_8rps_y_venus",
                                                       60, 2.6, pass, 0.4, 0.8, 'y', venus, 30},
                                           motion_case{"heldout10_spin120px_1pxpf_2_5rps_z", 120,
                                                       2.6, pass, 0.2, 2.5, 'z', procedural, 30},
                                           motion_case{"heldout10_spin95px_1_5pxpf_1_8rps_y", 95,
                                                       2.6, pass, 0.3, 1.8, 'y', procedural, 30},
                                           motion_case{
                                               "heldout10_circle110px_1pxpf_0_6rps_y_tsukuba", 110,
                                               2.6, circle, 0.125, 0.6, 'y', tsukuba, 30},
                                           motion_case{"heldout10_spin130px_1pxpf_0_7rps_x_photo",
                                                       130, 2.6, pass, 0.2, 0.7, 'x', photo, 30}),
                         case_name);

// Held out, round 11: more slow balls, spinning or not, and a throw, on
// sizes, rates and backgrounds no round before has, written and committed
// before a change of the refit's follow_axis was tried (not kept), run once
// on the rule for a part of the object and once on the firmware before it:
// 7 of 8 pass on both, with the same figures. The last failed (4.02 / 12.17
// px) until a key's pattern the difference contradicts gave way to it
// (dsp/box_refit.h, contradicted_shift; traced for it).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSlow11, BoxOnMotion,
    ::testing::Values(motion_case{"heldout11_spin115px_1pxpf_0_6rps_x_photo4", 115, 2.6, pass, 0.2,
                                  0.6, 'x', photo4, 30},
                      motion_case{"heldout11_spin85px_1pxpf_0_9rps_z_photo", 85, 2.6, pass, 0.2,
                                  0.9, 'z', photo, 30},
                      motion_case{"heldout11_spin140px_1_5pxpf_0_8rps_x_tsukuba", 140, 2.6, pass,
                                  0.3, 0.8, 'x', tsukuba, 30},
                      motion_case{"heldout11_pass105px_1pxpf_photo2", 105, 2.6, pass, 0.2, 0.0, 'x',
                                  photo2, 30},
                      motion_case{"heldout11_spin65px_1pxpf_1_4rps_x_aloe", 65, 2.6, pass, 0.2, 1.4,
                                  'x', aloe, 30},
                      motion_case{"heldout11_circle100px_1pxpf_1rps_z_photo3", 100, 2.6, circle,
                                  0.125, 1.0, 'z', photo3, 30},
                      motion_case{"heldout11_throw100px_2rps_z_photo", 100, 2.6, thrown, 1.0, 2.0,
                                  'z', photo, 30},
                      motion_case{"heldout11_spin125px_2pxpf_0_5rps_y_venus", 125, 2.6, pass, 0.4,
                                  0.5, 'y', venus, 30}),
    case_name);

// Held out, round 12: slow balls spinning about y and x (the texture moving
// along or across the motion) and one not spinning, on sizes, rates and
// backgrounds no round before has, written and committed before a rule for
// a key whose pattern turns was tried, run once on that rule and once on
// the firmware before it: 5 of 8 pass on both (the rule moved the 115 px
// ball's mean 4.13 -> 2.28 px, its max stays 7.24); three failed. The last
// two but one here pass since a key of the outline (box max 7.24 -> 4.96 and
// 11.71 -> 2.68 px), the 75 px ball circling over cones (last) since a
// detection's box may grow to both differences' common part (7.61 -> 4.93).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSlow12, BoxOnMotion,
    ::testing::Values(motion_case{"heldout12_spin90px_1pxpf_0_7rps_y_photo4", 90, 2.6, pass, 0.2,
                                  0.7, 'y', photo4, 30},
                      motion_case{"heldout12_spin50px_1pxpf_0_6rps_y_photo2", 50, 2.6, pass, 0.2,
                                  0.6, 'y', photo2, 30},
                      motion_case{"heldout12_spin65px_2pxpf_0_9rps_y_aloe", 65, 2.6, pass, 0.4, 0.9,
                                  'y', aloe, 30},
                      motion_case{"heldout12_spin100px_1pxpf_0_6rps_x_venus", 100, 2.6, pass, 0.2,
                                  0.6, 'x', venus, 30},
                      motion_case{"heldout12_pass85px_1pxpf_tsukuba", 85, 2.6, pass, 0.2, 0.0, 'x',
                                  tsukuba, 30},
                      motion_case{"heldout12_spin115px_1_5pxpf_1_3rps_y_photo3", 115, 2.6, pass,
                                  0.3, 1.3, 'y', photo3, 30},
                      motion_case{"heldout12_spin150px_1pxpf_0_8rps_y", 150, 2.4, pass, 0.2, 0.8,
                                  'y', procedural, 30},
                      motion_case{"heldout12_circle75px_1pxpf_0_8rps_y_photo", 75, 2.6, circle,
                                  0.125, 0.8, 'y', photo, 30}),
    case_name);

// Held out, round 13: slow balls spinning fast enough that the texture
// outruns the ball (about y, x and z; one circling), on sizes, rates and
// backgrounds no case had, written and committed before a key of the
// outline (dsp/controller_key.cpp, follow_outline_key) ran on them, run once on
// it and once on the firmware before: 7 of 8 pass on both (the key moved four
// means: 1.02 -> 0.65, 2.08 -> 1.15, 1.26 -> 0.75, 1.00 -> 0.91 px). A 110 px
// ball circling over teddy at 2 rev/s failed on both (24.1 px; its
// detection a 67 x 34 px part) and was then traced: it passes since a
// detection's box may grow to both differences' common part (last here; a
// development case of that rule, no longer held out).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSlow13, BoxOnMotion,
    ::testing::Values(motion_case{"heldout13_spin135px_1pxpf_1_7rps_y_tsukuba", 135, 2.6, pass, 0.2,
                                  1.7, 'y', tsukuba, 30},
                      motion_case{"heldout13_spin105px_1_5pxpf_2_5rps_y_photo2", 105, 2.6, pass,
                                  0.3, 2.5, 'y', photo2, 30},
                      motion_case{"heldout13_spin170px_1pxpf_1_2rps_y", 170, 2.2, pass, 0.2, 1.2,
                                  'y', procedural, 30},
                      motion_case{"heldout13_spin120px_1pxpf_2_2rps_x_venus", 120, 2.6, pass, 0.2,
                                  2.2, 'x', venus, 30},
                      motion_case{"heldout13_spin145px_2pxpf_1_5rps_y_aloe", 145, 2.6, pass, 0.4,
                                  1.5, 'y', aloe, 30},
                      motion_case{"heldout13_spin95px_1pxpf_3_5rps_z_photo", 95, 2.6, pass, 0.2,
                                  3.5, 'z', photo, 30},
                      motion_case{"heldout13_spin80px_1pxpf_1_5rps_y_photo3", 80, 2.6, pass, 0.2,
                                  1.5, 'y', photo3, 30},
                      motion_case{"heldout13_circle110px_1pxpf_2rps_y_photo4", 110, 2.6, circle,
                                  0.125, 2.0, 'y', photo4, 30}),
    case_name);

// Held out, round 14: large slow balls spinning fast enough that the
// texture outruns them (about y, x and z; one circling), on sizes, rates
// and backgrounds no case had, written and committed disabled after a key's
// box short on both sides was grown (dsp/box_refit.h, outline_key_axis) and
// before any run, run once on it and once on the firmware before it: 8 of 8
// pass on both; the rule moved four means nearer (0.91 -> 0.75, 0.46 ->
// 0.43, 1.08 -> 0.90, 1.17 -> 1.16 px) and one further (0.58 -> 0.64 px).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSlow14, BoxOnMotion,
    ::testing::Values(motion_case{"heldout14_spin175px_1pxpf_2_5rps_y_cones", 175, 2.2, pass, 0.2,
                                  2.5, 'y', photo, 30},
                      motion_case{"heldout14_spin155px_1pxpf_1_8rps_y_kodim23", 155, 2.4, pass, 0.2,
                                  1.8, 'y', photo2, 30},
                      motion_case{"heldout14_spin130px_1_5pxpf_2rps_x_tsukuba", 130, 2.6, pass, 0.3,
                                  2.0, 'x', tsukuba, 30},
                      motion_case{"heldout14_spin185px_1pxpf_3rps_y", 185, 2.2, pass, 0.2, 3.0, 'y',
                                  procedural, 30},
                      motion_case{"heldout14_spin145px_1pxpf_1_5rps_z_aloe", 145, 2.6, pass, 0.2,
                                  1.5, 'z', aloe, 30},
                      motion_case{"heldout14_circle130px_1pxpf_1_5rps_y_venus", 130, 2.6, circle,
                                  0.125, 1.5, 'y', venus, 30},
                      motion_case{"heldout14_spin100px_2pxpf_2rps_y_teddy", 100, 2.6, pass, 0.4,
                                  2.0, 'y', photo4, 30},
                      motion_case{"heldout14_spin165px_1_5pxpf_1_2rps_x_kodim19", 165, 2.2, pass,
                                  0.3, 1.2, 'x', photo3, 30}),
    case_name);

// Held out, round 15: slow balls spinning about x and z (the texture moving
// across the motion or in the image plane) at 0.5-1.2 rev/s, on sizes and
// backgrounds no such case had, written and committed disabled after a box
// held where the difference is short and a key's displacement bounded by
// Dif(key, t) (dsp/box_refit.h, follow_axis, bounded_shift) and before any
// run, run once on them and once on the firmware before them: 7 of 8 pass
// on both; the rules moved two means nearer (1.45 / 3.92 -> 1.04 / 3.48,
// 1.04 / 3.20 -> 0.89 / 1.89 px). A 140 px ball circling over aloe (last)
// failed on both (3.74 / 10.92 -> 3.79 / 10.92 px) until an axis the key's
// box did not outline was read against Dif(key, t)'s first extent
// (dsp/box_refit.h, first_extent_shift; traced for it).
INSTANTIATE_TEST_SUITE_P(HeldOutSlow15, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout15_spin150px_1pxpf_0_8rps_z_teddy",
                                                       150, 2.4, pass, 0.2, 0.8, 'z', photo4, 30},
                                           motion_case{"heldout15_spin120px_1pxpf_0_6rps_x_kodim23",
                                                       120, 2.6, pass, 0.2, 0.6, 'x', photo2, 30},
                                           motion_case{"heldout15_spin170px_1pxpf_1rps_x", 170, 2.2,
                                                       pass, 0.2, 1.0, 'x', procedural, 30},
                                           motion_case{"heldout15_spin100px_1_5pxpf_0_7rps_z_venus",
                                                       100, 2.6, pass, 0.3, 0.7, 'z', venus, 30},
                                           motion_case{"heldout15_spin130px_1pxpf_1_2rps_z_tsukuba",
                                                       130, 2.6, pass, 0.2, 1.2, 'z', tsukuba, 30},
                                           motion_case{"heldout15_spin160px_2pxpf_0_7rps_x_cones",
                                                       160, 2.2, pass, 0.4, 0.7, 'x', photo, 30},
                                           motion_case{"heldout15_spin90px_1pxpf_0_5rps_z_kodim19",
                                                       90, 2.6, pass, 0.2, 0.5, 'z', photo3, 30},
                                           motion_case{"heldout15_circle140px_1pxpf_0_6rps_x_aloe",
                                                       140, 2.6, circle, 0.125, 0.6, 'x', aloe,
                                                       30}),
                         case_name);

// Held-out round 16: slow balls at 0.5-1 px per frame, written after the
// strided detection (dsp/stride_history.h) and before it was run on them,
// run once on it and once without it.
INSTANTIATE_TEST_SUITE_P(HeldOutSlow16, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout16_pass60px_halfpxpf_cones", 60, 2.6,
                                                       pass, 0.1, 0.0, 'x', photo, 30},
                                           motion_case{"heldout16_pass120px_halfpxpf_kodim23", 120,
                                                       2.6, pass, 0.1, 0.0, 'x', photo2, 30},
                                           motion_case{"heldout16_circle100px_halfpxpf_tsukuba",
                                                       100, 2.6, circle, 0.0625, 0.0, 'x', tsukuba,
                                                       30},
                                           motion_case{"heldout16_pass40px_0_75pxpf_aloe", 40, 2.6,
                                                       pass, 0.15, 0.0, 'x', aloe, 30},
                                           motion_case{"heldout16_circle70px_1pxpf_venus", 70, 2.6,
                                                       circle, 0.125, 0.0, 'x', venus, 30},
                                           motion_case{"heldout16_pass90px_halfpxpf_1rps_y", 90,
                                                       2.6, pass, 0.1, 1.0, 'y', procedural, 30}),
                         case_name);

// Held-out round 17: small balls and weakly textured passes at 0.5-1 px
// per frame, written after round 16 (whose balls one pair's differences
// detected, as early, without the stride) and run as round 16.
INSTANTIATE_TEST_SUITE_P(HeldOutSlow17, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout17_pass12px_1pxpf", 12, 2.6, pass,
                                                       0.2, 0.0, 'x', procedural, 30},
                                           motion_case{"heldout17_pass20px_halfpxpf_kodim19", 20,
                                                       2.6, pass, 0.1, 0.0, 'x', photo3, 30},
                                           motion_case{"heldout17_circle60px_halfpxpf_teddy", 60,
                                                       2.6, circle, 0.0625, 0.0, 'x', photo4, 30},
                                           motion_case{"heldout17_pass16px_1pxpf_aloe", 16, 2.6,
                                                       pass, 0.2, 0.0, 'x', aloe, 30},
                                           motion_case{"heldout17_circle30px_1pxpf_tsukuba", 30,
                                                       2.6, circle, 0.125, 0.0, 'x', tsukuba, 30}),
                         case_name);

// Detected too late for 30 frames until the strided detection
// (dsp/stride_history.h; one pair's differences found nothing in pairs
// 3-21 of the second): an 80 px ball at 0.5 px per frame over kodim19 (no
// start: box 2.40 / 3.26 px since, detected in pair 17), an 80 px ball
// circling over teddy (pair 25, 3 pairs scored: now pair 14, 0.49 / 0.81 px).
INSTANTIATE_TEST_SUITE_P(SlowDetection, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout3_pass80px_halfpxpf_photo3", 80, 2.6,
                                                       pass, 0.1, 0.0, 'x', photo3, 30},
                                           motion_case{"heldout7_circle80px_1pxpf_photo4", 80, 2.6,
                                                       circle, 0.125, 0.0, 'x', photo4, 30}),
                         case_name);

// Held out, round 18: slow small balls entering the view from its left
// edge (a strided detection there is not keyed: mutant fw-85), written
// before they were run. Two passed; the 20 px ball at 0.5 px per frame over
// kodim19 failed: its slow candidate was confirmed on Dif(key, t) while the
// edge cut it (pair 12, a box 11 px wide at x = 4, one past the border
// band: the extent reached x = 0, its trailing rim outside), and lost when
// the box reached the edge (pair 15); so again in pairs 25-27, and the pairs
// since the ball was wholly in view (27) untracked until 42. A candidate
// whose Dif(key, t) reaches the border band is not started since
// (confirm_slow_object; test_slow_candidate.cpp, DoesNotStartABallCutBy...),
// and that case is a development case of that rule. The first two run 40
// pairs since, not 30: started later, they had 4 scored pairs.
INSTANTIATE_TEST_SUITE_P(HeldOutEntering18, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout18_enter16px_1pxpf", 16, 2.6, enter,
                                                       0.2, 0.0, 'x', procedural, 40},
                                           motion_case{"heldout18_enter40px_1pxpf_teddy", 40, 2.6,
                                                       enter, 0.2, 0.0, 'x', photo4, 40},
                                           motion_case{"heldout18_enter20px_halfpxpf_kodim19", 20,
                                                       2.6, enter, 0.1, 0.0, 'x', photo3, 60}),
                         case_name);

// Held out, round 19: fast balls (20-30 px per frame), spinning, over six
// photographs, written before they were run, on the firmware as it stood
// (the slow candidate's cut-extent check in): these six pass; the two over
// teddy, with heldout2's 60 px ball the open case there, fail (below,
// DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(HeldOutFast19, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout19_pass45px_30pxpf_7rps_y_kodim23",
                                                       45, 2.2, pass, 6.0, 7.0, 'y', photo2, 14},
                                           motion_case{"heldout19_pass70px_25pxpf_9rps_x_cones", 70,
                                                       2.0, pass, 5.0, 9.0, 'x', photo, 14},
                                           motion_case{"heldout19_pass90px_30pxpf_4rps_z_venus", 90,
                                                       1.8, pass, 6.0, 4.0, 'z', venus, 13},
                                           motion_case{"heldout19_pass50px_30pxpf_9rps_x_tsukuba",
                                                       50, 2.2, pass, 6.0, 9.0, 'x', tsukuba, 14},
                                           motion_case{"heldout19_pass60px_20pxpf_6rps_x_aloe", 60,
                                                       2.2, pass, 4.0, 6.0, 'x', aloe, 14},
                                           motion_case{"heldout19_pass30px_30pxpf_3rps_y_kodim19",
                                                       30, 2.4, pass, 6.0, 3.0, 'y', photo3, 16}),
                         case_name);

// Fast balls over teddy whose shaded rim the differences miss: heldout2's
// 60 px ball (held out, round 2) and round 19's two. Before their box was
// fitted to the last pairs' extents (dsp/extent_window.h) they were left
// behind: the 60 px ball from its second tracked pair (box 8.9, 13.6, 31.3,
// 56.1 px off, depth 133 % while on the background); 80 px at 25 px per
// frame 7.33 / 12.84 px; 40 px at 30 px per frame 6.05 / 6.90 px. In all
// three Dif(t-1,t)'s trailing edge, object(t-1)'s rim, was within 1.5 px of
// the truth in every pair (2.6 once), while its leading edge, object(t)'s,
// was 3-14 px short in 13 of their 27 pairs (the ball's shaded side against
// teddy's dark areas, under the threshold), and its bottom up to 20 px
// short. Development cases of that rule since.
INSTANTIATE_TEST_SUITE_P(ShadedRim, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout2_pass60px_30pxpf_photo4", 60, 2.2,
                                                       pass, 6.0, 9.0, 'x', photo4, 14},
                                           motion_case{"heldout19_pass80px_25pxpf_5rps_x_teddy", 80,
                                                       1.9, pass, 5.0, 5.0, 'x', photo4, 14},
                                           motion_case{"heldout19_pass40px_30pxpf_8rps_z_teddy", 40,
                                                       2.4, pass, 6.0, 8.0, 'z', photo4, 14}),
                         case_name);

// Held out, round 20: fast balls whose rims the differences may miss,
// written before they were run, on the window fit: leftwards (the shaded
// side trailing), over teddy and the other darker photographs, and a throw
// over teddy (the fit across the image only).
INSTANTIATE_TEST_SUITE_P(HeldOutFast20, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout20_left60px_30pxpf_teddy", 60, 2.2,
                                                       pass_left, 6.0, 0.0, 'x', photo4, 14},
                                           motion_case{"heldout20_left80px_25pxpf_5rps_x_teddy", 80,
                                                       1.9, pass_left, 5.0, 5.0, 'x', photo4, 14},
                                           motion_case{"heldout20_left40px_30pxpf_6rps_z", 40, 2.4,
                                                       pass_left, 6.0, 6.0, 'z', procedural, 14},
                                           motion_case{"heldout20_left120px_20pxpf_2rps_y_venus",
                                                       120, 1.6, pass_left, 4.0, 2.0, 'y', venus,
                                                       14},
                                           motion_case{"heldout20_pass100px_20pxpf_3rps_z_teddy",
                                                       100, 1.7, pass, 4.0, 3.0, 'z', photo4, 14},
                                           motion_case{"heldout20_pass30px_25pxpf_teddy", 30, 2.6,
                                                       pass, 5.0, 0.0, 'x', photo4, 16},
                                           motion_case{"heldout20_pass70px_30pxpf_7rps_y_tsukuba",
                                                       70, 2.0, pass, 6.0, 7.0, 'y', tsukuba, 14},
                                           motion_case{"heldout20_throw80px_4rps_x_teddy", 80, 2.6,
                                                       thrown, 1.5, 4.0, 'x', photo4, 24}),
                         case_name);

// Held out, round 21: large balls at 5-12 px per frame (between the slow
// key frame's and the window fit's ranges) over teddy and venus, written
// to look for a case of the size across the motion and run once, on the
// window fit: these three passed; five failed (below: four are development
// cases of the motion read from the window since, one of an end read
// from the stereo pair, EndFromStereo).
INSTANTIATE_TEST_SUITE_P(HeldOutMedium21, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout21_throw120px_half_2rps_z_teddy",
                                                       120, 2.6, thrown, 0.5, 2.0, 'z', photo4, 40},
                                           motion_case{"heldout21_throw100px_half_3rps_x_teddy",
                                                       100, 2.6, thrown, 0.5, 3.0, 'x', photo4, 40},
                                           motion_case{"heldout21_pass80px_6pxpf_2rps_z_venus", 80,
                                                       2.6, pass, 1.3, 2.0, 'z', venus, 24}),
                         case_name);

// Round 21's cases that failed on the window fit, development cases of the
// motion read from the window (dsp/extent_window.h, window_step2) since:
// the 140 px pass at 6 px per frame (7.66 / 22.08 px before: its leading
// rim 26-35 px short, the extent's reach read no motion and its box
// stalled), the 100 px pass at 5 px per frame (3.48 / 14.14: a key taken
// where its pattern matched the ball's last place held the box), and the
// 140 px balls thrown at half speed over teddy (18.34 px in pair 7: the
// detection 107 px wide of 141, not grown while the ball rose, as it grew
// only where all four edges stood) and venus (6.07).
INSTANTIATE_TEST_SUITE_P(MediumSpeed, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout21_pass140px_6pxpf_3rps_x_teddy",
                                                       140, 2.6, pass, 1.2, 3.0, 'x', photo4, 24},
                                           motion_case{"heldout21_pass100px_5pxpf_2rps_x_teddy",
                                                       100, 2.6, pass, 1.0, 2.0, 'x', photo4, 24},
                                           motion_case{"heldout21_throw140px_half_3rps_x_teddy",
                                                       140, 2.6, thrown, 0.5, 3.0, 'x', photo4, 40},
                                           motion_case{"heldout21_throw140px_half_3rps_x_venus",
                                                       140, 2.6, thrown, 0.5, 3.0, 'x', venus, 40}),
                         case_name);

// Held out, round 22: written before they were run and run once, on the
// motion read from the window: circles at 4-6 px per frame (they start
// going down the image, across x), throws at 0.4-1 times the speed (their
// apexes) and medium passes, of 60-140 px over the photographs. These 13
// passed; the 60 px throw over venus failed (EndFromStereo, below, since).
INSTANTIATE_TEST_SUITE_P(
    HeldOutMedium22, BoxOnMotion,
    ::testing::Values(
        motion_case{"heldout22_circle60px_4pxpf_venus", 60, 2.6, circle, 0.5, 0.0, 'x', venus, 30},
        motion_case{"heldout22_circle100px_4pxpf_1rps_z_teddy", 100, 2.6, circle, 0.5, 1.0, 'z',
                    photo4, 30},
        motion_case{"heldout22_circle140px_6pxpf_2rps_x_aloe", 140, 2.6, circle, 0.75, 2.0, 'x',
                    aloe, 30},
        motion_case{"heldout22_circle120px_6pxpf_venus", 120, 2.6, circle, 0.75, 0.0, 'x', venus,
                    30},
        motion_case{"heldout22_circle80px_5pxpf_3rps_y_tsukuba", 80, 2.6, circle, 0.625, 3.0, 'y',
                    tsukuba, 30},
        motion_case{"heldout22_circle100px_6pxpf_kodim19", 100, 2.6, circle, 0.75, 0.0, 'x', photo3,
                    30},
        motion_case{"heldout22_throw100px_half_1rps_z_aloe", 100, 2.6, thrown, 0.5, 1.0, 'z', aloe,
                    40},
        motion_case{"heldout22_throw120px_0_8_4rps_y_tsukuba", 120, 2.6, thrown, 0.8, 4.0, 'y',
                    tsukuba, 34},
        motion_case{"heldout22_throw80px_0_4_kodim19", 80, 2.6, thrown, 0.4, 0.0, 'x', photo3, 40},
        motion_case{"heldout22_throw90px_1rps_x_venus", 90, 2.6, thrown, 1.0, 1.0, 'x', venus, 30},
        motion_case{"heldout22_throw130px_0_6_2rps_z_venus", 130, 2.6, thrown, 0.6, 2.0, 'z', venus,
                    36},
        motion_case{"heldout22_left120px_6pxpf_2rps_y_aloe", 120, 2.6, pass_left, 1.2, 2.0, 'y',
                    aloe, 24},
        motion_case{"heldout22_pass80px_4pxpf_1rps_x_venus", 80, 2.6, pass, 0.8, 1.0, 'x', venus,
                    24}),
    case_name);

// Round 23: written before they were run, on the motion read from the
// window: balls going away from the rig or coming towards it while they
// pass at 2-25 px per frame, their images shrinking or growing. Three
// passed; five failed, development cases of the size read from the depth
// since (dsp/size_at_depth.h), of which three passed and two were open.
// The 150 px ball going away over aloe passes since a key's outline is
// brought to the depth (keyed_span_at_depth); the 40 px ball coming nearer
// was open from when the box's sides were judged (27.3 %) until a size a
// key outlined was held after the key (pull_box, hold_axis; traced for it);
// the 120 px ball over teddy, whose shaded leading rim stood in Dif(t-1,t)
// while the ball moved on (4.69 / 19.25 px), until its box was placed from
// the window's trailing edge where its leading rim fades (extent_window.h,
// fading_rim_step2; traced for it).
INSTANTIATE_TEST_SUITE_P(
    HeldOutDepth23, BoxOnMotion,
    ::testing::Values(motion_case{"heldout23_recede60px_15pxpf", 60, 2.6, recede, 3.0, 0.0, 'x',
                                  procedural, 16},
                      motion_case{"heldout23_recede80px_25pxpf_5rps_y_venus", 80, 2.6, recede, 5.0,
                                  5.0, 'y', venus, 14},
                      motion_case{"heldout23_approach60px_5pxpf_3rps_x_tsukuba", 60, 2.6, approach,
                                  1.0, 3.0, 'x', tsukuba, 24},
                      motion_case{"heldout23_approach100px_15pxpf_teddy", 100, 2.6, approach, 3.0,
                                  0.0, 'x', photo4, 16},
                      motion_case{"heldout23_approach120px_25pxpf_4rps_z", 120, 2.6, approach, 5.0,
                                  4.0, 'z', procedural, 12},
                      motion_case{"heldout23_recede150px_2pxpf_1rps_z_aloe", 150, 2.6, recede, 0.4,
                                  1.0, 'z', aloe, 24},
                      motion_case{"heldout23_approach40px_2pxpf_2rps_y_kodim19", 40, 2.6, approach,
                                  0.4, 2.0, 'y', photo3, 24},
                      motion_case{"heldout23_recede120px_5pxpf_2rps_x_teddy", 120, 2.6, recede, 1.0,
                                  2.0, 'x', photo4, 24}),
    case_name);

// Rigs whose principal points differ by 16 px either way (a disparity of
// +-16 px at infinity): the size read from the depth takes the part of the
// disparity inversely proportional to depth (dsp/size_at_depth.h). Round
// 23's 80 px ball going away at 25 px a frame, written after the rule.
// Neither judges that subtraction: with the offset left in the ratio
// (mutant fw-110) the +16 px rig's box ends 6 px too wide (2.41 -> 2.47 px
// mean) and the -16 px rig's (measured disparity 20 -> 13 px where the
// pinhole's is 36 -> 29) 8 px too low, 12.5 % of the ball, both within the
// sides' bound.
INSTANTIATE_TEST_SUITE_P(PrincipalOffset, BoxOnMotion,
                         ::testing::Values(motion_case{"recede80px_25pxpf_5rps_y_venus_dcx16", 80,
                                                       2.6, recede, 5.0, 5.0, 'y', venus, 14, 16.0},
                                           motion_case{"recede80px_25pxpf_5rps_y_venus_dcxm16", 80,
                                                       2.6, recede, 5.0, 5.0, 'y', venus, 14,
                                                       -16.0}),
                         case_name);

// The same rigs under slow keyed balls, whose box is the key's carried over
// many pairs by the ratio of the disparities (follow_slow_object): round
// 25's ball going away over aloe and its ball coming nearer over teddy.
INSTANTIATE_TEST_SUITE_P(PrincipalOffsetKeyed, BoxOnMotion,
                         ::testing::Values(motion_case{"recede60px_1pxpf_aloe_dcxm16", 60, 2.6,
                                                       recede, 0.2, 0.0, 'x', aloe, 24, -16.0},
                                           motion_case{"recede60px_1pxpf_aloe_dcx16", 60, 2.6,
                                                       recede, 0.2, 0.0, 'x', aloe, 24, 16.0},
                                           motion_case{"approach50px_2pxpf_teddy_dcxm16", 50, 2.6,
                                                       approach, 0.4, 0.0, 'x', photo4, 24, -16.0},
                                           motion_case{"approach50px_2pxpf_teddy_dcx16", 50, 2.6,
                                                       approach, 0.4, 0.0, 'x', photo4, 24, 16.0}),
                         case_name);

// Held out, round 24: written before the size read from the depth
// (dsp/size_at_depth.h) and run once on it: more balls going away from
// the rig or towards it, over the other photographs. These three passed
// (two had passed without it, the 130 px ball over venus not); three
// failed (then in DISABLED_Open). The 170 px and 130 px balls going away pass
// since the window's extents read at the detection stand for the first
// disparity (extent_window::give_depth; the 130 px ball was traced for it),
// the 100 px ball since a turned detection is started (TurnedDetection).
INSTANTIATE_TEST_SUITE_P(
    HeldOutDepth24, BoxOnMotion,
    ::testing::Values(motion_case{"heldout24_recede40px_10pxpf_3rps_z_tsukuba", 40, 2.6, recede,
                                  2.0, 3.0, 'z', tsukuba, 20},
                      motion_case{"heldout24_approach80px_1pxpf_1rps_x_aloe", 80, 2.6, approach,
                                  0.2, 1.0, 'x', aloe, 24},
                      motion_case{"heldout24_approach130px_8pxpf_2rps_z_venus", 130, 2.6, approach,
                                  1.6, 2.0, 'z', venus, 20},
                      motion_case{"heldout24_recede170px_8pxpf_photo2", 170, 2.2, recede, 1.6, 0.0,
                                  'x', photo2, 20},
                      motion_case{"heldout24_recede130px_4pxpf_5rps_x_photo3", 130, 2.6, recede,
                                  0.8, 5.0, 'x', photo3, 24}),
    case_name);

// Held out, round 25: written before they were run, on a key's outline
// brought to the depth (keyed_span_at_depth), and run once on it and once
// on the tree before for comparison: slow balls, 1-3 px a frame, going
// away from the rig or coming nearer, keyed, over every backdrop. Two of
// eight passed, both ways. Development cases since: a key taken at the
// detection now stands for a disparity, and a key's outline takes the
// key's size at the depth; five pass, three are open. The 110 px ball
// over tsukuba (never detected: its SAD pattern read it still, keyed again
// and again) passes since a detection whose box steps on is started
// (dsp/detection_steps.h; traced on it); two are open.
INSTANTIATE_TEST_SUITE_P(HeldOutDepth25, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout25_recede60px_1pxpf_aloe", 60, 2.6,
                                                       recede, 0.2, 0.0, 'x', aloe, 24},
                                           motion_case{"heldout25_approach50px_2pxpf_teddy", 50,
                                                       2.6, approach, 0.4, 0.0, 'x', photo4, 24},
                                           motion_case{"heldout25_approach90px_1pxpf_2rps_z_venus",
                                                       90, 2.6, approach, 0.2, 2.0, 'z', venus, 24},
                                           motion_case{"heldout25_approach70px_3pxpf_1rps_x_cones",
                                                       70, 2.6, approach, 0.6, 1.0, 'x', photo, 24},
                                           motion_case{"heldout25_recede80px_2pxpf_3rps_z", 80, 2.6,
                                                       recede, 0.4, 3.0, 'z', procedural, 24},
                                           motion_case{"heldout25_recede110px_2pxpf_1rps_y_tsukuba",
                                                       110, 2.6, recede, 0.4, 1.0, 'y', tsukuba,
                                                       24}),
                         case_name);

// Held out, round 26: written before they were run, on the box placed
// from the window's trailing edge where a leading rim fades (its first
// form: the leading edge moving under a third as far as the trailing one),
// and run once on it: balls at 3-5 px a frame whose leading rim may enter
// a dark part of the backdrop (over teddy and its dark red box, venus,
// cones), going away, coming nearer or passing, both ways. Four passed,
// as on the tree before; four failed. The fading rim read from the leading
// edge's lag since (extent_window.h, fading_rim_step2): the 100 px
// ball coming nearer over teddy (4.44 / 13.64 px; traced for the size read
// short kept, a development case now) and the 120 px pass over teddy (1.66
// / 7.95) pass; the 140 px ball going away (detected at its 20th frame)
// since a detection whose box steps on is started (dsp/detection_steps.h;
// traced on it); the fourth since a side is read from the stereo pair
// (SideFromStereo).
INSTANTIATE_TEST_SUITE_P(HeldOutFading26, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout26_recede100px_4pxpf_teddy", 100,
                                                       2.6, recede, 0.8, 0.0, 'x', photo4, 24},
                                           motion_case{"heldout26_recede80px_3pxpf_2rps_z_teddy",
                                                       80, 2.6, recede, 0.6, 2.0, 'z', photo4, 24},
                                           motion_case{"heldout26_approach100px_4pxpf_teddy", 100,
                                                       2.6, approach, 0.8, 0.0, 'x', photo4, 24},
                                           motion_case{"heldout26_pass120px_4pxpf_2rps_x_teddy",
                                                       120, 2.6, pass, 0.8, 2.0, 'x', photo4, 24},
                                           motion_case{"heldout26_recede120px_4pxpf_venus", 120,
                                                       2.6, recede, 0.8, 0.0, 'x', venus, 24},
                                           motion_case{"heldout26_recede110px_5pxpf_2rps_x_cones",
                                                       110, 2.6, recede, 1.0, 2.0, 'x', photo, 24},
                                           motion_case{"heldout26_recede140px_5pxpf_1rps_y_teddy",
                                                       140, 2.6, recede, 1.0, 1.0, 'y', photo4,
                                                       24}),
                         case_name);

// Held out, round 27: written before they were run, on the detections'
// outline stepping on where the SAD reads a detection still
// (dsp/detection_steps.h; traced on round 25's ball over tsukuba and round
// 26's 140 px ball over teddy), to be run once on it: balls at 1-4 px a
// frame spinning about y (the texture across the path, with or against
// it), passing both ways, going away or coming nearer, over every
// photograph; the slowest, 1 px a frame, for a slow ball read as moving.
// Run once on the rule's first form (one edge stepping, alone or not): all
// eight passed; on the tree before, seven (the 130 px ball going away over
// kodim19 never detected). On the rule as kept (the opposite edge along:
// three slow balls' growing pieces had been started as moving), the same
// but the 100 px pass over teddy, 1.04 / 2.41 -> 1.25 / 2.80 px.
INSTANTIATE_TEST_SUITE_P(
    HeldOutSpinningSteps27, BoxOnMotion,
    ::testing::Values(motion_case{"heldout27_pass100px_3pxpf_2rps_y_teddy", 100, 2.6, pass, 0.6,
                                  2.0, 'y', photo4, 24},
                      motion_case{"heldout27_pass_left120px_3pxpf_1rps_y_tsukuba", 120, 2.6,
                                  pass_left, 0.6, 1.0, 'y', tsukuba, 24},
                      motion_case{"heldout27_recede90px_4pxpf_2rps_y_venus", 90, 2.6, recede, 0.8,
                                  2.0, 'y', venus, 24},
                      motion_case{"heldout27_approach110px_2pxpf_1rps_y_aloe", 110, 2.6, approach,
                                  0.4, 1.0, 'y', aloe, 20},
                      motion_case{"heldout27_pass140px_2pxpf_1rps_y_cones", 140, 2.6, pass, 0.4,
                                  1.0, 'y', photo, 24},
                      motion_case{"heldout27_recede130px_4pxpf_1rps_y_kodim19", 130, 2.6, recede,
                                  0.8, 1.0, 'y', photo3, 24},
                      motion_case{"heldout27_approach80px_1pxpf_2rps_y_teddy", 80, 2.6, approach,
                                  0.2, 2.0, 'y', photo4, 20},
                      motion_case{"heldout27_pass_left90px_2pxpf_3rps_y_kodim23", 90, 2.6,
                                  pass_left, 0.4, 3.0, 'y', photo2, 24}),
    case_name);

// A ball between a slow object's step and a moving one's (3 px a pair:
// over key_frame::max_step, under min_shift), spinning about y, from a
// co-simulated grid (stereosim run, scenario.path=pass, speed 0.6): the
// 48 px ball passed; the 73 px one was keyed (its pattern read still) and
// its key's displacement read 3, 6, 9 px, then 0 where the texture came
// round with the spin: the box 12 px behind (6.52 / 12.33 px). It passes
// since a displacement that falls back towards the key drops the key
// (dsp/controller_key.cpp, falls_back; traced on it). The two circles,
// spinning about x (the texture coming round on y), were written after the
// rule, looking for a case of its y axis (mutant fw-149): before it 3.54 /
// 23.09 and 5.65 / 12.36 px. The 73 px circle about y, found with them,
// failed (3.55 / 7.16 px) until a key of the outline took a drift across
// off its hull (dsp/box_refit.h, outline_key_axis; traced on it). The two
// balls on the circle's other side (drifting towards the start, leftwards)
// were written after that rule, looking for a case of its other end
// (mutant fw-156): before it 2.37 / 5.65 and 4.92 / 12.98 px, with it
// 1.32 / 3.35 and 2.12 / 4.63.
INSTANTIATE_TEST_SUITE_P(
    BetweenSlowAndMoving, BoxOnMotion,
    ::testing::Values(
        motion_case{"pass48px_3pxpf_1rps_y", 48, 2.6, pass, 0.6, 1.0, 'y', procedural, 30},
        motion_case{"pass73px_3pxpf_1rps_y", 73, 2.6, pass, 0.6, 1.0, 'y', procedural, 30},
        motion_case{"circle73px_3pxpf_1rps_x", 73, 2.6, circle, 0.375, 1.0, 'x', procedural, 30},
        motion_case{"circle90px_3pxpf_1rps_x", 90, 2.6, circle, 0.375, 1.0, 'x', procedural, 30},
        motion_case{"circle73px_3pxpf_1rps_y", 73, 2.6, circle, 0.375, 1.0, 'y', procedural, 30},
        motion_case{"circle_back73px_3pxpf_1rps_y", 73, 2.6, circle_back, 0.375, 1.0, 'y',
                    procedural, 30},
        motion_case{"circle_back90px_3pxpf_1rps_y_cones", 90, 2.6, circle_back, 0.375, 1.0, 'y',
                    photo, 30}),
    case_name);

// Held out, round 28: written before they were run, for a key taken only
// where the silhouette moved as a slow object does: balls at 3 px a frame
// (between max_step and min_shift) spinning 1-2 rev/s about every axis,
// every path, over the procedural plane and the photographs. Run first on
// the tree as it was (that rule was not kept: docs/firmware.md, "A key's
// displacement that falls back"): seven pass; the 80 px ball circling over
// cones fails (3.70 / 7.45 px; not traced). The same on the displacement
// that falls back dropping the key. The 80 px circle passes (1.88 / 2.96
// px) since a key of the outline takes a drift across off its hull
// (dsp/box_refit.h, outline_key_axis), found on the 73 px circle about y of
// BetweenSlowAndMoving (3.55 / 7.16 -> 1.26 / 2.15 px).
INSTANTIATE_TEST_SUITE_P(
    HeldOutBetween28, BoxOnMotion,
    ::testing::Values(motion_case{"heldout28_pass60px_3pxpf_2rps_y", 60, 2.6, pass, 0.6, 2.0, 'y',
                                  procedural, 30},
                      motion_case{"heldout28_pass_left90px_3pxpf_1rps_y_aloe", 90, 2.6, pass_left,
                                  0.6, 1.0, 'y', aloe, 24},
                      motion_case{"heldout28_pass110px_3pxpf_1rps_x_venus", 110, 2.6, pass, 0.6,
                                  1.0, 'x', venus, 24},
                      motion_case{"heldout28_pass_left70px_3pxpf_2rps_z_kodim23", 70, 2.6,
                                  pass_left, 0.6, 2.0, 'z', photo2, 24},
                      motion_case{"heldout28_recede100px_3pxpf_1rps_y", 100, 2.6, recede, 0.6, 1.0,
                                  'y', procedural, 24},
                      motion_case{"heldout28_approach60px_3pxpf_1rps_y_tsukuba", 60, 2.6, approach,
                                  0.6, 1.0, 'y', tsukuba, 20},
                      motion_case{"heldout28_pass130px_3pxpf_1rps_y_teddy", 130, 2.6, pass, 0.6,
                                  1.0, 'y', photo4, 24},
                      motion_case{"heldout28_circle80px_3pxpf_1rps_y_cones", 80, 2.6, circle, 0.375,
                                  1.0, 'y', photo, 30}),
    case_name);

// Held out, round 29: written before they were run, for a key of the
// outline whose object drifts across its motion (dsp/box_refit.h,
// outline_key_axis): balls 60-130 px circling at 1-4 px a frame, spinning
// 1-3 rev/s about every axis, over the procedural plane and the
// photographs. On the tree before, five of eight passed; on the rule's
// first form (the silhouette's drift alone) six, on its kept form six:
// the 90 px ball over kodim19 passes (4.50 / 7.90 -> 2.46 / 3.90 px). The
// 70 px ball over venus failed, as before the rule (now ShortFromStereo). The
// 120 px ball at 1 px a frame over cones, traced, is a development case
// since: it passes (3.80 / 5.74 -> 2.84 / 5.74 px) once a drift is read
// from Dif(key, t)'s first extent that held the key's box (its first, 106 of
// the key's 109 px, was the texture filling in; the 10 px it then grew was
// read as a drift). Its box is still 4-6 px off for its first 9 pairs.
INSTANTIATE_TEST_SUITE_P(
    HeldOutDrift29, BoxOnMotion,
    ::testing::Values(motion_case{"heldout29_circle60px_2pxpf_2rps_y_teddy", 60, 2.6, circle, 0.25,
                                  2.0, 'y', photo4, 30},
                      motion_case{"heldout29_circle90px_3pxpf_1rps_z_kodim19", 90, 2.6, circle,
                                  0.375, 1.0, 'z', photo3, 30},
                      motion_case{"heldout29_circle110px_2pxpf_1rps_y_aloe", 110, 2.6, circle, 0.25,
                                  1.0, 'y', aloe, 30},
                      motion_case{"heldout29_circle80px_4pxpf_2rps_y_tsukuba", 80, 2.6, circle, 0.5,
                                  2.0, 'y', tsukuba, 30},
                      motion_case{"heldout29_circle100px_3pxpf_3rps_y_kodim23", 100, 2.6, circle,
                                  0.375, 3.0, 'y', photo2, 30},
                      motion_case{"heldout29_circle130px_2pxpf_1rps_y", 130, 2.6, circle, 0.25, 1.0,
                                  'y', procedural, 30},
                      motion_case{"heldout29_circle120px_1pxpf_2rps_y_cones", 120, 2.6, circle,
                                  0.125, 2.0, 'y', photo, 30}),
    case_name);

// A side no difference outlines, read from the stereo pair
// (dsp/stereo_reach.h): three that were open (in DISABLED_Open), development
// cases since. The 120 px ball coming nearer over kodim19 (traced: its left
// rim moves 0.2-0.3 px a frame, its growth cancelling its motion, and its
// box stayed 23-31 px narrow; 12.81 / 16.34 -> 0.96 / 1.87 px), the 100 px
// ball passing leftwards over teddy (its shaded trailing side over teddy's
// dark box missed by 13 px in every pair; 5.47 / 10.81 -> 1.21 / 3.28 px),
// and the 100 px ball circling over venus (its right rim 0-18 grey levels
// off venus's dark frame, under the difference's threshold; 3.56 / 4.44 ->
// 1.13 / 1.64 px, not traced for the rule).
INSTANTIATE_TEST_SUITE_P(SideFromStereo, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout25_approach120px_2pxpf_kodim19", 120,
                                                       2.6, approach, 0.4, 0.0, 'x', photo3, 20},
                                           motion_case{"heldout26_pass_left100px_4pxpf_teddy", 100,
                                                       2.6, pass_left, 0.8, 0.0, 'x', photo4, 24},
                                           motion_case{"heldout6_circle100px_1pxpf_venus", 100, 2.6,
                                                       circle, 0.125, 0.0, 'x', venus, 30}),
                         case_name);

// An end no difference outlines, read from the stereo pair along y
// (dsp/stereo_reach.h, reach_past_ends): two that were open (in
// DISABLED_Open), development cases since. The 60 px ball thrown at 0.7
// times the speed over venus rode 3-6 px above it while it fell, its shaded
// lower rim 6-7 px short in Dif(t-1,t) (2.48 / 6.00 -> 1.63 / 4.68 px). The
// 140 px ball thrown at 0.6 times the speed over teddy was 10.6 px off at
// its bounce in the last pair, the 9 px it rose in no difference
// (1.39 / 10.56 -> 1.05 / 4.06 px): the top read past it, the box 10 px
// tall there (the bottom is not moved in), its centre half-way.
INSTANTIATE_TEST_SUITE_P(EndFromStereo, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout22_throw60px_0_7_2rps_x_venus", 60,
                                                       2.6, thrown, 0.7, 2.0, 'x', venus, 36},
                                           motion_case{"heldout21_throw140px_0_6_3rps_x_teddy", 140,
                                                       2.6, thrown, 0.6, 3.0, 'x', photo4, 36}),
                         case_name);

// Held out, round 30: written before they were run, for a side that does
// not move in the image (a ball coming nearer while it moves right, its left
// rim; going away, its right rim), 60-140 px at 1-3 px a frame, some
// spinning, over the photographs and the procedural plane. On the tree
// before the stereo reach six of eight passed, with it seven: the 140 px
// ball coming nearer over venus passes (5.88 / 11.58 -> 0.86 / 2.48 px).
// The 120 px ball going away over cones failed with it and without it
// (now ShortFromStereo).
INSTANTIATE_TEST_SUITE_P(
    HeldOutStillSide30, BoxOnMotion,
    ::testing::Values(motion_case{"heldout30_approach100px_2pxpf_teddy", 100, 2.6, approach, 0.4,
                                  0.0, 'x', photo4, 20},
                      motion_case{"heldout30_approach140px_2pxpf_1rps_y_venus", 140, 2.6, approach,
                                  0.4, 1.0, 'y', venus, 20},
                      motion_case{"heldout30_approach80px_2pxpf_aloe", 80, 2.6, approach, 0.4, 0.0,
                                  'x', aloe, 24},
                      motion_case{"heldout30_approach110px_3pxpf_2rps_z_tsukuba", 110, 2.6,
                                  approach, 0.6, 2.0, 'z', tsukuba, 20},
                      motion_case{"heldout30_recede90px_2pxpf_1rps_x_kodim19", 90, 2.6, recede, 0.4,
                                  1.0, 'x', photo3, 24},
                      motion_case{"heldout30_approach60px_2pxpf_kodim23", 60, 2.6, approach, 0.4,
                                  0.0, 'x', photo2, 24},
                      motion_case{"heldout30_approach130px_1pxpf_2rps_y", 130, 2.6, approach, 0.2,
                                  2.0, 'y', procedural, 24}),
    case_name);

// A side read from the stereo pair where the box stands past the object
// (dsp/stereo_reach.h, short_of_sides and short_of_ends): three that were
// open (in DISABLED_Open), development cases since. Round 30's 120 px ball
// going away over cones, its box 4-13 px too wide at its trailing side
// (5.02 / 7.18 px before, 1.04 / 2.02 with it), the rule's aim; round 29's
// 70 px ball circling over venus (2.73 / 6.39 -> 1.93 / 3.27 px), whose box
// stayed 7-9 px narrow and 2-7 px left of it: its left side is now moved in
// to the ball's left rim (the right one still short). Round 25's 140 px
// ball going away over kodim23, its box 4-7 px too large for 8 pairs, was
// 1.04 % off in depth (1.29 / 2.65 px) until the tiled depth was read on
// the box moved in (0.79 / 1.77 px, 0.74 %).
INSTANTIATE_TEST_SUITE_P(ShortFromStereo, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout30_recede120px_2pxpf_cones", 120,
                                                       2.6, recede, 0.4, 0.0, 'x', photo, 24},
                                           motion_case{"heldout29_circle70px_3pxpf_2rps_x_venus",
                                                       70, 2.6, circle, 0.375, 2.0, 'x', venus, 30},
                                           motion_case{"heldout25_recede140px_3pxpf_kodim23", 140,
                                                       2.6, recede, 0.6, 0.0, 'x', photo2, 24}),
                         case_name);

// The core matched again on the box moved in where the object stops short
// of it, under the tiled depth's size (dsp/controller_stereo.cpp,
// rematch_core): four that were open (in DISABLED_Open) on the depth,
// development cases since. Round 80's ball coming nearer over kodim23,
// 45 px by its 25th pair, its tracker's box 6 px past its left rim: the
// round core read the background there, 1.80 % far (0.56 % with the rule);
// round 91's 74 px ball circling over teddy, its box 10-16 px past its
// right rim for ten pairs, 2.60 -> 0.89 %; round 102's 60 px ball going
// away over aloe, 1.25 -> 0.50 %; the 140 px ball going away at 12 px a
// frame over teddy (in ShortSideGrown until the core's sub-pixel step at
// half pixels), 1.25 -> 0.92 %.
INSTANTIATE_TEST_SUITE_P(
    CoreMatchedAgain, BoxOnMotion,
    ::testing::Values(motion_case{"heldout80_38_approach29px_3_1m_kodim23", 29, 3.1, approach, 0.8,
                                  0.0, 'x', photo2, 40},
                      motion_case{"heldout91_11_circle74px_3_1m_2_9rps_z_teddy", 74, 3.1, circle,
                                  2.3, 2.9, 'z', photo4, 40},
                      motion_case{"heldout102d_17_recede60px_2_2m_3_0x_9_3rps_z_aloe", 60, 2.2,
                                  recede, 3.0, 9.3, 'z', aloe, 27},
                      motion_case{"recede140px_12pxpf_1rps_y_teddy_30f", 140, 2.6, recede, 2.0, 1.0,
                                  'y', photo4, 30}),
    case_name);

// Held out, round 24 (above, HeldOutDepth24): the 100 px ball going away
// at 1 px a frame over cones, spinning 2 rev/s about y, failed (detected
// only at its 23rd frame: no pair scored) until a detection whose texture
// turned is started as a moving one (dsp/controller_detect.cpp,
// texture_turned; this case was traced for it): its candidate's key read
// 0 px for 10 pairs while the ball moved 10. A development case since.
INSTANTIATE_TEST_SUITE_P(TurnedDetection, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout24_recede100px_1pxpf_2rps_y_photo",
                                                       100, 2.6, recede, 0.2, 2.0, 'y', photo, 24}),
                         case_name);

// A fast throw's apex: a small ball thrown at 2.2 times the default speed
// 4 m away (28 px a frame at the throw), where the extent window still
// reads the rise. Across y the box is fitted to the window only across a
// fast motion along x (dsp/controller_track.cpp, follow_object): fitted on
// any fast axis it went 9.5-15 px above the apex (mutant fw-103: 1.23-2.60
// / 9.54-14.92 px, depth 1.8-3.8 %; this firmware 0.79-1.05 / 1.95-2.41 px,
// 0.58-0.80 %).
// Written to show that bug, with the variants run beside them
// (docs/mutants.md): development cases, not held out.
INSTANTIATE_TEST_SUITE_P(ThrowApex, BoxOnMotion,
                         ::testing::Values(motion_case{"apex40px_2_2_4rps_x_teddy_4m", 40, 4.0,
                                                       thrown, 2.2, 4.0, 'x', photo4, 24},
                                           motion_case{"apex40px_2_2_4rps_x_venus_4m", 40, 4.0,
                                                       thrown, 2.2, 4.0, 'x', venus, 24},
                                           motion_case{"apex40px_2_2_teddy_4m", 40, 4.0, thrown,
                                                       2.2, 0.0, 'x', photo4, 24}),
                         case_name);

// A large ball thrown at half speed over teddy: its detection is a part of
// it (up to 38 px off its centre), which is grown on x where both
// differences' x edges stood, whatever its y edges did (the throw rises
// 8 px a frame).
// Grown only where all its edges stood, the box stayed narrow for its
// first pairs and the depth was 1.12-1.22 % off (mutant fw-105; this
// firmware 0.32-0.53 %). Written to show that bug, development cases.
INSTANTIATE_TEST_SUITE_P(LargeSlowThrow, BoxOnMotion,
                         ::testing::Values(motion_case{"throw200px_half_1rps_x_teddy", 200, 2.6,
                                                       thrown, 0.5, 1.0, 'x', photo4, 40},
                                           motion_case{"throw220px_half_1rps_x_teddy", 220, 2.6,
                                                       thrown, 0.5, 1.0, 'x', photo4, 40},
                                           motion_case{"throw200px_half_1rps_z_teddy", 200, 2.6,
                                                       thrown, 0.5, 1.0, 'z', photo4, 40}),
                         case_name);

// The rigs of PrincipalOffset under slower balls going away for 40 frames
// (2.0 m to 3.8 m, the image shrinking to half its start's): the box is
// carried from pair to pair by the ratio of the disparities less the
// principal points' offset (dsp/size_at_depth.h), and the depth is read
// over the box. With the offset kept in the ratio (mutant fw-110) the
// depth was 1.12-2.40 % off (the 60 px ball's box also 2.79 / 4.61 px off
// its centre, a side 27 % off); this firmware 0.41-0.57 %, 0.95-1.05 /
// 1.95-2.71 px. Written to show that bug, development cases.
INSTANTIATE_TEST_SUITE_P(PrincipalOffsetReceding, BoxOnMotion,
                         ::testing::Values(motion_case{"recede60px_3pxpf_1rps_y_teddy_dcx16", 60,
                                                       2.0, recede, 0.3, 1.0, 'y', photo4, 40,
                                                       16.0},
                                           motion_case{"recede80px_2pxpf_teddy_dcx12", 80, 2.0,
                                                       recede, 0.2, 0.0, 'x', photo4, 40, 12.0},
                                           motion_case{"recede80px_2pxpf_aloe_dcx16", 80, 2.0,
                                                       recede, 0.2, 0.0, 'x', aloe, 40, 16.0}),
                         case_name);

// Round 26's ball coming nearer over teddy, larger (110-130 px) and
// faster (6 px a frame): its leading rim fades into teddy's dark parts,
// where the differences measure its size short (dsp/extent_window.h,
// fading_rim_step2). That short size is a rim the differences missed: the
// box keeps the last size. Refused as a size (mutant fw-137: the follow
// gives up) or taken as the object's (fw-138: the box shrinks with the
// rim), the depth read over the box was 1.01-1.14 % off; this firmware
// 0.45-0.60 %. Written to show those bugs, development cases.
INSTANTIATE_TEST_SUITE_P(
    FadingRimNearer, BoxOnMotion,
    ::testing::Values(
        motion_case{"approach120px_6pxpf_teddy_3m", 120, 3.0, approach, 0.8, 0.0, 'x', photo4, 24},
        motion_case{"approach120px_6pxpf_teddy", 120, 2.6, approach, 0.8, 0.0, 'x', photo4, 24},
        motion_case{"approach130px_6pxpf_teddy", 130, 2.6, approach, 0.8, 0.0, 'x', photo4, 24},
        motion_case{"approach110px_6pxpf_teddy", 110, 2.6, approach, 0.8, 0.0, 'x', photo4, 24}),
    case_name);

// A 120 px ball going away over teddy at 8 px a frame, not spinning: its
// leading rim fades as the ball shrinks into teddy's dark parts. Found once
// the round box left FadingRimNearer's balls passing with fw-137, by a
// sweep of 48 balls 100-140 px coming nearer or going away at 6-8 px a
// frame over teddy, kodim19, cones and venus (every one passes on this
// firmware) run with that mutant: the follow given up, the depth was 1.19
// and 2.40 % off at its last two pairs; this firmware 0.58 %. Written to
// show that bug, a development case.
INSTANTIATE_TEST_SUITE_P(FadingRimReceding, BoxOnMotion,
                         ::testing::Values(motion_case{"recede120px_8pxpf_teddy", 120, 2.6, recede,
                                                       1.2, 0.0, 'x', photo4, 24}),
                         case_name);

// Balls 120-125 px going away over teddy at 6.5 px a frame, spinning
// 1 rev/s: a trailing edge that moved steadily where the leading rim fades
// is a motion the extent window read, and drops a key taken on the slowed
// box (dsp/controller_track.cpp, follow_object; dsp/controller_key.cpp).
// Not read as a motion (mutant fw-132), the depth was 1.02-1.16 % off;
// this firmware 0.62-0.78 %.
// Written to show that bug, development cases, in a neighbourhood where
// the firmware fails other cases (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(TrailingEdgeReceding, BoxOnMotion,
                         ::testing::Values(motion_case{"recede125px_6pxpf_1rps_y_teddy", 125, 2.6,
                                                       recede, 1.0, 1.0, 'y', photo4, 24},
                                           motion_case{"recede125px_6pxpf_1rps_y_teddy_2_5m", 125,
                                                       2.5, recede, 1.0, 1.0, 'y', photo4, 24},
                                           motion_case{"recede120px_6pxpf_1rps_y_teddy", 120, 2.6,
                                                       recede, 1.0, 1.0, 'y', photo4, 24}),
                         case_name);

// The circle from its other side, over cones, for 32 frames: 80-90 px
// balls at 3 px a frame spinning 1-1.5 rev/s about y, their box kept by a
// key of the outline whose silhouette drifts across the motion
// (dsp/box_refit.h, outline_key_axis). With the drift's first reading
// taken again every pair (mutant fw-155), read the wrong way (fw-157) or
// along the motion (fw-159) the depth was 1.08-1.18 % off (the three
// mutants alike); this firmware 0.41-0.66 %. Written to show those bugs,
// development cases; the same ball spinning about z, and over kodim19,
// fail on this firmware (DISABLED_Open). Since the round box they pass with
// those bugs too: DriftAcrossSmall shows them.
INSTANTIATE_TEST_SUITE_P(DriftAcrossCircleBack, BoxOnMotion,
                         ::testing::Values(motion_case{"circle_back90px_3pxpf_1rps_y_cones_32f", 90,
                                                       2.6, circle_back, 0.4, 1.0, 'y', photo, 32},
                                           motion_case{"circle_back80px_3pxpf_1rps_y_cones_32f", 80,
                                                       2.6, circle_back, 0.4, 1.0, 'y', photo, 32},
                                           motion_case{"circle_back90px_3pxpf_1_5rps_y_cones_32f",
                                                       90, 2.6, circle_back, 0.4, 1.5, 'y', photo,
                                                       32}),
                         case_name);

// Smaller balls on the circle's paths, 3 px a frame for 32 frames: 70 px
// spinning 1 rev/s about y on its other side over venus and kodim19, and
// 2 rev/s about x on the circle over kodim23. Found once the round box left
// DriftAcrossCircleBack's balls passing with the drift read wrong: a sweep
// of 116 slow spinning circles (70-130 px, 1-2 rev/s about y or x, seven
// backdrops; every one passes on this firmware) run with fw-157. With the
// drift's first reading taken every pair (fw-155), read the wrong way
// (fw-157) or along the motion (fw-159), alike, the depth was 1.39-2.68 %
// off (over venus the box 2-4 px narrow from pair 20); this firmware
// 0.43-0.56 %. Written to show those bugs, development cases.
INSTANTIATE_TEST_SUITE_P(DriftAcrossSmall, BoxOnMotion,
                         ::testing::Values(motion_case{"circle_back70px_3pxpf_1rps_y_venus_32f", 70,
                                                       2.6, circle_back, 0.4, 1.0, 'y', venus, 32},
                                           motion_case{"circle_back70px_3pxpf_1rps_y_kodim19_32f",
                                                       70, 2.6, circle_back, 0.4, 1.0, 'y', photo3,
                                                       32},
                                           motion_case{"circle70px_3pxpf_2rps_x_kodim23_32f", 70,
                                                       2.6, circle, 0.375, 2.0, 'x', photo2, 32}),
                         case_name);

// BetweenSlowAndMoving's 48 px pass at 3 px a frame spinning 1 rev/s about
// y, 2.8-3.2 m away and for 40 frames. A key is dropped only where its
// displacement falls back towards it (dsp/controller_key.cpp,
// falls_back). Dropped at a jump forward too (mutant fw-150), the box
// stood 9-12 px too wide at pairs 33-35 (a side 24.5 % off, 5.96 px off
// centre); this firmware 8.2 %, 3.58-3.64 px (not traced further).
// Written to show that bug, development cases.
INSTANTIATE_TEST_SUITE_P(KeyJumpForward, BoxOnMotion,
                         ::testing::Values(motion_case{"pass48px_3pxpf_1rps_y_3m_40f", 48, 3.0,
                                                       pass, 0.6, 1.0, 'y', procedural, 40},
                                           motion_case{"pass48px_3pxpf_1rps_y_2_8m_40f", 48, 2.8,
                                                       pass, 0.6, 1.0, 'y', procedural, 40},
                                           motion_case{"pass48px_3pxpf_1rps_y_3_2m_40f", 48, 3.2,
                                                       pass, 0.6, 1.0, 'y', procedural, 40}),
                         case_name);

// FastLargeSpinning's 60 px throw over kodim19, and a 50 px one over
// venus: a box may grow to the differences' common part only until a
// silhouette of its size is followed (box_may_be_part,
// dsp/controller_track.cpp). Grown so all track long (mutant fw-62), the
// depth was 1.23-1.41 % off; this firmware 0.59-0.71 %. Written to show
// that bug, development cases.
INSTANTIATE_TEST_SUITE_P(PartGrownAtDetection, BoxOnMotion,
                         ::testing::Values(motion_case{"throw60px_1rps_x_kodim19", 60, 2.6, thrown,
                                                       1.0, 1.0, 'x', photo3, 30},
                                           motion_case{"throw50px_1rps_x_venus", 50, 2.6, thrown,
                                                       1.0, 1.0, 'x', venus, 30}),
                         case_name);

// 125 px balls at 1.5 px a frame spinning 0.5 rev/s about y over kodim19
// and tsukuba, found while looking for mutant fw-76's cases: the texture
// turns against the path, so a slow candidate's key pattern read 2-3 px
// while the ball moved 6-9 px, then was lost, and the ball was keyed
// again from the next detection, pair after pair: detected at pair 28 of
// 30 and 37 of 40 before a candidate whose pattern turned was confirmed
// from Dif(key, t)'s outline (dsp/controller_detect.cpp, outline_shift);
// at pair 10 since. Its neighbours (0.3 and 1 rev/s, other speeds and
// backdrops) were detected by pair 14 either way.
INSTANTIATE_TEST_SUITE_P(TurnedCandidate, BoxOnMotion,
                         ::testing::Values(motion_case{"pass125px_1_5pxpf_0_5rps_y_kodim19", 125,
                                                       2.6, pass, 0.3, 0.5, 'y', photo3, 30},
                                           motion_case{"pass125px_1_5pxpf_0_5rps_y_tsukuba_40f",
                                                       125, 2.6, pass, 0.3, 0.5, 'y', tsukuba, 40}),
                         case_name);

// Held out, round 78: 40 cases drawn at random (seed 78) over the issue's
// envelope before they were run: every path, balls 12-240 px wide 2-4 m
// away, spinning 1-10 rev/s about any axis or not at all, over every
// backdrop, 24-40 frames. Run once on this firmware: five moved faster
// than 30 px a frame (out of the envelope, left out); of the other 35,
// these 26 passed and 9 failed (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep78, BoxOnMotion,
    ::testing::Values(motion_case{"heldout78_01_recede121px_2_4m_kodim23", 121, 2.4, recede, 3.5,
                                  0.0, 'x', photo2, 32},
                      motion_case{"heldout78_02_recede33px_3_3m_2_7rps_y", 33, 3.3, recede, 3.6,
                                  2.7, 'y', procedural, 24},
                      motion_case{"heldout78_05_enter24px_3_6m_tsukuba", 24, 3.6, enter, 2.2, 0.0,
                                  'x', tsukuba, 32},
                      motion_case{"heldout78_07_pass176px_2_9m_2_2rps_x_aloe", 176, 2.9, pass, 2.2,
                                  2.2, 'x', aloe, 40},
                      motion_case{"heldout78_08_approach55px_3_9m_aloe", 55, 3.9, approach, 0.7,
                                  0.0, 'y', aloe, 24},
                      motion_case{"heldout78_09_approach17px_2_4m_teddy", 17, 2.4, approach, 0.3,
                                  0.0, 'y', photo4, 40},
                      motion_case{"heldout78_10_circle160px_3_0m_6_7rps_x_aloe", 160, 3.0, circle,
                                  0.5, 6.7, 'x', aloe, 24},
                      motion_case{"heldout78_11_enter127px_2_5m_teddy", 127, 2.5, enter, 0.3, 0.0,
                                  'z', photo4, 32},
                      motion_case{"heldout78_12_pass51px_2_7m_tsukuba", 51, 2.7, pass, 1.9, 0.0,
                                  'y', tsukuba, 32},
                      motion_case{"heldout78_15_pass80px_3_0m_5_6rps_z_venus", 80, 3.0, pass, 2.8,
                                  5.6, 'z', venus, 40},
                      motion_case{"heldout78_17_recede79px_2_8m_aloe", 79, 2.8, recede, 1.6, 0.0,
                                  'z', aloe, 32},
                      motion_case{"heldout78_18_thrown21px_3_8m_8_8rps_z_kodim19", 21, 3.8, thrown,
                                  0.8, 8.8, 'z', photo3, 24},
                      motion_case{"heldout78_20_circle176px_3_9m_7_5rps_y_aloe", 176, 3.9, circle,
                                  1.1, 7.5, 'y', aloe, 40},
                      motion_case{"heldout78_21_thrown119px_3_2m_tsukuba", 119, 3.2, thrown, 0.7,
                                  0.0, 'x', tsukuba, 24},
                      motion_case{"heldout78_22_enter135px_3_2m_6_2rps_y_aloe", 135, 3.2, enter,
                                  2.2, 6.2, 'y', aloe, 32},
                      motion_case{"heldout78_23_left58px_3_0m_4_5rps_x_aloe", 58, 3.0, pass_left,
                                  4.8, 4.5, 'x', aloe, 32},
                      motion_case{"heldout78_24_back53px_3_1m_9rps_z_kodim23", 53, 3.1, circle_back,
                                  2.5, 9.0, 'z', photo2, 32},
                      motion_case{"heldout78_25_approach135px_3_8m_5_3rps_z_kodim23", 135, 3.8,
                                  approach, 2.3, 5.3, 'z', photo2, 24},
                      motion_case{"heldout78_26_left68px_2_1m_9rps_y_aloe", 68, 2.1, pass_left, 4.8,
                                  9.0, 'y', aloe, 32},
                      motion_case{"heldout78_27_enter46px_2_7m_2_3rps_y_teddy", 46, 2.7, enter, 0.6,
                                  2.3, 'y', photo4, 32},
                      motion_case{"heldout78_28_recede101px_2_7m_7_5rps_z", 101, 2.7, recede, 0.4,
                                  7.5, 'z', procedural, 24},
                      motion_case{"heldout78_29_enter123px_3_8m_7_5rps_y_venus", 123, 3.8, enter,
                                  3.0, 7.5, 'y', venus, 32},
                      motion_case{"heldout78_30_enter32px_3_1m_1_6rps_x_kodim19", 32, 3.1, enter,
                                  1.0, 1.6, 'x', photo3, 32},
                      motion_case{"heldout78_35_thrown42px_3_3m_7_5rps_y", 42, 3.3, thrown, 1.6,
                                  7.5, 'y', procedural, 40},
                      motion_case{"heldout78_36_thrown85px_2_4m_3_7rps_y_kodim19", 85, 2.4, thrown,
                                  0.7, 3.7, 'y', photo3, 40},
                      motion_case{"heldout78_37_thrown80px_2_6m_5_9rps_y_aloe", 80, 2.6, thrown,
                                  0.8, 5.9, 'y', aloe, 24}),
    case_name);

// Balls of 80-96 px whose depth was their core's one match (tiled from 97
// px then), the depth 1.02-6.08 % off at one pair with the box within its
// bounds (then in DISABLED_Open); they pass since the tiled depth starts at
// 80 px (dsp/object_depth.h). Balls 120-140 px going away over teddy at 6-8
// px a frame (85-100 px when they failed), the 90 px circle from its other
// side over kodim19, the 80 px circle over venus and the 100 px circle at
// 1 px a frame over cones, shrinking to 80-96 px in its view.
INSTANTIATE_TEST_SUITE_P(
    TiledFromEighty, BoxOnMotion,
    ::testing::Values(
        motion_case{"recede140px_6pxpf_2rps_x_teddy", 140, 2.6, recede, 1.0, 2.0, 'x', photo4, 24},
        motion_case{"recede130px_6pxpf_1rps_y_teddy_speed0_9", 130, 2.6, recede, 0.9, 1.0, 'y',
                    photo4, 24},
        motion_case{"recede130px_6pxpf_1rps_z_teddy", 130, 2.6, recede, 1.0, 1.0, 'z', photo4, 24},
        motion_case{"recede125px_6pxpf_1_5rps_y_teddy", 125, 2.6, recede, 1.0, 1.5, 'y', photo4,
                    24},
        motion_case{"circle_back90px_3pxpf_1rps_y_kodim19_32f", 90, 2.6, circle_back, 0.4, 1.0, 'y',
                    photo3, 32},
        motion_case{"circle80px_3pxpf_2rps_x_venus_32f", 80, 2.6, circle, 0.4, 2.0, 'x', venus, 32},
        motion_case{"recede120px_8pxpf_1rps_y_teddy", 120, 2.6, recede, 1.2, 1.0, 'y', photo4, 24},
        motion_case{"recede130px_6pxpf_0_5rps_y_teddy", 130, 2.6, recede, 1.0, 0.5, 'y', photo4,
                    24},
        motion_case{"recede125px_6pxpf_1rps_x_teddy", 125, 2.6, recede, 1.0, 1.0, 'x', photo4, 24},
        motion_case{"circle100px_1pxpf_2rps_y_cones_40f", 100, 2.6, circle, 0.125, 2.0, 'y', photo,
                    40}),
    case_name);

// Held out, round 80: 40 cases drawn at random (seed 80, the envelope of
// round 78: every path, balls 12-240 px wide 2-4 m away, speeds 0.3-5,
// spinning 1-10 rev/s about any axis or not at all a third of the time,
// every backdrop, 24-40 frames) before they were run, on the firmware with
// the round box. Seven moved faster than 30 px a frame (left out); of the
// other 33, these 23 passed and 10 failed (DISABLED_Open). The 30 px ball
// passing left over venus failed on a pair where it touched the image's
// first column; such pairs are not judged since (ball_truth::in_both_views):
// 24 pass.
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep80, BoxOnMotion,
    ::testing::Values(motion_case{"heldout80_01_pass152px_3_5m_3_0rps_z", 152, 3.5, pass, 4.8, 3.0,
                                  'z', procedural, 32},
                      motion_case{"heldout80_03_circle107px_2_7m_2_8rps_y_cones", 107, 2.7, circle,
                                  1.1, 2.8, 'y', photo, 32},
                      motion_case{"heldout80_04_left180px_2_0m_3_7rps_y", 180, 2.0, pass_left, 0.3,
                                  3.7, 'y', procedural, 32},
                      motion_case{"heldout80_08_pass152px_4_0m_8_7rps_x_aloe", 152, 4.0, pass, 4.9,
                                  8.7, 'x', aloe, 32},
                      motion_case{"heldout80_10_recede206px_2_5m_5_8rps_z_aloe", 206, 2.5, recede,
                                  1.9, 5.8, 'z', aloe, 24},
                      motion_case{"heldout80_11_thrown156px_3_1m_6_0rps_x", 156, 3.1, thrown, 1.9,
                                  6.0, 'x', procedural, 32},
                      motion_case{"heldout80_12_enter110px_2_8m_8_4rps_y_kodim19", 110, 2.8, enter,
                                  1.4, 8.4, 'y', photo3, 40},
                      motion_case{"heldout80_13_back79px_2_6m_6_4rps_x_cones", 79, 2.6, circle_back,
                                  1.7, 6.4, 'x', photo, 24},
                      motion_case{"heldout80_15_approach59px_4_0m_2_8rps_z", 59, 4.0, approach, 0.8,
                                  2.8, 'z', procedural, 24},
                      motion_case{"heldout80_16_back97px_3_4m_9_1rps_x_tsukuba", 97, 3.4,
                                  circle_back, 1.8, 9.1, 'x', tsukuba, 32},
                      motion_case{"heldout80_18_left15px_3_6m_7_8rps_x_teddy", 15, 3.6, pass_left,
                                  4.8, 7.8, 'x', photo4, 32},
                      motion_case{"heldout80_19_back200px_2_6m_9_5rps_z_aloe", 200, 2.6,
                                  circle_back, 3.7, 9.5, 'z', aloe, 24},
                      motion_case{"heldout80_21_back70px_3_0m_7_9rps_x_kodim23", 70, 3.0,
                                  circle_back, 2.2, 7.9, 'x', photo2, 32},
                      motion_case{"heldout80_23_left42px_3_7m_kodim19", 42, 3.7, pass_left, 0.4,
                                  0.0, 'x', photo3, 32},
                      motion_case{"heldout80_24_recede94px_2_6m_cones", 94, 2.6, recede, 1.0, 0.0,
                                  'z', photo, 32},
                      motion_case{"heldout80_26_left165px_2_5m", 165, 2.5, pass_left, 2.7, 0.0, 'x',
                                  procedural, 32},
                      motion_case{"heldout80_27_approach33px_3_8m_6_5rps_x_tsukuba", 33, 3.8,
                                  approach, 1.3, 6.5, 'x', tsukuba, 40},
                      motion_case{"heldout80_29_left30px_3_8m_venus", 30, 3.8, pass_left, 2.8, 0.0,
                                  'z', venus, 32},
                      motion_case{"heldout80_31_pass119px_2_1m_6_2rps_x_kodim23", 119, 2.1, pass,
                                  0.7, 6.2, 'x', photo2, 32},
                      motion_case{"heldout80_32_approach81px_2_8m_teddy", 81, 2.8, approach, 1.4,
                                  0.0, 'z', photo4, 32},
                      motion_case{"heldout80_33_back152px_2_9m_9_4rps_y_cones", 152, 2.9,
                                  circle_back, 1.9, 9.4, 'y', photo, 24},
                      motion_case{"heldout80_36_back236px_2_4m_aloe", 236, 2.4, circle_back, 0.8,
                                  0.0, 'y', aloe, 40},
                      motion_case{"heldout80_39_left221px_3_8m_kodim19", 221, 3.8, pass_left, 2.5,
                                  0.0, 'y', photo3, 32}),
    case_name);

// A side of the box shorter than the ball's by over an eighth, grown back
// to a sphere's shape (dsp/round_box.h); then in DISABLED_Open. The 140 px
// ball going away over teddy at 12 px a frame, 20.4 px off at one pair past
// its 24th (the box 48 px high on an 88 px ball); a 30 px ball coming nearer
// over cones (a side 20.6 % off); a run of 40 frames of a 20 px ball
// coming nearer over kodim19 (0.6 px past its bound). The 100 px ball going
// away slowly over teddy for 40 frames, which passed with this rule, is in
// DISABLED_Open since the core is matched again on the box moved in.
INSTANTIATE_TEST_SUITE_P(ShortSideGrown, BoxOnMotion,
                         ::testing::Values(motion_case{"approach30px_5pxpf_2rps_y_cones_3m_40f", 30,
                                                       3.0, approach, 0.4, 2.0, 'y', photo, 40},
                                           motion_case{"approach20px_5pxpf_2rps_y_kodim19_3m_40f",
                                                       20, 3.0, approach, 0.4, 2.0, 'y', photo3,
                                                       40}),
                         case_name);

// A detection that is a sliver of its ball, grown to both differences'
// common part where that part holds it and is round, read over the whole
// frame (dsp/controller_track.cpp, grow_part, measure_motion); until then in
// DISABLED_Open. A 160 px ball thrown at half speed over kodim19, found by
// a sweep of 45 large balls (160-230 px) thrown at half speed over five
// backdrops (44 passed): detected as a 35 x 11 px sliver of its top, its
// box grew by about 20 px a pair and was 54.87 px off, above the ball's
// centre, at its first judged pair (49 x 110 px short), depth 1.84 % off
// (now 0.65 / 1.49 px, 0.46 %). The circle from its other side at 3 px a frame for 32
// frames, beside DriftAcrossCircleBack: a 90 px ball spinning about z over
// cones, 35.7 px off at one pair before the round box (its box a 14 x 8 px
// part of the ball), then 0.89 / 1.83 px with its depth 1.14 % off (now
// 0.77 / 1.44 px, 0.53 %).
INSTANTIATE_TEST_SUITE_P(RoundCommonPart, BoxOnMotion,
                         ::testing::Values(motion_case{"throw160px_half_kodim19", 160, 2.6, thrown,
                                                       0.5, 0.0, 'x', photo3, 40},
                                           motion_case{"circle_back90px_3pxpf_1rps_z_cones_32f", 90,
                                                       2.6, circle_back, 0.4, 1.0, 'z', photo, 32}),
                         case_name);

// A reach that draws the reported box out on one axis past a sphere's
// image is not taken on that axis (dsp/controller_stereo.cpp,
// widen_to_stereo_reach); until then in DISABLED_Open. Balls going away a
// few tenths of a metre before the background plane, which then matches
// inside the object's disparity span: 120-140 px over teddy (one end or
// side widened 41-44 px at one pair, 13.7-22.8 px off), round 78's 160 px
// ball over kodim23 (24.7 px), round 80's 44 px over kodim23 and 46 px over
// aloe (9.5 and 10.3 px).
INSTANTIATE_TEST_SUITE_P(ReachKeptRound, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout78_31_recede160px_2_9m_kodim23", 160,
                                                       2.9, recede, 0.3, 0.0, 'y', photo2, 32},
                                           motion_case{"recede140px_6pxpf_1rps_y_teddy_3m", 140,
                                                       3.0, recede, 1.0, 1.0, 'y', photo4, 24},
                                           motion_case{"recede120px_8pxpf_2rps_x_teddy_3m", 120,
                                                       3.0, recede, 1.2, 2.0, 'x', photo4, 24},
                                           motion_case{"recede130px_6pxpf_1rps_y_teddy_3m", 130,
                                                       3.0, recede, 1.0, 1.0, 'y', photo4, 24},
                                           motion_case{"heldout80_30_recede44px_3_5m_kodim23", 44,
                                                       3.5, recede, 1.7, 0.0, 'x', photo2, 32},
                                           motion_case{"heldout80_35_recede46px_3_9m_4_4rps_y_aloe",
                                                       46, 3.9, recede, 1.6, 4.4, 'y', aloe, 32}),
                         case_name);

// A reach's end is taken only where the next tile is not the object's
// either (dsp/stereo_reach.cpp, find_end); until then in DISABLED_Open.
// Round 84's balls going away near the background plane, which matches
// inside their disparity span: the reach ran over it to a flat patch and
// widened both axes at once (158 px over teddy: 17 px left and 33 px up at
// one pair, 20.1 px off; 85 px over venus, 7.3 px).
INSTANTIATE_TEST_SUITE_P(ReachEndConfirmed, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout84_10_recede158px_3_2m_teddy", 158,
                                                       3.2, recede, 3.8, 0.0, 'x', photo4, 40},
                                           motion_case{
                                               "heldout84_29_recede85px_3_8m_6_3rps_z_venus", 85,
                                               3.8, recede, 4.9, 6.3, 'z', venus, 32}),
                         case_name);

// A reach refused as drawn out is no size to judge the other axis's reach
// against (dsp/controller_stereo.cpp, widen_to_stereo_reach); until then in
// DISABLED_Open: round 84's 129 px ball going away over teddy had its width
// reach (37-44 px) refused at two pairs and its height reach (9 and 16 px)
// taken against it, a side 18 px (20.9 %) too long.
INSTANTIATE_TEST_SUITE_P(ReachJudgedWithoutTheRefused, BoxOnMotion,
                         ::testing::Values(motion_case{
                             "heldout84_35_recede129px_3_0m_5_2rps_x_teddy", 129, 3.0, recede, 3.0,
                             5.2, 'x', photo4, 40}),
                         case_name);

// No key is taken or kept while the depth moves a side of the box by more
// than max_step px a pair (dsp/controller_key.cpp, follow_slow_object);
// until then in DISABLED_Open: a 120 px ball going away over teddy at 6 px
// a frame, spinning 2 rev/s: its depth 1.13 % off at its 26th pair, its
// box 5.28 px off at its 27th (not traced).
INSTANTIATE_TEST_SUITE_P(NoKeyWhileTheDepthResizes, BoxOnMotion,
                         ::testing::Values(motion_case{"recede120px_6pxpf_2rps_x_teddy_30f", 120,
                                                       2.6, recede, 0.8, 2.0, 'x', photo4, 30}),
                         case_name);

// A bounce that brings the ball back to where it was two frames before:
// object(t-1) read at the end of the differences' common part the last box
// holds (dsp/box_refit.h, returned_axis); until then in DISABLED_Open: the
// 30 px throw over teddy (above), its two differences 54 px high at the
// bounce, no box followed, and the SAD box pulled towards their common
// part: the box reported 41 x 43 px for the 35 px ball, its height 8 px
// (22.9 %) too large, past the bound of 20 %.
INSTANTIATE_TEST_SUITE_P(ReturnedAtTheBounce, BoxOnMotion,
                         ::testing::Values(motion_case{"throw30px_2_2_4rps_x_teddy_4m", 30, 4.0,
                                                       thrown, 2.2, 4.0, 'x', photo4, 24}),
                         case_name);

// A ball whose speed changes across the extent window (on the circle, or
// on its other side, as it turns): the window's velocity changing every
// pair where every edge shows it (dsp/extent_window.h, window_axis);
// until then in DISABLED_Open, one velocity over the window put the box
// past the ball at one pair: 8.23 px (112 px over venus), 6.23 px (210 px
// over kodim23), and on the 209 px ball over venus at 30 px a frame a
// depth 1.17 % near.
INSTANTIATE_TEST_SUITE_P(
    SpeedChangeInTheWindow, BoxOnMotion,
    ::testing::Values(motion_case{"heldout80_00_back112px_3_1m_4_3rps_z_venus", 112, 3.1,
                                  circle_back, 3.6, 4.3, 'z', venus, 32},
                      motion_case{"heldout80_25_circle210px_3_2m_6_1rps_x_kodim23", 210, 3.2,
                                  circle, 3.6, 6.1, 'x', photo2, 40},
                      motion_case{"heldout86_09_back209px_2_4m_9_2rps_x_venus", 209, 2.4,
                                  circle_back, 3.7, 9.2, 'x', venus, 40}),
    case_name);

// The depth of an object of 24-59 px read on a round core, the ellipse
// inscribed in its box less a tenth a side (dsp/object_core.h); until then
// in DISABLED_Open, failing on the depth alone (38-55 px balls at
// 1.01-1.45 % at one pair, their boxes 2-3 px too wide or off, the square
// core's corners on the background). Round 80's 55 px circle over kodim23
// is open again (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(RoundCore, BoxOnMotion,
                         ::testing::Values(motion_case{"circle50px_2pxpf_1rps_x_aloe", 50, 2.6,
                                                       circle, 0.2, 1.0, 'x', aloe, 30},
                                           motion_case{"heldout80_07_circle43px_3_3m_tsukuba", 43,
                                                       3.3, circle, 0.4, 0.0, 'y', tsukuba, 32},
                                           motion_case{"heldout80_20_thrown43px_3_5m_3_6rps_y_aloe",
                                                       43, 3.5, thrown, 0.3, 3.6, 'y', aloe, 40},
                                           motion_case{"heldout85_18_back38px_3_4m_kodim19", 38,
                                                       3.4, circle_back, 1.7, 0.0, 'x', photo3, 24},
                                           motion_case{"throw40px_2_0_4rps_x_teddy_3_5m", 40, 3.5,
                                                       thrown, 2.0, 4.0, 'x', photo4, 24}),
                         case_name);

// Small balls, 17-22 px, failing on the depth alone in DISABLED_Open
// (1.01-1.29 % far at one or two pairs, their boxes 1-2 px off or too
// large, a seventh's corners on the background) until a core of 16-23 px
// was trimmed by a fifth (dsp/object_core.h): 0.54, 0.68 and 0.88 %.
// With the fifth alone round 78's 17 px ball coming nearer over teddy
// (HeldOutSweep78) failed, its box 5 px narrow at one pair, until a box
// carried with no difference stands for the depth it was sized at
// (dsp/controller_track.cpp, track_object).
INSTANTIATE_TEST_SUITE_P(
    SmallCoreFifth, BoxOnMotion,
    ::testing::Values(motion_case{"heldout78_03_left22px_2_9m_6_8rps_z_kodim23", 22, 2.9, pass_left,
                                  0.9, 6.8, 'z', photo2, 40},
                      motion_case{"heldout78_32_circle21px_3_5m_cones", 21, 3.5, circle, 1.3, 0.0,
                                  'x', photo, 32},
                      motion_case{"heldout85_17_pass17px_3_9m_tsukuba", 17, 3.9, pass, 4.6, 0.0,
                                  'x', tsukuba, 24}),
    case_name);

// Held out, round 84: 40 cases drawn at random (seed 84, round 80's
// envelope) before they were run, on the firmware with the reach kept
// round (ReachKeptRound). Seven moved faster than 30 px a frame (left
// out); of the other 33, these 26 passed and 7 failed (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep84, BoxOnMotion,
    ::testing::Values(
        motion_case{"heldout84_00_back210px_2_1m_3_9rps_x_aloe", 210, 2.1, circle_back, 0.3, 3.9,
                    'x', aloe, 32},
        motion_case{"heldout84_01_enter167px_2_3m_5_7rps_y_tsukuba", 167, 2.3, enter, 4.8, 5.7, 'y',
                    tsukuba, 40},
        motion_case{"heldout84_03_back149px_2_2m_2_2rps_z_cones", 149, 2.2, circle_back, 1.4, 2.2,
                    'z', photo, 32},
        motion_case{"heldout84_04_left199px_2_2m_2_3rps_z_aloe", 199, 2.2, pass_left, 0.6, 2.3, 'z',
                    aloe, 24},
        motion_case{"heldout84_06_enter237px_2_7m_9_0rps_y_venus", 237, 2.7, enter, 1.7, 9.0, 'y',
                    venus, 24},
        motion_case{"heldout84_07_pass235px_3_6m_6_4rps_x_kodim23", 235, 3.6, pass, 0.4, 6.4, 'x',
                    photo2, 32},
        motion_case{"heldout84_08_recede111px_3_3m_6_9rps_y_cones", 111, 3.3, recede, 1.6, 6.9, 'y',
                    photo, 24},
        motion_case{"heldout84_14_approach40px_2_9m_tsukuba", 40, 2.9, approach, 1.3, 0.0, 'x',
                    tsukuba, 24},
        motion_case{"heldout84_16_enter163px_3_2m_6_4rps_z", 163, 3.2, enter, 3.9, 6.4, 'z',
                    procedural, 32},
        motion_case{"heldout84_17_enter126px_3_6m_tsukuba", 126, 3.6, enter, 2.8, 0.0, 'x', tsukuba,
                    32},
        motion_case{"heldout84_18_circle90px_2_5m_2_1rps_z_tsukuba", 90, 2.5, circle, 2.6, 2.1, 'z',
                    tsukuba, 40},
        motion_case{"heldout84_19_enter190px_2_8m_6_6rps_z_teddy", 190, 2.8, enter, 2.0, 6.6, 'z',
                    photo4, 24},
        motion_case{"heldout84_20_pass206px_2_0m_venus", 206, 2.0, pass, 0.8, 0.0, 'x', venus, 40},
        motion_case{"heldout84_22_circle111px_3_9m_4_2rps_y", 111, 3.9, circle, 1.8, 4.2, 'y',
                    procedural, 24},
        motion_case{"heldout84_23_left193px_3_5m_3_8rps_y_venus", 193, 3.5, pass_left, 3.5, 3.8,
                    'y', venus, 24},
        motion_case{"heldout84_24_pass125px_3_5m_7_5rps_x_cones", 125, 3.5, pass, 0.8, 7.5, 'x',
                    photo, 32},
        motion_case{"heldout84_25_circle202px_2_5m_9_9rps_z_kodim23", 202, 2.5, circle, 1.5, 9.9,
                    'z', photo2, 32},
        motion_case{"heldout84_26_thrown180px_3_1m_5_9rps_x_aloe", 180, 3.1, thrown, 1.7, 5.9, 'x',
                    aloe, 32},
        motion_case{"heldout84_27_pass83px_3_5m_3_3rps_y_cones", 83, 3.5, pass, 3.9, 3.3, 'y',
                    photo, 32},
        motion_case{"heldout84_28_approach76px_2_9m_aloe", 76, 2.9, approach, 2.3, 0.0, 'x', aloe,
                    24},
        motion_case{"heldout84_30_circle66px_3_3m_aloe", 66, 3.3, circle, 0.9, 0.0, 'x', aloe, 40},
        motion_case{"heldout84_31_back165px_2_0m_5_4rps_x_tsukuba", 165, 2.0, circle_back, 0.5, 5.4,
                    'x', tsukuba, 32},
        motion_case{"heldout84_33_thrown15px_3_3m_6_0rps_x_kodim23", 15, 3.3, thrown, 1.3, 6.0, 'x',
                    photo2, 24},
        motion_case{"heldout84_34_pass191px_3_3m", 191, 3.3, pass, 2.6, 0.0, 'x', procedural, 24},
        motion_case{"heldout84_37_left203px_2_4m_aloe", 203, 2.4, pass_left, 3.4, 0.0, 'x', aloe,
                    40},
        motion_case{"heldout84_39_enter100px_3_5m_9_6rps_y_tsukuba", 100, 3.5, enter, 5.0, 9.6, 'y',
                    tsukuba, 32}),
    case_name);

// Held out, round 85: 40 cases drawn at random (seed 85, round 80's
// envelope) before they were run, on the firmware whose reach's end is
// confirmed by the next tile (ReachEndConfirmed). Eleven moved faster than
// 30 px a frame (left out); of the other 29, these 26 passed and 3 failed
// (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep85, BoxOnMotion,
    ::testing::Values(motion_case{"heldout85_00_circle191px_3_2m_2_7rps_y_tsukuba", 191, 3.2,
                                  circle, 0.8, 2.7, 'y', tsukuba, 40},
                      motion_case{"heldout85_02_recede42px_2_0m_6_6rps_y_aloe", 42, 2.0, recede,
                                  2.9, 6.6, 'y', aloe, 40},
                      motion_case{"heldout85_03_circle177px_3_7m_2_0rps_x", 177, 3.7, circle, 0.9,
                                  2.0, 'x', procedural, 32},
                      motion_case{"heldout85_04_thrown140px_3_7m_aloe", 140, 3.7, thrown, 3.5, 0.0,
                                  'x', aloe, 40},
                      motion_case{"heldout85_05_enter238px_3_5m_kodim23", 238, 3.5, enter, 0.6, 0.0,
                                  'x', photo2, 24},
                      motion_case{"heldout85_06_enter121px_3_1m_tsukuba", 121, 3.1, enter, 1.1, 0.0,
                                  'x', tsukuba, 40},
                      motion_case{"heldout85_08_back92px_2_4m_1_2rps_y_kodim23", 92, 2.4,
                                  circle_back, 1.1, 1.2, 'y', photo2, 24},
                      motion_case{"heldout85_10_left207px_3_2m_5_8rps_z_teddy", 207, 3.2, pass_left,
                                  1.0, 5.8, 'z', photo4, 24},
                      motion_case{"heldout85_11_recede200px_2_9m_3_2rps_z_venus", 200, 2.9, recede,
                                  1.9, 3.2, 'z', venus, 40},
                      motion_case{"heldout85_13_back130px_2_4m_tsukuba", 130, 2.4, circle_back, 1.2,
                                  0.0, 'x', tsukuba, 24},
                      motion_case{"heldout85_14_circle166px_2_4m", 166, 2.4, circle, 1.8, 0.0, 'x',
                                  procedural, 40},
                      motion_case{"heldout85_16_back152px_3_0m_2_4rps_x_teddy", 152, 3.0,
                                  circle_back, 3.7, 2.4, 'x', photo4, 24},
                      motion_case{"heldout85_19_left234px_3_5m", 234, 3.5, pass_left, 1.9, 0.0, 'x',
                                  procedural, 24},
                      motion_case{"heldout85_21_approach178px_2_4m_2_9rps_x_cones", 178, 2.4,
                                  approach, 0.6, 2.9, 'x', photo, 40},
                      motion_case{"heldout85_24_enter230px_3_6m_venus", 230, 3.6, enter, 2.1, 0.0,
                                  'x', venus, 32},
                      motion_case{"heldout85_25_thrown81px_3_1m_7_5rps_z_tsukuba", 81, 3.1, thrown,
                                  1.3, 7.5, 'z', tsukuba, 24},
                      motion_case{"heldout85_27_left39px_3_7m_teddy", 39, 3.7, pass_left, 3.2, 0.0,
                                  'x', photo4, 24},
                      motion_case{"heldout85_28_left77px_3_4m_teddy", 77, 3.4, pass_left, 1.4, 0.0,
                                  'x', photo4, 40},
                      motion_case{"heldout85_29_back227px_4_0m_teddy", 227, 4.0, circle_back, 3.3,
                                  0.0, 'x', photo4, 24},
                      motion_case{"heldout85_30_approach180px_3_2m_tsukuba", 180, 3.2, approach,
                                  1.0, 0.0, 'x', tsukuba, 32},
                      motion_case{"heldout85_32_left62px_3_1m_tsukuba", 62, 3.1, pass_left, 4.3,
                                  0.0, 'x', tsukuba, 24},
                      motion_case{"heldout85_34_circle151px_2_1m_6_3rps_y_venus", 151, 2.1, circle,
                                  2.7, 6.3, 'y', venus, 40},
                      motion_case{"heldout85_36_approach68px_2_2m_kodim23", 68, 2.2, approach, 1.0,
                                  0.0, 'x', photo2, 32},
                      motion_case{"heldout85_37_recede76px_2_8m_6_5rps_y_cones", 76, 2.8, recede,
                                  4.7, 6.5, 'y', photo, 32},
                      motion_case{"heldout85_38_enter131px_2_8m_4_8rps_x_tsukuba", 131, 2.8, enter,
                                  2.4, 4.8, 'x', tsukuba, 32},
                      motion_case{"heldout85_39_circle71px_3_6m_4_6rps_z_tsukuba", 71, 3.6, circle,
                                  1.4, 4.6, 'z', tsukuba, 40}),
    case_name);

// Held out, round 86: 40 cases drawn at random (seed 86, round 80's
// envelope) before they were run, on the firmware with a small core a
// fifth (SmallCoreFifth). Eleven moved faster than 30 px a frame (left
// out); of the other 29, 26 passed and 3 failed (DISABLED_Open). The
// 222 px ball on the circle's other side is open again (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep86, BoxOnMotion,
    ::testing::Values(
        motion_case{"heldout86_00_pass154px_3_7m_cones", 154, 3.7, pass, 1.8, 0.0, 'x', photo, 40},
        motion_case{"heldout86_03_left87px_4_0m_4_3rps_y_venus", 87, 4.0, pass_left, 1.0, 4.3, 'y',
                    venus, 40},
        motion_case{"heldout86_04_circle64px_3_4m_3_9rps_z_tsukuba", 64, 3.4, circle, 0.5, 3.9, 'z',
                    tsukuba, 32},
        motion_case{"heldout86_05_recede168px_2_8m_aloe", 168, 2.8, recede, 3.1, 0.0, 'x', aloe,
                    40},
        motion_case{"heldout86_06_approach119px_2_1m_kodim23", 119, 2.1, approach, 0.8, 0.0, 'x',
                    photo2, 24},
        motion_case{"heldout86_07_recede136px_3_6m_8_3rps_z", 136, 3.6, recede, 4.6, 8.3, 'z',
                    procedural, 40},
        motion_case{"heldout86_08_pass208px_3_6m", 208, 3.6, pass, 1.9, 0.0, 'x', procedural, 40},
        motion_case{"heldout86_11_pass77px_2_5m_6_2rps_z_venus", 77, 2.5, pass, 4.0, 6.2, 'z',
                    venus, 32},
        motion_case{"heldout86_12_enter237px_2_9m_cones", 237, 2.9, enter, 4.5, 0.0, 'x', photo,
                    32},
        motion_case{"heldout86_13_pass221px_2_6m_4_7rps_y_kodim19", 221, 2.6, pass, 0.5, 4.7, 'y',
                    photo3, 40},
        motion_case{"heldout86_14_back187px_3_5m_3_6rps_x_kodim19", 187, 3.5, circle_back, 2.6, 3.6,
                    'x', photo3, 24},
        motion_case{"heldout86_15_enter206px_2_3m", 206, 2.3, enter, 4.0, 0.0, 'x', procedural, 24},
        motion_case{"heldout86_16_left32px_2_9m_5_7rps_y_kodim23", 32, 2.9, pass_left, 5.0, 5.7,
                    'y', photo2, 32},
        motion_case{"heldout86_17_thrown55px_2_7m_cones", 55, 2.7, thrown, 0.8, 0.0, 'x', photo,
                    24},
        motion_case{"heldout86_19_enter153px_3_4m_kodim23", 153, 3.4, enter, 2.8, 0.0, 'x', photo2,
                    40},
        motion_case{"heldout86_20_left222px_4_0m_7_3rps_y_aloe", 222, 4.0, pass_left, 1.5, 7.3, 'y',
                    aloe, 24},
        motion_case{"heldout86_21_approach113px_2_8m_9_6rps_x_tsukuba", 113, 2.8, approach, 1.9,
                    9.6, 'x', tsukuba, 24},
        motion_case{"heldout86_22_enter141px_2_8m_1_7rps_y_cones", 141, 2.8, enter, 3.6, 1.7, 'y',
                    photo, 32},
        motion_case{"heldout86_26_thrown145px_3_8m", 145, 3.8, thrown, 0.9, 0.0, 'x', procedural,
                    32},
        motion_case{"heldout86_27_recede230px_2_5m_tsukuba", 230, 2.5, recede, 1.1, 0.0, 'x',
                    tsukuba, 40},
        motion_case{"heldout86_28_enter222px_3_7m_1_9rps_x", 222, 3.7, enter, 0.7, 1.9, 'x',
                    procedural, 32},
        motion_case{"heldout86_34_enter122px_3_7m_kodim23", 122, 3.7, enter, 0.5, 0.0, 'x', photo2,
                    40},
        motion_case{"heldout86_36_pass116px_2_1m_1_2rps_y_tsukuba", 116, 2.1, pass, 1.0, 1.2, 'y',
                    tsukuba, 40},
        motion_case{"heldout86_38_circle70px_2_0m_6_3rps_x_kodim23", 70, 2.0, circle, 3.1, 6.3, 'x',
                    photo2, 32},
        motion_case{"heldout86_39_recede31px_3_8m_9_3rps_x", 31, 3.8, recede, 3.5, 9.3, 'x',
                    procedural, 40}),
    case_name);

// Held out, round 91: 40 cases drawn at random (seed 91, round 78's
// envelope: every path, balls 12-240 px wide 2-4 m away, 0.3-5 times the
// path's speed, half of them spinning 1-10 rev/s about any axis, every
// backdrop, 24-40 frames) before they were run, on the firmware with the
// depth gated against the track's line (since removed). Eleven moved
// faster than 30 px a frame (left out); of the other 29, 27 passed and 2
// failed (DISABLED_Open). The firmware before the gate passed the same 27
// and failed the same 2 (its depth maxima on three passing cases higher).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep91, BoxOnMotion,
    ::testing::Values(
        motion_case{"heldout91_00_left163px_2_3m_aloe", 163, 2.3, pass_left, 3.5, 0.0, 'x', aloe,
                    32},
        motion_case{"heldout91_01_approach223px_2_5m_8_2rps_x_kodim19", 223, 2.5, approach, 1.2,
                    8.2, 'x', photo3, 32},
        motion_case{"heldout91_02_left208px_3_7m_7_3rps_z_teddy", 208, 3.7, pass_left, 4.1, 7.3,
                    'z', photo4, 32},
        motion_case{"heldout91_03_enter108px_3_5m_7_2rps_y_kodim23", 108, 3.5, enter, 4.0, 7.2, 'y',
                    photo2, 32},
        motion_case{"heldout91_05_pass112px_2_9m_venus", 112, 2.9, pass, 2.8, 0.0, 'x', venus, 32},
        motion_case{"heldout91_06_back146px_3_6m_aloe", 146, 3.6, circle_back, 2.0, 0.0, 'x', aloe,
                    40},
        motion_case{"heldout91_07_enter127px_3_8m_7_0rps_y_tsukuba", 127, 3.8, enter, 4.2, 7.0, 'y',
                    tsukuba, 24},
        motion_case{"heldout91_08_recede57px_3_5m_3_8rps_z_kodim23", 57, 3.5, recede, 3.7, 3.8, 'z',
                    photo2, 40},
        motion_case{"heldout91_09_left116px_2_1m_kodim23", 116, 2.1, pass_left, 4.2, 0.0, 'x',
                    photo2, 24},
        motion_case{"heldout91_13_left128px_2_8m_5_3rps_z_venus", 128, 2.8, pass_left, 4.4, 5.3,
                    'z', venus, 24},
        motion_case{"heldout91_14_circle173px_2_5m_1_5rps_z_venus", 173, 2.5, circle, 3.7, 1.5, 'z',
                    venus, 24},
        motion_case{"heldout91_17_thrown195px_3_8m_5_5rps_z_cones", 195, 3.8, thrown, 0.4, 5.5, 'z',
                    photo, 40},
        motion_case{"heldout91_18_enter141px_2_6m_aloe", 141, 2.6, enter, 2.7, 0.0, 'x', aloe, 24},
        motion_case{"heldout91_19_back102px_2_1m_kodim19", 102, 2.1, circle_back, 1.0, 0.0, 'x',
                    photo3, 40},
        motion_case{"heldout91_20_left62px_2_3m_venus", 62, 2.3, pass_left, 2.3, 0.0, 'x', venus,
                    40},
        motion_case{"heldout91_21_circle191px_2_7m_tsukuba", 191, 2.7, circle, 2.8, 0.0, 'x',
                    tsukuba, 32},
        motion_case{"heldout91_22_left153px_3_2m_6_1rps_y_kodim23", 153, 3.2, pass_left, 2.7, 6.1,
                    'y', photo2, 32},
        motion_case{"heldout91_23_circle66px_3_1m_cones", 66, 3.1, circle, 3.5, 0.0, 'x', photo,
                    40},
        motion_case{"heldout91_25_pass234px_3_8m_tsukuba", 234, 3.8, pass, 4.6, 0.0, 'x', tsukuba,
                    24},
        motion_case{"heldout91_28_enter132px_2_1m_cones", 132, 2.1, enter, 3.6, 0.0, 'x', photo,
                    40},
        motion_case{"heldout91_30_circle146px_3_9m_5_3rps_z_cones", 146, 3.9, circle, 2.7, 5.3, 'z',
                    photo, 32},
        motion_case{"heldout91_31_back64px_3_2m_cones", 64, 3.2, circle_back, 1.2, 0.0, 'x', photo,
                    40},
        motion_case{"heldout91_32_left129px_2_9m_2_6rps_z_kodim23", 129, 2.9, pass_left, 1.5, 2.6,
                    'z', photo2, 40},
        motion_case{"heldout91_33_enter238px_3_2m_2_0rps_z", 238, 3.2, enter, 3.7, 2.0, 'z',
                    procedural, 40},
        motion_case{"heldout91_34_left78px_2_5m_7_4rps_x_venus", 78, 2.5, pass_left, 2.9, 7.4, 'x',
                    venus, 24},
        motion_case{"heldout91_35_circle115px_3_7m_kodim19", 115, 3.7, circle, 2.1, 0.0, 'x',
                    photo3, 32},
        motion_case{"heldout91_37_thrown76px_3_8m_5_7rps_x_cones", 76, 3.8, thrown, 2.1, 5.7, 'x',
                    photo, 32}),
    case_name);

// Open: small balls thrown fast 3.5-4 m away, found while looking for the
// apex cases above. The box centre stays within its bounds, but at one pair
// near the bounce the depth is off by more than 1 % (23.7 px of disparity
// at 4 m: 1 % is 0.24 px). 30 px at 28 px a frame: 1.22 / 3.87 px, depth
// 1.37 % (pair 16), and one box side 1 px past its bound (passes:
// ReturnedAtTheBounce); 40 px at 3.5 m, 30 px a frame: 0.72 / 1.92 px,
// depth 1.45 % (pair 17; passes: RoundCore).
// Round 78's nine held-out failures (HeldOutSweep78): seven of its ten
// balls under 30 px wide fail (the 16 px and 17 px circles over kodim23
// with the depth 26 % and 70 % off; the 17 px one 5.3 % since a fifth's
// core, and the 21-22 px ones pass: SmallCoreFifth), the 185 px ball going away over aloe
// loses its track (the 160 px one over kodim23 passes: ReachKeptRound; the
// 185 px one left out since: its scene gives 3 judgeable pairs).
// Balls 120-140 px going away over teddy at 6-8 px a frame, most spinning,
// tried beside round 23's 120 px ball (which passes): 10 of 24 failed at 24
// frames, 7 of them on the depth alone (TiledFromEighty since); three were
// 13.7-22.8 px off at one pair (ReachKeptRound since), and one more at 30
// frames past its 24th (the depth 1.13 % off at about 77 px, untiled;
// passes since no key is kept while the depth resizes the box:
// NoKeyWhileTheDepthResizes).
// Found while looking for the drift mutants' cases beside
// DriftAcrossCircleBack: a 35 px circle over cones (6.06 px off at one pair).
// Round 80's nine held-out failures (HeldOutSweep80): four on the depth
// alone, 1.07-1.20 % too far at one or two pairs (43-55 px balls over
// kodim23, tsukuba, aloe, which pass: RoundCore; a 29 px ball coming
// nearer); a 112 px ball on the
// circle's other side over venus 8.2 px off at one pair, a 210 px circle
// 6.23 px (both pass: SpeedChangeInTheWindow); a 174 px
// ball going away 24.5 px off before it reaches the
// background plane, its tracker's box held at 153 x 151 px while it shrank
// (the 44 px and 46 px ones pass: ReachKeptRound; the 174 px one since
// the depth gate, open again since it was removed: DISABLED_Open).
// Round 84's seven held-out failures (HeldOutSweep84): four balls going
// away (85-158 px) 7.3-26.4 px off near the background plane, their boxes
// grown on both axes at once (two pass: ReachEndConfirmed; the 157 px one
// over tsukuba failed on the depth alone, 1.01 %, passed with the depth
// gate and is open again without it;
// the 129 px one over teddy passes: ReachJudgedWithoutTheRefused); a 44 px
// circle over aloe (9.36 px, depth 1.93 %; passed with the depth gate, open
// again without it), a 34 px ball entering over
// venus (depth 1.48 %), and a 235 px ball on the circle's other side that left TRACK for a pair.
// Round 85's three held-out failures (HeldOutSweep85): a 17 px pass over
// tsukuba (depth 1.01 %; passes: SmallCoreFifth) and a 38 px ball on the circle's other side over
// kodim19 (1.29 %; passes: RoundCore) on the depth alone; a 111 px ball going away from 4 m
// over teddy, 2.88 / 3.31 px, with 4 pairs scored of the 5 a case needs
// (from pair 10 it is not wholly before the background plane at 5 m; left
// out since: its scene gives 4 judgeable pairs).
// Found by a sweep of 144 slow passes and circles (50-140 px at 1-2 px a frame,
// spinning 0.5-1 rev/s about z or x), 143 of which pass: a 50 px circle over
// aloe, its depth 1.01 % off at one pair (passes: RoundCore).
// Not run by default (DISABLED_): the firmware does not meet them yet.
// Round 86's three held-out failures (HeldOutSweep86): a 209 px ball on
// the circle's other side over venus at 30 px a frame, spinning 9.2 rev/s,
// depth 1.17 % near at one pair (its box 25-35 px short of its height for
// three pairs; passes: SpeedChangeInTheWindow); a 227 px ball going
// away over teddy, its box 9-12 px too
// large from pair 20 and its depth 1.27-1.67 % far at its last four pairs
// (near the background plane); a 229 px ball on the circle's other side
// over tsukuba lost TRACK at pair 25 and was detected again for three
// pairs after a box 12 px too wide.

// Balls whose depth turns, which no box case had when a pair's depth off
// the track's line was first reported at the line: balls thrown at 1-4 m/s
// against the background's wall from 3.5-4.5 m, bouncing back at 0.75 of
// that speed (scene::trajectory::rebound: the depth turns within a frame),
// and balls swung on a horizontal circle whose depth turns smoothly at its
// nearest or farthest point. Written before they were run; on the line 5
// of these 14 passed and 9 failed, all on the depth (the bounce's pair
// replaced by the line going on past the wall, 1.12-3.72 %; the smooth
// turn extrapolated 0.76 % off, 1.32-1.47 %), and 13 passed with nothing
// replaced. With the gate removed (the measured depth reported) the same 13
// pass; the 25 px ball over teddy fails on its own measured depth, 1.05 %
// (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    DepthTurns, BoxOnMotion,
    ::testing::Values(
        motion_case{"rebound40px_2mps_4_2m", 40, 4.2, rebound, 0.5, 0.0, 'x', procedural, 30, 0.0,
                    2.0},
        motion_case{"rebound70px_3mps_3_8m_cones", 70, 3.8, rebound, 1.0, 0.0, 'x', photo, 30, 0.0,
                    3.0},
        motion_case{"rebound100px_4mps_3_5m_2rps_y_venus", 100, 3.5, rebound, 0.6, 2.0, 'y', venus,
                    30, 0.0, 4.0},
        motion_case{"rebound55px_2_5mps_4m_3rps_x_kodim23", 55, 4.0, rebound, 0.8, 3.0, 'x', photo2,
                    30, 0.0, 2.5},
        motion_case{"rebound30px_1mps_4_5m_aloe", 30, 4.5, rebound, 0.4, 0.0, 'x', aloe, 34, 0.0,
                    1.0},
        motion_case{"rebound80px_3mps_4m_5rps_z_tsukuba", 80, 4.0, rebound, 1.0, 5.0, 'z', tsukuba,
                    28, 0.0, 3.0},
        motion_case{"rebound45px_1_5mps_4_4m_1rps_y_kodim19", 45, 4.4, rebound, 0.6, 1.0, 'y',
                    photo3, 30, 0.0, 1.5},
        motion_case{"orbit_near40px_2_5m", 40, 2.5, orbit_near, 2.0, 0.0, 'x', procedural, 28},
        motion_case{"orbit_near80px_2_2m_2rps_y_cones", 80, 2.2, orbit_near, 2.5, 2.0, 'y', photo,
                    28},
        motion_case{"orbit_near25px_2_8m_teddy", 25, 2.8, orbit_near, 1.5, 0.0, 'x', photo4, 32},
        motion_case{"orbit_near120px_2m_4rps_x_venus", 120, 2.0, orbit_near, 2.0, 4.0, 'x', venus,
                    28},
        motion_case{"orbit_far50px_2_4m_kodim19", 50, 2.4, orbit_far, 2.0, 0.0, 'x', photo3, 28},
        motion_case{"orbit_far90px_2_2m_3rps_z_aloe", 90, 2.2, orbit_far, 2.5, 3.0, 'z', aloe, 28}),
    case_name);

// Held out, round 92: 20 balls whose depth turns, drawn at random (seed
// 92, a script outside the tree) after the bounce and the curvature were
// kept and committed before they were run: 10 thrown at the wall (20-120
// px, from 3.3-4.5 m at 1-4 m/s, sideways at up to 200 px over the run)
// and 10 swung round (20-150 px, 2-3 m, 1-3 times the circle's speed), on
// the eight backgrounds, 60 % spinning at 0.5-8 rev/s. 14 passed, 6 failed
// (DISABLED_Open); on the line 7 passed, with nothing replaced 17. Used
// since to try a rule (docs/firmware.md, "A depth that turns"), so no
// longer held out. With the gate removed 17 pass (three balls swung round
// whose depths the fit replaced out of DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutTurns92, BoxOnMotion,
    ::testing::Values(motion_case{"heldout92_00_rebound54px_4_3m_3_9mps_4_6rps_z_venus", 54, 4.3,
                                  rebound, 0.9, 4.6, 'z', venus, 21, 0.0, 3.9},
                      motion_case{"heldout92_01_orbit_near106px_2_1m_2_7x_aloe", 106, 2.1,
                                  orbit_near, 2.7, 0.0, 'x', aloe, 25},
                      motion_case{"heldout92_02_rebound40px_4_2m_2_4mps_1_7rps_z_kodim23", 40, 4.2,
                                  rebound, 0.9, 1.7, 'z', photo2, 27, 0.0, 2.4},
                      motion_case{"heldout92_03_orbit_near37px_2_4m_1_8x_7_6rps_y_cones", 37, 2.4,
                                  orbit_near, 1.8, 7.6, 'y', photo, 29},
                      motion_case{"heldout92_05_orbit_far94px_2_3m_3_0x", 94, 2.3, orbit_far, 3.0,
                                  0.0, 'y', procedural, 24},
                      motion_case{"heldout92_07_orbit_far146px_2_5m_1_6x_1_2rps_z_tsukuba", 146,
                                  2.5, orbit_far, 1.6, 1.2, 'z', tsukuba, 31},
                      motion_case{"heldout92_08_rebound91px_4_0m_3_9mps_6_1rps_x_tsukuba", 91, 4.0,
                                  rebound, 1.1, 6.1, 'x', tsukuba, 24, 0.0, 3.9},
                      motion_case{"heldout92_09_orbit_near55px_2_7m_2_2x_0_6rps_x_kodim23", 55, 2.7,
                                  orbit_near, 2.2, 0.6, 'x', photo2, 27},
                      motion_case{"heldout92_10_rebound84px_3_7m_2_6mps_6_6rps_x_aloe", 84, 3.7,
                                  rebound, 0.4, 6.6, 'x', aloe, 33, 0.0, 2.6},
                      motion_case{"heldout92_11_orbit_near76px_2_4m_1_8x_4_6rps_z_venus", 76, 2.4,
                                  orbit_near, 1.8, 4.6, 'z', venus, 29},
                      motion_case{"heldout92_12_rebound102px_4_5m_2_2mps_teddy", 102, 4.5, rebound,
                                  1.1, 0.0, 'x', photo4, 19, 0.0, 2.2},
                      motion_case{"heldout92_13_orbit_far106px_2_2m_2_2x_1_0rps_z_kodim23", 106,
                                  2.2, orbit_far, 2.2, 1.0, 'z', photo2, 27},
                      motion_case{"heldout92_15_orbit_near37px_2_9m_2_6x_kodim23", 37, 2.9,
                                  orbit_near, 2.6, 0.0, 'y', photo2, 25},
                      motion_case{"heldout92_16_rebound69px_3_8m_3_4mps_3_0rps_x_venus", 69, 3.8,
                                  rebound, 0.4, 3.0, 'x', venus, 28, 0.0, 3.4},
                      motion_case{"heldout92_17_orbit_far113px_2_5m_2_8x_4_3rps_x_teddy", 113, 2.5,
                                  orbit_far, 2.8, 4.3, 'x', photo4, 24},
                      motion_case{"heldout92_18_rebound61px_4_0m_3_1mps_tsukuba", 61, 4.0, rebound,
                                  0.6, 0.0, 'y', tsukuba, 27, 0.0, 3.1},
                      motion_case{"heldout92_19_orbit_far128px_2_9m_1_9x_kodim23", 128, 2.9,
                                  orbit_far, 1.9, 0.0, 'z', photo2, 28}),
    case_name);

// Held out, round 93: 12 balls whose depth turns (6 thrown at the wall, 6
// swung round, round 92's envelope) and 8 going away from or coming nearer
// the rig (20-200 px from 2-4 m, 0.3-5 times the path's speed), drawn at
// random (seed 93, a script outside the tree) and committed before they
// were run, after round 92 had been used to try a rule. 15 passed, 5
// failed (DISABLED_Open); on the line 14 passed, with nothing replaced 16,
// as with the gate removed (the 103 px ball thrown at the wall from 4.5 m,
// 0.57 %, out of DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutTurns93, BoxOnMotion,
    ::testing::Values(motion_case{"heldout93_00_rebound31px_3_7m_1_5mps_5_9rps_x_aloe", 31, 3.7,
                                  rebound, 0.4, 5.9, 'x', aloe, 49, 0.0, 1.5},
                      motion_case{"heldout93_01_orbit_near114px_2_4m_1_2x_7_2rps_z", 114, 2.4,
                                  orbit_near, 1.2, 7.2, 'z', procedural, 36},
                      motion_case{"heldout93_02_rebound103px_4_5m_1_5mps_5_4rps_x_cones", 103, 4.5,
                                  rebound, 0.6, 5.4, 'x', photo, 21, 0.0, 1.5},
                      motion_case{"heldout93_03_orbit_far36px_2_1m_1_3x_tsukuba", 36, 2.1,
                                  orbit_far, 1.3, 0.0, 'y', tsukuba, 34},
                      motion_case{"heldout93_05_orbit_near42px_2_5m_2_9x_7_2rps_z_tsukuba", 42, 2.5,
                                  orbit_near, 2.9, 7.2, 'z', tsukuba, 24},
                      motion_case{"heldout93_06_rebound52px_4_1m_3_5mps_5_4rps_z_kodim23", 52, 4.1,
                                  rebound, 0.6, 5.4, 'z', photo2, 24, 0.0, 3.5},
                      motion_case{"heldout93_07_orbit_near127px_2_5m_1_0x", 127, 2.5, orbit_near,
                                  1.0, 0.0, 'x', procedural, 40},
                      motion_case{"heldout93_10_rebound26px_3_9m_2_8mps_2_9rps_y_cones", 26, 3.9,
                                  rebound, 0.9, 2.9, 'y', photo, 31, 0.0, 2.8},
                      motion_case{"heldout93_11_orbit_near92px_2_1m_1_5x_4_8rps_y_venus", 92, 2.1,
                                  orbit_near, 1.5, 4.8, 'y', venus, 32},
                      motion_case{"heldout93_12_approach114px_3_0m_1_9x", 114, 3.0, approach, 1.9,
                                  0.0, 'z', procedural, 40},
                      motion_case{"heldout93_13_approach170px_3_2m_0_7x", 170, 3.2, approach, 0.7,
                                  0.0, 'z', procedural, 24},
                      motion_case{"heldout93_15_approach56px_4_0m_4_6x_kodim23", 56, 4.0, approach,
                                  4.6, 0.0, 'z', photo2, 40},
                      motion_case{"heldout93_16_recede66px_2_6m_2_1x_4_1rps_y_kodim19", 66, 2.6,
                                  recede, 2.1, 4.1, 'y', photo3, 24},
                      motion_case{"heldout93_17_approach124px_2_1m_2_3x_3_7rps_y_aloe", 124, 2.1,
                                  approach, 2.3, 3.7, 'y', aloe, 40},
                      motion_case{"heldout93_18_recede172px_2_4m_1_8x_1_4rps_x_tsukuba", 172, 2.4,
                                  recede, 1.8, 1.4, 'x', tsukuba, 40},
                      motion_case{"heldout93_19_recede76px_2_6m_2_7x_kodim23", 76, 2.6, recede, 2.7,
                                  0.0, 'y', photo2, 40}),
    case_name);

// Held out, rounds 94 and 95: 30 cases each, drawn at random (seeds 94
// and 95, a script outside the tree) over every path (the depth turns
// among them), balls 12-240 px wide (20-110 px thrown at the wall, 30-150
// px swung round), half of them spinning 1-10 rev/s, every backdrop,
// 24-40 frames, and committed before they were run. Cases moving faster
// than 30 px a frame are out of the envelope and left out. They decide
// whether the firmware keeps the depth gate: it stays only if it passes
// more of them than the same firmware with nothing replaced; on a tie or
// fewer, the measured depth is reported. Five moved faster than 30 px a
// frame (left out: four passed, a 48 px throw at 62 px a frame failed). Of
// the other 55, the gate passed 41 and nothing replaced 44 (three balls
// swung round, whose depths the fit replaced: 1.09-1.29 % against
// 0.59-0.65 %), none the other way; so the gate was removed (docs/
// firmware.md, "The measured depth"). These 44 pass; the 11 that fail are
// in DISABLED_Open.
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep94, BoxOnMotion,
    ::testing::Values(motion_case{"heldout94_01_orbit_near115px_3_0m_1_0x_4_9rps_y_tsukuba", 115,
                                  3.0, orbit_near, 1.0, 4.9, 'y', tsukuba, 30},
                      motion_case{"heldout94_02_orbit_far96px_2_4m_2_7x_kodim23", 96, 2.4,
                                  orbit_far, 2.7, 0.0, 'y', photo2, 26},
                      motion_case{"heldout94_03_orbit_far141px_2_5m_3_0x_venus", 141, 2.5,
                                  orbit_far, 3.0, 0.0, 'y', venus, 35},
                      motion_case{"heldout94_04_pass62px_3_5m_0_7x_aloe", 62, 3.5, pass, 0.7, 0.0,
                                  'x', aloe, 34},
                      motion_case{"heldout94_07_thrown85px_3_3m_0_4x_venus", 85, 3.3, thrown, 0.4,
                                  0.0, 'x', venus, 29},
                      motion_case{"heldout94_12_back53px_2_4m_0_3x_4_4rps_x_kodim23", 53, 2.4,
                                  circle_back, 0.3, 4.4, 'x', photo2, 28},
                      motion_case{"heldout94_13_enter25px_2_2m_3_5x_aloe", 25, 2.2, enter, 3.5, 0.0,
                                  'x', aloe, 26},
                      motion_case{"heldout94_14_orbit_near62px_2_1m_2_8x_tsukuba", 62, 2.1,
                                  orbit_near, 2.8, 0.0, 'z', tsukuba, 38},
                      motion_case{"heldout94_15_pass21px_3_2m_3_6x_teddy", 21, 3.2, pass, 3.6, 0.0,
                                  'y', photo4, 37},
                      motion_case{"heldout94_17_circle29px_3_7m_1_2x_cones", 29, 3.7, circle, 1.2,
                                  0.0, 'y', photo, 38},
                      motion_case{"heldout94_18_left29px_2_0m_2_4x_cones", 29, 2.0, pass_left, 2.4,
                                  0.0, 'y', photo, 30},
                      motion_case{"heldout94_19_thrown64px_2_8m_0_5x_tsukuba", 64, 2.8, thrown, 0.5,
                                  0.0, 'z', tsukuba, 28},
                      motion_case{"heldout94_20_back174px_2_7m_0_6x_aloe", 174, 2.7, circle_back,
                                  0.6, 0.0, 'y', aloe, 30},
                      motion_case{"heldout94_21_recede117px_3_0m_1_9x", 117, 3.0, recede, 1.9, 0.0,
                                  'x', procedural, 31},
                      motion_case{"heldout94_22_thrown43px_3_9m_1_9x_3_8rps_x_cones", 43, 3.9,
                                  thrown, 1.9, 3.8, 'x', photo, 30},
                      motion_case{"heldout94_24_pass41px_3_6m_1_2x_9_1rps_y_venus", 41, 3.6, pass,
                                  1.2, 9.1, 'y', venus, 37},
                      motion_case{"heldout94_25_orbit_far108px_2_6m_1_8x_aloe", 108, 2.6, orbit_far,
                                  1.8, 0.0, 'z', aloe, 28},
                      motion_case{"heldout94_26_approach151px_2_7m_0_4x_venus", 151, 2.7, approach,
                                  0.4, 0.0, 'x', venus, 28},
                      motion_case{"heldout94_27_back49px_3_0m_0_4x_3_3rps_z_kodim23", 49, 3.0,
                                  circle_back, 0.4, 3.3, 'z', photo2, 27},
                      motion_case{"heldout94_29_orbit_far134px_2_5m_2_5x_aloe", 134, 2.5, orbit_far,
                                  2.5, 0.0, 'x', aloe, 30}),
    case_name);

INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep95, BoxOnMotion,
    ::testing::Values(motion_case{"heldout95_00_rebound48px_4_5m_3_8mps_5_4rps_x", 48, 4.5, rebound,
                                  0.8, 5.4, 'x', procedural, 26, 0.0, 3.8},
                      motion_case{"heldout95_01_orbit_far47px_2_2m_2_1x_cones", 47, 2.2, orbit_far,
                                  2.1, 0.0, 'x', photo, 35},
                      motion_case{"heldout95_02_back111px_2_8m_0_5x_9_6rps_z_kodim23", 111, 2.8,
                                  circle_back, 0.5, 9.6, 'z', photo2, 36},
                      motion_case{"heldout95_03_orbit_near45px_2_7m_1_2x_4_2rps_z_aloe", 45, 2.7,
                                  orbit_near, 1.2, 4.2, 'z', aloe, 33},
                      motion_case{"heldout95_04_pass13px_3_4m_1_3x_9_3rps_x_venus", 13, 3.4, pass,
                                  1.3, 9.3, 'x', venus, 36},
                      motion_case{"heldout95_05_left176px_3_6m_0_4x_9_1rps_z_venus", 176, 3.6,
                                  pass_left, 0.4, 9.1, 'z', venus, 31},
                      motion_case{"heldout95_06_rebound45px_4_2m_3_1mps_6_8rps_y_kodim23", 45, 4.2,
                                  rebound, 0.8, 6.8, 'y', photo2, 27, 0.0, 3.1},
                      motion_case{"heldout95_07_approach115px_3_8m_0_5x_4_5rps_z_kodim19", 115, 3.8,
                                  approach, 0.5, 4.5, 'z', photo3, 32},
                      motion_case{"heldout95_09_enter120px_3_7m_0_5x_kodim19", 120, 3.7, enter, 0.5,
                                  0.0, 'y', photo3, 31},
                      motion_case{"heldout95_10_rebound21px_3_9m_1_5mps_venus", 21, 3.9, rebound,
                                  0.9, 0.0, 'y', venus, 35, 0.0, 1.5},
                      motion_case{"heldout95_12_left96px_2_7m_4_4x_3_0rps_x_tsukuba", 96, 2.7,
                                  pass_left, 4.4, 3.0, 'x', tsukuba, 26},
                      motion_case{"heldout95_13_thrown125px_3_2m_0_6x_7_4rps_z_aloe", 125, 3.2,
                                  thrown, 0.6, 7.4, 'z', aloe, 30},
                      motion_case{"heldout95_14_enter53px_2_8m_1_3x_3_7rps_y_kodim23", 53, 2.8,
                                  enter, 1.3, 3.7, 'y', photo2, 27},
                      motion_case{"heldout95_17_rebound24px_4_1m_1_1mps_1_4rps_z_aloe", 24, 4.1,
                                  rebound, 0.6, 1.4, 'z', aloe, 36, 0.0, 1.1},
                      motion_case{"heldout95_18_orbit_far48px_2_8m_1_3x_6_6rps_z", 48, 2.8,
                                  orbit_far, 1.3, 6.6, 'z', procedural, 37},
                      motion_case{"heldout95_19_orbit_far101px_2_8m_1_9x_9_8rps_x_cones", 101, 2.8,
                                  orbit_far, 1.9, 9.8, 'x', photo, 25},
                      motion_case{"heldout95_20_pass28px_2_4m_4_3x_9_3rps_x_aloe", 28, 2.4, pass,
                                  4.3, 9.3, 'x', aloe, 40},
                      motion_case{"heldout95_21_pass21px_3_5m_2_9x_9_7rps_z_kodim19", 21, 3.5, pass,
                                  2.9, 9.7, 'z', photo3, 32},
                      motion_case{"heldout95_22_left31px_3_3m_2_9x_2_4rps_x", 31, 3.3, pass_left,
                                  2.9, 2.4, 'x', procedural, 34},
                      motion_case{"heldout95_23_circle76px_3_8m_1_3x_cones", 76, 3.8, circle, 1.3,
                                  0.0, 'x', photo, 33},
                      motion_case{"heldout95_24_rebound23px_3_7m_1_3mps_6_8rps_z_kodim23", 23, 3.7,
                                  rebound, 0.4, 6.8, 'z', photo2, 27, 0.0, 1.3},
                      motion_case{"heldout95_25_pass122px_3_1m_1_6x_4_0rps_y_cones", 122, 3.1, pass,
                                  1.6, 4.0, 'y', photo, 37},
                      motion_case{"heldout95_27_approach117px_2_4m_0_4x_7_1rps_y_kodim23", 117, 2.4,
                                  approach, 0.4, 7.1, 'y', photo2, 29},
                      motion_case{"heldout95_28_pass181px_2_3m_2_9x_2_0rps_y_cones", 181, 2.3, pass,
                                  2.9, 2.0, 'y', photo, 37}),
    case_name);

// Open cases whose box a key of the outline held at its size where the
// key was taken while the depth moved it (docs/firmware.md, "An outline
// key the depth outgrows"): round 95's 59 px ball going away slowly over
// venus (traced; 3.77 / 17.42 px -> 1.04 / 1.96 px), and four that the
// rule passed with it: round 80's 174 px ball going away (depth 2.78 ->
// 0.55 %), round 92's 87 px and 102 px balls thrown at the wall (box max
// 7.94 -> 4.56 px, mean 4.09 -> 1.12 px) and round 94's 27 px one (depth
// 1.04 -> 0.92 %). Development cases.
INSTANTIATE_TEST_SUITE_P(
    OutlineKeyOutgrown, BoxOnMotion,
    ::testing::Values(motion_case{"heldout80_17_recede174px_2_8m_5_3rps_z", 174, 2.8, recede, 0.6,
                                  5.3, 'z', procedural, 40},
                      motion_case{"heldout92_06_rebound87px_3_4m_2_1mps_7_2rps_z_cones", 87, 3.4,
                                  rebound, 0.8, 7.2, 'z', photo, 43, 0.0, 2.1},
                      motion_case{"heldout92_14_rebound102px_3_7m_1_0mps_venus", 102, 3.7, rebound,
                                  0.7, 0.0, 'x', venus, 59, 0.0, 1.0},
                      motion_case{"heldout94_00_rebound27px_4_3m_3_5mps_teddy", 27, 4.3, rebound,
                                  0.6, 0.0, 'y', photo4, 37, 0.0, 3.5},
                      motion_case{"heldout95_29_recede59px_2_3m_0_4x_venus", 59, 2.3, recede, 0.4,
                                  0.0, 'z', venus, 37}),
    case_name);

// Held out, round 96: 30 cases drawn at random (seed 96, rounds 94 and
// 95's envelope, a script outside the tree) and committed before they were
// run, after an outline key was dropped once the depth since it moves a
// side (docs/firmware.md, "An outline key the depth outgrows"), with the
// firmware before and after that rule. Cases moving faster than 30 px a
// frame are out of the envelope and left out: four. Of the other 26, 22
// passed and 4 failed (DISABLED_Open) with the rule and without it, every
// figure the same.
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep96, BoxOnMotion,
    ::testing::Values(motion_case{"heldout96_00_enter31px_3_3m_4_0x_4_1rps_x", 31, 3.3, enter, 4.0,
                                  4.1, 'x', procedural, 29},
                      motion_case{"heldout96_01_recede82px_2_2m_4_9x_2_2rps_x_aloe", 82, 2.2,
                                  recede, 4.9, 2.2, 'x', aloe, 39},
                      motion_case{"heldout96_02_approach31px_3_4m_0_8x_tsukuba", 31, 3.4, approach,
                                  0.8, 0.0, 'z', tsukuba, 24},
                      motion_case{"heldout96_04_orbit_near86px_2_3m_2_6x_4_9rps_z", 86, 2.3,
                                  orbit_near, 2.6, 4.9, 'z', procedural, 32},
                      motion_case{"heldout96_05_rebound37px_4_1m_3_9mps_7_7rps_z_kodim19", 37, 4.1,
                                  rebound, 0.9, 7.7, 'z', photo3, 38, 0.0, 3.9},
                      motion_case{"heldout96_06_enter23px_3_1m_0_7x_2_6rps_y", 23, 3.1, enter, 0.7,
                                  2.6, 'y', procedural, 39},
                      motion_case{"heldout96_07_thrown20px_4_0m_0_3x_6_9rps_x", 20, 4.0, thrown,
                                  0.3, 6.9, 'x', procedural, 35},
                      motion_case{"heldout96_08_thrown108px_2_1m_0_6x_2_6rps_x_kodim19", 108, 2.1,
                                  thrown, 0.6, 2.6, 'x', photo3, 34},
                      motion_case{"heldout96_09_back121px_3_3m_0_4x_cones", 121, 3.3, circle_back,
                                  0.4, 0.0, 'y', photo, 31},
                      motion_case{"heldout96_10_orbit_near77px_2_4m_1_6x_kodim23", 77, 2.4,
                                  orbit_near, 1.6, 0.0, 'z', photo2, 25},
                      motion_case{"heldout96_11_left54px_3_6m_4_1x_2_2rps_x", 54, 3.6, pass_left,
                                  4.1, 2.2, 'x', procedural, 37},
                      motion_case{"heldout96_12_recede91px_2_6m_1_4x_5_9rps_z", 91, 2.6, recede,
                                  1.4, 5.9, 'z', procedural, 26},
                      motion_case{"heldout96_13_orbit_far38px_2_2m_2_1x_3_6rps_y_kodim19", 38, 2.2,
                                  orbit_far, 2.1, 3.6, 'y', photo3, 30},
                      motion_case{"heldout96_15_thrown52px_3_8m_0_4x_3_1rps_x_tsukuba", 52, 3.8,
                                  thrown, 0.4, 3.1, 'x', tsukuba, 39},
                      motion_case{"heldout96_16_back92px_2_8m_0_5x_kodim23", 92, 2.8, circle_back,
                                  0.5, 0.0, 'y', photo2, 26},
                      motion_case{"heldout96_19_rebound32px_3_9m_3_8mps_9_5rps_x_tsukuba", 32, 3.9,
                                  rebound, 0.9, 9.5, 'x', tsukuba, 36, 0.0, 3.8},
                      motion_case{"heldout96_20_pass148px_2_5m_3_0x_8_2rps_z_kodim19", 148, 2.5,
                                  pass, 3.0, 8.2, 'z', photo3, 26},
                      motion_case{"heldout96_21_enter19px_2_4m_3_2x_5_6rps_y_venus", 19, 2.4, enter,
                                  3.2, 5.6, 'y', venus, 40},
                      motion_case{"heldout96_22_pass123px_2_5m_1_9x_4_8rps_y_aloe", 123, 2.5, pass,
                                  1.9, 4.8, 'y', aloe, 34},
                      motion_case{"heldout96_23_orbit_near114px_2_7m_3_0x_tsukuba", 114, 2.7,
                                  orbit_near, 3.0, 0.0, 'x', tsukuba, 39},
                      motion_case{"heldout96_27_circle55px_3_1m_0_8x_kodim19", 55, 3.1, circle, 0.8,
                                  0.0, 'z', photo3, 31},
                      motion_case{"heldout96_28_left200px_3_2m_0_4x_1_3rps_x", 200, 3.2, pass_left,
                                  0.4, 1.3, 'x', procedural, 35}),
    case_name);

// Held out, round 97: 30 cases drawn at random (seed 97, rounds 94 and
// 95's envelope, a script outside the tree) and committed before they were
// run, with a reach refused where the background beside the object matches
// at its depth (docs/firmware.md, "Open") and without it. Decision declared
// then: the rule is kept only if, over this round and HeldOutWall97
// together, it passes more of the cases in the envelope (30 px a frame at
// most) than the firmware without it. Two moved faster (left out); of the
// other 28, 22 passed and 6 failed (DISABLED_Open), with the rule and
// without it: a tie, so the rule was not kept.
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep97, BoxOnMotion,
    ::testing::Values(motion_case{"heldout97_01_pass172px_3_6m_0_8x_4_9rps_z_cones", 172, 3.6, pass,
                                  0.8, 4.9, 'z', photo, 34},
                      motion_case{"heldout97_02_circle178px_2_4m_2_6x_cones", 178, 2.4, circle, 2.6,
                                  0.0, 'x', photo, 31},
                      motion_case{"heldout97_03_orbit_near72px_2_1m_2_5x_1_6rps_z_teddy", 72, 2.1,
                                  orbit_near, 2.5, 1.6, 'z', photo4, 26},
                      motion_case{"heldout97_04_pass47px_4_0m_0_6x_6_2rps_z_kodim19", 47, 4.0, pass,
                                  0.6, 6.2, 'z', photo3, 35},
                      motion_case{"heldout97_05_left98px_3_9m_0_3x_kodim23", 98, 3.9, pass_left,
                                  0.3, 0.0, 'x', photo2, 39},
                      motion_case{"heldout97_06_pass70px_3_0m_0_3x_aloe", 70, 3.0, pass, 0.3, 0.0,
                                  'z', aloe, 37},
                      motion_case{"heldout97_08_recede35px_2_4m_0_4x_teddy", 35, 2.4, recede, 0.4,
                                  0.0, 'y', photo4, 34},
                      motion_case{"heldout97_09_pass228px_2_5m_0_5x_5_5rps_z_cones", 228, 2.5, pass,
                                  0.5, 5.5, 'z', photo, 30},
                      motion_case{"heldout97_12_rebound20px_3_7m_3_0mps_2_2rps_x_aloe", 20, 3.7,
                                  rebound, 0.5, 2.2, 'x', aloe, 29, 0.0, 3.0},
                      motion_case{"heldout97_13_left147px_2_8m_0_7x", 147, 2.8, pass_left, 0.7, 0.0,
                                  'x', procedural, 24},
                      motion_case{"heldout97_14_back213px_3_4m_3_7x_6_3rps_y_kodim23", 213, 3.4,
                                  circle_back, 3.7, 6.3, 'y', photo2, 27},
                      motion_case{"heldout97_15_pass205px_3_1m_1_8x_7_9rps_x_venus", 205, 3.1, pass,
                                  1.8, 7.9, 'x', venus, 28},
                      motion_case{"heldout97_16_orbit_far110px_2_3m_2_2x_cones", 110, 2.3,
                                  orbit_far, 2.2, 0.0, 'x', photo, 29},
                      motion_case{"heldout97_19_approach153px_2_3m_0_5x_kodim19", 153, 2.3,
                                  approach, 0.5, 0.0, 'y', photo3, 38},
                      motion_case{"heldout97_22_orbit_far66px_2_7m_2_5x", 66, 2.7, orbit_far, 2.5,
                                  0.0, 'z', procedural, 32},
                      motion_case{"heldout97_23_pass69px_3_0m_0_5x_1_7rps_y_aloe", 69, 3.0, pass,
                                  0.5, 1.7, 'y', aloe, 37},
                      motion_case{"heldout97_24_enter96px_3_3m_1_9x_8_4rps_z_tsukuba", 96, 3.3,
                                  enter, 1.9, 8.4, 'z', tsukuba, 30},
                      motion_case{"heldout97_25_pass17px_3_3m_1_3x_7_5rps_z_kodim19", 17, 3.3, pass,
                                  1.3, 7.5, 'z', photo3, 33},
                      motion_case{"heldout97_26_back144px_2_5m_1_3x", 144, 2.5, circle_back, 1.3,
                                  0.0, 'x', procedural, 37},
                      motion_case{"heldout97_27_circle59px_3_2m_2_3x_venus", 59, 3.2, circle, 2.3,
                                  0.0, 'z', venus, 27},
                      motion_case{"heldout97_28_rebound33px_4_4m_1_7mps_tsukuba", 33, 4.4, rebound,
                                  0.6, 0.0, 'x', tsukuba, 40, 0.0, 1.7},
                      motion_case{"heldout97_29_pass68px_2_2m_0_5x_1_4rps_y_venus", 68, 2.2, pass,
                                  0.5, 1.4, 'y', venus, 29}),
    case_name);

// Held out, round 97 at the wall: 16 balls thrown at the background's wall
// or going away towards it (seed 197, rounds 94 and 95's envelope for those
// two paths), committed with HeldOutSweep97 before they were run. 12
// passed and 4 failed (DISABLED_Open), with the rule and without it.
INSTANTIATE_TEST_SUITE_P(
    HeldOutWall97, BoxOnMotion,
    ::testing::Values(motion_case{"heldout97w_01_recede134px_3_3m_0_5x_venus", 134, 3.3, recede,
                                  0.5, 0.0, 'y', venus, 39},
                      motion_case{"heldout97w_02_recede71px_3_0m_2_3x_3_2rps_y_tsukuba", 71, 3.0,
                                  recede, 2.3, 3.2, 'y', tsukuba, 30},
                      motion_case{"heldout97w_03_recede134px_3_1m_3_5x_8_1rps_y_cones", 134, 3.1,
                                  recede, 3.5, 8.1, 'y', photo, 35},
                      motion_case{"heldout97w_05_rebound61px_4_3m_1_5mps_kodim19", 61, 4.3, rebound,
                                  0.9, 0.0, 'y', photo3, 34, 0.0, 1.5},
                      motion_case{"heldout97w_07_rebound34px_3_6m_3_9mps_9_3rps_z_aloe", 34, 3.6,
                                  rebound, 1.0, 9.3, 'z', aloe, 36, 0.0, 3.9},
                      motion_case{"heldout97w_08_rebound20px_4_4m_3_9mps_8_9rps_x_tsukuba", 20, 4.4,
                                  rebound, 1.0, 8.9, 'x', tsukuba, 32, 0.0, 3.9},
                      motion_case{"heldout97w_09_rebound49px_4_1m_1_8mps_1_6rps_x", 49, 4.1,
                                  rebound, 0.5, 1.6, 'x', procedural, 24, 0.0, 1.8},
                      motion_case{"heldout97w_10_rebound66px_3_9m_3_6mps_3_4rps_z_kodim23", 66, 3.9,
                                  rebound, 0.4, 3.4, 'z', photo2, 28, 0.0, 3.6},
                      motion_case{"heldout97w_11_recede54px_3_5m_0_7x_tsukuba", 54, 3.5, recede,
                                  0.7, 0.0, 'y', tsukuba, 29},
                      motion_case{"heldout97w_12_recede70px_3_1m_3_2x_kodim23", 70, 3.1, recede,
                                  3.2, 0.0, 'x', photo2, 29},
                      motion_case{"heldout97w_13_rebound55px_3_9m_3_2mps_teddy", 55, 3.9, rebound,
                                  0.5, 0.0, 'x', photo4, 25, 0.0, 3.2},
                      motion_case{"heldout97w_15_rebound74px_3_6m_1_3mps_8_5rps_y_kodim19", 74, 3.6,
                                  rebound, 0.6, 8.5, 'y', photo3, 32, 0.0, 1.3}),
    case_name);

// Seven open cases that pass since a reach is refused beside a background
// at the object's depth (docs/firmware.md, "A reach beside a background
// at the object's depth"), development cases of that rule: four balls
// thrown at the wall (round 93's 21 px and 72 px, round 95's 70 px, round
// 96's 74 px; traced on the 72 px one, their boxes widened 25-43 px at the
// bounce) and three large balls going away near it (round 86's 227 px,
// round 93's 132 px and round 95's 182 px; not traced). Round 95's 70 px
// ball fails on its depth since the core's sub-pixel step at half pixels
// (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    ReachBesideTheWall, BoxOnMotion,
    ::testing::Values(motion_case{"heldout86_23_recede227px_3_0m_teddy", 227, 3.0, recede, 1.0, 0.0,
                                  'x', photo4, 40},
                      motion_case{"heldout93_04_rebound21px_3_5m_3_3mps_1_1rps_y_cones", 21, 3.5,
                                  rebound, 0.8, 1.1, 'y', photo, 33, 0.0, 3.3},
                      motion_case{"heldout93_08_rebound72px_4_4m_4_0mps_aloe", 72, 4.4, rebound,
                                  1.1, 0.0, 'z', aloe, 20, 0.0, 4.0},
                      motion_case{"heldout93_14_recede132px_3_1m_0_7x_teddy", 132, 3.1, recede, 0.7,
                                  0.0, 'z', photo4, 32},
                      motion_case{"heldout95_11_recede182px_3_0m_0_3x_aloe", 182, 3.0, recede, 0.3,
                                  0.0, 'y', aloe, 38},
                      motion_case{"heldout96_14_rebound74px_4_4m_2_3mps_5_6rps_y_aloe", 74, 4.4,
                                  rebound, 0.7, 5.6, 'y', aloe, 26, 0.0, 2.3}),
    case_name);

// Held out, round 98 at the wall: 40 balls thrown at the background's wall
// or going away towards it (seed 198, HeldOutWall97's envelope), committed
// before they were run, with and without the reach refused beside a
// background at the object's depth (docs/firmware.md, "Open"), not kept
// after round 97, where none of the balls met the fault. Decision declared
// here: the rule is kept only if, over rounds 97 and 98 together (cases
// within 30 px a frame), it passes more than the firmware without it; as
// round 97 tied, this round decides. All 40 moved within 30 px a frame:
// 31 passed with the rule and 26 without it, none the other way (65 to
// 60 over both rounds): kept. The nine failures are in DISABLED_Open.
INSTANTIATE_TEST_SUITE_P(
    HeldOutWall98, BoxOnMotion,
    ::testing::Values(motion_case{"heldout98w_00_rebound53px_4_0m_4_0mps_5_8rps_x_venus", 53, 4.0,
                                  rebound, 0.9, 5.8, 'x', venus, 29, 0.0, 4.0},
                      motion_case{"heldout98w_01_recede142px_2_1m_1_2x_tsukuba", 142, 2.1, recede,
                                  1.2, 0.0, 'z', tsukuba, 32},
                      motion_case{"heldout98w_03_recede42px_2_2m_0_7x_tsukuba", 42, 2.2, recede,
                                  0.7, 0.0, 'y', tsukuba, 25},
                      motion_case{"heldout98w_04_rebound100px_3_8m_2_2mps_tsukuba", 100, 3.8,
                                  rebound, 0.4, 0.0, 'z', tsukuba, 39, 0.0, 2.2},
                      motion_case{"heldout98w_05_rebound46px_3_8m_2_0mps_kodim19", 46, 3.8, rebound,
                                  0.7, 0.0, 'y', photo3, 28, 0.0, 2.0},
                      motion_case{"heldout98w_06_rebound48px_4_4m_2_6mps_2_3rps_z_kodim19", 48, 4.4,
                                  rebound, 1.1, 2.3, 'z', photo3, 27, 0.0, 2.6},
                      motion_case{"heldout98w_07_rebound60px_4_3m_3_2mps_8_1rps_z_venus", 60, 4.3,
                                  rebound, 0.9, 8.1, 'z', venus, 27, 0.0, 3.2},
                      motion_case{"heldout98w_08_recede79px_3_2m_3_8x_2_1rps_y_kodim23", 79, 3.2,
                                  recede, 3.8, 2.1, 'y', photo2, 34},
                      motion_case{"heldout98w_10_recede230px_2_5m_3_3x_5_7rps_x_tsukuba", 230, 2.5,
                                  recede, 3.3, 5.7, 'x', tsukuba, 30},
                      motion_case{"heldout98w_11_rebound102px_3_8m_2_9mps_aloe", 102, 3.8, rebound,
                                  1.0, 0.0, 'y', aloe, 28, 0.0, 2.9},
                      motion_case{"heldout98w_12_recede230px_3_3m_1_5x_kodim19", 230, 3.3, recede,
                                  1.5, 0.0, 'y', photo3, 39},
                      motion_case{"heldout98w_14_recede45px_2_2m_0_5x_kodim23", 45, 2.2, recede,
                                  0.5, 0.0, 'x', photo2, 34},
                      motion_case{"heldout98w_15_recede50px_3_9m_0_5x_1_5rps_x_kodim19", 50, 3.9,
                                  recede, 0.5, 1.5, 'x', photo3, 30},
                      motion_case{"heldout98w_16_rebound24px_4_0m_1_8mps_kodim23", 24, 4.0, rebound,
                                  0.8, 0.0, 'z', photo2, 39, 0.0, 1.8},
                      motion_case{"heldout98w_17_rebound33px_3_8m_1_1mps_1_6rps_y_cones", 33, 3.8,
                                  rebound, 0.6, 1.6, 'y', photo, 33, 0.0, 1.1},
                      motion_case{"heldout98w_19_recede81px_2_3m_0_4x_tsukuba", 81, 2.3, recede,
                                  0.4, 0.0, 'x', tsukuba, 30},
                      motion_case{"heldout98w_21_recede23px_3_9m_0_4x_2_5rps_x_cones", 23, 3.9,
                                  recede, 0.4, 2.5, 'x', photo, 36},
                      motion_case{"heldout98w_22_recede162px_2_2m_2_6x_kodim19", 162, 2.2, recede,
                                  2.6, 0.0, 'x', photo3, 35},
                      motion_case{"heldout98w_23_rebound52px_4_0m_3_1mps_8_7rps_y", 52, 4.0,
                                  rebound, 0.5, 8.7, 'y', procedural, 25, 0.0, 3.1},
                      motion_case{"heldout98w_24_recede57px_2_7m_0_5x_5_5rps_z_cones", 57, 2.7,
                                  recede, 0.5, 5.5, 'z', photo, 38},
                      motion_case{"heldout98w_25_rebound39px_4_4m_3_6mps_2_7rps_y_aloe", 39, 4.4,
                                  rebound, 1.0, 2.7, 'y', aloe, 27, 0.0, 3.6},
                      motion_case{"heldout98w_27_recede33px_4_0m_0_5x_7_0rps_y_teddy", 33, 4.0,
                                  recede, 0.5, 7.0, 'y', photo4, 24},
                      motion_case{"heldout98w_29_rebound30px_3_7m_1_7mps_kodim19", 30, 3.7, rebound,
                                  0.6, 0.0, 'x', photo3, 33, 0.0, 1.7},
                      motion_case{"heldout98w_30_rebound27px_3_8m_3_0mps_9_4rps_y", 27, 3.8,
                                  rebound, 0.4, 9.4, 'y', procedural, 26, 0.0, 3.0},
                      motion_case{"heldout98w_31_rebound30px_3_7m_3_1mps_cones", 30, 3.7, rebound,
                                  1.1, 0.0, 'y', photo, 36, 0.0, 3.1},
                      motion_case{"heldout98w_32_rebound25px_4_0m_3_1mps_3_2rps_x_tsukuba", 25, 4.0,
                                  rebound, 0.6, 3.2, 'x', tsukuba, 35, 0.0, 3.1},
                      motion_case{"heldout98w_33_rebound22px_4_0m_2_4mps_teddy", 22, 4.0, rebound,
                                  0.8, 0.0, 'z', photo4, 28, 0.0, 2.4},
                      motion_case{"heldout98w_34_rebound27px_4_0m_3_8mps_1_4rps_z_venus", 27, 4.0,
                                  rebound, 1.0, 1.4, 'z', venus, 29, 0.0, 3.8},
                      motion_case{"heldout98w_36_rebound67px_4_3m_3_1mps_teddy", 67, 4.3, rebound,
                                  0.9, 0.0, 'y', photo4, 26, 0.0, 3.1},
                      motion_case{"heldout98w_37_recede127px_3_0m_2_1x_kodim19", 127, 3.0, recede,
                                  2.1, 0.0, 'y', photo3, 28},
                      motion_case{"heldout98w_38_recede20px_4_0m_1_7x_kodim19", 20, 4.0, recede,
                                  1.7, 0.0, 'z', photo3, 27}),
    case_name);

// Held out, round 99: 30 cases drawn at random (seed 99, rounds 94 and
// 95's envelope) and committed before they were run, with and without the
// sub-pixel step read at half-pixel shifts (docs/firmware.md, "Open").
// Decision declared then: that step is kept only if, over this round and
// HeldOutSmall99 together, it passes more of the cases in the envelope (30
// px a frame at most) than the firmware without it. One moved faster (left
// out); of the other 29, 26 passed and 3 failed (DISABLED_Open) without it.
// Over both rounds, 40 of 48 passed with the step and 40 without it: a tie
// (two passed with it only, two without it only), so it was not kept.
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep99, BoxOnMotion,
    ::testing::Values(motion_case{"heldout99_00_recede38px_3_2m_0_6x_1_8rps_z_venus", 38, 3.2,
                                  recede, 0.6, 1.8, 'z', venus, 40},
                      motion_case{"heldout99_01_orbit_far93px_2_1m_2_2x_7_5rps_z_kodim19", 93, 2.1,
                                  orbit_far, 2.2, 7.5, 'z', photo3, 35},
                      motion_case{"heldout99_02_recede158px_2_4m_1_1x_6_1rps_x_cones", 158, 2.4,
                                  recede, 1.1, 6.1, 'x', photo, 39},
                      motion_case{"heldout99_03_enter40px_2_5m_0_3x_9_9rps_z_cones", 40, 2.5, enter,
                                  0.3, 9.9, 'z', photo, 38},
                      motion_case{"heldout99_04_rebound93px_4_1m_2_1mps_9_3rps_x_aloe", 93, 4.1,
                                  rebound, 1.1, 9.3, 'x', aloe, 29, 0.0, 2.1},
                      motion_case{"heldout99_05_rebound62px_3_5m_2_4mps_venus", 62, 3.5, rebound,
                                  0.4, 0.0, 'x', venus, 26, 0.0, 2.4},
                      motion_case{"heldout99_06_thrown30px_2_0m_0_8x", 30, 2.0, thrown, 0.8, 0.0,
                                  'x', procedural, 30},
                      motion_case{"heldout99_07_approach26px_2_8m_2_6x_7_3rps_x_kodim23", 26, 2.8,
                                  approach, 2.6, 7.3, 'x', photo2, 28},
                      motion_case{"heldout99_08_orbit_near136px_2_1m_1_2x_9_9rps_y_kodim23", 136,
                                  2.1, orbit_near, 1.2, 9.9, 'y', photo2, 30},
                      motion_case{"heldout99_10_rebound33px_4_1m_1_6mps_8_4rps_y_venus", 33, 4.1,
                                  rebound, 0.4, 8.4, 'y', venus, 37, 0.0, 1.6},
                      motion_case{"heldout99_11_enter59px_2_4m_0_3x_8_7rps_y_kodim19", 59, 2.4,
                                  enter, 0.3, 8.7, 'y', photo3, 33},
                      motion_case{"heldout99_13_recede29px_3_5m_0_4x_9_7rps_y_cones", 29, 3.5,
                                  recede, 0.4, 9.7, 'y', photo, 40},
                      motion_case{"heldout99_14_back182px_3_7m_2_8x_venus", 182, 3.7, circle_back,
                                  2.8, 0.0, 'y', venus, 33},
                      motion_case{"heldout99_15_recede218px_3_7m_0_5x_7_1rps_z_aloe", 218, 3.7,
                                  recede, 0.5, 7.1, 'z', aloe, 30},
                      motion_case{"heldout99_16_recede33px_2_4m_0_3x_3_7rps_x_kodim23", 33, 2.4,
                                  recede, 0.3, 3.7, 'x', photo2, 32},
                      motion_case{"heldout99_17_orbit_far59px_2_8m_2_4x_8_8rps_z_venus", 59, 2.8,
                                  orbit_far, 2.4, 8.8, 'z', venus, 24},
                      motion_case{"heldout99_18_left54px_2_4m_1_3x_kodim23", 54, 2.4, pass_left,
                                  1.3, 0.0, 'z', photo2, 40},
                      motion_case{"heldout99_20_pass240px_3_6m_0_4x_1_5rps_y_tsukuba", 240, 3.6,
                                  pass, 0.4, 1.5, 'y', tsukuba, 33},
                      motion_case{"heldout99_21_circle116px_4_0m_2_8x_2_6rps_y_tsukuba", 116, 4.0,
                                  circle, 2.8, 2.6, 'y', tsukuba, 28},
                      motion_case{"heldout99_22_thrown179px_3_7m_2_1x_6_1rps_z_kodim23", 179, 3.7,
                                  thrown, 2.1, 6.1, 'z', photo2, 35},
                      motion_case{"heldout99_24_orbit_far39px_2_1m_1_5x_1_1rps_y_aloe", 39, 2.1,
                                  orbit_far, 1.5, 1.1, 'y', aloe, 26},
                      motion_case{"heldout99_25_enter85px_2_0m_2_0x_1_1rps_y_venus", 85, 2.0, enter,
                                  2.0, 1.1, 'y', venus, 32},
                      motion_case{"heldout99_26_thrown18px_3_8m_0_9x_5_6rps_z_teddy", 18, 3.8,
                                  thrown, 0.9, 5.6, 'z', photo4, 29},
                      motion_case{"heldout99_28_left64px_2_4m_1_4x_cones", 64, 2.4, pass_left, 1.4,
                                  0.0, 'z', photo, 27},
                      motion_case{"heldout99_29_thrown142px_2_3m_0_4x_venus", 142, 2.3, thrown, 0.4,
                                  0.0, 'z', venus, 29}),
    case_name);

// Held out, round 99's small balls: 20 balls of 12-40 px on every path
// (seed 199, rounds 94 and 95's envelope otherwise), committed with
// HeldOutSweep99 before they were run. One moved faster (left out); of the
// other 19, 14 passed and 5 failed (DISABLED_Open) Its 30 px circle over venus
// fails since the box is held at the extent's end (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSmall99, BoxOnMotion,
    ::testing::Values(motion_case{"heldout99s_00_enter29px_3_7m_2_0x_5_3rps_z_tsukuba", 29, 3.7,
                                  enter, 2.0, 5.3, 'z', tsukuba, 32},
                      motion_case{"heldout99s_02_rebound16px_4_0m_3_6mps_4_4rps_z_tsukuba", 16, 4.0,
                                  rebound, 0.8, 4.4, 'z', tsukuba, 37, 0.0, 3.6},
                      motion_case{"heldout99s_04_pass26px_3_1m_2_5x_kodim23", 26, 3.1, pass, 2.5,
                                  0.0, 'x', photo2, 37},
                      motion_case{"heldout99s_05_pass24px_2_2m_1_3x", 24, 2.2, pass, 1.3, 0.0, 'x',
                                  procedural, 34},
                      motion_case{"heldout99s_07_thrown14px_3_7m_1_7x_kodim23", 14, 3.7, thrown,
                                  1.7, 0.0, 'y', photo2, 40},
                      motion_case{"heldout99s_08_recede19px_3_0m_1_0x_teddy", 19, 3.0, recede, 1.0,
                                  0.0, 'y', photo4, 33},
                      motion_case{"heldout99s_09_back16px_2_7m_0_3x_teddy", 16, 2.7, circle_back,
                                  0.3, 0.0, 'z', photo4, 30},
                      motion_case{"heldout99s_11_back28px_3_3m_2_1x", 28, 3.3, circle_back, 2.1,
                                  0.0, 'z', procedural, 37},
                      motion_case{"heldout99s_12_pass33px_2_3m_0_5x_kodim19", 33, 2.3, pass, 0.5,
                                  0.0, 'z', photo3, 24},
                      motion_case{"heldout99s_13_enter17px_3_1m_4_9x_aloe", 17, 3.1, enter, 4.9,
                                  0.0, 'x', aloe, 24},
                      motion_case{"heldout99s_14_recede28px_3_7m_0_7x", 28, 3.7, recede, 0.7, 0.0,
                                  'x', procedural, 24},
                      motion_case{"heldout99s_15_circle40px_2_9m_1_2x_3_9rps_y_tsukuba", 40, 2.9,
                                  circle, 1.2, 3.9, 'y', tsukuba, 36},
                      motion_case{"heldout99s_17_approach39px_3_9m_0_5x_2_0rps_x_venus", 39, 3.9,
                                  approach, 0.5, 2.0, 'x', venus, 35}),
    case_name);

// Thirteen open cases that pass since the core's sub-pixel step reads the
// SADs a half pixel either side of its minimum (docs/firmware.md, "A
// sub-pixel step at half pixels"), development cases of that step: balls
// of 13-55 px, twelve that failed on the depth at one or two pairs
// (1.02-1.49 %) and one on a side 0.8 px over; round 80's 55 px circle is
// the one traced (a texture spot at its limb seen by one camera only).
INSTANTIATE_TEST_SUITE_P(
    HalfPelCore, BoxOnMotion,
    ::testing::Values(motion_case{"heldout80_02_circle55px_3_9m_kodim23", 55, 3.9, circle, 2.9, 0.0,
                                  'z', photo2, 24},
                      motion_case{"heldout84_21_enter34px_3_8m_4_2rps_x_venus", 34, 3.8, enter, 1.5,
                                  4.2, 'x', venus, 40},
                      motion_case{"heldout94_09_enter36px_2_8m_1_3x_tsukuba", 36, 2.8, enter, 1.3,
                                  0.0, 'x', tsukuba, 37},
                      motion_case{"heldout94_11_enter21px_3_3m_1_2x_kodim23", 21, 3.3, enter, 1.2,
                                  0.0, 'x', photo2, 28},
                      motion_case{"heldout96_25_rebound35px_4_1m_2_3mps_9_5rps_x_tsukuba", 35, 4.1,
                                  rebound, 1.0, 9.5, 'x', tsukuba, 32, 0.0, 2.3},
                      motion_case{"heldout96_29_back13px_3_4m_1_5x_3_5rps_y_cones", 13, 3.4,
                                  circle_back, 1.5, 3.5, 'y', photo, 25},
                      motion_case{"heldout97_10_approach15px_2_0m_1_0x_5_7rps_x_teddy", 15, 2.0,
                                  approach, 1.0, 5.7, 'x', photo4, 40},
                      motion_case{"heldout97_20_circle23px_3_4m_1_3x_6_1rps_x_cones", 23, 3.4,
                                  circle, 1.3, 6.1, 'x', photo, 29},
                      motion_case{"heldout97w_04_recede28px_3_4m_0_9x_4_8rps_z_teddy", 28, 3.4,
                                  recede, 0.9, 4.8, 'z', photo4, 26},
                      motion_case{"heldout98w_20_rebound26px_4_4m_2_4mps_6_5rps_z_teddy", 26, 4.4,
                                  rebound, 0.7, 6.5, 'z', photo4, 26, 0.0, 2.4},
                      motion_case{"heldout99_27_approach14px_3_6m_0_6x_5_4rps_y_teddy", 14, 3.6,
                                  approach, 0.6, 5.4, 'y', photo4, 35},
                      motion_case{"heldout99s_16_pass14px_2_2m_3_4x_teddy", 14, 2.2, pass, 3.4, 0.0,
                                  'y', photo4, 32}),
    case_name);

// Held out, round 100: 30 cases drawn at random (seed 100, rounds 94 and
// 95's envelope) and committed before they were run, with and without the
// sub-pixel step at half pixels on the core's match only (the tiles' as
// before; docs/firmware.md, "Open"). Decision declared here: that step is
// kept only if, over this round and HeldOutSmall100 together, it passes
// more of the cases in the envelope (30 px a frame at most) than the
// firmware without it. One moved faster (left out); of the other 49, 40
// passed with the step and 39 without it (two the one way, one the
// other): kept. Of this round's 29, 24 passed and 5 failed
// (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep100, BoxOnMotion,
    ::testing::Values(motion_case{"heldout100_00_thrown48px_3_9m_0_5x_4_1rps_z_cones", 48, 3.9,
                                  thrown, 0.5, 4.1, 'z', photo, 27},
                      motion_case{"heldout100_01_left109px_2_5m_1_9x_tsukuba", 109, 2.5, pass_left,
                                  1.9, 0.0, 'x', tsukuba, 31},
                      motion_case{"heldout100_03_recede210px_3_1m_3_8x_cones", 210, 3.1, recede,
                                  3.8, 0.0, 'x', photo, 29},
                      motion_case{"heldout100_04_pass73px_2_3m_3_3x_2_5rps_x_kodim19", 73, 2.3,
                                  pass, 3.3, 2.5, 'x', photo3, 38},
                      motion_case{"heldout100_05_orbit_far132px_2_4m_2_2x_kodim19", 132, 2.4,
                                  orbit_far, 2.2, 0.0, 'x', photo3, 40},
                      motion_case{"heldout100_06_back95px_2_7m_2_0x_aloe", 95, 2.7, circle_back,
                                  2.0, 0.0, 'y', aloe, 36},
                      motion_case{"heldout100_07_pass137px_3_8m_1_9x_8_6rps_z_venus", 137, 3.8,
                                  pass, 1.9, 8.6, 'z', venus, 40},
                      motion_case{"heldout100_08_approach179px_2_5m_0_4x_kodim23", 179, 2.5,
                                  approach, 0.4, 0.0, 'y', photo2, 25},
                      motion_case{"heldout100_10_orbit_near43px_2_8m_2_5x_5_1rps_z_cones", 43, 2.8,
                                  orbit_near, 2.5, 5.1, 'z', photo, 39},
                      motion_case{"heldout100_11_circle141px_2_2m_1_6x_7_5rps_x_venus", 141, 2.2,
                                  circle, 1.6, 7.5, 'x', venus, 28},
                      motion_case{"heldout100_12_orbit_near146px_2_6m_2_9x_5_0rps_x_aloe", 146, 2.6,
                                  orbit_near, 2.9, 5.0, 'x', aloe, 25},
                      motion_case{"heldout100_13_circle197px_2_3m_0_3x_1_8rps_y_cones", 197, 2.3,
                                  circle, 0.3, 1.8, 'y', photo, 36},
                      motion_case{"heldout100_14_pass61px_2_9m_0_8x_2_7rps_z_teddy", 61, 2.9, pass,
                                  0.8, 2.7, 'z', photo4, 37},
                      motion_case{"heldout100_15_thrown143px_3_7m_0_4x_venus", 143, 3.7, thrown,
                                  0.4, 0.0, 'y', venus, 32},
                      motion_case{"heldout100_16_left21px_4_0m_0_9x_3_4rps_y", 21, 4.0, pass_left,
                                  0.9, 3.4, 'y', procedural, 24},
                      motion_case{"heldout100_18_orbit_near53px_2_7m_1_9x_cones", 53, 2.7,
                                  orbit_near, 1.9, 0.0, 'x', photo, 24},
                      motion_case{"heldout100_19_orbit_near118px_2_8m_2_1x_7_3rps_z", 118, 2.8,
                                  orbit_near, 2.1, 7.3, 'z', procedural, 34},
                      motion_case{"heldout100_20_rebound39px_3_9m_1_6mps_teddy", 39, 3.9, rebound,
                                  0.9, 0.0, 'z', photo4, 26, 0.0, 1.6},
                      motion_case{"heldout100_21_orbit_far63px_2_7m_1_9x_cones", 63, 2.7, orbit_far,
                                  1.9, 0.0, 'z', photo, 33},
                      motion_case{"heldout100_22_thrown159px_3_2m_0_6x_5_1rps_z_tsukuba", 159, 3.2,
                                  thrown, 0.6, 5.1, 'z', tsukuba, 26},
                      motion_case{"heldout100_24_rebound53px_4_5m_3_3mps_tsukuba", 53, 4.5, rebound,
                                  0.5, 0.0, 'x', tsukuba, 36, 0.0, 3.3},
                      motion_case{"heldout100_25_left83px_3_0m_0_7x_teddy", 83, 3.0, pass_left, 0.7,
                                  0.0, 'y', photo4, 31},
                      motion_case{"heldout100_26_enter24px_3_8m_0_6x_1_8rps_y", 24, 3.8, enter, 0.6,
                                  1.8, 'y', procedural, 39},
                      motion_case{"heldout100_28_orbit_near70px_3_0m_2_5x_kodim19", 70, 3.0,
                                  orbit_near, 2.5, 0.0, 'x', photo3, 38}),
    case_name);

// Held out, round 100's small balls: 20 balls of 12-40 px on every path
// (seed 200), committed with HeldOutSweep100 before they were run. 16
// passed and 4 failed (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSmall100, BoxOnMotion,
    ::testing::Values(motion_case{"heldout100s_00_pass36px_3_5m_0_3x", 36, 3.5, pass, 0.3, 0.0, 'y',
                                  procedural, 38},
                      motion_case{"heldout100s_01_thrown29px_2_9m_1_0x_6_8rps_x_teddy", 29, 2.9,
                                  thrown, 1.0, 6.8, 'x', photo4, 36},
                      motion_case{"heldout100s_02_enter26px_2_9m_0_6x_cones", 26, 2.9, enter, 0.6,
                                  0.0, 'y', photo, 28},
                      motion_case{"heldout100s_03_thrown21px_2_3m_0_5x_9_5rps_z_kodim19", 21, 2.3,
                                  thrown, 0.5, 9.5, 'z', photo3, 34},
                      motion_case{"heldout100s_04_left14px_3_1m_0_6x_tsukuba", 14, 3.1, pass_left,
                                  0.6, 0.0, 'z', tsukuba, 29},
                      motion_case{"heldout100s_05_approach21px_4_0m_0_7x_kodim19", 21, 4.0,
                                  approach, 0.7, 0.0, 'x', photo3, 34},
                      motion_case{"heldout100s_07_pass14px_2_4m_2_2x_9_6rps_y_cones", 14, 2.4, pass,
                                  2.2, 9.6, 'y', photo, 33},
                      motion_case{"heldout100s_08_enter35px_2_0m_0_6x_cones", 35, 2.0, enter, 0.6,
                                  0.0, 'y', photo, 31},
                      motion_case{"heldout100s_09_pass23px_3_8m_2_0x_5_3rps_y_kodim19", 23, 3.8,
                                  pass, 2.0, 5.3, 'y', photo3, 25},
                      motion_case{"heldout100s_11_pass12px_3_9m_4_5x_teddy", 12, 3.9, pass, 4.5,
                                  0.0, 'x', photo4, 28},
                      motion_case{"heldout100s_12_thrown21px_3_8m_2_2x_4_7rps_x_aloe", 21, 3.8,
                                  thrown, 2.2, 4.7, 'x', aloe, 40},
                      motion_case{"heldout100s_13_orbit_near22px_2_1m_2_6x_5_0rps_z_cones", 22, 2.1,
                                  orbit_near, 2.6, 5.0, 'z', photo, 24},
                      motion_case{"heldout100s_14_left15px_3_3m_0_4x_cones", 15, 3.3, pass_left,
                                  0.4, 0.0, 'x', photo, 31},
                      motion_case{"heldout100s_15_orbit_far22px_2_7m_2_4x_1_8rps_z_kodim19", 22,
                                  2.7, orbit_far, 2.4, 1.8, 'z', photo3, 35},
                      motion_case{"heldout100s_16_recede15px_3_3m_1_3x_9_5rps_z_aloe", 15, 3.3,
                                  recede, 1.3, 9.5, 'z', aloe, 25},
                      motion_case{"heldout100s_17_pass16px_2_3m_2_2x_8_2rps_y_venus", 16, 2.3, pass,
                                  2.2, 8.2, 'y', venus, 24}),
    case_name);

// Round 91's two held-out failures (HeldOutSweep91), on the depth alone: a
// 14 px ball going away over cones (1.42 % at one pair) and a 74 px circle
// over teddy spinning 2.9 rev/s about z (2.92 % at one pair).
// DepthTurns' one failure: a 25 px ball thrown at the wall over teddy from
// 4.3 m, its measured depth 1.05 % far at its last pair, 14 pairs after
// its bounce (not traced).
// Held-out rounds 92 and 93's failures (HeldOutTurns92, HeldOutTurns93):
// a 30 px ball swung round, a side 0.6 px over, and a 96 px ball thrown at
// the wall (18.03 px at one pair, its depth 1.25 %).
// Six that failed on the depth alone at one pair and passed while a pair's
// depth off the track's fitted depths was reported at the fit (the depth
// gate, removed since: docs/firmware.md, "The measured depth"): round 78's
// 21 px ball entering over venus (2.09 %) and 29 px circle over kodim23
// (1.37 %), round 80's 55 px circle over kodim23 (1.07 %), round 84's 44
// px circle over aloe (2.04 %) and 157 px ball going away over tsukuba
// (1.01 %), and round 86's 222 px ball on the circle's other side over
// aloe (1.11 %).
// Held-out round 102's failures (HeldOutSweep102, HeldOutDepth102), on
// the firmware with the size's depth kept: on the depth alone, balls of
// 13-93 px going away (the 93 px one passed without the rule: 0.56 ->
// 1.19 %); on the box, balls of 22-37 px on circles, an orbit and thrown
// at the wall (7.3-9.3 px at one pair); on a side, 37 px and 42 px orbits
// and a 26 px ball going away.
// Held-out round 103's failures (HeldOutSweep103, HeldOutDepth103): on
// the depth alone, a 13 px ball on the circle's other side and a 189 px
// ball coming nearer; on the box, balls of 19-110 px going away, entering,
// on the circle's other side and thrown at the wall (6.8-31.6 px at one
// pair; the 36 px one thrown at the wall 4.21 px without the rule, 9.44
// px with it, docs/firmware.md); on a side, a 23 px ball thrown at the
// wall.
// A 25 px ball thrown at the wall over teddy (HalfPelCore), a side 0.4 px
// over at one pair since the size's depth is kept (not traced).
// Held-out round 104's failures (HeldOutSweep104, HeldOutDepth104), the
// same with and without the depth line: balls going away, on the box (a
// 124 px one 35.77 px off at one pair, a 104 px one 9.67 px; a 158 px one
// scored on 4 pairs of the 5 a case needs, left out since: its scene gives
// 4 judgeable pairs), on a side (a 17 px one) and on
// the depth (a 15 px one 68.51 % at one pair: two wrong matches in a row,
// the first reported at the line, 67.28 -> 0.23 %, the second taken as
// the rule says; 2.08 % at another pair too); a 133 px ball entering at
// 18 px a frame, 6.57 px off at one pair.
// Held-out round 105's failures (HeldOutSweep105, HeldOutDepth105), the
// same with and without the pattern key's part of a size's depth: balls
// of 22-90 px thrown at the wall, a 15 px ball and a 211 px ball going
// away (not traced).
// Held-out round 101's failures (HeldOutSweep101, HeldOutCurve101): on
// the depth alone, balls of 17-40 px on circles and an orbit (1.04-1.40 %)
// and a 36 px ball thrown at the wall (1.71 %); a 44 px circle at 25 px a
// frame on the box (9.04 px at one pair, mean 2.88 px).
// Round 99's 30 px circle over venus, which passed until the silhouette's
// box was held at the extent's end (HeldOutSmall99: 5.34 -> 9.22 px at one
// pair, not traced).
// Held-out rounds 94 and 95's failures (HeldOutSweep94, HeldOutSweep95):
// on the depth alone, balls of 13-36 px entering (1.16-1.68 %) or coming
// nearer (a 13 px one, 24.1 %); on the box, 20 px and 27 px circles at
// 21-24 px a frame (7.91 and 10.52 px at one pair); a 94 px ball thrown
// at the wall on its depth (1.20 %).
// Held-out round 97's failures (HeldOutSweep97, HeldOutWall97), all ten
// balls of 14-28 px: five on the depth alone (1.02-1.88 %), three on a
// side 0.8-2.8 px past its bound, a 16 px pass on both (8.08 px, 1.04 %)
// and a 16 px ball going away on both (a side 1 px over, 2.58 %).
// Held-out round 96's failures (HeldOutSweep96): a 35 px ball thrown at
// the wall (depth 1.37 %), a 20 px throw over venus (7.78 px) and a 13 px
// ball on the circle's other side (depth 1.49 %).
// Held-out round 100's failures (HeldOutSweep100, HeldOutSmall100): on
// the box, balls of 22-25 px (8.91 px; 3.30 / 6.28 px; a side 0.6 px
// over) and a 100 px ball on the circle's other side at 0.3 times the
// path's speed (34.43 px, a side 41.8 px over, 2.88 %); on the depth,
// balls of 14-33 px (1.04-16.4 %); a 55 px ball entering slowly, scored
// on 3 pairs of the 5 a case needs.
// Three that passed until the core's sub-pixel step at half pixels and
// fail on the depth since: round 80's 82 px ball on the circle's other
// side (0.92 -> 1.05 %), round 95's 70 px ball thrown at the wall
// (ReachBesideTheWall: 0.62 -> 1.44 %, box 3.43 -> 7.67 px) and round 99's
// 43 px ball swung round (0.91 -> 1.00 %).
// Held-out round 99's failures (HeldOutSweep99, HeldOutSmall99): on the
// depth alone, 14 px balls passing and coming nearer (1.29 and 1.07 %); a
// 13 px ball thrown at the wall, a side 2 px over and 1.92 %; balls of 33
// and 34 px thrown at the wall, a side 0.2 and 1.4 px over; a 22 px ball
// on the circle's other side at 25 px a frame (8.90 px, 1.23 %); a 16 px
// ball going away (9.53 px, 68.8 %); a 31 px ball entering at 2.5 px a
// frame over cones, never detected.
// A 100 px ball going away slowly over teddy for 40 frames, which passed
// until the core was matched again on the box moved in (CoreMatchedAgain):
// its tracker's box 5-11 px short of its height, a side then 0.4 px past
// its bound at the last pair (20.8 % of 53 px); its depth 0.41 -> 0.77 %.
// Held-out round 98's failures (HeldOutWall98): seven balls of 12-26 px
// on the depth (1.17-3.32 %; a 24 px one a side 0.2 px over too), a 104 px
// ball thrown at the wall (6.41 px, 1.05 %) and a 77 px ball going away
// (9.58 px, a side 3.6 px over, 1.66 %).
INSTANTIATE_TEST_SUITE_P(
    DISABLED_Open, BoxOnMotion,
    ::testing::Values(
        motion_case{"heldout78_00_circle16px_3_8m_3_3rps_x_kodim23", 16, 3.8, circle, 2.6, 3.3, 'x',
                    photo2, 40},
        motion_case{"heldout78_13_recede14px_2_3m_1_7rps_z_aloe", 14, 2.3, recede, 3.2, 1.7, 'z',
                    aloe, 40},
        motion_case{"heldout78_14_enter21px_2_3m_7_4rps_y_venus", 21, 2.3, enter, 3.4, 7.4, 'y',
                    venus, 24},
        motion_case{"heldout84_11_back235px_3_0m_8_4rps_x_kodim19", 235, 3.0, circle_back, 2.2, 8.4,
                    'x', photo3, 32},
        motion_case{"heldout84_32_recede157px_2_7m_2_2rps_z_tsukuba", 157, 2.7, recede, 2.2, 2.2,
                    'z', tsukuba, 40},
        motion_case{"heldout86_01_back222px_3_4m_5_5rps_y_aloe", 222, 3.4, circle_back, 2.1, 5.5,
                    'y', aloe, 24},
        motion_case{"heldout86_25_back229px_3_7m_2_4rps_y_tsukuba", 229, 3.7, circle_back, 1.0, 2.4,
                    'y', tsukuba, 40},
        motion_case{"heldout92_04_rebound96px_3_5m_1_7mps_5_7rps_x_teddy", 96, 3.5, rebound, 0.8,
                    5.7, 'x', photo4, 46, 0.0, 1.7},
        motion_case{"heldout93_09_orbit_far30px_2_4m_1_3x_kodim23", 30, 2.4, orbit_far, 1.3, 0.0,
                    'x', photo2, 34},
        motion_case{"circle35px_3pxpf_2rps_x_cones_32f", 35, 2.6, circle, 0.4, 2.0, 'x', photo, 32},
        motion_case{"heldout94_05_circle27px_2_1m_3_0x_aloe", 27, 2.1, circle, 3.0, 0.0, 'z', aloe,
                    30},
        motion_case{"heldout94_08_circle20px_2_5m_2_6x_venus", 20, 2.5, circle, 2.6, 0.0, 'z',
                    venus, 30},
        motion_case{"heldout94_16_enter13px_3_1m_4_3x_kodim19", 13, 3.1, enter, 4.3, 0.0, 'z',
                    photo3, 40},
        motion_case{"heldout95_15_rebound94px_4_3m_2_1mps_aloe", 94, 4.3, rebound, 0.5, 0.0, 'z',
                    aloe, 32, 0.0, 2.1},
        motion_case{"heldout96_26_thrown20px_4_0m_1_2x_3_6rps_z_venus", 20, 4.0, thrown, 1.2, 3.6,
                    'z', venus, 35},
        motion_case{"heldout97_07_left14px_3_1m_3_2x_7_1rps_z_kodim19", 14, 3.1, pass_left, 3.2,
                    7.1, 'z', photo3, 37},
        motion_case{"heldout97_11_pass16px_3_1m_0_9x_8_6rps_x_kodim23", 16, 3.1, pass, 0.9, 8.6,
                    'x', photo2, 36},
        motion_case{"heldout97_17_circle19px_3_8m_1_2x_2_4rps_y_venus", 19, 3.8, circle, 1.2, 2.4,
                    'y', venus, 38},
        motion_case{"heldout97_21_recede16px_2_2m_3_9x_aloe", 16, 2.2, recede, 3.9, 0.0, 'y', aloe,
                    40},
        motion_case{"heldout97w_14_recede16px_2_6m_1_5x_6_5rps_x_kodim23", 16, 2.6, recede, 1.5,
                    6.5, 'x', photo2, 34},
        motion_case{"heldout98w_09_recede13px_3_2m_1_4x_2_2rps_y_kodim19", 13, 3.2, recede, 1.4,
                    2.2, 'y', photo3, 39},
        motion_case{"heldout98w_13_recede77px_2_4m_1_5x_teddy", 77, 2.4, recede, 1.5, 0.0, 'z',
                    photo4, 40},
        motion_case{"heldout98w_18_recede12px_2_5m_1_3x_5_0rps_x_venus", 12, 2.5, recede, 1.3, 5.0,
                    'x', venus, 34},
        motion_case{"heldout98w_26_recede13px_3_3m_1_4x_1_3rps_x_aloe", 13, 3.3, recede, 1.4, 1.3,
                    'x', aloe, 35},
        motion_case{"heldout98w_28_rebound104px_4_2m_3_4mps_1_2rps_z_tsukuba", 104, 4.2, rebound,
                    0.4, 1.2, 'z', tsukuba, 39, 0.0, 3.4},
        motion_case{"heldout98w_35_recede14px_2_5m_1_9x_cones", 14, 2.5, recede, 1.9, 0.0, 'y',
                    photo, 38},
        motion_case{"heldout98w_39_recede21px_3_1m_4_8x_venus", 21, 3.1, recede, 4.8, 0.0, 'z',
                    venus, 36},
        motion_case{"heldout99s_03_enter31px_2_8m_0_5x_cones", 31, 2.8, enter, 0.5, 0.0, 'y', photo,
                    25},
        motion_case{"heldout99s_18_rebound13px_3_9m_2_5mps_1_1rps_x_kodim19", 13, 3.9, rebound, 0.8,
                    1.1, 'x', photo3, 32, 0.0, 2.5},
        motion_case{"heldout80_22_back82px_3_6m_teddy", 82, 3.6, circle_back, 2.6, 0.0, 'y', photo4,
                    24},
        motion_case{"heldout95_16_rebound70px_4_2m_2_8mps_4_0rps_x_cones", 70, 4.2, rebound, 0.6,
                    4.0, 'x', photo, 39, 0.0, 2.8},
        motion_case{"heldout100s_10_circle22px_2_9m_0_4x_venus", 22, 2.9, circle, 0.4, 0.0, 'y',
                    venus, 25},
        motion_case{"heldout100s_18_thrown25px_2_7m_0_4x_4_9rps_x_venus", 25, 2.7, thrown, 0.4, 4.9,
                    'x', venus, 28},
        motion_case{"heldout100_09_back100px_2_2m_0_3x_teddy", 100, 2.2, circle_back, 0.3, 0.0, 'x',
                    photo4, 40},
        motion_case{"heldout100_23_left14px_2_9m_0_3x_2_0rps_x_teddy", 14, 2.9, pass_left, 0.3, 2.0,
                    'x', photo4, 27},
        motion_case{"heldout100_27_enter55px_2_4m_0_3x_teddy", 55, 2.4, enter, 0.3, 0.0, 'z',
                    photo4, 24},
        motion_case{"heldout99s_01_circle30px_2_7m_1_3x_6_2rps_z_venus", 30, 2.7, circle, 1.3, 6.2,
                    'z', venus, 39},
        motion_case{"heldout101_03_circle17px_3_6m_2_0x_venus", 17, 3.6, circle, 2.0, 0.0, 'y',
                    venus, 36},
        motion_case{"heldout101_09_orbit_far40px_2_8m_2_5x_kodim23", 40, 2.8, orbit_far, 2.5, 0.0,
                    'y', photo2, 26},
        motion_case{"heldout101_29_circle30px_3_8m_1_1x_2_4rps_x_aloe", 30, 3.8, circle, 1.1, 2.4,
                    'x', aloe, 38},
        motion_case{"heldout101c_10_circle44px_2_3m_3_1x_4_0rps_y_venus", 44, 2.3, circle, 3.1, 4.0,
                    'y', venus, 24},
        motion_case{"heldout101c_17_rebound36px_3_7m_1_8mps_8_3rps_x_teddy", 36, 3.7, rebound, 1.0,
                    8.3, 'x', photo4, 32, 0.0, 1.8},
        motion_case{"rebound25px_1_5mps_4_3m_teddy", 25, 4.3, rebound, 0.5, 0.0, 'x', photo4, 34,
                    0.0, 1.5},
        motion_case{"heldout102_15_orbit_far37px_2_1m_1_3x_kodim23", 37, 2.1, orbit_far, 1.3, 0.0,
                    'x', photo2, 25},
        motion_case{"heldout102_20_back27px_3_8m_3_5x_cones", 27, 3.8, circle_back, 3.5, 0.0, 'y',
                    photo, 27},
        motion_case{"heldout102_24_orbit_near33px_2_7m_3_0x_5_1rps_x_teddy", 33, 2.7, orbit_near,
                    3.0, 5.1, 'x', photo4, 40},
        motion_case{"heldout102_27_orbit_far42px_2_6m_1_2x_teddy", 42, 2.6, orbit_far, 1.2, 0.0,
                    'y', photo4, 40},
        motion_case{"heldout102_28_circle22px_2_0m_0_5x_7_1rps_y", 22, 2.0, circle, 0.5, 7.1, 'y',
                    procedural, 30},
        motion_case{"heldout102d_01_recede13px_3_1m_0_5x_6_5rps_z_kodim19", 13, 3.1, recede, 0.5,
                    6.5, 'z', photo3, 36},
        motion_case{"heldout102d_04_recede26px_2_4m_3_9x_2_1rps_x_kodim19", 26, 2.4, recede, 3.9,
                    2.1, 'x', photo3, 37},
        motion_case{"heldout102d_12_rebound37px_4_0m_1_3mps_9_7rps_z_teddy", 37, 4.0, rebound, 0.9,
                    9.7, 'z', photo4, 37, 0.0, 1.3},
        motion_case{"heldout102d_13_recede25px_3_3m_3_3x_kodim23", 25, 3.3, recede, 3.3, 0.0, 'z',
                    photo2, 26},
        motion_case{"heldout102d_16_recede19px_2_4m_1_6x_aloe", 19, 2.4, recede, 1.6, 0.0, 'z',
                    aloe, 39},
        motion_case{"heldout103_07_back13px_3_0m_1_7x_7_6rps_y_cones", 13, 3.0, circle_back, 1.7,
                    7.6, 'y', photo, 29},
        motion_case{"heldout103_09_recede19px_2_2m_2_0x_5_1rps_x_kodim23", 19, 2.2, recede, 2.0,
                    5.1, 'x', photo2, 25},
        motion_case{"heldout103_14_back27px_2_1m_2_9x_8_2rps_y_kodim23", 27, 2.1, circle_back, 2.9,
                    8.2, 'y', photo2, 28},
        motion_case{"heldout103_16_approach189px_3_7m_0_5x_venus", 189, 3.7, approach, 0.5, 0.0,
                    'z', venus, 27},
        motion_case{"heldout103_21_enter28px_3_2m_2_1x_9_4rps_y_venus", 28, 3.2, enter, 2.1, 9.4,
                    'y', venus, 25},
        motion_case{"heldout103d_01_rebound36px_3_6m_1_4mps_teddy", 36, 3.6, rebound, 1.0, 0.0, 'y',
                    photo4, 36, 0.0, 1.4},
        motion_case{"heldout103d_09_rebound23px_3_7m_1_1mps_kodim23", 23, 3.7, rebound, 0.5, 0.0,
                    'x', photo2, 36, 0.0, 1.1},
        motion_case{"heldout103d_10_rebound110px_4_4m_1_2mps_6_0rps_z_venus", 110, 4.4, rebound,
                    0.8, 6.0, 'z', venus, 27, 0.0, 1.2},
        motion_case{"heldout103d_12_recede32px_4_0m_0_4x_kodim19", 32, 4.0, recede, 0.4, 0.0, 'x',
                    photo3, 29},
        motion_case{"heldout103d_18_rebound95px_3_7m_3_4mps_4_1rps_z_teddy", 95, 3.7, rebound, 1.0,
                    4.1, 'z', photo4, 32, 0.0, 3.4},
        motion_case{"heldout104_20_enter133px_2_9m_3_6x_kodim19", 133, 2.9, enter, 3.6, 0.0, 'z',
                    photo3, 31},
        motion_case{"heldout104_25_recede17px_3_1m_0_4x_3_2rps_z_kodim23", 17, 3.1, recede, 0.4,
                    3.2, 'z', photo2, 40},
        motion_case{"heldout104d_01_recede15px_2_1m_2_0x_kodim23", 15, 2.1, recede, 2.0, 0.0, 'y',
                    photo2, 30},
        motion_case{"heldout104d_05_recede124px_3_7m_0_5x_venus", 124, 3.7, recede, 0.5, 0.0, 'z',
                    venus, 36},
        motion_case{"heldout104d_06_recede104px_3_4m_0_3x_kodim19", 104, 3.4, recede, 0.3, 0.0, 'y',
                    photo3, 26},
        motion_case{"heldout105_04_rebound90px_4_1m_2_5mps_teddy", 90, 4.1, rebound, 0.8, 0.0, 'y',
                    photo4, 40, 0.0, 2.5},
        motion_case{"heldout105_28_rebound22px_3_6m_1_2mps_5_2rps_x_teddy", 22, 3.6, rebound, 1.0,
                    5.2, 'x', photo4, 29, 0.0, 1.2},
        motion_case{"heldout105d_07_rebound47px_4_3m_3_2mps_aloe", 47, 4.3, rebound, 1.0, 0.0, 'y',
                    aloe, 26, 0.0, 3.2},
        motion_case{"heldout105d_08_recede15px_2_9m_1_1x_teddy", 15, 2.9, recede, 1.1, 0.0, 'z',
                    photo4, 33},
        motion_case{"heldout105d_18_recede211px_3_3m_0_5x_9_3rps_z_teddy", 211, 3.3, recede, 0.5,
                    9.3, 'z', photo4, 40},
        motion_case{"recede100px_3pxpf_teddy_2m_40f", 100, 2.0, recede, 0.2, 0.0, 'x', photo4, 40}),
    case_name);

// Seven open cases that pass since the silhouette's box is held at
// Dif(t-1,t)'s extent end where the SAD box of its size read that end
// (dsp/box_refit.h, held_at_extent_end; docs/firmware.md, "A box held at
// the extent's end"), development cases of that rule: balls of 17-44 px
// on circles, an orbit and going away at 13-25 px a frame. Three failed
// on a box the window's velocity placed 6-9 px past the ball at one pair
// where its motion turned or slowed (round 99's 22 px ball circling,
// traced: 8.90 -> 2.41 px); four on the depth at a pair (1.01-1.75 %, not
// traced).
INSTANTIATE_TEST_SUITE_P(
    HeldAtExtentEnd, BoxOnMotion,
    ::testing::Values(motion_case{"heldout78_06_back17px_3_1m_kodim23", 17, 3.1, circle_back, 2.9,
                                  0.0, 'y', photo2, 24},
                      motion_case{"heldout78_16_circle29px_2_5m_8_7rps_x_kodim23", 29, 2.5, circle,
                                  1.7, 8.7, 'x', photo2, 32},
                      motion_case{"heldout84_02_circle44px_3_3m_1_4rps_x_aloe", 44, 3.3, circle,
                                  2.5, 1.4, 'x', aloe, 40},
                      motion_case{"heldout98w_02_recede24px_3_2m_4_1x_6_4rps_x_venus", 24, 3.2,
                                  recede, 4.1, 6.4, 'x', venus, 30},
                      motion_case{"heldout99_23_back22px_2_9m_3_2x_aloe", 22, 2.9, circle_back, 3.2,
                                  0.0, 'x', aloe, 39},
                      motion_case{"heldout100s_06_back23px_2_7m_3_1x_tsukuba", 23, 2.7, circle_back,
                                  3.1, 0.0, 'z', tsukuba, 40},
                      motion_case{"heldout100s_19_orbit_near28px_2_4m_2_7x_7_5rps_z_aloe", 28, 2.4,
                                  orbit_near, 2.7, 7.5, 'z', aloe, 28}),
    case_name);

// Held out, round 101: 30 cases drawn at random (seed 101, rounds 94 and
// 95's envelope) and committed before they were run, with and without the
// silhouette's box held at Dif(t-1,t)'s extent end where the SAD box of
// the same size read it (dsp/box_refit.h, held_at_extent_end). Decision
// declared here: that rule is kept only if, over this round and
// HeldOutCurve101 together, it passes more of the cases in the envelope
// (30 px a frame at most) than the firmware without it; on a tie or fewer
// it is not kept. Eight of the 50 moved faster (left out); of the other
// 42, 37 passed with the rule and 35 without it (a 15 px ball on the
// circle's other side, 9.18 px and 57.5 % -> 3.09 px and 0.36 %, and a
// 42 px circle, 8.15 -> 3.98 px; none the other way): kept. Of this
// round's 26, 23 passed and 3 failed (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep101, BoxOnMotion,
    ::testing::Values(motion_case{"heldout101_00_orbit_near117px_2_9m_2_1x_1_4rps_z_kodim19", 117,
                                  2.9, orbit_near, 2.1, 1.4, 'z', photo3, 31},
                      motion_case{"heldout101_01_back51px_3_6m_0_8x_3_3rps_x_cones", 51, 3.6,
                                  circle_back, 0.8, 3.3, 'x', photo, 38},
                      motion_case{"heldout101_02_rebound37px_4_0m_2_9mps_2_9rps_y_aloe", 37, 4.0,
                                  rebound, 0.6, 2.9, 'y', aloe, 33, 0.0, 2.9},
                      motion_case{"heldout101_04_circle43px_2_8m_2_0x_5_2rps_z_cones", 43, 2.8,
                                  circle, 2.0, 5.2, 'z', photo, 35},
                      motion_case{"heldout101_05_pass36px_2_7m_0_6x_venus", 36, 2.7, pass, 0.6, 0.0,
                                  'x', venus, 29},
                      motion_case{"heldout101_06_back15px_2_3m_2_1x_aloe", 15, 2.3, circle_back,
                                  2.1, 0.0, 'y', aloe, 29},
                      motion_case{"heldout101_08_pass67px_3_1m_2_2x_8_4rps_z_aloe", 67, 3.1, pass,
                                  2.2, 8.4, 'z', aloe, 28},
                      motion_case{"heldout101_10_thrown170px_2_7m_0_4x_tsukuba", 170, 2.7, thrown,
                                  0.4, 0.0, 'z', tsukuba, 38},
                      motion_case{"heldout101_11_pass21px_3_4m_0_8x_2_4rps_y_kodim19", 21, 3.4,
                                  pass, 0.8, 2.4, 'y', photo3, 37},
                      motion_case{"heldout101_12_left58px_3_6m_4_5x_3_5rps_x", 58, 3.6, pass_left,
                                  4.5, 3.5, 'x', procedural, 24},
                      motion_case{"heldout101_13_orbit_far57px_2_6m_2_3x_4_0rps_y_aloe", 57, 2.6,
                                  orbit_far, 2.3, 4.0, 'y', aloe, 30},
                      motion_case{"heldout101_14_rebound55px_3_8m_1_4mps_4_3rps_y_venus", 55, 3.8,
                                  rebound, 0.4, 4.3, 'y', venus, 25, 0.0, 1.4},
                      motion_case{"heldout101_15_circle56px_2_4m_1_9x_2_1rps_x_aloe", 56, 2.4,
                                  circle, 1.9, 2.1, 'x', aloe, 30},
                      motion_case{"heldout101_16_orbit_far88px_2_8m_2_0x_kodim23", 88, 2.8,
                                  orbit_far, 2.0, 0.0, 'x', photo2, 38},
                      motion_case{"heldout101_17_rebound52px_3_8m_1_8mps_aloe", 52, 3.8, rebound,
                                  0.6, 0.0, 'x', aloe, 33, 0.0, 1.8},
                      motion_case{"heldout101_18_pass25px_3_2m_0_8x", 25, 3.2, pass, 0.8, 0.0, 'y',
                                  procedural, 32},
                      motion_case{"heldout101_19_rebound67px_4_5m_2_4mps", 67, 4.5, rebound, 0.9,
                                  0.0, 'x', procedural, 37, 0.0, 2.4},
                      motion_case{"heldout101_21_back73px_2_2m_0_4x_tsukuba", 73, 2.2, circle_back,
                                  0.4, 0.0, 'y', tsukuba, 40},
                      motion_case{"heldout101_22_left19px_3_4m_1_0x_3_1rps_x_cones", 19, 3.4,
                                  pass_left, 1.0, 3.1, 'x', photo, 31},
                      motion_case{"heldout101_25_orbit_near70px_2_0m_2_8x_aloe", 70, 2.0,
                                  orbit_near, 2.8, 0.0, 'x', aloe, 28},
                      motion_case{"heldout101_26_left17px_2_1m_1_7x_cones", 17, 2.1, pass_left, 1.7,
                                  0.0, 'z', photo, 32},
                      motion_case{"heldout101_27_recede115px_3_4m_0_4x_cones", 115, 3.4, recede,
                                  0.4, 0.0, 'x', photo, 33},
                      motion_case{"heldout101_28_back24px_3_4m_0_9x_tsukuba", 24, 3.4, circle_back,
                                  0.9, 0.0, 'x', tsukuba, 25}),
    case_name);

// Held out with round 101: 20 balls of 15-45 px on turning paths (thrown,
// circles, orbits, rebounds) at 1-4 times their base speed (seed 201),
// committed with HeldOutSweep101 before they were run, under its rule.
// Four thrown at over 30 px a frame are left out; of the other 16, 14
// passed and 2 failed (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutCurve101, BoxOnMotion,
    ::testing::Values(motion_case{"heldout101c_01_orbit_near25px_2_6m_1_9x", 25, 2.6, orbit_near,
                                  1.9, 0.0, 'y', procedural, 31},
                      motion_case{"heldout101c_02_circle41px_3_8m_1_0x_6_0rps_x_aloe", 41, 3.8,
                                  circle, 1.0, 6.0, 'x', aloe, 24},
                      motion_case{"heldout101c_03_orbit_far40px_2_8m_2_4x_teddy", 40, 2.8,
                                  orbit_far, 2.4, 0.0, 'z', photo4, 39},
                      motion_case{"heldout101c_05_orbit_near24px_2_0m_2_8x_2_8rps_x_kodim19", 24,
                                  2.0, orbit_near, 2.8, 2.8, 'x', photo3, 40},
                      motion_case{"heldout101c_06_thrown20px_3_2m_1_6x_kodim19", 20, 3.2, thrown,
                                  1.6, 0.0, 'y', photo3, 33},
                      motion_case{"heldout101c_07_orbit_far16px_2_2m_1_9x_8_5rps_x_cones", 16, 2.2,
                                  orbit_far, 1.9, 8.5, 'x', photo, 35},
                      motion_case{"heldout101c_08_orbit_far39px_2_5m_2_6x_tsukuba", 39, 2.5,
                                  orbit_far, 2.6, 0.0, 'x', tsukuba, 39},
                      motion_case{"heldout101c_09_orbit_near15px_2_2m_2_0x_8_8rps_y_tsukuba", 15,
                                  2.2, orbit_near, 2.0, 8.8, 'y', tsukuba, 37},
                      motion_case{"heldout101c_12_rebound44px_3_9m_3_5mps_5_1rps_y_kodim23", 44,
                                  3.9, rebound, 1.1, 5.1, 'y', photo2, 31, 0.0, 3.5},
                      motion_case{"heldout101c_13_circle18px_3_2m_2_0x_kodim23", 18, 3.2, circle,
                                  2.0, 0.0, 'x', photo2, 36},
                      motion_case{"heldout101c_14_circle21px_3_6m_2_0x_1_4rps_z", 21, 3.6, circle,
                                  2.0, 1.4, 'z', procedural, 26},
                      motion_case{"heldout101c_15_circle38px_3_1m_1_2x_tsukuba", 38, 3.1, circle,
                                  1.2, 0.0, 'z', tsukuba, 39},
                      motion_case{"heldout101c_16_circle42px_2_0m_3_4x_cones", 42, 2.0, circle, 3.4,
                                  0.0, 'y', photo, 28},
                      motion_case{"heldout101c_19_orbit_far19px_2_4m_1_0x_3_4rps_z_teddy", 19, 2.4,
                                  orbit_far, 1.0, 3.4, 'z', photo4, 29}),
    case_name);

// Open cases that pass since a size kept stands for the depth it was sized
// at while the object goes away (docs/firmware.md, "A size's depth kept
// while the object goes away"): four balls of 25-34 px thrown at the wall
// whose box was held at its first size or a key's while they shrank (sides
// 4-7 px over), three balls of 14-19 px going away and a 43 px ball swung
// round far (on the depth, 1.00-1.13 % -> 0.32-0.66 %; a 16 px one 9.53
// px and 68.8 % at one pair -> 2.51 px, 0.58 %).
INSTANTIATE_TEST_SUITE_P(
    SizeDepthKept, BoxOnMotion,
    ::testing::Values(motion_case{"heldout91_10_recede14px_3_8m_cones", 14, 3.8, recede, 2.7, 0.0,
                                  'x', photo, 32},
                      motion_case{"heldout97w_00_rebound25px_3_5m_1_4mps_cones", 25, 3.5, rebound,
                                  0.5, 0.0, 'y', photo, 30, 0.0, 1.4},
                      motion_case{"heldout97w_06_recede19px_3_1m_2_5x", 19, 3.1, recede, 2.5, 0.0,
                                  'y', procedural, 36},
                      motion_case{"heldout99_09_rebound34px_4_0m_1_8mps_kodim23", 34, 4.0, rebound,
                                  0.6, 0.0, 'y', photo2, 26, 0.0, 1.8},
                      motion_case{"heldout99s_10_recede16px_2_5m_1_0x_4_6rps_x_tsukuba", 16, 2.5,
                                  recede, 1.0, 4.6, 'x', tsukuba, 33},
                      motion_case{"heldout99s_19_rebound33px_4_0m_1_5mps_tsukuba", 33, 4.0, rebound,
                                  0.7, 0.0, 'y', tsukuba, 35, 0.0, 1.5},
                      motion_case{"heldout99_12_orbit_far43px_2_7m_1_2x_kodim19", 43, 2.7,
                                  orbit_far, 1.2, 0.0, 'y', photo3, 31},
                      motion_case{"heldout100_17_rebound33px_3_9m_1_7mps", 33, 3.9, rebound, 0.9,
                                  0.0, 'z', procedural, 26, 0.0, 1.7}),
    case_name);

// Open cases that pass since a depth no motion of the ball reaches is
// reported at the line of the track's last three (docs/firmware.md, "A
// depth no motion reaches"): a 13 px ball coming nearer (24.27 % at one
// pair -> 0.52 %) and a 17 px pass (16.43 -> 0.99 %), both over teddy,
// their neighbours' depths within 1 %.
INSTANTIATE_TEST_SUITE_P(DepthOffItsLine, BoxOnMotion,
                         ::testing::Values(motion_case{"heldout94_06_approach13px_3_9m_1_4x_teddy",
                                                       13, 3.9, approach, 1.4, 0.0, 'x', photo4,
                                                       25},
                                           motion_case{"heldout100_29_pass17px_2_7m_0_7x_teddy", 17,
                                                       2.7, pass, 0.7, 0.0, 'x', photo4, 33}),
                         case_name);

// An open case that passes since a box placed from a pattern key stands
// for the last pair's depth (docs/firmware.md, "A size's depth kept while
// the object goes away"; held out in round 105): round 102's 93 px ball
// going away at half speed, spinning 7 rev/s (1.19 -> 0.56 %).
INSTANTIATE_TEST_SUITE_P(KeyBoxAtPairDepth, BoxOnMotion,
                         ::testing::Values(motion_case{
                             "heldout102_09_recede93px_3_9m_0_5x_7_0rps_x_venus", 93, 3.9, recede,
                             0.5, 7.0, 'x', venus, 28}),
                         case_name);

// Held out, round 102: 30 cases drawn at random (seed 102, rounds 94 and
// 95's envelope) and committed before they were run, with and without the
// box's size standing for the depth it was sized at while the object goes
// away (a size the track or a key carried keeps that depth until the
// depth's change moves a side: dsp/size_at_depth.h). Decision declared
// here: that rule is kept only if, over this round and HeldOutDepth102
// together, it passes more of the cases in the envelope (30 px a frame at
// most) than the firmware without it; on a tie or fewer it is not kept.
// Two of the 50 moved faster (left out); of the other 48, 36 passed with
// the rule and 37 without it (a 93 px ball going away, 0.56 -> 1.19 %):
// not kept. The revised form (round 103) passes the same 36; of this
// round's 28, 22 pass and 6 fail (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep102, BoxOnMotion,
    ::testing::Values(motion_case{"heldout102_00_thrown91px_2_7m_1_4x_venus", 91, 2.7, thrown, 1.4,
                                  0.0, 'x', venus, 33},
                      motion_case{"heldout102_01_orbit_near60px_2_6m_2_4x_kodim23", 60, 2.6,
                                  orbit_near, 2.4, 0.0, 'z', photo2, 36},
                      motion_case{"heldout102_03_circle102px_3_1m_1_2x_5_3rps_x_kodim19", 102, 3.1,
                                  circle, 1.2, 5.3, 'x', photo3, 26},
                      motion_case{"heldout102_04_enter37px_2_4m_1_0x_kodim23", 37, 2.4, enter, 1.0,
                                  0.0, 'y', photo2, 29},
                      motion_case{"heldout102_05_enter22px_3_2m_1_8x_6_0rps_y_teddy", 22, 3.2,
                                  enter, 1.8, 6.0, 'y', photo4, 34},
                      motion_case{"heldout102_06_orbit_far99px_2_6m_2_1x_kodim19", 99, 2.6,
                                  orbit_far, 2.1, 0.0, 'z', photo3, 36},
                      motion_case{"heldout102_08_pass40px_3_9m_4_3x_1_7rps_z_venus", 40, 3.9, pass,
                                  4.3, 1.7, 'z', venus, 32},
                      motion_case{"heldout102_10_thrown72px_3_1m_0_3x_3_5rps_x_cones", 72, 3.1,
                                  thrown, 0.3, 3.5, 'x', photo, 28},
                      motion_case{"heldout102_11_pass42px_2_6m_2_3x_3_2rps_x_teddy", 42, 2.6, pass,
                                  2.3, 3.2, 'x', photo4, 30},
                      motion_case{"heldout102_12_pass48px_3_6m_3_1x_8_6rps_z_kodim19", 48, 3.6,
                                  pass, 3.1, 8.6, 'z', photo3, 32},
                      motion_case{"heldout102_13_left201px_3_8m_2_2x_aloe", 201, 3.8, pass_left,
                                  2.2, 0.0, 'z', aloe, 28},
                      motion_case{"heldout102_14_pass26px_2_8m_0_5x_9_5rps_x_kodim23", 26, 2.8,
                                  pass, 0.5, 9.5, 'x', photo2, 26},
                      motion_case{"heldout102_16_circle89px_3_8m_0_4x_aloe", 89, 3.8, circle, 0.4,
                                  0.0, 'y', aloe, 26},
                      motion_case{"heldout102_17_enter61px_2_9m_2_8x", 61, 2.9, enter, 2.8, 0.0,
                                  'x', procedural, 32},
                      motion_case{"heldout102_18_orbit_near145px_2_9m_1_3x_cones", 145, 2.9,
                                  orbit_near, 1.3, 0.0, 'x', photo, 26},
                      motion_case{"heldout102_19_rebound72px_4_5m_2_5mps_kodim23", 72, 4.5, rebound,
                                  0.4, 0.0, 'z', photo2, 39, 0.0, 2.5},
                      motion_case{"heldout102_21_left114px_3_3m_0_5x_1_6rps_x_venus", 114, 3.3,
                                  pass_left, 0.5, 1.6, 'x', venus, 31},
                      motion_case{"heldout102_22_orbit_far124px_2_1m_1_7x_4_2rps_y_kodim19", 124,
                                  2.1, orbit_far, 1.7, 4.2, 'y', photo3, 30},
                      motion_case{"heldout102_23_approach90px_2_8m_0_3x_aloe", 90, 2.8, approach,
                                  0.3, 0.0, 'y', aloe, 26},
                      motion_case{"heldout102_25_pass14px_2_9m_3_3x_5_0rps_y_venus", 14, 2.9, pass,
                                  3.3, 5.0, 'y', venus, 31},
                      motion_case{"heldout102_26_back32px_3_6m_2_4x_kodim19", 32, 3.6, circle_back,
                                  2.4, 0.0, 'z', photo3, 27},
                      motion_case{"heldout102_29_approach72px_2_8m_1_7x_kodim23", 72, 2.8, approach,
                                  1.7, 0.0, 'z', photo2, 36}),
    case_name);

// Held out with round 102: 20 balls whose depth changes (thrown at the
// wall and back, going away, coming nearer; seed 202), committed with
// HeldOutSweep102 before they were run, under its rule. 14 pass and 6
// fail (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutDepth102, BoxOnMotion,
    ::testing::Values(motion_case{"heldout102d_00_recede83px_2_8m_0_5x_venus", 83, 2.8, recede, 0.5,
                                  0.0, 'x', venus, 38},
                      motion_case{"heldout102d_02_recede50px_2_9m_2_4x", 50, 2.9, recede, 2.4, 0.0,
                                  'z', procedural, 40},
                      motion_case{"heldout102d_03_rebound72px_3_9m_2_5mps_cones", 72, 3.9, rebound,
                                  1.0, 0.0, 'x', photo, 25, 0.0, 2.5},
                      motion_case{"heldout102d_05_rebound34px_4_2m_1_9mps_tsukuba", 34, 4.2,
                                  rebound, 0.5, 0.0, 'x', tsukuba, 25, 0.0, 1.9},
                      motion_case{"heldout102d_06_approach21px_2_8m_1_3x_venus", 21, 2.8, approach,
                                  1.3, 0.0, 'y', venus, 29},
                      motion_case{"heldout102d_07_rebound52px_3_8m_3_9mps_cones", 52, 3.8, rebound,
                                  0.6, 0.0, 'x', photo, 40, 0.0, 3.9},
                      motion_case{"heldout102d_08_recede66px_2_6m_0_7x_aloe", 66, 2.6, recede, 0.7,
                                  0.0, 'y', aloe, 33},
                      motion_case{"heldout102d_09_approach84px_3_8m_1_4x_kodim23", 84, 3.8,
                                  approach, 1.4, 0.0, 'y', photo2, 38},
                      motion_case{"heldout102d_10_rebound89px_3_7m_2_3mps", 89, 3.7, rebound, 0.9,
                                  0.0, 'x', procedural, 39, 0.0, 2.3},
                      motion_case{"heldout102d_11_rebound28px_4_3m_3_6mps_aloe", 28, 4.3, rebound,
                                  0.8, 0.0, 'x', aloe, 36, 0.0, 3.6},
                      motion_case{"heldout102d_14_rebound43px_4_1m_2_7mps_4_8rps_x_tsukuba", 43,
                                  4.1, rebound, 0.6, 4.8, 'x', tsukuba, 40, 0.0, 2.7},
                      motion_case{"heldout102d_15_approach163px_3_4m_1_3x_8_9rps_z_aloe", 163, 3.4,
                                  approach, 1.3, 8.9, 'z', aloe, 35},
                      motion_case{"heldout102d_18_approach98px_3_8m_2_9x_4_8rps_y_kodim23", 98, 3.8,
                                  approach, 2.9, 4.8, 'y', photo2, 25},
                      motion_case{"heldout102d_19_approach116px_2_4m_1_1x_3_1rps_z_kodim19", 116,
                                  2.4, approach, 1.1, 3.1, 'z', photo3, 31}),
    case_name);

// Held out, round 103: 30 cases drawn at random (seed 103, rounds 94 and
// 95's envelope) and committed before they were run, with and without a
// revised form of round 102's rule: the box's size stands for the depth it
// was sized at while the object goes away, and also where a key's box is
// placed (a key's size carried stands for the key's depth, one resized
// for the last pair's). Decision declared here, as round 102's: kept only
// if, over this round and HeldOutDepth103 together, it passes more of the
// cases in the envelope (30 px a frame at most) than the firmware without
// it; on a tie or fewer it is not kept. Three of the 50 moved faster
// (left out); of the other 47, 37 passed with the rule and 36 without it
// (a 92 px ball thrown at the wall, 1.95 -> 0.87 %), none the other way:
// kept. Over rounds 102 and 103 together the kept form ties, 73 and 73.
// Of this round's 27, 22 pass and 5 fail (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep103, BoxOnMotion,
    ::testing::Values(motion_case{"heldout103_01_approach172px_3_7m_0_4x_3_0rps_x", 172, 3.7,
                                  approach, 0.4, 3.0, 'x', procedural, 31},
                      motion_case{"heldout103_02_left95px_3_2m_0_7x_venus", 95, 3.2, pass_left, 0.7,
                                  0.0, 'z', venus, 31},
                      motion_case{"heldout103_03_orbit_far75px_2_8m_1_5x_6_2rps_z_aloe", 75, 2.8,
                                  orbit_far, 1.5, 6.2, 'z', aloe, 32},
                      motion_case{"heldout103_04_back182px_3_5m_1_3x_kodim19", 182, 3.5,
                                  circle_back, 1.3, 0.0, 'y', photo3, 40},
                      motion_case{"heldout103_05_back14px_3_7m_0_4x_aloe", 14, 3.7, circle_back,
                                  0.4, 0.0, 'x', aloe, 35},
                      motion_case{"heldout103_06_left149px_3_3m_3_0x_7_0rps_x_cones", 149, 3.3,
                                  pass_left, 3.0, 7.0, 'x', photo, 36},
                      motion_case{"heldout103_08_approach124px_2_6m_0_7x_3_2rps_x_kodim19", 124,
                                  2.6, approach, 0.7, 3.2, 'x', photo3, 31},
                      motion_case{"heldout103_10_enter27px_3_3m_0_6x_5_1rps_y_kodim23", 27, 3.3,
                                  enter, 0.6, 5.1, 'y', photo2, 29},
                      motion_case{"heldout103_11_back36px_3_6m_0_3x_aloe", 36, 3.6, circle_back,
                                  0.3, 0.0, 'z', aloe, 35},
                      motion_case{"heldout103_12_thrown32px_3_3m_0_4x_8_9rps_z_kodim23", 32, 3.3,
                                  thrown, 0.4, 8.9, 'z', photo2, 37},
                      motion_case{"heldout103_13_recede142px_3_5m_2_9x_tsukuba", 142, 3.5, recede,
                                  2.9, 0.0, 'z', tsukuba, 37},
                      motion_case{"heldout103_15_approach122px_3_8m_2_0x", 122, 3.8, approach, 2.0,
                                  0.0, 'z', procedural, 27},
                      motion_case{"heldout103_17_back91px_3_3m_1_6x_cones", 91, 3.3, circle_back,
                                  1.6, 0.0, 'z', photo, 25},
                      motion_case{"heldout103_19_back44px_3_5m_2_8x_aloe", 44, 3.5, circle_back,
                                  2.8, 0.0, 'z', aloe, 33},
                      motion_case{"heldout103_20_circle41px_3_9m_1_5x_6_3rps_x_tsukuba", 41, 3.9,
                                  circle, 1.5, 6.3, 'x', tsukuba, 27},
                      motion_case{"heldout103_22_orbit_far47px_2_0m_2_6x_kodim19", 47, 2.0,
                                  orbit_far, 2.6, 0.0, 'x', photo3, 34},
                      motion_case{"heldout103_23_back35px_2_8m_0_5x_6_8rps_y_aloe", 35, 2.8,
                                  circle_back, 0.5, 6.8, 'y', aloe, 32},
                      motion_case{"heldout103_24_thrown45px_2_6m_0_7x_venus", 45, 2.6, thrown, 0.7,
                                  0.0, 'x', venus, 27},
                      motion_case{"heldout103_26_rebound60px_3_5m_3_3mps_9_8rps_z_tsukuba", 60, 3.5,
                                  rebound, 0.5, 9.8, 'z', tsukuba, 37, 0.0, 3.3},
                      motion_case{"heldout103_27_left27px_2_2m_0_6x", 27, 2.2, pass_left, 0.6, 0.0,
                                  'z', procedural, 24},
                      motion_case{"heldout103_28_approach238px_2_4m_0_7x_2_0rps_y", 238, 2.4,
                                  approach, 0.7, 2.0, 'y', procedural, 32},
                      motion_case{"heldout103_29_enter89px_2_4m_0_7x_teddy", 89, 2.4, enter, 0.7,
                                  0.0, 'x', photo4, 30}),
    case_name);

// Held out with round 103: 20 balls whose depth changes (seed 203),
// committed with HeldOutSweep103 before they were run, under its rule.
// 15 pass and 5 fail (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutDepth103, BoxOnMotion,
    ::testing::Values(motion_case{"heldout103d_00_rebound21px_4_0m_1_1mps_kodim19", 21, 4.0,
                                  rebound, 1.0, 0.0, 'y', photo3, 24, 0.0, 1.1},
                      motion_case{"heldout103d_02_recede22px_3_5m_0_7x_6_4rps_y_kodim23", 22, 3.5,
                                  recede, 0.7, 6.4, 'y', photo2, 27},
                      motion_case{"heldout103d_03_rebound95px_4_5m_1_4mps_cones", 95, 4.5, rebound,
                                  1.0, 0.0, 'y', photo, 39, 0.0, 1.4},
                      motion_case{"heldout103d_04_recede90px_3_6m_1_8x_8_3rps_x", 90, 3.6, recede,
                                  1.8, 8.3, 'x', procedural, 28},
                      motion_case{"heldout103d_05_rebound63px_3_6m_1_8mps_cones", 63, 3.6, rebound,
                                  0.7, 0.0, 'y', photo, 25, 0.0, 1.8},
                      motion_case{"heldout103d_06_rebound92px_4_2m_1_1mps_tsukuba", 92, 4.2,
                                  rebound, 1.0, 0.0, 'x', tsukuba, 28, 0.0, 1.1},
                      motion_case{"heldout103d_07_recede230px_3_4m_2_1x_venus", 230, 3.4, recede,
                                  2.1, 0.0, 'y', venus, 33},
                      motion_case{"heldout103d_08_rebound42px_3_5m_2_5mps_8_4rps_x_aloe", 42, 3.5,
                                  rebound, 1.0, 8.4, 'x', aloe, 26, 0.0, 2.5},
                      motion_case{"heldout103d_11_approach27px_3_4m_0_4x_cones", 27, 3.4, approach,
                                  0.4, 0.0, 'x', photo, 37},
                      motion_case{"heldout103d_13_rebound34px_3_6m_3_8mps_kodim19", 34, 3.6,
                                  rebound, 0.9, 0.0, 'z', photo3, 24, 0.0, 3.8},
                      motion_case{"heldout103d_14_approach17px_2_5m_1_5x_venus", 17, 2.5, approach,
                                  1.5, 0.0, 'y', venus, 39},
                      motion_case{"heldout103d_15_rebound24px_3_9m_1_0mps_4_3rps_z_teddy", 24, 3.9,
                                  rebound, 0.4, 4.3, 'z', photo4, 39, 0.0, 1.0},
                      motion_case{"heldout103d_16_recede36px_3_1m_2_5x_6_4rps_x", 36, 3.1, recede,
                                  2.5, 6.4, 'x', procedural, 35},
                      motion_case{"heldout103d_17_recede19px_3_9m_1_1x_aloe", 19, 3.9, recede, 1.1,
                                  0.0, 'x', aloe, 35},
                      motion_case{"heldout103d_19_recede82px_3_0m_1_0x_7_4rps_z", 82, 3.0, recede,
                                  1.0, 7.4, 'z', procedural, 38}),
    case_name);

// Held out, round 104: 30 cases drawn at random (seed 104, rounds 94 and
// 95's envelope) and committed before they were run, with and without a
// wrong match's depth reported at the line of the track's last three
// (dsp/depth_line.h). Decision declared here: the rule replaces only a
// depth no motion of the ball reaches (over 6.25 % off that line), so on
// fresh cases it should change nothing or turn a fail into a pass. Kept
// only if, over this round and HeldOutDepth104 together, no case in the
// envelope (30 px a frame at most) passes without it and fails with it,
// and it passes at least as many; otherwise it is removed. Three of the 50
// moved faster (left out); of the other 47, 41 passed with the rule and 41
// without it, none either way: kept. Two pairs changed: one in the
// envelope, a 15 px ball going away (-67.28 -> 0.23 %, failing on the
// next pair's), and one of a 52 px throw at 61 px a frame (195.28 -> 2.12
// %). Of this round's 28, 26 pass and 2 fail (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep104, BoxOnMotion,
    ::testing::Values(motion_case{"heldout104_00_pass163px_3_5m_0_6x_7_4rps_x_kodim23", 163, 3.5,
                                  pass, 0.6, 7.4, 'x', photo2, 27},
                      motion_case{"heldout104_01_thrown17px_3_3m_0_8x_teddy", 17, 3.3, thrown, 0.8,
                                  0.0, 'x', photo4, 36},
                      motion_case{"heldout104_02_enter205px_2_3m_0_7x_5_0rps_x_teddy", 205, 2.3,
                                  enter, 0.7, 5.0, 'x', photo4, 29},
                      motion_case{"heldout104_03_orbit_near32px_2_0m_2_6x_2_5rps_z_venus", 32, 2.0,
                                  orbit_near, 2.6, 2.5, 'z', venus, 34},
                      motion_case{"heldout104_04_left34px_4_0m_0_5x_aloe", 34, 4.0, pass_left, 0.5,
                                  0.0, 'x', aloe, 39},
                      motion_case{"heldout104_05_orbit_far37px_2_2m_1_3x", 37, 2.2, orbit_far, 1.3,
                                  0.0, 'x', procedural, 36},
                      motion_case{"heldout104_06_pass19px_2_3m_1_7x_2_4rps_x_kodim23", 19, 2.3,
                                  pass, 1.7, 2.4, 'x', photo2, 31},
                      motion_case{"heldout104_07_left15px_3_2m_2_3x_aloe", 15, 3.2, pass_left, 2.3,
                                  0.0, 'z', aloe, 30},
                      motion_case{"heldout104_08_recede30px_3_7m_2_1x_aloe", 30, 3.7, recede, 2.1,
                                  0.0, 'z', aloe, 40},
                      motion_case{"heldout104_09_orbit_far70px_2_7m_2_2x_9_3rps_x_aloe", 70, 2.7,
                                  orbit_far, 2.2, 9.3, 'x', aloe, 38},
                      motion_case{"heldout104_10_left16px_3_2m_1_6x_teddy", 16, 3.2, pass_left, 1.6,
                                  0.0, 'z', photo4, 27},
                      motion_case{"heldout104_11_orbit_near109px_2_2m_1_1x_kodim19", 109, 2.2,
                                  orbit_near, 1.1, 0.0, 'y', photo3, 29},
                      motion_case{"heldout104_12_recede32px_2_4m_0_4x_3_1rps_x_cones", 32, 2.4,
                                  recede, 0.4, 3.1, 'x', photo, 30},
                      motion_case{"heldout104_13_orbit_far33px_2_5m_1_5x_aloe", 33, 2.5, orbit_far,
                                  1.5, 0.0, 'x', aloe, 30},
                      motion_case{"heldout104_14_approach12px_3_7m_0_7x_3_0rps_x", 12, 3.7,
                                  approach, 0.7, 3.0, 'x', procedural, 39},
                      motion_case{"heldout104_15_pass39px_2_4m_0_9x_aloe", 39, 2.4, pass, 0.9, 0.0,
                                  'z', aloe, 32},
                      motion_case{"heldout104_16_left177px_2_3m_0_8x_aloe", 177, 2.3, pass_left,
                                  0.8, 0.0, 'x', aloe, 24},
                      motion_case{"heldout104_17_thrown64px_2_9m_0_3x_8_9rps_x_kodim23", 64, 2.9,
                                  thrown, 0.3, 8.9, 'x', photo2, 29},
                      motion_case{"heldout104_19_left25px_3_1m_0_4x_7_2rps_x_teddy", 25, 3.1,
                                  pass_left, 0.4, 7.2, 'x', photo4, 27},
                      motion_case{"heldout104_22_circle163px_2_2m_1_3x_8_4rps_x_kodim19", 163, 2.2,
                                  circle, 1.3, 8.4, 'x', photo3, 25},
                      motion_case{"heldout104_23_enter18px_3_4m_0_3x_6_4rps_x_kodim19", 18, 3.4,
                                  enter, 0.3, 6.4, 'x', photo3, 26},
                      motion_case{"heldout104_24_rebound92px_3_8m_3_1mps", 92, 3.8, rebound, 0.4,
                                  0.0, 'z', procedural, 28, 0.0, 3.1},
                      motion_case{"heldout104_26_circle227px_2_2m_1_3x_teddy", 227, 2.2, circle,
                                  1.3, 0.0, 'y', photo4, 37},
                      motion_case{"heldout104_27_orbit_far126px_2_5m_1_1x_3_4rps_z", 126, 2.5,
                                  orbit_far, 1.1, 3.4, 'z', procedural, 36},
                      motion_case{"heldout104_28_enter90px_3_0m_2_0x_2_0rps_y_teddy", 90, 3.0,
                                  enter, 2.0, 2.0, 'y', photo4, 28},
                      motion_case{"heldout104_29_orbit_near32px_2_0m_1_1x_cones", 32, 2.0,
                                  orbit_near, 1.1, 0.0, 'y', photo, 25}),
    case_name);

// Held out with round 104: 20 balls whose depth changes (seed 204),
// committed with HeldOutSweep104 before they were run, under its rule.
// One moved faster (left out); of the other 19, 15 pass and 4 fail
// (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutDepth104, BoxOnMotion,
    ::testing::Values(motion_case{"heldout104d_02_rebound33px_3_7m_1_9mps_3_9rps_z_teddy", 33, 3.7,
                                  rebound, 0.5, 3.9, 'z', photo4, 28, 0.0, 1.9},
                      motion_case{"heldout104d_03_recede57px_3_5m_0_3x_aloe", 57, 3.5, recede, 0.3,
                                  0.0, 'z', aloe, 38},
                      motion_case{"heldout104d_04_recede37px_3_9m_0_4x_3_9rps_y_teddy", 37, 3.9,
                                  recede, 0.4, 3.9, 'y', photo4, 24},
                      motion_case{"heldout104d_07_rebound50px_4_1m_3_8mps", 50, 4.1, rebound, 0.9,
                                  0.0, 'z', procedural, 38, 0.0, 3.8},
                      motion_case{"heldout104d_08_approach95px_3_5m_1_5x_teddy", 95, 3.5, approach,
                                  1.5, 0.0, 'y', photo4, 37},
                      motion_case{"heldout104d_09_approach17px_2_7m_0_6x_3_5rps_x_kodim23", 17, 2.7,
                                  approach, 0.6, 3.5, 'x', photo2, 36},
                      motion_case{"heldout104d_10_rebound73px_3_7m_2_7mps_4_3rps_x_cones", 73, 3.7,
                                  rebound, 0.9, 4.3, 'x', photo, 30, 0.0, 2.7},
                      motion_case{"heldout104d_11_recede46px_3_8m_0_5x_aloe", 46, 3.8, recede, 0.5,
                                  0.0, 'y', aloe, 30},
                      motion_case{"heldout104d_12_recede196px_2_7m_2_9x_venus", 196, 2.7, recede,
                                  2.9, 0.0, 'z', venus, 24},
                      motion_case{"heldout104d_14_rebound47px_4_5m_3_8mps_7_7rps_z_tsukuba", 47,
                                  4.5, rebound, 0.4, 7.7, 'z', tsukuba, 38, 0.0, 3.8},
                      motion_case{"heldout104d_15_rebound74px_4_4m_3_2mps", 74, 4.4, rebound, 0.7,
                                  0.0, 'z', procedural, 35, 0.0, 3.2},
                      motion_case{"heldout104d_16_rebound36px_3_5m_2_1mps_aloe", 36, 3.5, rebound,
                                  0.6, 0.0, 'y', aloe, 32, 0.0, 2.1},
                      motion_case{"heldout104d_17_recede107px_2_3m_0_8x_5_1rps_x_tsukuba", 107, 2.3,
                                  recede, 0.8, 5.1, 'x', tsukuba, 40},
                      motion_case{"heldout104d_18_approach55px_2_2m_0_4x_9_3rps_z_tsukuba", 55, 2.2,
                                  approach, 0.4, 9.3, 'z', tsukuba, 36},
                      motion_case{"heldout104d_19_rebound63px_4_0m_1_7mps_6_4rps_x_kodim19", 63,
                                  4.0, rebound, 0.5, 6.4, 'x', photo3, 35, 0.0, 1.7}),
    case_name);

// Held out, round 105: 30 cases drawn at random (seed 105, rounds 94 and
// 95's envelope) and committed before they were run, with and without the
// pattern key's part of a size's depth (follow_slow_object: a key's box
// of the key's size stands for the key's depth; mutant fw-291 removes it),
// which on all 984 cases of stop 96 cost one case and gained none.
// Decision declared here: the part is removed only if, over this round and
// HeldOutDepth105 together, no case in the envelope (30 px a frame at
// most) passes with it and fails without it, and the firmware without it
// passes at least as many; otherwise it stays. Seven of the 50 moved
// faster (left out); of the other 43, 38 passed with the part and 38
// without it, none either way (one case's figures moved: a 44 px throw's
// box mean 1.63 -> 1.50 px): removed. Of this round's 28, 26 pass and 2
// fail (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutSweep105, BoxOnMotion,
    ::testing::Values(motion_case{"heldout105_00_orbit_near53px_2_8m_2_9x_7_9rps_y_teddy", 53, 2.8,
                                  orbit_near, 2.9, 7.9, 'y', photo4, 29},
                      motion_case{"heldout105_01_enter20px_3_8m_0_4x_9_4rps_y_venus", 20, 3.8,
                                  enter, 0.4, 9.4, 'y', venus, 38},
                      motion_case{"heldout105_02_approach168px_3_8m_0_6x_teddy", 168, 3.8, approach,
                                  0.6, 0.0, 'z', photo4, 40},
                      motion_case{"heldout105_03_back14px_2_7m_3_0x_kodim23", 14, 2.7, circle_back,
                                  3.0, 0.0, 'y', photo2, 36},
                      motion_case{"heldout105_05_left66px_2_7m_2_2x_aloe", 66, 2.7, pass_left, 2.2,
                                  0.0, 'x', aloe, 36},
                      motion_case{"heldout105_06_enter218px_3_2m_0_3x_1_5rps_x_tsukuba", 218, 3.2,
                                  enter, 0.3, 1.5, 'x', tsukuba, 37},
                      motion_case{"heldout105_07_approach124px_3_0m_0_5x_7_3rps_x_tsukuba", 124,
                                  3.0, approach, 0.5, 7.3, 'x', tsukuba, 33},
                      motion_case{"heldout105_08_back86px_3_3m_0_8x_8_8rps_x_cones", 86, 3.3,
                                  circle_back, 0.8, 8.8, 'x', photo, 39},
                      motion_case{"heldout105_09_thrown44px_3_2m_0_4x_kodim19", 44, 3.2, thrown,
                                  0.4, 0.0, 'y', photo3, 31},
                      motion_case{"heldout105_10_left159px_2_4m_4_9x_teddy", 159, 2.4, pass_left,
                                  4.9, 0.0, 'z', photo4, 32},
                      motion_case{"heldout105_11_left52px_3_4m_3_2x", 52, 3.4, pass_left, 3.2, 0.0,
                                  'y', procedural, 29},
                      motion_case{"heldout105_12_thrown117px_3_2m_0_3x_kodim19", 117, 3.2, thrown,
                                  0.3, 0.0, 'y', photo3, 35},
                      motion_case{"heldout105_13_enter36px_2_4m_1_8x_8_3rps_x_kodim19", 36, 2.4,
                                  enter, 1.8, 8.3, 'x', photo3, 32},
                      motion_case{"heldout105_14_left135px_2_1m_1_9x_9_7rps_z", 135, 2.1, pass_left,
                                  1.9, 9.7, 'z', procedural, 26},
                      motion_case{"heldout105_15_enter111px_2_2m_3_1x_aloe", 111, 2.2, enter, 3.1,
                                  0.0, 'z', aloe, 38},
                      motion_case{"heldout105_16_approach85px_2_3m_0_3x_teddy", 85, 2.3, approach,
                                  0.3, 0.0, 'x', photo4, 38},
                      motion_case{"heldout105_18_left62px_3_9m_2_6x_cones", 62, 3.9, pass_left, 2.6,
                                  0.0, 'z', photo, 36},
                      motion_case{"heldout105_19_pass205px_3_8m_1_7x_6_4rps_z_aloe", 205, 3.8, pass,
                                  1.7, 6.4, 'z', aloe, 27},
                      motion_case{"heldout105_21_approach52px_3_0m_0_6x_cones", 52, 3.0, approach,
                                  0.6, 0.0, 'y', photo, 39},
                      motion_case{"heldout105_22_rebound27px_4_2m_2_6mps_tsukuba", 27, 4.2, rebound,
                                  1.1, 0.0, 'y', tsukuba, 33, 0.0, 2.6},
                      motion_case{"heldout105_23_enter13px_2_7m_4_4x_6_3rps_y_aloe", 13, 2.7, enter,
                                  4.4, 6.3, 'y', aloe, 37},
                      motion_case{"heldout105_24_rebound35px_3_8m_1_0mps_8_3rps_z_venus", 35, 3.8,
                                  rebound, 1.0, 8.3, 'z', venus, 36, 0.0, 1.0},
                      motion_case{"heldout105_25_approach164px_3_6m_2_1x_tsukuba", 164, 3.6,
                                  approach, 2.1, 0.0, 'z', tsukuba, 25},
                      motion_case{"heldout105_26_left232px_2_0m_1_1x_2_2rps_y_kodim23", 232, 2.0,
                                  pass_left, 1.1, 2.2, 'y', photo2, 32},
                      motion_case{"heldout105_27_enter43px_2_2m_0_6x_3_5rps_y", 43, 2.2, enter, 0.6,
                                  3.5, 'y', procedural, 29},
                      motion_case{"heldout105_29_enter209px_2_4m_2_6x_aloe", 209, 2.4, enter, 2.6,
                                  0.0, 'y', aloe, 33}),
    case_name);

// Held out with round 105: 20 balls whose depth changes (seed 205),
// committed with HeldOutSweep105 before they were run, under its rule.
// Five moved faster (left out); of the other 15, 12 pass and 3 fail
// (DISABLED_Open).
INSTANTIATE_TEST_SUITE_P(
    HeldOutDepth105, BoxOnMotion,
    ::testing::Values(motion_case{"heldout105d_00_recede51px_2_2m_3_2x_7_3rps_z_kodim23", 51, 2.2,
                                  recede, 3.2, 7.3, 'z', photo2, 27},
                      motion_case{"heldout105d_01_rebound70px_3_7m_3_1mps_9_7rps_y", 70, 3.7,
                                  rebound, 1.1, 9.7, 'y', procedural, 40, 0.0, 3.1},
                      motion_case{"heldout105d_02_recede32px_3_5m_3_3x_1_7rps_y_kodim19", 32, 3.5,
                                  recede, 3.3, 1.7, 'y', photo3, 33},
                      motion_case{"heldout105d_03_rebound63px_4_0m_4_0mps_cones", 63, 4.0, rebound,
                                  0.9, 0.0, 'y', photo, 39, 0.0, 4.0},
                      motion_case{"heldout105d_04_approach30px_3_9m_2_1x_kodim19", 30, 3.9,
                                  approach, 2.1, 0.0, 'x', photo3, 27},
                      motion_case{"heldout105d_05_approach72px_3_6m_2_0x_4_8rps_z_venus", 72, 3.6,
                                  approach, 2.0, 4.8, 'z', venus, 24},
                      motion_case{"heldout105d_09_recede29px_3_1m_2_2x_1_2rps_z_cones", 29, 3.1,
                                  recede, 2.2, 1.2, 'z', photo, 29},
                      motion_case{"heldout105d_10_rebound50px_3_8m_2_0mps_4_1rps_x_venus", 50, 3.8,
                                  rebound, 0.8, 4.1, 'x', venus, 38, 0.0, 2.0},
                      motion_case{"heldout105d_13_approach38px_2_8m_0_5x_kodim23", 38, 2.8,
                                  approach, 0.5, 0.0, 'x', photo2, 25},
                      motion_case{"heldout105d_15_approach32px_3_2m_0_7x_kodim23", 32, 3.2,
                                  approach, 0.7, 0.0, 'z', photo2, 38},
                      motion_case{"heldout105d_17_recede200px_3_3m_3_3x_2_5rps_y_kodim19", 200, 3.3,
                                  recede, 3.3, 2.5, 'y', photo3, 40},
                      motion_case{"heldout105d_19_rebound22px_3_8m_2_3mps_venus", 22, 3.8, rebound,
                                  0.7, 0.0, 'y', venus, 34, 0.0, 2.3}),
    case_name);

}  // namespace
