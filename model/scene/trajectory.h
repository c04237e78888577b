// A ball's path: its centre (world frame, metres) as a function of time
// (seconds). Before start_time_s the ball rests where the path starts, so a
// scenario can hold it still for a few frames and then set it moving.
//
// Kinds (make them with the factory functions):
// - still:     p(t) = start.
// - line:      p(t) = start + velocity * (t - t0).
// - circle:    p(t) = centre + R (cos(a) axis_u + sin(a) axis_v),
//              a = phase + angular_speed * (t - t0); axis_u, axis_v are
//              orthonormal, so any plane (including a vertical one) works.
// - ballistic: thrown from start with velocity under gravity g along +Y
//              (world Y points down); with a floor it bounces where the
//              CENTRE reaches Y = bounce_y (floor plane Y minus the radius),
//              the vertical speed reversed and scaled by the restitution;
//              horizontal motion continues unchanged; the throw must start
//              at or above the floor (start.y <= bounce_y). Closed form per flight
//              (no time stepping): exact to rounding at any t.
// - rebound:   a line towards a wall facing the rig (a ball thrown against
//              the wall behind the scene): where the CENTRE reaches
//              Z = wall_z (the wall's Z minus the radius) the depth speed is
//              reversed and scaled by the restitution, X and Y go on; the
//              line must start in front of the wall (start.z <= wall_z).
#pragma once

#include "model/scene/geometry.h"

namespace scene {

struct trajectory {
    enum class kind { still, line, circle, ballistic, rebound };

    kind type = kind::still;
    double start_time_s = 0.0;
    vec3 start;     // still / line / ballistic / rebound: position at start_time_s
    vec3 velocity;  // line: constant; ballistic, rebound: initial, m/s

    vec3 circle_centre;
    vec3 axis_u{1.0, 0.0, 0.0};
    vec3 axis_v{0.0, 1.0, 0.0};
    double circle_radius_m = 0.0;
    double angular_speed_rad_s = 0.0;
    double phase_rad = 0.0;

    double gravity_m_s2 = 9.81;  // standard gravity, along +Y
    bool has_floor = false;
    double bounce_y_m = 0.0;   // centre Y at contact
    double restitution = 0.7;  // speed across the floor or wall kept at each bounce
    double wall_z_m = 0.0;     // rebound: centre Z at contact

    static trajectory still(vec3 position);
    static trajectory line(vec3 start, vec3 velocity, double start_time_s = 0.0);
    static trajectory circle(vec3 centre, double radius_m, vec3 axis_u, vec3 axis_v,
                             double angular_speed_rad_s, double phase_rad = 0.0,
                             double start_time_s = 0.0);
    // A throw from `start` with `velocity`; bounces at bounce_y_m if has_floor.
    static trajectory ballistic(vec3 start, vec3 velocity, double start_time_s = 0.0,
                                bool has_floor = false, double bounce_y_m = 0.0,
                                double restitution = 0.7);
    // A line from `start` with `velocity` that bounces back off the wall at wall_z_m.
    static trajectory rebound(vec3 start, vec3 velocity, double wall_z_m, double restitution,
                              double start_time_s = 0.0);

    vec3 position(double t_s) const;
    // Time since the motion started (0 before it).
    double elapsed(double t_s) const { return t_s > start_time_s ? t_s - start_time_s : 0.0; }
};

}  // namespace scene
