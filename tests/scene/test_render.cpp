// Rendering: determinism, background parallax f b / Z, the still start of
// the default sequence, lighting changes, the band limit of the procedural
// texture, a real image on the plane, and speed.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "model/scene/sequence.h"
#include "tests/support/data_path.h"
#include "tests/support/photo_texture.h"

namespace {

using scene::vec3;

bool same_bytes(const scene::rgb_image& a, const scene::rgb_image& b) {
    if (a.width != b.width || a.height != b.height) return false;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        if (a.pixels[i].r != b.pixels[i].r || a.pixels[i].g != b.pixels[i].g ||
            a.pixels[i].b != b.pixels[i].b) {
            return false;
        }
    }
    return true;
}

// Gray (OpenCV's RGB2GRAY) as float, for phase correlation.
cv::Mat gray_float(const scene::rgb_image& img) {
    cv::Mat rgb(img.height, img.width, CV_8UC3, const_cast<dsp::rgb8*>(img.pixels.data()));
    cv::Mat gray, out;
    cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
    gray.convertTo(out, CV_64F);
    return out;
}

// Largest channel difference between left(x + shift, y) and right(x, y) and
// the number of pixels where they differ at all.
struct shift_compare {
    int max_diff = 0;
    long differing = 0;
    long compared = 0;
};

shift_compare compare_shifted(const scene::rgb_image& left, const scene::rgb_image& right,
                              int shift) {
    shift_compare c;
    for (int y = 0; y < right.height; ++y) {
        for (int x = 0; x + shift < right.width; ++x) {
            const dsp::rgb8 l = left.at(x + shift, y), r = right.at(x, y);
            const int d = std::max({std::abs(l.r - r.r), std::abs(l.g - r.g), std::abs(l.b - r.b)});
            c.max_diff = std::max(c.max_diff, d);
            c.differing += d != 0;
            ++c.compared;
        }
    }
    return c;
}

scene::scene_desc background_only(scene::background_desc bg) {
    scene::scene_desc d;
    d.background = std::move(bg);
    return d;
}

TEST(Render, SameSeedSameBytesOtherSeedOtherImage) {
    const scene::sequence a(scene::default_scenario());
    const scene::sequence b(scene::default_scenario());
    const scene::stereo_frame fa = a.render(37), fb = b.render(37);
    EXPECT_TRUE(same_bytes(fa.left, fb.left));
    EXPECT_TRUE(same_bytes(fa.right, fb.right));

    scene::scenario other = scene::default_scenario();
    other.scene.background.procedural.seed = 2;
    other.scene.balls[0].material.texture.seed = 8;
    const scene::stereo_frame fo = scene::sequence(other).render(37);
    const shift_compare bg = compare_shifted(fo.right, fa.right, 0);
    std::printf("seed 1 vs seed 2: %.1f%% of right-image pixels differ (max %d levels)\n",
                100.0 * bg.differing / bg.compared, bg.max_diff);
    EXPECT_GT(static_cast<double>(bg.differing) / bg.compared, 0.9);
    // The ball's own texture follows its seed: compare inside its box.
    const dsp::box box = fa.balls[0].right.pixel_box;
    int ball_diff = 0;
    for (int y = box.y; y < box.bottom(); ++y) {
        for (int x = box.x; x < box.right(); ++x) {
            if (fa.coverage_right.at(x, y) == 255) {
                ball_diff =
                    std::max(ball_diff, std::abs(fa.right.at(x, y).r - fo.right.at(x, y).r));
            }
        }
    }
    std::printf("ball texture seed 7 vs 8: max difference on the ball %d levels\n", ball_diff);
    EXPECT_GT(ball_diff, 20);
}

