// Ball trajectories against closed forms and a brute-force time-stepped
// simulation written here; the default scenario's promises (still start, 3D
// motion at 1-3 m, inside both views, large vertical change).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/scene/sequence.h"
#include "model/scene/trajectory.h"

namespace {

using scene::vec3;

constexpr double pi = 3.14159265358979323846;

double distance(vec3 a, vec3 b) {
    return scene::length(a - b);
}

TEST(Trajectory, StillAndLine) {
    const scene::trajectory s = scene::trajectory::still({0.1, 0.2, 2.0});
    EXPECT_EQ(distance(s.position(0.0), {0.1, 0.2, 2.0}), 0.0);
    EXPECT_EQ(distance(s.position(3.7), {0.1, 0.2, 2.0}), 0.0);

    const scene::trajectory l = scene::trajectory::line({0.1, 0.2, 2.0}, {0.5, -0.25, -1.0}, 0.5);
    EXPECT_EQ(distance(l.position(0.0), {0.1, 0.2, 2.0}),
              0.0);  // rests before its start
    EXPECT_EQ(distance(l.position(0.5), {0.1, 0.2, 2.0}), 0.0);
    EXPECT_LT(distance(l.position(1.3), {0.1 + 0.4, 0.2 - 0.2, 2.0 - 0.8}), 1e-15);
}

TEST(Trajectory, CircleInAVerticalPlane) {
    // A vertical circle facing the rig (in the X-Y plane) at 2 m, 1 turn per
    // second.
    const vec3 c{0.0, -0.1, 2.0};
    const scene::trajectory t =
        scene::trajectory::circle(c, 0.3, {1, 0, 0}, {0, 1, 0}, 2.0 * pi, 0.25 * pi, 0.2);
    double worst_radius = 0.0, worst_pos = 0.0;
    for (int i = 0; i <= 100; ++i) {
        const double time = 0.2 + i * 0.01;
        const vec3 p = t.position(time);
        worst_radius = std::max(worst_radius, std::fabs(distance(p, c) - 0.3));
        const double a = 0.25 * pi + 2.0 * pi * (time - 0.2);
        worst_pos = std::max(worst_pos,
                             distance(p, {c.x + 0.3 * std::cos(a), c.y + 0.3 * std::sin(a), c.z}));
    }
    std::printf("circle: worst |radius error| %.2e m, worst position error %.2e m\n", worst_radius,
                worst_pos);
    EXPECT_LT(worst_radius, 1e-12);
    EXPECT_LT(worst_pos, 1e-12);
    EXPECT_LT(distance(t.position(1.2), t.position(0.2)), 1e-12);  // one full turn
    EXPECT_LT(distance(t.position(0.0), t.position(0.2)),
              1e-15);  // rests before the start
    // A non-orthogonal second axis is orthonormalised: still a circle.
    const scene::trajectory skew = scene::trajectory::circle(c, 0.3, {1, 0, 0}, {1, 1, 1}, 1.0);
    EXPECT_NEAR(distance(skew.position(0.7), c), 0.3, 1e-12);
}

TEST(Trajectory, BallisticWithoutFloorIsAParabola) {
    const scene::trajectory t =
        scene::trajectory::ballistic({0.0, 0.0, 2.0}, {0.3, -3.0, -0.5}, 0.1);
    for (double time : {0.1, 0.2, 0.4, 0.9}) {
        const double tau = time - 0.1;
        const vec3 expected{0.3 * tau, -3.0 * tau + 0.5 * 9.81 * tau * tau, 2.0 - 0.5 * tau};
        EXPECT_LT(distance(t.position(time), expected), 1e-12) << time;
    }
    // Apex v^2 / 2g above the start, at t = v / g.
    const double apex_t = 0.1 + 3.0 / 9.81;
    EXPECT_NEAR(t.position(apex_t).y, -9.0 / (2.0 * 9.81), 1e-12);
}

// Brute force: velocity Verlet with a tiny step, reflecting the vertical
// speed (times the restitution) when the centre crosses the floor.
vec3 simulate_bounce(vec3 p, vec3 v, double g, double floor_y, double e, double duration) {
    const double dt = 1e-6;
    const long steps = static_cast<long>(duration / dt + 0.5);
    for (long i = 0; i < steps; ++i) {
        p = p + v * dt;
        p.y += 0.5 * g * dt * dt;
        v.y += g * dt;
        if (p.y > floor_y && v.y > 0.0) {
            p.y = floor_y - (p.y - floor_y) * e;  // reflect the overshoot
            v.y = -e * v.y;
        }
    }
    return p;
}

TEST(Trajectory, BouncingMatchesTimeSteppedSimulation) {
    const vec3 start{-0.3, 0.0, 2.6}, velocity{0.14, -2.0, -0.45};
    const double floor_y = 0.30, e = 0.8;
    const scene::trajectory t =
        scene::trajectory::ballistic(start, velocity, 0.0, true, floor_y, e);
    double worst = 0.0, lowest = -1e9;
    for (double time : {0.3, 0.55, 0.9, 1.4, 2.0}) {
        const vec3 ref = simulate_bounce(start, velocity, 9.81, floor_y, e, time);
        const double err = distance(t.position(time), ref);
        std::printf(
            "t = %.2f s: closed form (%.4f, %.4f, %.4f), simulation (%.4f, "
            "%.4f, %.4f), "
            "|diff| %.1e m\n",
            time, t.position(time).x, t.position(time).y, t.position(time).z, ref.x, ref.y, ref.z,
            err);
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-4) << time;
    }
    // Never below the floor, and apex heights shrink by e^2 per bounce.
    std::vector<double> apex;
    double prev_y = t.position(0.0).y, prev_dy = -1.0;
    for (int i = 1; i <= 300000; ++i) {
        const double y = t.position(i * 1e-5).y;
        lowest = std::max(lowest, y);
        const double dy = y - prev_y;
        if (prev_dy < 0.0 && dy >= 0.0) apex.push_back(prev_y);  // Y down: a minimum of Y
        prev_dy = dy;
        prev_y = y;
    }
    EXPECT_LE(lowest, floor_y + 1e-12);
    ASSERT_GE(apex.size(), 3u);
    for (size_t k = 1; k + 1 < apex.size() && k < 4; ++k) {
        const double ratio = (floor_y - apex[k + 1]) / (floor_y - apex[k]);
        std::printf("bounce %zu: apex height ratio %.5f (e^2 = %.5f)\n", k, ratio, e * e);
        EXPECT_NEAR(ratio, e * e, 1e-3);
    }
}

