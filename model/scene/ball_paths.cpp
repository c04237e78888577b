#include "model/scene/ball_paths.h"

#include <cmath>

namespace scene {

double motion_start_s(int still_frames, double frame_period_s) {
    return (still_frames > 0 ? still_frames - 1 : 0) * frame_period_s;
}

trajectory thrown_ball_path(double depth_m, double ball_radius_m, double speed, double start_s) {
    // Written so that a 5 cm ball bounces at exactly 0.30 m (docs/design-brief.md's default).
    const double bounce_y = 0.30 + (0.05 - ball_radius_m);
    trajectory path = trajectory::ballistic({-0.30, 0.0, depth_m},
                                            {0.14 * speed, -2.0 * speed, -0.45 * speed}, start_s,
                                            /*has_floor=*/true, bounce_y, /*restitution=*/0.8);
    path.gravity_m_s2 *= speed * speed;
    return path;
}

trajectory circling_path(double depth_m, double speed, double start_s) {
    const double pi = std::acos(-1.0);
    const double radius = 0.15 * depth_m, linear_speed = 0.41 * depth_m * speed;  // m, m/s
    return trajectory::circle({0.0, 0.0, depth_m}, radius, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0},
                              linear_speed / radius, pi, start_s);
}

trajectory line_path(double depth_m, double speed, double start_s) {
    return trajectory::line({-0.25, -0.05, depth_m}, {1.0 * speed, 0.1 * speed, 0.0}, start_s);
}

trajectory pass_path(double depth_m, double speed, double start_s) {
    return trajectory::line({-0.08 * depth_m, -0.02 * depth_m, depth_m},
                            {0.26 * depth_m * speed, 0.02 * depth_m * speed, 0.0}, start_s);
}

trajectory resting_path(double depth_m) {
    return trajectory::still({-0.30, 0.0, depth_m});
}

}  // namespace scene
