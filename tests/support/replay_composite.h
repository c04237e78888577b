// A recorded-like replay sequence made from a real stereo pair
// (../shared/data) and the scene renderer's textured ball: the generator the
// replay scoring tests use (code, not images, in the repository). Frame n
// is the real pair, cropped to the window from its top-left corner, with the
// ball of scene frame n composited over it by the renderer's own pixel
// coverage (out = rendered + (1 - coverage) x (real - rendered background),
// exact at the ball's edge pixels). The truth CSV is the renderer's analytic
// truth of that frame: the ball's centre, its right-image ellipse centre and
// its visible-surface depth (model/scene/sphere_projection.h), plus an
// unknown column the reader must ignore.
#pragma once

#include <string>

namespace testsupport {

struct composite_spec {
    std::string left_png, right_png;  // the real pair (left view, right view)
    int width = 448, height = 372;    // the crop (the sensors' window)
    int frames = 12;
    int still_frames = 3;  // frames the ball rests before it moves
    double depth_m = 1.3;  // the ball's line at this depth (in front of the scene)
    double radius_m = 0.05;
    double speed = 1.0;  // line path time scale (scene::line_path)
};

// Writes DIR/left/frame_NNNN.png, DIR/right/..., DIR/truth.csv and
// DIR/replay.txt (the manifest, the project's default rig as calibration:
// f = 6 mm / 7.6 um = 789.47 px, baseline 120 mm, centred principal
// points). Returns the manifest's path, "" with *error on failure.
std::string write_composite_replay(const composite_spec& spec, const std::string& dir,
                                   std::string* error);

}  // namespace testsupport
