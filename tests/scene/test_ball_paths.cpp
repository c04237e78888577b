// scene::pass_path (model/scene/ball_paths.h) against its documented figures,
// worked out by hand with the pinhole model u = cx + f X / Z (f = 6 mm / 7.6 um
// = 789.47 px, cx = 319.5, cy = 239.5): the start 0.08 f = 63.16 px left of and
// 0.02 f = 15.79 px above the image centre at any depth; per 24.5 ms frame
// 0.26 x 0.0245 x f = 5.03 px right and 0.02 x 0.0245 x f = 0.387 px down.
#include <gtest/gtest.h>

#include <cmath>

#include "model/scene/ball_paths.h"
#include "model/scene/camera.h"
#include "model/scene/sphere_projection.h"

namespace {

constexpr double frame_s = 0.0245;

TEST(BallPaths, PassLooksTheSameAtAnyDepth) {
    const scene::stereo_rig rig;
    const scene::pinhole_camera right = rig.right();
    for (const double depth_m : {1.0, 1.4, 2.6, 4.0}) {
        const scene::trajectory path = scene::pass_path(depth_m, 1.0, 0.0);
        const scene::vec2 start = right.project(path.position(0.0));
        EXPECT_NEAR(start.x, 319.5 - 63.158, 1e-3) << depth_m;
        EXPECT_NEAR(start.y, 239.5 - 15.789, 1e-3) << depth_m;
        const scene::vec2 next = right.project(path.position(frame_s));
        EXPECT_NEAR(next.x - start.x, 5.029, 1e-3) << depth_m;
        EXPECT_NEAR(next.y - start.y, 0.387, 1e-3) << depth_m;
        EXPECT_DOUBLE_EQ(path.position(frame_s).z, depth_m);
    }
    // Twice the speed: the same line in half the time.
    const scene::trajectory fast = scene::pass_path(2.0, 2.0, 0.0);
    const scene::trajectory slow = scene::pass_path(2.0, 1.0, 0.0);
    EXPECT_NEAR(fast.position(frame_s).x, slow.position(2 * frame_s).x, 1e-12);
}

// What the path is for: a ball half the image wide (320 px at 1.4 m) stays
// wholly inside the view for 30 frames of the pass.
TEST(BallPaths, HalfImageWideBallStaysInViewForThirtyFrames) {
    const scene::stereo_rig rig;
    const double depth_m = 1.4, focal = rig.focal_px();
    const double radius_m = 320.0 * depth_m / std::sqrt(4.0 * focal * focal + 320.0 * 320.0);
    const scene::trajectory path = scene::pass_path(depth_m, 1.0, 0.0);
    for (int n = 0; n < 30; ++n) {
        const scene::sphere_image image =
            scene::project_sphere(rig.right(), path.position(n * frame_s), radius_m);
        ASSERT_TRUE(image.valid) << n;
        EXPECT_TRUE(image.inside_image) << n;
        EXPECT_NEAR(image.max_x - image.min_x, 320.0, 2.0) << n;  // the tangent cone's width
    }
}

}  // namespace
