// The rendered ball's centroid against the closed-form ellipse centre.
// Pixel intensities are measured with OpenCV's moments (an independent
// centroid); pixel-index coordinates in both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "model/scene/renderer.h"
#include "model/scene/sequence.h"
#include "model/scene/sphere_projection.h"

namespace {

using scene::vec3;

constexpr double pi = 3.14159265358979323846;

cv::Mat red_channel(const scene::rgb_image& img) {
    cv::Mat m(img.height, img.width, CV_8UC1);
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) m.at<uint8_t>(y, x) = img.at(x, y).r;
    }
    return m;
}

cv::Mat as_mat(const scene::gray_image& img) {
    return cv::Mat(img.height, img.width, CV_8UC1, const_cast<uint8_t*>(img.pixels.data())).clone();
}

scene::vec2 centroid(const cv::Mat& m) {
    const cv::Moments mo = cv::moments(m, false);
    return {mo.m10 / mo.m00, mo.m01 / mo.m00};
}

// A ball `distance` metres from the camera `id` along `direction`.
scene::scene_desc ball_scene(scene::camera_id id, vec3 direction, double distance, bool flat) {
    scene::scene_desc d;
    d.background = scene::background_desc::uniform({0.0, 0.0, 0.0}, 5.0);
    scene::ball_desc b;
    b.radius_m = 0.05;
    b.path =
        scene::trajectory::still(d.rig.camera(id).centre + scene::normalized(direction) * distance);
    if (flat) {
        // Uniform white disc: the intensity is 255 times the covered fraction.
        b.material.albedo = {1.0, 1.0, 1.0};
        b.material.texture.contrast = 0.0;
        b.material.shaded = false;
    }
    d.balls.push_back(b);
    return d;
}

struct centroid_case {
    const char* name;
    vec3 direction;
    double distance_m;
};

TEST(BallCentroid, WithinQuarterPixelOfEllipseCentre) {
    const double tan20 = std::tan(20.0 * pi / 180.0);
    const centroid_case cases[] = {
        {"on axis, 2 m", {0, 0, 1}, 2.0},
        {"on axis, 1 m", {0, 0, 1}, 1.0},
        // 20 degrees off the camera's axis along the image diagonal (4:3), so
        // the whole ellipse stays inside the 640 x 480 image.
        {"20 deg off axis (diagonal), 1 m", {0.8 * tan20, 0.6 * tan20, 1}, 1.0},
        {"20 deg off axis (diagonal), 2 m", {0.8 * tan20, 0.6 * tan20, 1}, 2.0},
        {"20 deg off axis (left), 2.5 m", {-tan20, 0, 1}, 2.5},
        {"20 deg off axis (up-left), 1.2 m", {-0.8 * tan20, -0.6 * tan20, 1}, 1.2},
    };
    double worst_flat = 0.0, worst_mask = 0.0, worst_point = 0.0;
    for (scene::camera_id id : {scene::camera_id::right, scene::camera_id::left}) {
        const char* cam_name = id == scene::camera_id::left ? "left" : "right";
        for (const centroid_case& c : cases) {
            const scene::renderer flat(ball_scene(id, c.direction, c.distance_m, true));
            const scene::renderer textured(ball_scene(id, c.direction, c.distance_m, false));
            const scene::ball_desc& ball = flat.desc().balls[0];
            const scene::sphere_image si = scene::project_sphere(
                flat.desc().rig.camera(id), ball.path.position(0.0), ball.radius_m);
            ASSERT_TRUE(si.inside_image) << c.name;

            scene::rgb_image img, img_textured;
            scene::gray_image coverage;
            flat.render(id, 0.0, &img);
            textured.render(id, 0.0, &img_textured, &coverage);
            const scene::vec2 flat_c = centroid(red_channel(img));
            const scene::vec2 mask_c = centroid(as_mat(coverage));
            const double flat_err =
                std::hypot(flat_c.x - si.ellipse_centre.x, flat_c.y - si.ellipse_centre.y);
            const double mask_err =
                std::hypot(mask_c.x - si.ellipse_centre.x, mask_c.y - si.ellipse_centre.y);
            const double point_err =
                std::hypot(flat_c.x - si.point_centre.x, flat_c.y - si.point_centre.y);
            std::printf(
                "%-5s %-34s ellipse centre (%8.3f, %8.3f): |flat render "
                "centroid - centre| %.4f "
                "px, |textured coverage-mask centroid - centre| %.4f px, "
                "|centroid - projected "
                "3D centre| %.4f px\n",
                cam_name, c.name, si.ellipse_centre.x, si.ellipse_centre.y, flat_err, mask_err,
                point_err);
            EXPECT_LT(flat_err, 0.25) << cam_name << " " << c.name;
            EXPECT_LT(mask_err, 0.25) << cam_name << " " << c.name;
            worst_flat = std::max(worst_flat, flat_err);
            worst_mask = std::max(worst_mask, mask_err);
            worst_point = std::max(worst_point, point_err);

            // The rendered area (sum of coverage) matches the closed-form area.
            const double area = cv::sum(as_mat(coverage))[0] / 255.0;
            EXPECT_NEAR(area, si.area_px, 0.01 * si.area_px) << cam_name << " " << c.name;
        }
    }
    std::printf(
        "worst centroid error: flat %.4f px, coverage mask %.4f px; "
        "worst distance to "
        "the projected 3D centre %.4f px\n",
        worst_flat, worst_mask, worst_point);
    // The test can tell the ellipse centre from the naive projection of the
    // sphere's centre: close and off axis they differ by more than the tolerance.
    EXPECT_GT(worst_point, 0.5);
}

