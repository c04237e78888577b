#include "model/scene/trajectory.h"

#include <algorithm>
#include <cmath>

namespace scene {
namespace {

// Vertical position (down positive) after `tau` seconds of a bouncing throw.
double bouncing_y(double y0, double vy0, double g, double bounce_y, double restitution,
                  double tau) {
    double y = y0, vy = vy0, t = tau;
    // Bounded: each flight is either the last one or consumes its duration;
    // when the flights become shorter than a nanosecond the ball lies still.
    for (int bounce = 0; bounce < 10000; ++bounce) {
        // Time to reach the floor: y + vy s + g s^2 / 2 = bounce_y, s > 0.
        const double disc = vy * vy + 2.0 * g * (bounce_y - y);
        const double s = disc > 0.0 ? std::max(0.0, (-vy + std::sqrt(disc)) / g) : 0.0;
        if (t <= s) return y + vy * t + 0.5 * g * t * t;
        t -= s;
        const double impact = vy + g * s;  // > 0: moving down at contact
        y = bounce_y;
        vy = -restitution * impact;
        if (-vy * 2.0 / g < 1e-9) return bounce_y;
    }
    return bounce_y;
}

}  // namespace

trajectory trajectory::still(vec3 position) {
    trajectory t;
    t.type = kind::still;
    t.start = position;
    return t;
}

trajectory trajectory::line(vec3 start, vec3 velocity, double start_time_s) {
    trajectory t;
    t.type = kind::line;
    t.start = start;
    t.velocity = velocity;
    t.start_time_s = start_time_s;
    return t;
}

trajectory trajectory::circle(vec3 centre, double radius_m, vec3 axis_u, vec3 axis_v,
                              double angular_speed_rad_s, double phase_rad, double start_time_s) {
    trajectory t;
    t.type = kind::circle;
    t.circle_centre = centre;
    t.circle_radius_m = radius_m;
    t.axis_u = normalized(axis_u);
    // Orthonormalise v against u so the path is a true circle.
    t.axis_v = normalized(axis_v - t.axis_u * dot(axis_v, t.axis_u));
    t.angular_speed_rad_s = angular_speed_rad_s;
    t.phase_rad = phase_rad;
    t.start_time_s = start_time_s;
    return t;
}

trajectory trajectory::ballistic(vec3 start, vec3 velocity, double start_time_s, bool has_floor,
                                 double bounce_y_m, double restitution) {
    trajectory t;
    t.type = kind::ballistic;
    t.start = start;
    t.velocity = velocity;
    t.start_time_s = start_time_s;
    t.has_floor = has_floor;
    t.bounce_y_m = bounce_y_m;
    t.restitution = restitution;
    return t;
}

trajectory trajectory::rebound(vec3 start, vec3 velocity, double wall_z_m, double restitution,
                               double start_time_s) {
    trajectory t = line(start, velocity, start_time_s);
    t.type = kind::rebound;
    t.wall_z_m = wall_z_m;
    t.restitution = restitution;
    return t;
}

vec3 trajectory::position(double t_s) const {
    const double tau = elapsed(t_s);
    switch (type) {
        case kind::still:
            return start;
        case kind::line:
            return start + velocity * tau;
        case kind::rebound: {
            vec3 p = start + velocity * tau;
            if (velocity.z > 0.0 && p.z > wall_z_m) {
                const double contact_s = (wall_z_m - start.z) / velocity.z;
                p.z = wall_z_m - restitution * velocity.z * (tau - contact_s);
            }
            return p;
        }
        case kind::circle: {
            const double a = phase_rad + angular_speed_rad_s * tau;
            return circle_centre + axis_u * (circle_radius_m * std::cos(a)) +
                   axis_v * (circle_radius_m * std::sin(a));
        }
        case kind::ballistic: {
            vec3 p{start.x + velocity.x * tau, 0.0, start.z + velocity.z * tau};
            if (has_floor) {
                p.y = bouncing_y(start.y, velocity.y, gravity_m_s2, bounce_y_m, restitution, tau);
            } else {
                p.y = start.y + velocity.y * tau + 0.5 * gravity_m_s2 * tau * tau;
            }
            return p;
        }
    }
    return start;
}

}  // namespace scene