TEST(Render, BackgroundParallaxIsFocalTimesBaselineOverDepth) {
    const scene::stereo_rig rig;
    // Integer parallax: depth f b / 20 makes left(x + 20) see exactly what
    // right(x) sees.
    {
        const double depth = rig.focal_px() * rig.baseline_m / 20.0;
        const scene::renderer r(background_only(
            scene::background_desc::procedural_plane(scene::procedural_texture_params{}, depth)));
        scene::rgb_image left, right;
        r.render(scene::camera_id::left, 0.0, &left);
        r.render(scene::camera_id::right, 0.0, &right);
        const shift_compare at20 = compare_shifted(left, right, 20);
        const shift_compare at19 = compare_shifted(left, right, 19);
        const shift_compare at21 = compare_shifted(left, right, 21);
        std::printf(
            "procedural plane at %.4f m (parallax 20 px): left(x+20) vs "
            "right(x): max "
            "diff %d, %ld of %ld pixels differ; at 19 px max diff %d, at "
            "21 px %d\n",
            depth, at20.max_diff, at20.differing, at20.compared, at19.max_diff, at21.max_diff);
        EXPECT_LE(at20.max_diff, 1);  // rounding of the same value computed twice
        EXPECT_LT(at20.differing, at20.compared / 1000);
        EXPECT_GT(at19.max_diff, 10);
        EXPECT_GT(at21.max_diff, 10);
    }
    // Fractional parallax at the default 5 m: 789.47 * 0.12 / 5 = 18.947 px,
    // measured by OpenCV's phase correlation.
    {
        const scene::renderer r(background_only(
            scene::background_desc::procedural_plane(scene::procedural_texture_params{}, 5.0)));
        scene::rgb_image left, right;
        r.render(scene::camera_id::left, 0.0, &left);
        r.render(scene::camera_id::right, 0.0, &right);
        cv::Mat window;
        cv::createHanningWindow(window, cv::Size(640, 480), CV_64F);
        const cv::Point2d shift = cv::phaseCorrelate(gray_float(right), gray_float(left), window);
        const double expected = rig.focal_px() * rig.baseline_m / 5.0;
        std::printf(
            "procedural plane at 5 m: phase correlation shift (%.4f, %.4f) "
            "px, expected "
            "(%.4f, 0)\n",
            shift.x, shift.y, expected);
        EXPECT_NEAR(shift.x, expected, 0.05);
        EXPECT_NEAR(shift.y, 0.0, 0.05);
    }
}

TEST(Render, RealImageOnThePlaneHasTheSameParallax) {
    // Middlebury tsukuba im3 (384 x 288) mapped on the plane, fitted to both
    // views.
    const std::shared_ptr<const scene::texture_image> tex = testsupport::load_photo_texture(
        test_support::data_path("middlebury_2001_2003/tsukuba/im3.png"));
    ASSERT_NE(tex, nullptr);
    const scene::stereo_rig rig;
    const double depth = rig.focal_px() * rig.baseline_m / 16.0;  // 16 px parallax
    const scene::background_desc bg = scene::background_desc::image_plane(tex, rig, depth);
    std::printf(
        "tsukuba on the plane at %.3f m: texel %.2f mm (pixel footprint "
        "%.2f mm)\n",
        depth, 1e3 * bg.texel_size_m, 1e3 * depth / rig.focal_px());
    const scene::renderer r(background_only(bg));
    scene::rgb_image left, right;
    r.render(scene::camera_id::left, 0.0, &left);
    r.render(scene::camera_id::right, 0.0, &right);
    const shift_compare at16 = compare_shifted(left, right, 16);
    const shift_compare at15 = compare_shifted(left, right, 15);
    std::printf(
        "left(x+16) vs right(x): max diff %d, %ld of %ld differ; at 15 "
        "px max diff %d\n",
        at16.max_diff, at16.differing, at16.compared, at15.max_diff);
    EXPECT_LE(at16.max_diff, 1);
    EXPECT_LT(at16.differing, at16.compared / 1000);
    EXPECT_GT(at15.max_diff, 10);
    // The image content is really there: the centre of the right view shows
    // the centre of the picture (mean colour within a few levels).
    const cv::Scalar tex_mean = cv::mean(cv::imread(
        test_support::data_path("middlebury_2001_2003/tsukuba/im3.png"), cv::IMREAD_COLOR));
    cv::Mat rgb(right.height, right.width, CV_8UC3, right.pixels.data());
    const cv::Scalar view_mean = cv::mean(rgb);
    std::printf(
        "mean colour: picture (R %.1f G %.1f B %.1f), right view (R %.1f "
        "G %.1f B %.1f)\n",
        tex_mean[2], tex_mean[1], tex_mean[0], view_mean[0], view_mean[1], view_mean[2]);
    EXPECT_NEAR(view_mean[1], tex_mean[1], 8.0);
}

