// Pinhole projection, disparity and the closed-form sphere image against
// plain formulas and brute force written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/scene/camera.h"
#include "model/scene/sphere_projection.h"

namespace {

using scene::vec3;

constexpr double pi = 3.14159265358979323846;
// docs/design-brief.md default rig: 6 mm lens / 7.6 um pitch, 120 mm baseline, VGA.
constexpr double f_px = 0.006 / 7.6e-6;
constexpr double baseline = 0.120;

TEST(Projection, DefaultRigNumbers) {
    const scene::stereo_rig rig;
    EXPECT_NEAR(rig.focal_px(), 789.4736842105263, 1e-9);
    EXPECT_DOUBLE_EQ(rig.cx_right(), 319.5);
    EXPECT_DOUBLE_EQ(rig.cy_right(), 239.5);
    EXPECT_DOUBLE_EQ(rig.cx_left(), 319.5);
    EXPECT_DOUBLE_EQ(rig.cy_left(), 239.5);
    EXPECT_DOUBLE_EQ(rig.left().centre.x, -0.120);
    const dsp::camera_rig d = scene::to_dsp_rig(rig);
    EXPECT_EQ(d.baseline_um, 120000);
    EXPECT_EQ(d.focal_length_um, 6000);
    EXPECT_EQ(d.pixel_pitch_nm, 7600);
    EXPECT_EQ(d.cx_right_q8, 320 * 256 - 128);
    EXPECT_EQ(d.cy_left_q8, 240 * 256 - 128);
    const dsp::point3_um p = scene::to_point3_um({0.1234564, -0.5, 2.0000006});
    EXPECT_EQ(p.x, 123456);
    EXPECT_EQ(p.y, -500000);
    EXPECT_EQ(p.z, 2000001);
}

TEST(Projection, PointsAndDisparityMatchPinholeFormulas) {
    scene::stereo_rig rig;
    rig.principal_dx_left = 1.25;  // a non-centred left principal point shifts disparity
    rig.principal_dy_left = -0.5;
    const double cxl = 319.5 + 1.25, cyl = 239.5 - 0.5;
    double worst = 0.0;
    int count = 0;
    for (double z = 0.5; z <= 6.0; z += 0.25) {
        for (double x = -1.0; x <= 1.0; x += 0.125) {
            for (double y = -0.75; y <= 0.75; y += 0.125) {
                const scene::vec2 r = rig.right().project({x, y, z});
                const scene::vec2 l = rig.left().project({x, y, z});
                const double exp_xr = 319.5 + f_px * x / z, exp_yr = 239.5 + f_px * y / z;
                const double exp_xl = cxl + f_px * (x + baseline) / z, exp_yl = cyl + f_px * y / z;
                worst = std::max({worst, std::fabs(r.x - exp_xr), std::fabs(r.y - exp_yr),
                                  std::fabs(l.x - exp_xl), std::fabs(l.y - exp_yl)});
                const double d = l.x - r.x;
                const double exp_d = f_px * baseline / z + 1.25;
                worst = std::max(worst, std::fabs(d - exp_d));
                worst = std::max(worst, std::fabs(rig.disparity_px(z) - exp_d));
                worst = std::max(worst, std::fabs(rig.depth_m(exp_d) - z));
                ++count;
            }
        }
    }
    std::printf("points: %d, worst |error| vs closed form %.3g px\n", count, worst);
    EXPECT_LT(worst, 1e-9);
    // The rays back-project: the ray through the projection passes through the
    // point.
    const vec3 p{0.3, -0.2, 1.7};
    const scene::vec2 xy = rig.right().project(p);
    const vec3 d = rig.right().ray_direction(xy.x, xy.y);
    EXPECT_NEAR(d.x * p.z, p.x, 1e-12);
    EXPECT_NEAR(d.y * p.z, p.y, 1e-12);
}

// The sphere's limb (the circle of tangent points seen from the camera)
// projected point by point: its extreme x and y are the ellipse's bounding
// box, and their midpoints its centre (an ellipse is centrally symmetric).
struct limb_extent {
    double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
};

limb_extent project_limb(const scene::pinhole_camera& cam, vec3 c, double r) {
    const vec3 to_cam = cam.centre - c;
    const double dist = scene::length(to_cam);
    const vec3 w = to_cam * (1.0 / dist);
    const vec3 helper = std::fabs(w.x) < 0.9 ? vec3{1, 0, 0} : vec3{0, 1, 0};
    const vec3 e1 = scene::normalized(scene::cross(w, helper));
    const vec3 e2 = scene::cross(w, e1);
    // Tangent points P: (P - C).(O - C) = r^2.
    const vec3 circle_centre = c + w * (r * r / dist);
    const double circle_radius = r * std::sqrt(1.0 - r * r / (dist * dist));
    limb_extent e;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * pi * i / n;
        const vec3 p = circle_centre + (e1 * std::cos(a) + e2 * std::sin(a)) * circle_radius;
        const scene::vec2 q = cam.project(p);
        e.min_x = std::min(e.min_x, q.x);
        e.max_x = std::max(e.max_x, q.x);
        e.min_y = std::min(e.min_y, q.y);
        e.max_y = std::max(e.max_y, q.y);
    }
    return e;
}