// A ball thrown against the wall behind the scene: time-stepped with the
// depth speed reflected (times the restitution) where the centre crosses the
// wall, and the contact and a later depth worked out by hand.
TEST(Trajectory, ReboundOffTheWallMatchesTimeSteppedSimulation) {
    const vec3 start{0.1, -0.05, 4.0}, velocity{0.5, 0.05, 2.0};
    const double wall_z = 4.8, e = 0.75, t0 = 0.05;
    const scene::trajectory t = scene::trajectory::rebound(start, velocity, wall_z, e, t0);
    EXPECT_LT(distance(t.position(0.0), start), 1e-12);  // rests before it starts
    // Contact 0.8 m / 2 m/s = 0.4 s after the start; 0.2 s later 0.3 m back.
    EXPECT_NEAR(t.position(t0 + 0.4).z, wall_z, 1e-12);
    EXPECT_NEAR(t.position(t0 + 0.6).z, 4.5, 1e-12);
    EXPECT_NEAR(t.position(t0 + 0.6).x, 0.1 + 0.5 * 0.6, 1e-12);
    for (double time : {0.2, 0.449, 0.451, 0.7, 1.5}) {
        vec3 p = start, v = velocity;
        const double dt = 1e-6;
        for (long i = 0; i < static_cast<long>((time - t0) / dt + 0.5); ++i) {
            p = p + v * dt;
            if (p.z > wall_z && v.z > 0.0) {
                p.z = wall_z - (p.z - wall_z) * e;
                v.z = -e * v.z;
            }
        }
        EXPECT_LT(distance(t.position(time), p), 1e-5) << time;
        EXPECT_LE(t.position(time).z, wall_z + 1e-12) << time;
    }
}