TEST(Render, DefaultSequenceIsStillThenMoves) {
    const scene::sequence seq(scene::default_scenario(6));
    const scene::stereo_frame f0 = seq.render(0), f5 = seq.render(5), f6 = seq.render(6);
    EXPECT_TRUE(same_bytes(f0.left, f5.left));
    EXPECT_TRUE(same_bytes(f0.right, f5.right));
    const shift_compare moved = compare_shifted(f6.right, f5.right, 0);
    std::printf("frame 5 -> 6: %ld pixels change, max %d levels\n", moved.differing,
                moved.max_diff);
    EXPECT_GT(moved.differing, 100);
    EXPECT_GT(moved.max_diff, 30);
    // The ball is the only thing that moves: every changed pixel touches the
    // ball's box in frame 5 or 6.
    const dsp::box a = f5.balls[0].right.pixel_box, b = f6.balls[0].right.pixel_box;
    long outside = 0;
    for (int y = 0; y < f6.right.height; ++y) {
        for (int x = 0; x < f6.right.width; ++x) {
            const bool in_a = x >= a.x && x < a.right() && y >= a.y && y < a.bottom();
            const bool in_b = x >= b.x && x < b.right() && y >= b.y && y < b.bottom();
            const dsp::rgb8 p = f5.right.at(x, y), q = f6.right.at(x, y);
            if (!in_a && !in_b && (p.r != q.r || p.g != q.g || p.b != q.b)) ++outside;
        }
    }
    EXPECT_EQ(outside, 0);
}

TEST(Render, LightingStepAndRampScaleEveryPixel) {
    scene::scenario s = scene::default_scenario();
    const double t_step = 10.5 * s.frame_period_s;
    s.scene.light = scene::lighting::with_step(t_step, 0.6);
    const scene::sequence step(s);
    // Compare the same instant without and with the gain: freeze the ball.
    s.scene.balls[0].path = scene::trajectory::still({-0.3, 0.0, 2.6});
    s.scene.light = scene::lighting::with_step(t_step, 0.6);
    const scene::sequence frozen(s);
    const scene::stereo_frame before = frozen.render(10), after = frozen.render(11);
    EXPECT_DOUBLE_EQ(before.light_gain, 1.0);
    EXPECT_DOUBLE_EQ(after.light_gain, 0.6);
    // round(0.6 v) against 0.6 round(v): within 0.5 + 0.6 * 0.5 levels, except
    // where the bright frame clipped at 255.
    double worst = 0.0;
    long clipped = 0, clipped_off_ball = 0;
    for (size_t i = 0; i < before.right.pixels.size(); ++i) {
        const dsp::rgb8 p = before.right.pixels[i], q = after.right.pixels[i];
        const uint8_t pv[3] = {p.r, p.g, p.b}, qv[3] = {q.r, q.g, q.b};
        for (int c = 0; c < 3; ++c) {
            if (pv[c] == 255) {
                ++clipped;
                clipped_off_ball += before.coverage_right.pixels[i] == 0;
                continue;
            }
            worst = std::max(worst, std::fabs(qv[c] - 0.6 * pv[c]));
        }
    }
    std::printf(
        "gain step 1 -> 0.6: worst |after - 0.6 before| = %.2f levels "
        "(%ld clipped "
        "channel values skipped, %ld of them off the ball)\n",
        worst, clipped, clipped_off_ball);
    EXPECT_LE(worst, 0.8);
    // Clipping is rare (the texture's tails beyond ~3.6 sigma).
    EXPECT_LT(clipped, static_cast<long>(before.right.pixels.size() * 3 / 10000));
    const cv::Mat g_before = gray_float(before.right), g_after = gray_float(after.right);
    std::printf("mean gray before %.2f, after %.2f (ratio %.4f)\n", cv::mean(g_before)[0],
                cv::mean(g_after)[0], cv::mean(g_after)[0] / cv::mean(g_before)[0]);
    EXPECT_NEAR(cv::mean(g_after)[0] / cv::mean(g_before)[0], 0.6, 0.005);

    scene::lighting ramp = scene::lighting::with_ramp(1.0, 2.0, 0.5);
    EXPECT_DOUBLE_EQ(ramp.gain_at(0.5), 1.0);
    EXPECT_DOUBLE_EQ(ramp.gain_at(1.5), 0.75);
    EXPECT_DOUBLE_EQ(ramp.gain_at(2.5), 0.5);
}