TEST(BallCentroid, FlatDiscIntensityIsCoverage) {
    // With a flat white ball on black the pixel value is 255 * covered fraction
    // quantized to 1/16: the total intensity is the ellipse area.
    const scene::renderer r(ball_scene(scene::camera_id::right, {0, 0, 1}, 1.5, true));
    scene::rgb_image img;
    r.render(scene::camera_id::right, 0.0, &img);
    const scene::sphere_image si = scene::project_sphere(r.desc().rig.right(), {0, 0, 1.5}, 0.05);
    const double area = cv::sum(red_channel(img))[0] / 255.0;
    std::printf("flat disc at 1.5 m: intensity area %.2f px2, closed form %.2f px2\n", area,
                si.area_px);
    EXPECT_NEAR(area, si.area_px, 0.005 * si.area_px);
    // Outside the closed-form box nothing is drawn.
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const bool in_box = x >= si.pixel_box.x && x < si.pixel_box.right() &&
                                y >= si.pixel_box.y && y < si.pixel_box.bottom();
            if (!in_box) {
                ASSERT_EQ(img.at(x, y).r, 0) << x << "," << y;
            }
        }
    }
}

TEST(BallCentroid, StereoPairShowsTheTrueDisparity) {
    // In the default sequence the ball's coverage-mask centroids in the left
    // and right images differ by the ground-truth disparity of the ellipse
    // centres (the left image shows the ball further right).
    const scene::sequence seq(scene::default_scenario());
    double worst = 0.0;
    for (int n : {0, 30, 60, 90}) {
        const scene::stereo_frame f = seq.render(n);
        const scene::vec2 l = centroid(as_mat(f.coverage_left));
        const scene::vec2 r = centroid(as_mat(f.coverage_right));
        const scene::ball_truth& t = f.balls[0];
        std::printf(
            "frame %2d: centroid disparity %.4f px, ground truth %.4f px "
            "(f b / Z_centre "
            "%.4f, f b / Z_visible %.4f), rows %.4f vs %.4f\n",
            n, l.x - r.x, t.disparity_ellipse_px, t.disparity_centre_px, t.disparity_visible_px,
            l.y, r.y);
        EXPECT_NEAR(l.x - r.x, t.disparity_ellipse_px, 0.05);
        EXPECT_NEAR(l.y, r.y, 0.1);
        EXPECT_NEAR(r.x, t.right.ellipse_centre.x, 0.25);
        EXPECT_NEAR(r.y, t.right.ellipse_centre.y, 0.25);
        worst = std::max(worst, std::fabs(l.x - r.x - t.disparity_ellipse_px));
    }
    std::printf("worst |centroid disparity - truth| %.4f px\n", worst);
}

}  // namespace