// Area and area centroid of the set of pixels-plane points whose ray hits the
// sphere, on a fine grid of rays.
struct grid_moments {
    double area = 0.0, cx = 0.0, cy = 0.0;
};

grid_moments ray_grid(const scene::pinhole_camera& cam, vec3 c, double r, const limb_extent& e,
                      double step) {
    double n = 0.0, sx = 0.0, sy = 0.0;
    for (double y = std::floor(e.min_y) - 1.0 + 0.5 * step; y < e.max_y + 1.0; y += step) {
        for (double x = std::floor(e.min_x) - 1.0 + 0.5 * step; x < e.max_x + 1.0; x += step) {
            const vec3 d{(x - cam.cx) / cam.focal_px, (y - cam.cy) / cam.focal_px, 1.0};
            const vec3 oc = c - cam.centre;
            const double b = scene::dot(d, oc);
            if (b * b - scene::dot(d, d) * (scene::dot(oc, oc) - r * r) >= 0.0) {
                n += 1.0;
                sx += x;
                sy += y;
            }
        }
    }
    return {n * step * step, sx / n, sy / n};
}

struct sphere_case {
    const char* name;
    vec3 direction;  // from the camera, unnormalized
    double distance_m;
    double radius_m;
};

TEST(Projection, SphereEllipseMatchesLimbAndRayGrid) {
    const scene::stereo_rig rig;
    const double tan20 = std::tan(20.0 * pi / 180.0);
    // 20 degrees off axis along the image diagonal (4:3), and the extremes of the
    // ranges.
    const sphere_case cases[] = {
        {"on axis 2 m r5cm", {0, 0, 1}, 2.0, 0.05},
        {"on axis 1 m r5cm", {0, 0, 1}, 1.0, 0.05},
        {"20deg diag 1 m r5cm", {0.8 * tan20, 0.6 * tan20, 1}, 1.0, 0.05},
        {"20deg x 2.5 m r5cm", {tan20, 0, 1}, 2.5, 0.05},
        {"-15deg x 3 m r5cm", {-std::tan(15.0 * pi / 180.0), 0, 1}, 3.0, 0.05},
        {"up-left 0.6 m r5cm", {-0.2, -0.15, 1}, 0.6, 0.05},
    };
    for (scene::camera_id id : {scene::camera_id::right, scene::camera_id::left}) {
        const scene::pinhole_camera cam = rig.camera(id);
        for (const sphere_case& sc : cases) {
            const vec3 c = cam.centre + scene::normalized(sc.direction) * sc.distance_m;
            const scene::sphere_image si = scene::project_sphere(cam, c, sc.radius_m);
            ASSERT_TRUE(si.valid);
            const limb_extent e = project_limb(cam, c, sc.radius_m);
            const double box_err =
                std::max({std::fabs(si.min_x - e.min_x), std::fabs(si.max_x - e.max_x),
                          std::fabs(si.min_y - e.min_y), std::fabs(si.max_y - e.max_y)});
            const double centre_err = std::hypot(si.ellipse_centre.x - 0.5 * (e.min_x + e.max_x),
                                                 si.ellipse_centre.y - 0.5 * (e.min_y + e.max_y));
            const grid_moments g = ray_grid(cam, c, sc.radius_m, e, 0.05);
            const double grid_centre_err =
                std::hypot(si.ellipse_centre.x - g.cx, si.ellipse_centre.y - g.cy);
            const double area_rel = std::fabs(si.area_px - g.area) / si.area_px;
            const double point_vs_ellipse = std::hypot(si.ellipse_centre.x - si.point_centre.x,
                                                       si.ellipse_centre.y - si.point_centre.y);
            std::printf(
                "%-5s %-22s centre (%.3f, %.3f) bbox err %.2e px, centre vs "
                "limb %.2e px, vs ray "
                "grid %.2e px, area %.1f px2 (grid rel err %.1e), |ellipse - "
                "point proj| %.3f px\n",
                id == scene::camera_id::left ? "left" : "right", sc.name, si.ellipse_centre.x,
                si.ellipse_centre.y, box_err, centre_err, grid_centre_err, si.area_px, area_rel,
                point_vs_ellipse);
            EXPECT_LT(box_err, 1e-6);
            EXPECT_LT(centre_err, 1e-6);
            EXPECT_LT(grid_centre_err, 2e-3);
            EXPECT_LT(area_rel, 2e-3);
            // Closed form spelled out once more: u0 = X Z / (Z^2 - r^2).
            const vec3 cc = c - cam.centre;
            const double zz = cc.z * cc.z - sc.radius_m * sc.radius_m;
            EXPECT_NEAR(si.ellipse_centre.x, cam.cx + cam.focal_px * cc.x * cc.z / zz, 1e-9);
            EXPECT_NEAR(si.point_centre.x, cam.cx + cam.focal_px * cc.x / cc.z, 1e-9);
        }
    }
}