TEST(Render, ProceduralBackgroundIsBandLimited) {
    // Spectral energy of the right image above the texture's highest
    // frequency (1 / min wavelength on the plane = f / (Z lambda_min) cycles
    // per pixel) is negligible; the texture has the requested statistics.
    const scene::procedural_texture_params params;
    const scene::stereo_rig rig;
    const scene::renderer r(background_only(scene::background_desc::procedural_plane(params, 5.0)));
    scene::rgb_image right;
    r.render(scene::camera_id::right, 0.0, &right);
    cv::Mat g = gray_float(right);
    cv::Scalar mean, stddev;
    cv::meanStdDev(g, mean, stddev);
    std::printf("procedural background: mean %.1f, std %.1f levels (params %.0f, %.0f)\n", mean[0],
                stddev[0], params.mean_level, params.contrast);
    EXPECT_NEAR(mean[0], params.mean_level, 15.0);
    EXPECT_NEAR(stddev[0], params.contrast, 15.0);

    cv::Mat window, spectrum;
    cv::createHanningWindow(window, g.size(), CV_64F);
    cv::dft((g - mean[0]).mul(window), spectrum, cv::DFT_COMPLEX_OUTPUT);
    // Shortest texture wavelength in image pixels at 5 m.
    const double min_wavelength_px = params.min_wavelength_m * rig.focal_px() / 5.0;
    double total = 0.0, above = 0.0;
    for (int v = 0; v < g.rows; ++v) {
        for (int u = 0; u < g.cols; ++u) {
            const double fu = (u <= g.cols / 2 ? u : u - g.cols) / double(g.cols);
            const double fv = (v <= g.rows / 2 ? v : v - g.rows) / double(g.rows);
            const cv::Vec2d c = spectrum.at<cv::Vec2d>(v, u);
            const double e = c[0] * c[0] + c[1] * c[1];
            total += e;
            // 1.5x the limit leaves room for the window's spectral leakage.
            if (std::hypot(fu, fv) > 1.5 / min_wavelength_px) above += e;
        }
    }
    std::printf(
        "highest texture frequency %.3f cycles/px (wavelength %.1f px); "
        "energy above "
        "1.5x that: %.2e of the total\n",
        1.0 / min_wavelength_px, min_wavelength_px, above / total);
    EXPECT_LT(above / total, 1e-3);
}

TEST(Render, VgaStereoFrameTime) {
    const scene::sequence seq(scene::default_scenario());
    scene::stereo_frame f;
    seq.render(0, &f);  // warm up buffers
    const int frames = 10;
    const auto t0 = std::chrono::steady_clock::now();
    for (int n = 80; n < 80 + frames; ++n) seq.render(n, &f);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() /
        frames;
    std::printf("render: %.2f ms per VGA stereo pair (both cameras, ball %.0f px2)\n", ms,
                f.balls[0].right.area_px);
#ifdef NDEBUG
    EXPECT_LT(ms,
              500.0);  // "well under a second" per VGA frame, with room for a loaded CI
#endif
}

}  // namespace