TEST(DefaultScenario, StillThenMovesIn3DInsideBothViews) {
    const int still = 6;
    const scene::scenario s = scene::default_scenario(still);
    const scene::sequence seq(s);
    EXPECT_DOUBLE_EQ(s.frame_period_s, 0.0245);
    ASSERT_EQ(s.scene.balls.size(), 1u);
    EXPECT_DOUBLE_EQ(s.scene.balls[0].radius_m, 0.05);
    const vec3 first = seq.truth(0)[0].centre_m;
    for (int n = 1; n < still; ++n) EXPECT_EQ(distance(seq.truth(n)[0].centre_m, first), 0.0) << n;
    EXPECT_GT(distance(seq.truth(still)[0].centre_m, first), 0.01);

    double min_z = 1e9, max_z = -1e9, min_y = 1e9, max_y = -1e9, max_speed_px = 0.0;
    double margin = 1e9;
    std::vector<double> speeds;
    scene::vec2 prev = seq.truth(0)[0].right.ellipse_centre;
    for (int n = 0; n < s.frame_count; ++n) {
        const scene::ball_truth t = seq.truth(n)[0];
        ASSERT_TRUE(t.in_both_views) << n;
        min_z = std::min(min_z, t.centre_m.z);
        max_z = std::max(max_z, t.centre_m.z);
        min_y = std::min(min_y, t.centre_m.y);
        max_y = std::max(max_y, t.centre_m.y);
        for (const scene::sphere_image* v : {&t.right, &t.left}) {
            margin =
                std::min({margin, v->min_x + 0.5, v->min_y + 0.5,
                          s.scene.rig.width - 0.5 - v->max_x, s.scene.rig.height - 0.5 - v->max_y});
        }
        const double speed =
            std::hypot(t.right.ellipse_centre.x - prev.x, t.right.ellipse_centre.y - prev.y);
        max_speed_px = std::max(max_speed_px, speed);
        if (n >= still) speeds.push_back(speed);
        prev = t.right.ellipse_centre;
        // Ground-truth disparities: the ellipse centres' differ from f b / Z by
        // the factor Z^2 / (Z^2 - r^2) (same Y, cameras side by side).
        const double z = t.centre_m.z, r = t.radius_m;
        EXPECT_NEAR(t.disparity_ellipse_px, t.disparity_centre_px * z * z / (z * z - r * r), 1e-9);
        EXPECT_NEAR(t.disparity_centre_px, s.scene.rig.focal_px() * 0.12 / z, 1e-9);
        EXPECT_GT(t.disparity_visible_px, t.disparity_centre_px);
    }
    std::sort(speeds.begin(), speeds.end());
    std::printf(
        "default scenario, %d frames: centre Z %.3f..%.3f m, Y "
        "%.3f..%.3f m, min margin "
        "to the image edges %.1f px, image speed median %.1f, max %.1f "
        "px/frame\n",
        s.frame_count, min_z, max_z, min_y, max_y, margin, speeds[speeds.size() / 2], max_speed_px);
    EXPECT_GE(min_z, 1.0);
    EXPECT_LE(max_z, 3.0);
    EXPECT_GT(max_z - min_z, 0.5);  // moves in depth
    EXPECT_GT(max_y - min_y, 0.3);  // significant vertical change
    EXPECT_GT(margin, 20.0);
    EXPECT_LT(max_speed_px, 30.0);
}

}  // namespace
