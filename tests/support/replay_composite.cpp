#include "tests/support/replay_composite.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "model/scene/background.h"
#include "model/scene/ball_paths.h"
#include "model/scene/png_io.h"
#include "model/scene/sequence.h"

namespace testsupport {

namespace {

// The pair's file, scaled down by `downscale` and cropped (OpenCV reads
// PNG and JPEG; area averaging, as a camera's larger pixels would).
scene::rgb_image load_window(const std::string& path, const composite_spec& spec) {
    cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
    if (bgr.empty()) throw std::runtime_error("cannot read " + path);
    if (spec.downscale != 1.0) {
        const cv::Size size(static_cast<int>(std::lround(bgr.cols / spec.downscale)),
                            static_cast<int>(std::lround(bgr.rows / spec.downscale)));
        cv::resize(bgr, bgr, size, 0, 0, cv::INTER_AREA);
    }
    if (spec.crop_x < 0 || spec.crop_y < 0 || spec.crop_x + spec.width > bgr.cols ||
        spec.crop_y + spec.height > bgr.rows)
        throw std::runtime_error(path + ": " + std::to_string(bgr.cols) + " x " +
                                 std::to_string(bgr.rows) + " scaled is too small for the crop");
    scene::rgb_image out(spec.width, spec.height);
    for (int y = 0; y < spec.height; ++y) {
        const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(spec.crop_y + y);
        for (int x = 0; x < spec.width; ++x) {
            const cv::Vec3b p = row[spec.crop_x + x];
            out.at(x, y) = {p[2], p[1], p[0]};
        }
    }
    return out;
}

// The renderer's rig for the pair at the sequence's scale: cx_left - cx_right
// = -offset, so the rig's disparity_px(Z) is f B / Z - offset, the pair's.
scene::stereo_rig rig_of(const composite_spec& spec) {
    scene::stereo_rig rig;
    rig.width = spec.width;
    rig.height = spec.height;
    rig.focal_length_m = spec.calibration.focal_px / spec.downscale * rig.pixel_pitch_m;
    rig.baseline_m = spec.calibration.baseline_m;
    const double offset = spec.calibration.disparity_offset_px / spec.downscale;
    rig.principal_dx_left = -0.5 * offset;
    rig.principal_dx_right = 0.5 * offset;
    return rig;
}

uint8_t channel(double v) {
    return static_cast<uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

// rendered + (1 - c) (real - background): the ball over the real image.
scene::rgb_image composite(const scene::rgb_image& rendered, const scene::rgb_image& background,
                           const scene::gray_image& coverage, const scene::rgb_image& real) {
    scene::rgb_image out = real;
    for (int y = 0; y < real.height; ++y) {
        for (int x = 0; x < real.width; ++x) {
            const double c = coverage.at(x, y) / 255.0;
            if (c <= 0.0) continue;
            const dsp::rgb8 r = rendered.at(x, y), b = background.at(x, y), p = real.at(x, y);
            out.at(x, y) = {channel(r.r + (1 - c) * (p.r - b.r)),
                            channel(r.g + (1 - c) * (p.g - b.g)),
                            channel(r.b + (1 - c) * (p.b - b.b))};
        }
    }
    return out;
}

}  // namespace

std::string write_composite_replay(const composite_spec& spec, const std::string& dir,
                                   std::string* error) {
    namespace fs = std::filesystem;
    scene::rgb_image real[2];
    try {
        real[0] = load_window(spec.left_png, spec);
        real[1] = load_window(spec.right_png, spec);
    } catch (const std::exception& e) {
        *error = e.what();
        return {};
    }
    scene::scenario s;
    s.scene.rig = rig_of(spec);
    s.scene.background =
        scene::background_desc::procedural_plane(scene::procedural_texture_params{}, 5.0);
    scene::ball_desc ball;
    ball.radius_m = spec.radius_m;
    ball.spin_rad_s = spec.spin_rps * 2.0 * M_PI;
    ball.spin_axis = spec.spin_axis == scene_axis::x   ? scene::vec3{1.0, 0.0, 0.0}
                     : spec.spin_axis == scene_axis::y ? scene::vec3{0.0, 1.0, 0.0}
                                                       : scene::vec3{0.0, 0.0, 1.0};
    const double start_s = scene::motion_start_s(spec.still_frames, s.frame_period_s);
    ball.path = spec.pass ? scene::pass_path(spec.depth_m, spec.speed, start_s)
                          : scene::line_path(spec.depth_m, spec.speed, start_s);
    s.scene.balls.push_back(ball);
    scene::scenario empty = s;
    empty.scene.balls.clear();
    const scene::sequence with_ball(s), without(empty);
    fs::create_directories(dir + "/left");
    fs::create_directories(dir + "/right");
    std::ofstream truth(dir + "/truth.csv");
    truth << "frame,x_mm,y_mm,z_mm,u_right_px,v_right_px,z_visible_mm,note_id\n";
    for (int n = 0; n < spec.frames; ++n) {
        const scene::stereo_frame f = with_ball.render(n), bg = without.render(n);
        char name[64];
        std::snprintf(name, sizeof name, "/frame_%04d.png", n);
        scene::write_png(dir + "/left" + name,
                         composite(f.left, bg.left, f.coverage_left, real[0]));
        scene::write_png(dir + "/right" + name,
                         composite(f.right, bg.right, f.coverage_right, real[1]));
        const scene::ball_truth& t = f.balls.front();
        char row[256];
        std::snprintf(row, sizeof row, "%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%d\n", n,
                      t.centre_m.x * 1e3, t.centre_m.y * 1e3, t.centre_m.z * 1e3,
                      t.right.ellipse_centre.x, t.right.ellipse_centre.y,
                      t.visible_mean_depth_m * 1e3, 1000 + n);
        truth << row;
    }
    const scene::stereo_rig& rig = s.scene.rig;
    std::ofstream manifest(dir + "/replay.txt");
    manifest.precision(10);
    manifest << "stereosim_replay 1\n"
             << "# " << spec.left_png << " / " << spec.right_png << " with a rendered ball\n"
             << "size " << spec.width << " " << spec.height << "\nframes " << spec.frames
             << "\nleft left/frame_%04d.png\nright right/frame_%04d.png\n"
             << "focal_px " << rig.focal_px() << "\nbaseline_m " << rig.baseline_m
             << "\nprincipal_left " << rig.cx_left() << " " << rig.cy_left() << "\nprincipal_right "
             << rig.cx_right() << " " << rig.cy_right() << "\ntruth truth.csv\n";
    if (!truth || !manifest) {
        *error = "cannot write into " + dir;
        return {};
    }
    return dir + "/replay.txt";
}

}  // namespace testsupport
