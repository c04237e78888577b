// A scenario (rig, background, balls on trajectories, lighting, frame
// period) and the stereo sequence it produces: frame n is taken at
// t = n * frame_period_s by both cameras at once (instantaneous exposure, no
// motion blur), with per-ball ground truth.
//
// Ground truth per ball per frame (ball_truth), world frame = the right
// camera's frame, metres; image coordinates in the pixel-index convention of
// camera.h:
// - centre_m: the sphere's centre; X and Y are scored against it.
// - visible_mean_depth_m: the mean Z of the surface visible from the RIGHT
//   camera, weighted by projected image area (the mean Z over the ball's
//   image pixels; see sphere_projection.h). Stereo sees the surface, so depth
//   is scored against this; about Z_centre - 2/3 r (times the cosine of the
//   angle off the optical axis, plus ~r/(2 D) of perspective).
// - right, left: each camera's closed-form ellipse (centre, bounding box,
//   area, touched pixels) and the projection of the centre point.
// - disparities: of the ellipse centres, of the centre point (f b / Z_c) and
//   of the visible mean depth (f b / Z_visible), all x_left - x_right.
// - rendered_*: filled only by render(): what the right image really shows
//   of the ball (sub-samples not occluded and inside the image).
#pragma once

#include <limits>
#include <vector>

#include "model/scene/camera.h"
#include "model/scene/images.h"
#include "model/scene/renderer.h"
#include "model/scene/sphere_projection.h"

namespace scene {

struct scenario {
    scene_desc scene;
    double frame_period_s =
        0.0245;             // docs/design-brief.md: one sensor frame = one 24.5 ms sync period
    int frame_count = 100;  // nominal length; any n >= 0 can be rendered
};

struct ball_truth {
    vec3 centre_m;
    double radius_m = 0.0;
    double visible_mean_depth_m = 0.0;
    sphere_image right;
    sphere_image left;
    double disparity_ellipse_px = 0.0;  // left.ellipse_centre.x - right.ellipse_centre.x
    double disparity_centre_px = 0.0;   // rig.disparity_px(centre_m.z)
    double disparity_visible_px = 0.0;  // rig.disparity_px(visible_mean_depth_m)
    // The whole ball nearer than the background plane: the renderer hides
    // what lies behind the plane, so a ball going away past it (or touching
    // it) is not all in the images, whatever its ellipse.
    bool in_front_of_background = true;
    // The whole ellipse inside both images and clear of their outermost
    // pixels (there a whole ball and a cut one look the same), the ball in
    // front of the background.
    bool in_both_views = false;

    int rendered_subsamples = 0;         // right image, visible sub-samples
    double rendered_area_px = 0.0;       // the same in pixels (sub-samples / n^2)
    double rendered_mean_depth_m = 0.0;  // mean Z over those sub-samples
};

struct stereo_frame {
    int index = 0;
    double time_s = 0.0;
    double light_gain = 1.0;
    rgb_image left;
    rgb_image right;
    gray_image coverage_left;  // 255 * fraction of each pixel covered by a ball
    gray_image coverage_right;
    std::vector<ball_truth> balls;
};

class sequence {
  public:
    explicit sequence(scenario s);

    const scenario& desc() const { return m_scenario; }
    const stereo_rig& rig() const { return m_scenario.scene.rig; }
    double time_of(int n) const { return n * m_scenario.frame_period_s; }

    // Ground truth of frame n without rendering (cheap).
    std::vector<ball_truth> truth(int n) const;
    // Renders frame n into out (buffers are reused across calls).
    void render(int n, stereo_frame* out) const;
    stereo_frame render(int n) const;

    const renderer& scene_renderer() const { return m_renderer; }

  private:
    scenario m_scenario;
    renderer m_renderer;
};

// Ground truth of one ball at one time for a rig, in front of a background
// plane at background_depth_m (world Z; none by default).
ball_truth ball_truth_at(const stereo_rig& rig, const ball_desc& ball, double t_s,
                         double background_depth_m = std::numeric_limits<double>::infinity());

// The firmware tests' default: the default rig; the procedural background at
// 5 m; one orange textured 5 cm ball, still for the first still_frames
// frames (identical images), then thrown up and forward (towards the rig),
// bouncing on a floor 0.35 m below the optical axis with restitution 0.8:
// centre depth 2.6 m -> 1.56 m, centre Y from -0.20 m to +0.30 m, inside
// both views with >= 60 px margin over frame_count = 100 frames (2.45 s).
// Image speed: median 7.7 px per frame, up to 24 px per frame at the bounces.
scenario default_scenario(int still_frames = 6);

}  // namespace scene