TEST(Projection, PixelBoxCoversEllipseAndClips) {
    const scene::stereo_rig rig;
    const scene::pinhole_camera cam = rig.right();
    const scene::sphere_image si = scene::project_sphere(cam, {0.0, 0.0, 2.0}, 0.05);
    // Pixel i covers [i - 0.5, i + 0.5): the box starts at the pixel holding
    // min_x.
    EXPECT_EQ(si.pixel_box.x, static_cast<int>(std::floor(si.min_x + 0.5)));
    EXPECT_EQ(si.pixel_box.right() - 1, static_cast<int>(std::floor(si.max_x + 0.5)));
    EXPECT_TRUE(si.inside_image);
    // Radius on the image f r / sqrt(Z^2 - r^2) on axis.
    const double radius_px = f_px * 0.05 / std::sqrt(4.0 - 0.0025);
    EXPECT_NEAR(si.max_x - si.ellipse_centre.x, radius_px, 1e-9);
    EXPECT_NEAR(si.area_px, pi * radius_px * radius_px, 1e-6);
    // Half out of the image: clipped box, not inside.
    const scene::sphere_image edge = scene::project_sphere(cam, {-0.81, 0.0, 2.0}, 0.05);
    EXPECT_FALSE(edge.inside_image);
    EXPECT_EQ(edge.pixel_box.x, 0);
    EXPECT_GT(edge.pixel_box.width, 0);
    // Behind or around the camera: not a bounded ellipse.
    EXPECT_FALSE(scene::project_sphere(cam, {0.0, 0.0, 0.04}, 0.05).valid);
    EXPECT_FALSE(scene::project_sphere(cam, {0.0, 0.0, -1.0}, 0.05).valid);
}

}  // namespace
