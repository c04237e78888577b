// A recorded-like replay sequence made from a real stereo pair
// (../shared/data) and the scene renderer's textured ball: the generator the
// replay scoring tests use (code, not images, in the repository). Frame n
// is the real pair (PNG or JPEG), scaled down by `downscale` (area
// averaging) and cropped to the window at (crop_x, crop_y), with the ball of
// scene frame n composited over it by the renderer's own pixel coverage
// (out = rendered + (1 - coverage) x (real - rendered background), exact at
// the ball's edge pixels). The ball is rendered with the pair's calibration
// at that scale, so it sits at its true disparity among the real scene's.
// The truth CSV is the renderer's analytic truth of that frame: the ball's
// centre, its right-image ellipse centre and its visible-surface depth
// (model/scene/sphere_projection.h), plus an unknown column the reader must
// ignore.
#pragma once

#include <string>

namespace testsupport {

// A rectified pair's calibration at its full (file) size: depth Z = f B /
// (d + disparity_offset_px) for a disparity d = x_left - x_right between the
// files (Middlebury's dmin: the views were cropped differently).
struct pair_calibration {
    double focal_px = 6e-3 / 7.6e-6;  // the project's default rig: 6 mm / 7.6 um
    double baseline_m = 0.120;
    double disparity_offset_px = 0.0;
};

enum class scene_axis { x, y, z };

struct composite_spec {
    std::string left_png, right_png;  // the real pair (left view, right view)
    pair_calibration calibration;
    double downscale = 1.0;         // file pixels per sequence pixel
    int crop_x = 0, crop_y = 0;     // the crop's corner in the scaled pair
    int width = 448, height = 372;  // the crop (the sensors' window)
    int frames = 12;
    int still_frames = 3;  // frames the ball rests before it moves
    double depth_m = 1.3;  // the ball's line at this depth (in front of the scene)
    double radius_m = 0.05;
    double speed = 1.0;                    // line path time scale (scene::line_path)
    bool pass = false;                     // scene::pass_path (stays in view at any focal length)
    double spin_rps = 0.0;                 // the ball's spin, revolutions per second ...
    scene_axis spin_axis = scene_axis::y;  // ... about this axis
};

// Writes DIR/left/frame_NNNN.png, DIR/right/..., DIR/truth.csv and
// DIR/replay.txt (the manifest: the calibration at the sequence's scale,
// f / downscale, its principal points apart by the offset / downscale).
// Returns the manifest's path, "" with *error on failure (an unreadable
// pair, or one too small for the crop).
std::string write_composite_replay(const composite_spec& spec, const std::string& dir,
                                   std::string* error);

}  // namespace testsupport
