// Closed-form image of a sphere in a pinhole camera, and the mean depth of
// its visible surface.
//
// A sphere (centre C, radius r) seen from a camera centre O projects to an
// ellipse. With C' = C - O = (X, Y, Z), k = |C'|^2 - r^2 and the ray
// d = (u, v, 1) through normalized image point (u, v) = ((x-cx)/f, (y-cy)/f),
// the ray meets the sphere iff Q(u, v) = (d.C')^2 - |d|^2 k >= 0: a conic.
// Its centre, bounding box and area in closed form:
//   centre  u0 = X Z / (Z^2 - r^2),  v0 = Y Z / (Z^2 - r^2)
//   extent  u = (X Z +- r sqrt(X^2 + Z^2 - r^2)) / (Z^2 - r^2)   (same in v with Y)
//   area    pi Q(u0, v0) / sqrt(det A),  A = [[Y^2+Z^2-r^2, -XY], [-XY, X^2+Z^2-r^2]]
// (times f, f, f^2 for pixels). The ellipse centre is NOT the projection of
// the sphere's centre, f X / Z: off axis they differ by f (X/Z) r^2 / (Z^2 - r^2).
// Valid only when the whole sphere is in front of the camera (Z > r).
#pragma once

#include "dsp/image.h"
#include "model/scene/camera.h"
#include "model/scene/geometry.h"

namespace scene {

struct sphere_image {
    bool valid = false;   // Z > r: the image is a bounded ellipse
    vec2 ellipse_centre;  // centre of the projected ellipse, px (= its area centroid)
    vec2 point_centre;    // projection of the sphere's centre point, px
    double min_x = 0.0, max_x = 0.0, min_y = 0.0, max_y = 0.0;  // ellipse bounding box, px
    double area_px = 0.0;                                       // ellipse area, px^2
    dsp::box pixel_box;         // pixels the ellipse touches, clipped to the image (may be empty)
    bool inside_image = false;  // the whole ellipse lies within the image's pixels
};

sphere_image project_sphere(const pinhole_camera& camera, vec3 centre, double radius);

// Mean depth (world Z, metres) of the sphere surface visible from the camera,
// weighted by projected image area, i.e. the mean Z of the first ray hit over
// the ellipse's (unclipped) image area: (1 / area) * integral of Z(x, y) dx dy.
// Far away and on axis this tends to Z_centre - 2/3 r; in general the 2/3 r
// lies along the line of sight, so Z_centre - Z_visible ~ r (2/3 cos(b) +
// r / (2 D)) for a centre at distance D, b off the optical axis (measured in
// tests/scene/test_visible_depth.cpp to within 0.005 r). Computed by product
// quadrature over the ellipse in the coordinates (psi, phi) with
// (u, v) = centre + sin(psi) (a1 cos(phi) e1 + a2 sin(phi) e2), where the
// square-root edge behaviour of Z becomes smooth (cos psi): Gauss-Legendre in
// psi, trapezoid (periodic) in phi; accurate to ~1e-12 relative.
// Returns 0 when the image is not valid (Z <= r).
double visible_mean_depth(const pinhole_camera& camera, vec3 centre, double radius);

// First intersection of the ray O + t d (t > 0) with the sphere; false if none.
bool intersect_sphere(vec3 origin, vec3 direction, vec3 centre, double radius, double* t);

}  // namespace scene
