// A ball going away past the background plane: the truth says it is not in
// the views from the frame it touches the plane, and the renderer (its own
// ray against the plane, per sub-sample) agrees: while the truth says it is
// in front, the rendered ball is its whole ellipse; once it is wholly behind
// the plane, no sub-sample shows it.
#include <gtest/gtest.h>

#include <cstdio>

#include "model/scene/sequence.h"
#include "model/scene/trajectory.h"

namespace {

scene::scenario receding_through_the_background() {
    scene::scenario s;
    s.scene.background = scene::background_desc::procedural_plane({}, 5.0);
    scene::ball_desc ball;
    ball.radius_m = 0.2;
    // From 4.0 m straight away at 2 m a second: touches the plane at 4.8 m
    // (0.4 s: frame 17 at 24.5 ms a frame), wholly behind it from 5.2 m (frame 25).
    ball.path = scene::trajectory::line({0.0, 0.0, 4.0}, {0.0, 0.0, 2.0}, 0.0);
    s.scene.balls.push_back(ball);
    s.frame_count = 32;
    return s;
}

TEST(BallBehindBackground, NotInTheViewsFromWhereItTouchesThePlane) {
    const scene::sequence seq(receding_through_the_background());
    int in_front = 0, behind = 0;
    for (int n = 0; n < 32; n += 2) {
        const scene::stereo_frame f = seq.render(n);
        const scene::ball_truth& t = f.balls[0];
        const double near_side = t.centre_m.z - t.radius_m, far_side = t.centre_m.z + t.radius_m;
        std::printf("frame %2d: ball %.3f-%.3f m, truth in front %d, rendered %.0f of %.0f px2\n",
                    n, near_side, far_side, t.in_front_of_background, t.rendered_area_px,
                    t.right.area_px);
        EXPECT_EQ(t.in_front_of_background, far_side < 5.0) << n;
        EXPECT_EQ(t.in_both_views, t.in_front_of_background) << n;  // on the axis, in the images
        if (t.in_front_of_background) {
            ++in_front;
            EXPECT_NEAR(t.rendered_area_px, t.right.area_px, 0.01 * t.right.area_px) << n;
        }
        if (near_side > 5.0) {
            ++behind;
            EXPECT_EQ(t.rendered_subsamples, 0) << n;
        }
        // Wherever the renderer hides part of the ball, the truth says so.
        if (t.rendered_area_px < 0.99 * t.right.area_px) EXPECT_FALSE(t.in_front_of_background);
    }
    EXPECT_GE(in_front, 6);
    EXPECT_GE(behind, 3);
}

TEST(BallBehindBackground, NoPlaneNoLimit) {
    const scene::scenario s = receding_through_the_background();
    const scene::ball_truth t = scene::ball_truth_at(s.scene.rig, s.scene.balls[0], 0.6);
    EXPECT_GT(t.centre_m.z, 5.0);
    EXPECT_TRUE(t.in_front_of_background);  // no background depth given
    EXPECT_FALSE(
        scene::ball_truth_at(s.scene.rig, s.scene.balls[0], 0.6, 5.0).in_front_of_background);
}

}  // namespace
