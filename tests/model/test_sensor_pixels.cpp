// Pixel values on the sensor's data pins: with noise off they are exactly the
// scene's RGB image mosaicked in the profile's Bayer order (scene::mosaic is
// the reference), with gain and black level by closed form; dark pixels read
// the black level, border pixels repeat the outermost CFA cell; noise has the
// configured statistics and is reproducible by seed; a replayed PNG sequence
// reaches the pins unchanged.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "model/scene/bayer_mosaic.h"
#include "model/scene/renderer.h"
#include "model/scene/replay.h"
#include "model/sensor/scene_sources.h"
#include "model/sensor/sensor_core.h"
#include "sensor_test_util.h"
#include "tests/support/data_path.h"

using namespace sensor;
using namespace sensor_test;

namespace {

// Image coordinate a readout column/row shows, by brute force: the image
// position itself, or for a border position the nearest image position with
// the same parity (so the same CFA colour). -1 for dark.
int image_coord(int readout_index, int dark_before, int border_before, int active,
                int border_after) {
    const int i = readout_index - dark_before - border_before;
    if (readout_index < dark_before || i >= active + border_after) return -1;
    int best = -1;
    for (int v = 0; v < active; ++v)
        if (((v - i) % 2 == 0) && (best < 0 || std::abs(v - i) < std::abs(best - i))) best = v;
    return best;
}

// Runs the core for `frames` frames (OE high from cycle 0) and returns the readouts.
std::vector<readout> capture(sensor_core& core, int frames) {
    const sensor_profile& p = core.profile();
    const uint64_t cycles =
        static_cast<uint64_t>(p.startup_latency_pclks + p.extra_delay_max_pclks) +
        static_cast<uint64_t>(p.frame_pclks()) * frames;
    auto out = frames_from_pins(run(core, cycles, oe_from(0)));
    if (out.size() > static_cast<size_t>(frames)) out.resize(frames);
    return out;
}

// Compares one readout with the expected mosaic; returns mismatches.
int compare_readout(const readout& got, const sensor_profile& p, const scene::gray_image& mosaic,
                    const std::function<int(int)>& response, int dark_value) {
    int bad = 0;
    EXPECT_EQ(got.size(), static_cast<size_t>(p.readout_rows()));
    for (int r = 0; r < static_cast<int>(got.size()); ++r) {
        EXPECT_EQ(got[r].size(), static_cast<size_t>(p.readout_cols()));
        const int y = image_coord(r, p.dark_rows_top, p.border_rows_before, p.active_rows,
                                  p.border_rows_after);
        for (int c = 0; c < static_cast<int>(got[r].size()); ++c) {
            const int x = image_coord(c, p.dark_cols_left, p.border_cols_before, p.active_cols,
                                      p.border_cols_after);
            const int want = (x < 0 || y < 0) ? dark_value : response(mosaic.at(x, y));
            if (got[r][c] != want) ++bad;
        }
    }
    return bad;
}

}  // namespace

TEST(SensorPixels, NoiseOffPixelsAreTheMosaickedSceneInEveryCfaOrder) {
    for (dsp::cfa_order order :
         {dsp::cfa_order::rggb, dsp::cfa_order::bggr, dsp::cfa_order::grbg, dsp::cfa_order::gbrg}) {
        sensor_profile p = small_profile();
        p.cfa = order;
        p.black_level = 0;
        pattern_source source(p.active_cols, p.active_rows);
        sensor_core core(p, scene::camera_id::left, source);
        const auto frames = capture(core, 3);
        ASSERT_EQ(frames.size(), 3u);
        for (int k = 0; k < 3; ++k) {
            scene::rgb_image rgb(p.active_cols, p.active_rows);
            for (int y = 0; y < p.active_rows; ++y)
                for (int x = 0; x < p.active_cols; ++x)
                    rgb.at(x, y) = pattern_source::pixel(0, k, x, y);
            const scene::gray_image mosaic = scene::mosaic(rgb, order);
            EXPECT_EQ(compare_readout(
                          frames[k], p, mosaic, [](int s) { return s; }, 0),
                      0)
                << dsp::cfa_order_name(order) << " frame " << k;
        }
    }
}

