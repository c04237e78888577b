// Several balls: the nearer one hides the farther one, the plane hides a ball
// behind it, and a spinning ball's texture turns with it. Visibility is
// checked against a brute-force ray cast written here on the same sub-sample
// grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/scene/renderer.h"
#include "model/scene/sphere_projection.h"

namespace {

using scene::vec3;

constexpr double pi = 3.14159265358979323846;

scene::ball_desc flat_ball(vec3 centre, vec3 albedo) {
    scene::ball_desc b;
    b.radius_m = 0.05;
    b.path = scene::trajectory::still(centre);
    b.material.albedo = albedo;
    b.material.texture.contrast = 0.0;
    b.material.shaded = false;
    return b;
}

// For every 4x4 sub-sample of the image, which sphere the ray meets first
// (before the plane): counts per sphere.
std::vector<long> brute_force_visible(const scene::pinhole_camera& cam,
                                      const std::vector<vec3>& centres, double r, double plane_z) {
    std::vector<long> counts(centres.size(), 0);
    const int n = 4;
    for (int py = 0; py < cam.height * n; ++py) {
        for (int px = 0; px < cam.width * n; ++px) {
            const double x = (px + 0.5) / n - 0.5, y = (py + 0.5) / n - 0.5;
            const vec3 d{(x - cam.cx) / cam.focal_px, (y - cam.cy) / cam.focal_px, 1.0};
            double best = plane_z;
            int hit = -1;
            for (size_t k = 0; k < centres.size(); ++k) {
                // |t d - c|^2 = r^2, smaller root.
                const double a = scene::dot(d, d), b = scene::dot(d, centres[k]);
                const double c = scene::dot(centres[k], centres[k]) - r * r;
                const double disc = b * b - a * c;
                if (disc < 0.0) continue;
                const double t = (b - std::sqrt(disc)) / a;
                if (t > 0.0 && t < best) {
                    best = t;
                    hit = static_cast<int>(k);
                }
            }
            if (hit >= 0) ++counts[static_cast<size_t>(hit)];
        }
    }
    return counts;
}

TEST(Occlusion, NearerBallHidesFartherPlaneHidesBallBehindIt) {
    scene::scene_desc d;
    d.background = scene::background_desc::uniform({0.0, 0.0, 0.0}, 3.0);
    const std::vector<vec3> centres = {
        {0.0, 0.0, 1.5},    // red, in front
        {0.04, 0.02, 2.0},  // green, partly behind the red one
        {-0.3, 0.0, 3.02},  // blue, centre behind the plane at 3 m: only its front cap shows
        {0.3, 0.1, 3.5},    // white, wholly behind the plane
    };
    d.balls = {flat_ball(centres[0], {1, 0, 0}), flat_ball(centres[1], {0, 1, 0}),
               flat_ball(centres[2], {0, 0, 1}), flat_ball(centres[3], {1, 1, 1})};
    const scene::renderer r(d);
    scene::rgb_image img;
    std::vector<scene::ball_render_stats> stats;
    r.render(scene::camera_id::right, 0.0, &img, nullptr, &stats);
    const std::vector<long> expected = brute_force_visible(d.rig.right(), centres, 0.05, 3.0);
    for (size_t k = 0; k < centres.size(); ++k) {
        std::printf(
            "ball %zu at Z %.2f m: rendered visible sub-samples %d, brute "
            "force %ld\n",
            k, centres[k].z, stats[k].visible_subsamples, expected[k]);
        EXPECT_NEAR(stats[k].visible_subsamples, expected[k], 2) << k;
    }
    EXPECT_GT(expected[1], 0);
    // The cap in front of the plane is a disc smaller than the ball's ellipse.
    const double full = scene::project_sphere(d.rig.right(), centres[2], 0.05).area_px * 16.0;
    std::printf("ball 2: %.0f of %.0f sub-samples of its ellipse poke through the plane\n",
                static_cast<double>(stats[2].visible_subsamples), full);
    EXPECT_GT(stats[2].visible_subsamples, 0);
    EXPECT_LT(stats[2].visible_subsamples, 0.9 * full);
    EXPECT_EQ(stats[3].visible_subsamples, 0);
    // Pure colours: no green where red covers a whole pixel, nothing white at
    // all.
    long red_pixels = 0, green_under_red = 0, white = 0;
    for (const dsp::rgb8& p : img.pixels) {
        red_pixels += p.r == 255;
        green_under_red += p.r == 255 && p.g > 0;
        white += p.r > 0 && p.g > 0 && p.b > 0;
    }
    EXPECT_GT(red_pixels, 1000);
    EXPECT_EQ(green_under_red, 0);
    EXPECT_EQ(white, 0);
}

TEST(Occlusion, SpinningBallTurnsItsTexture) {
    scene::scene_desc d;
    d.background = scene::background_desc::uniform({0.0, 0.0, 0.0}, 5.0);
    scene::ball_desc b;
    b.radius_m = 0.05;
    b.path = scene::trajectory::line({0.0, 0.0, 1.0}, {0.0, 0.0, 0.0},
                                     0.0);  // still, started
    b.spin_axis = scene::normalized(vec3{0.2, 1.0, 0.1});
    b.spin_rad_s = 2.0 * pi;  // one turn per second
    d.balls.push_back(b);
    const scene::renderer r(d);
    scene::rgb_image at0, at_quarter, at_turn;
    r.render(scene::camera_id::right, 0.0, &at0);
    r.render(scene::camera_id::right, 0.25, &at_quarter);
    r.render(scene::camera_id::right, 1.0, &at_turn);
    int quarter_diff = 0, turn_diff = 0;
    for (size_t i = 0; i < at0.pixels.size(); ++i) {
        quarter_diff = std::max(quarter_diff, std::abs(at0.pixels[i].r - at_quarter.pixels[i].r));
        turn_diff = std::max(turn_diff, std::abs(at0.pixels[i].r - at_turn.pixels[i].r));
    }
    std::printf(
        "spin: max red difference after a quarter turn %d, after a full "
        "turn %d\n",
        quarter_diff, turn_diff);
    EXPECT_GT(quarter_diff, 20);
    EXPECT_LE(turn_diff, 1);
}

}  // namespace
