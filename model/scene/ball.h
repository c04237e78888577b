// A ball: a sphere of given radius on a trajectory, with a Lambertian,
// textured surface. The texture is fixed to the ball (a function of the
// normal in the ball's own frame), which turns at spin_rad_s about spin_axis
// once the trajectory has started.
//
// Radiance at a surface point with world normal n:
//   light_level * albedo * texture(R(t)^T n) * (ambient + (1 - ambient) max(0, n . L))
// or, unshaded (flat, for centroid tests), light_level * albedo * texture.
#pragma once

#include "model/scene/geometry.h"
#include "model/scene/texture.h"
#include "model/scene/trajectory.h"

namespace scene {

struct ball_material {
    // An orange ball; fully lit it reaches 0.7 * 255 = 179 levels in red, so
    // only the brightest texture spots (> 2.2 sigma) clip at 255.
    vec3 albedo{0.70, 0.35, 0.15};  // per-channel reflectance
    sphere_texture_params texture;
    bool shaded = true;
};

struct ball_desc {
    double radius_m = 0.05;  // docs/design-brief.md default ball radius
    ball_material material;
    trajectory path;
    vec3 spin_axis{0.0, 1.0, 0.0};  // unit
    double spin_rad_s = 0.0;

    // The ball's orientation (body to world) at time t.
    mat3 orientation(double t_s) const {
        return rotation_about(spin_axis, spin_rad_s * path.elapsed(t_s));
    }
};

}  // namespace scene