// Gain 1.5 and black level 16: out = min(255, 16 + round(1.5 s)); dark = 16.
TEST(SensorPixels, GainAndBlackLevelByClosedForm) {
    sensor_profile p = small_profile();
    pattern_source source(p.active_cols, p.active_rows);
    sensor_config cfg;
    cfg.gain_q8 = 384;
    sensor_core core(p, scene::camera_id::right, source, cfg);
    const auto frames = capture(core, 2);
    ASSERT_EQ(frames.size(), 2u);
    for (int k = 0; k < 2; ++k) {
        scene::rgb_image rgb(p.active_cols, p.active_rows);
        for (int y = 0; y < p.active_rows; ++y)
            for (int x = 0; x < p.active_cols; ++x)
                rgb.at(x, y) = pattern_source::pixel(1, k, x, y);
        const auto response = [](int s) {
            return std::min(255, 16 + static_cast<int>(std::floor(1.5 * s + 0.5)));
        };
        EXPECT_EQ(compare_readout(frames[k], p, scene::mosaic(rgb, p.cfa), response, 16), 0);
    }
    // Exposure twice the reference doubles the signal the same way.
    sensor_config twice;
    twice.exposure_lines = 2 * p.exposure_lines;
    pattern_source source2(p.active_cols, p.active_rows);
    sensor_core core2(p, scene::camera_id::right, source2, twice);
    const auto f2 = capture(core2, 1);
    scene::rgb_image rgb(p.active_cols, p.active_rows);
    for (int y = 0; y < p.active_rows; ++y)
        for (int x = 0; x < p.active_cols; ++x) rgb.at(x, y) = pattern_source::pixel(1, 0, x, y);
    EXPECT_EQ(compare_readout(
                  f2[0], p, scene::mosaic(rgb, p.cfa),
                  [](int s) { return std::min(255, 16 + 2 * s); }, 16),
              0);
}

// A real photograph (Kodak kodim19, read by OpenCV, a 96 x 64 crop) through
// the sensor: every active pixel equals the crop's RGGB mosaic.
TEST(SensorPixels, RealImageThroughTheSensorIsItsMosaic) {
    const cv::Mat bgr =
        cv::imread(test_support::data_path("kodak_demosaic_gt/kodim19.png"), cv::IMREAD_COLOR);
    ASSERT_FALSE(bgr.empty());
    sensor_profile p = small_profile();
    p.active_cols = 96;
    p.active_rows = 64;
    p.line_pclks = 140;
    p.frame_lines = 90;
    p.vsync_pclks = 2 * 140;
    p.cfa = dsp::cfa_order::rggb;
    p.black_level = 0;
    scene::rgb_image crop(p.active_cols, p.active_rows);
    for (int y = 0; y < p.active_rows; ++y)
        for (int x = 0; x < p.active_cols; ++x) {
            const cv::Vec3b v = bgr.at<cv::Vec3b>(200 + y, 300 + x);
            crop.at(x, y) = {v[2], v[1], v[0]};
        }
    still_source source(crop);
    sensor_core core(p, scene::camera_id::left, source);
    const auto frames = capture(core, 1);
    ASSERT_EQ(frames.size(), 1u);
    // Reference written plainly: R at even/even, B at odd/odd, G elsewhere.
    scene::gray_image want(p.active_cols, p.active_rows);
    for (int y = 0; y < p.active_rows; ++y)
        for (int x = 0; x < p.active_cols; ++x) {
            const cv::Vec3b v = bgr.at<cv::Vec3b>(200 + y, 300 + x);
            want.at(x, y) = (x % 2 == 0 && y % 2 == 0)   ? v[2]
                            : (x % 2 == 1 && y % 2 == 1) ? v[0]
                                                         : v[1];
        }
    EXPECT_EQ(compare_readout(
                  frames[0], p, want, [](int s) { return s; }, 0),
              0);
}

TEST(SensorPixels, FrameRequestsCarryTheTrueTiming) {
    sensor_profile p = small_profile();
    pattern_source source(p.active_cols, p.active_rows);
    sensor_config cfg;
    cfg.clock_origin = 1000;
    sensor_core core(p, scene::camera_id::right, source, cfg);
    const auto rec = run(core, 7 + 3 * 1200, oe_from(0));
    ASSERT_EQ(source.requests.size(), 3u);
    const auto vs = rises(rec, pin_word::vsync_bit);
    for (size_t k = 0; k < 3; ++k) {
        const frame_request& r = source.requests[k];
        EXPECT_EQ(r.camera, scene::camera_id::right);
        EXPECT_EQ(r.scene_frame, k);
        EXPECT_EQ(r.frame_start, 1000 + static_cast<int64_t>(vs[k]) * 1050);
        EXPECT_EQ(r.exposure, 20 * 40 * 1050);  // exposure_lines * line * period
        // The exposure ends at the first active pixel's rising edge:
        // line first_row_line + active_row0, column href_start + active_col0.
        const int64_t first_active = static_cast<int64_t>(vs[k]) + (4 + 2) * 40 + 3 + 3;
        EXPECT_EQ(r.exposure_start + r.exposure, 1000 + first_active * 1050);
        EXPECT_EQ(core.truth()[k].start_tick, r.frame_start);
        EXPECT_EQ(core.truth()[k].first_active_cycle, static_cast<uint64_t>(first_active));
    }
}

