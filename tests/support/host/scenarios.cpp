#include "tests/support/host/scenarios.h"

#include <cmath>

#include "model/scene/ball_paths.h"

namespace host {

namespace {

// The default scene with one ball on `path`.
scene::scenario one_ball_scenario(const scene::trajectory& path, int frames,
                                  double radius_m = 0.05) {
    scene::scenario s;
    s.scene.background =
        scene::background_desc::procedural_plane(scene::procedural_texture_params{}, 5.0);
    scene::ball_desc ball;
    ball.radius_m = radius_m;  // docs/design-brief.md default ball: 0.05
    ball.path = path;
    s.scene.balls.push_back(ball);
    s.frame_count = frames;
    return s;
}

}  // namespace

double ball_radius_for_width(double diameter_px, double depth_m, double focal_px) {
    return diameter_px * depth_m / std::sqrt(4.0 * focal_px * focal_px + diameter_px * diameter_px);
}

scene::scenario static_scenario(int frames) {
    return one_ball_scenario(scene::resting_path(2.6), frames);
}

scene::scenario circling_scenario(double depth_m, int still_frames, int frames) {
    const double period = scene::scenario{}.frame_period_s;
    return one_ball_scenario(
        scene::circling_path(depth_m, /*speed=*/1.0, scene::motion_start_s(still_frames, period)),
        frames);
}

scene::scenario pass_scenario(double depth_m, double ball_radius_m, int still_frames, int frames) {
    const double period = scene::scenario{}.frame_period_s;
    return one_ball_scenario(
        scene::pass_path(depth_m, /*speed=*/1.0, scene::motion_start_s(still_frames, period)),
        frames, ball_radius_m);
}

scene::scenario exit_return_scenario(int still_frames) {
    const double period = scene::scenario{}.frame_period_s;
    const double radius = 0.5, speed = 1.2;  // m, m/s
    const double pi = std::acos(-1.0);
    // Phase pi: the leftmost point; increasing angle goes up (-Y) first.
    return one_ball_scenario(
        scene::trajectory::circle({0.7, 0.0, 2.5}, radius, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0},
                                  speed / radius, pi, scene::motion_start_s(still_frames, period)),
        still_frames + 110);
}

scene::scenario turntable_return_scenario() {
    const double period = scene::scenario{}.frame_period_s;
    const double radius_m = 0.5, speed_m_s = 0.25, pi = std::acos(-1.0);
    // From 20 degrees before the circle's nearest point (2.5 m), x = 0.85 + r sin a,
    // z = 3 - r cos a: rightwards and nearer, then out past the right edge.
    return one_ball_scenario(scene::trajectory::circle({0.85, 0.0, 3.0}, radius_m, {0.0, 0.0, -1.0},
                                                       {1.0, 0.0, 0.0}, speed_m_s / radius_m,
                                                       -pi / 9.0, scene::motion_start_s(3, period)),
                             255, 0.08);
}

namespace {

// The first ball on `first`, the second still at 2.4 m on the left until
// second_object_start_frame(), then to the right at 0.25 m/s.
scene::scenario first_then_new_object_scenario(const scene::trajectory& first) {
    const double period = scene::scenario{}.frame_period_s;
    scene::scenario s = one_ball_scenario(first, second_object_start_frame() + 40, 0.06);
    scene::ball_desc second = s.scene.balls.front();
    second.path = scene::trajectory::line({-0.5, 0.0, 2.4}, {0.25, 0.0, 0.0},
                                          second_object_start_frame() * period);
    s.scene.balls.push_back(second);
    return s;
}

}  // namespace

scene::scenario exit_then_new_object_scenario() {
    const double period = scene::scenario{}.frame_period_s;
    return first_then_new_object_scenario(scene::trajectory::line(
        {0.3, 0.05, 4.5}, {1.2, 0.0, 0.0}, scene::motion_start_s(3, period)));
}

scene::scenario vanish_then_new_object_scenario() {
    const double period = scene::scenario{}.frame_period_s;
    return first_then_new_object_scenario(scene::trajectory::line(
        {0.3, 0.05, 3.2}, {0.05, 0.0, 1.5}, scene::motion_start_s(3, period)));
}

scene::scenario dropped_then_new_object_scenario(bool second_moves) {
    const double period = scene::scenario{}.frame_period_s;
    scene::scenario s = first_then_new_object_scenario(scene::trajectory::ballistic(
        {0.3, -0.25, 3.0}, {0.0, 0.0, 0.0}, scene::motion_start_s(3, period), true, 0.2, 0.3));
    if (!second_moves) s.scene.balls.back().path = scene::trajectory::still({-0.5, 0.0, 2.4});
    return s;
}

scene::scenario dropped_then_speck_scenario() {
    scene::scenario s = dropped_then_new_object_scenario(true);
    s.scene.balls.back().radius_m = 0.004;
    return s;
}

scene::scenario slow_then_new_object_scenario() {
    const double period = scene::scenario{}.frame_period_s;
    return first_then_new_object_scenario(scene::trajectory::line(
        {0.0, 0.05, 3.0}, {0.07, 0.0, 0.0}, scene::motion_start_s(3, period)));
}

scene::scenario spinning_then_new_object_scenario() {
    scene::scenario s = first_then_new_object_scenario(scene::trajectory::still({0.3, 0.05, 3.0}));
    const double pi = std::acos(-1.0);
    s.scene.balls.front().spin_rad_s = 2.0 * 2.0 * pi;
    return s;
}

exit_return_frames exit_return_timing(const scene::sequence& sequence, int frames) {
    exit_return_frames f;
    for (int n = 0; n < frames; ++n) {
        const scene::sphere_image image = sequence.truth(n).front().right;
        const bool inside = image.valid && image.inside_image;
        const bool outside = !image.valid || image.pixel_box.empty();
        if (f.first_outside < 0) {
            if (inside) f.last_inside = n;
            if (outside) f.first_outside = n;
        } else if (f.first_inside_again < 0) {
            if (outside) f.last_outside = n;
            if (inside) f.first_inside_again = n;
        }
    }
    return f;
}

scene::scenario lighting_change_scenario(int change_frame, double gain, int ramp_frames,
                                         int frames) {
    scene::scenario s = static_scenario(frames);
    const double t0 = change_frame * s.frame_period_s;
    s.scene.light = ramp_frames > 0
                        ? scene::lighting::with_ramp(t0, t0 + ramp_frames * s.frame_period_s, gain)
                        : scene::lighting::with_step(t0, gain);
    return s;
}

}  // namespace host