// Noise: mean and variance of a flat grey field and of the dark pixels match
// sigma^2 = read^2 + shot * signal (+ 1/12 for rounding to whole DN).
TEST(SensorPixels, NoiseStatisticsAndSeeds) {
    sensor_profile p = small_profile();
    p.active_cols = 64;
    p.active_rows = 48;
    p.dark_cols_left = p.dark_cols_right = 8;
    p.dark_rows_top = p.dark_rows_bottom = 2;
    p.line_pclks = 100;
    p.frame_lines = 70;
    p.vsync_pclks = 200;
    p.first_row_line = 5;
    scene::rgb_image flat(p.active_cols, p.active_rows);
    for (auto& px : flat.pixels) px = {100, 100, 100};

    const auto run_noisy = [&](uint64_t seed) {
        still_source source(flat);
        sensor_config cfg;
        cfg.noise = true;
        cfg.seed = seed;
        cfg.read_noise_dn = 1.0;
        cfg.shot_noise_dn2_per_dn = 0.1;
        sensor_core core(p, scene::camera_id::left, source, cfg);
        return capture(core, 20);
    };
    const auto frames = run_noisy(7);
    ASSERT_EQ(frames.size(), 20u);
    double sum_a = 0, sum2_a = 0, sum_d = 0, sum2_d = 0;
    long n_a = 0, n_d = 0;
    for (const readout& f : frames)
        for (int r = 0; r < static_cast<int>(f.size()); ++r)
            for (int c = 0; c < static_cast<int>(f[r].size()); ++c) {
                const bool dark = r < 2 || r >= 2 + 1 + 48 + 1 || c < 8 || c >= 8 + 1 + 64 + 1;
                const bool active = r >= 3 && r < 51 && c >= 9 && c < 73;
                const double v = f[r][c];
                if (dark) {
                    sum_d += v, sum2_d += v * v, ++n_d;
                } else if (active) {
                    sum_a += v, sum2_a += v * v, ++n_a;
                }
            }
    const double mean_a = sum_a / n_a, var_a = sum2_a / n_a - mean_a * mean_a;
    const double mean_d = sum_d / n_d, var_d = sum2_d / n_d - mean_d * mean_d;
    std::printf(
        "active: n=%ld mean %.3f (expect 116) var %.3f (expect %.3f); dark: n=%ld mean %.3f "
        "(expect 16) var %.3f (expect %.3f)\n",
        n_a, mean_a, var_a, 11.0 + 1.0 / 12, n_d, mean_d, var_d, 1.0 + 1.0 / 12);
    EXPECT_NEAR(mean_a, 116.0, 0.1);
    EXPECT_NEAR(var_a, 11.0 + 1.0 / 12, 0.4);
    EXPECT_NEAR(mean_d, 16.0, 0.05);
    EXPECT_NEAR(var_d, 1.0 + 1.0 / 12, 0.06);

    EXPECT_EQ(run_noisy(7), frames) << "same seed, same noise";
    const auto other = run_noisy(8);
    long differ = 0, total = 0;
    for (size_t k = 0; k < frames.size(); ++k)
        for (size_t r = 0; r < frames[k].size(); ++r)
            for (size_t c = 0; c < frames[k][r].size(); ++c, ++total)
                differ += frames[k][r][c] != other[k][r][c];
    std::printf("seed 7 vs seed 8: %.1f%% of pixels differ\n", 100.0 * differ / total);
    EXPECT_GT(differ, total / 2);
}

// A PNG sequence written by OpenCV, replayed through scene::replay into two
// sensors: each camera's active pixels are the mosaic of its files' pixels.
TEST(SensorPixels, ReplayedFilesReachThePins) {
    const sensor_profile p = [] {
        sensor_profile q = small_profile();
        q.black_level = 0;
        return q;
    }();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("stereosim_sensor_replay_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    cv::RNG rng(12345);
    std::vector<cv::Mat> files[2];
    for (int side = 0; side < 2; ++side)
        for (int k = 0; k < 2; ++k) {
            cv::Mat bgr(p.active_rows, p.active_cols, CV_8UC3);
            rng.fill(bgr, cv::RNG::UNIFORM, 0, 256);
            const std::string name = (side == 0 ? "L_" : "R_") + std::to_string(k) + ".png";
            ASSERT_TRUE(cv::imwrite((dir / name).string(), bgr));
            files[side].push_back(bgr);
        }
    std::ofstream(dir / "seq.txt")
        << "stereosim_replay 1\nsize 16 12\nframes 2\nleft L_%d.png\n"
           "right R_%d.png\nfocal_px 100\nbaseline_m 0.1\n"
           "principal_left 7.5 5.5\nprincipal_right 7.5 5.5\nafter_last hold\n";
    scene::replay replay((dir / "seq.txt").string(), p.active_cols, p.active_rows);
    replay_source source(replay);
    for (int side = 0; side < 2; ++side) {
        const scene::camera_id cam = side == 0 ? scene::camera_id::left : scene::camera_id::right;
        sensor_core core(p, cam, source);
        const auto frames = capture(core, 2);
        ASSERT_EQ(frames.size(), 2u);
        for (int k = 0; k < 2; ++k) {
            scene::rgb_image rgb(p.active_cols, p.active_rows);
            for (int y = 0; y < p.active_rows; ++y)
                for (int x = 0; x < p.active_cols; ++x) {
                    const cv::Vec3b v = files[side][k].at<cv::Vec3b>(y, x);
                    rgb.at(x, y) = {v[2], v[1], v[0]};
                }
            EXPECT_EQ(compare_readout(
                          frames[k], p, scene::mosaic(rgb, p.cfa), [](int s) { return s; }, 0),
                      0)
                << "side " << side << " frame " << k;
        }
    }
    std::filesystem::remove_all(dir);
}

// The scene renderer through renderer_source: each frame is the renderer's
// image at the middle of the frame's exposure window, mosaicked.
TEST(SensorPixels, RenderedSceneAtMidExposureReachesThePins) {
    sensor_profile p = small_profile();
    p.active_cols = 32;
    p.active_rows = 24;
    p.line_pclks = 60;
    p.frame_lines = 40;
    p.black_level = 0;
    scene::scene_desc desc;
    desc.rig.width = 32;
    desc.rig.height = 24;
    desc.rig.pixel_pitch_m = 7.6e-6 * 20;  // f = 39.5 px: the ball spans a few pixels
    desc.background = scene::background_desc::uniform({60.0, 80.0, 100.0});
    scene::ball_desc ball;
    ball.path = scene::trajectory::line({-0.3, 0.0, 1.0}, {4.0, 0.0, 0.0});
    desc.balls.push_back(ball);
    const scene::renderer renderer(desc);
    renderer_source source(renderer);
    sensor_core core(p, scene::camera_id::right, source);
    const auto frames = capture(core, 3);
    ASSERT_EQ(frames.size(), 3u);
    int moved = 0;
    for (int k = 0; k < 3; ++k) {
        // Exposure: exposure_lines (20) line periods ending at the first
        // active pixel's rising edge; rendered at its middle.
        const double end_ticks = static_cast<double>(core.truth()[k].first_active_cycle) * 1050;
        const double t = (end_ticks - 0.5 * 20 * 60 * 1050) / 18e9;
        scene::rgb_image img;
        renderer.render(scene::camera_id::right, t, &img);
        EXPECT_EQ(compare_readout(
                      frames[k], p, scene::mosaic(img, p.cfa), [](int s) { return s; }, 0),
                  0)
            << "frame " << k << " at t = " << t;
        if (k > 0) moved += frames[k] != frames[k - 1];
    }
    EXPECT_EQ(moved, 2) << "the ball moves between frames, so the render time matters";
}

TEST(SensorPixels, WrongImageSizeIsAClearError) {
    const sensor_profile p = small_profile();
    pattern_source source(p.active_cols + 2, p.active_rows);
    sensor_core core(p, scene::camera_id::left, source);
    try {
        run(core, 100, oe_from(0));
        FAIL() << "no error for a wrong-size image";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("18x12"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("16x12"), std::string::npos) << e.what();
    }
}
