#include "model/scene/sequence.h"

#include <utility>

#include "model/scene/ball_paths.h"

namespace scene {

namespace {

// A ball whose pixels reach an image's outermost row or column: from the
// image it is one the border may cut, whatever its ellipse.
bool clear_of_border(const sphere_image& image, const pinhole_camera& camera) {
    const dsp::box b = image.pixel_box;
    return b.x > 0 && b.y > 0 && b.right() < camera.width && b.bottom() < camera.height;
}

}  // namespace

ball_truth ball_truth_at(const stereo_rig& rig, const ball_desc& ball, double t_s,
                         double background_depth_m) {
    ball_truth t;
    t.centre_m = ball.path.position(t_s);
    t.radius_m = ball.radius_m;
    const pinhole_camera right = rig.right(), left = rig.left();
    t.right = project_sphere(right, t.centre_m, t.radius_m);
    t.left = project_sphere(left, t.centre_m, t.radius_m);
    t.visible_mean_depth_m = visible_mean_depth(right, t.centre_m, t.radius_m);
    t.disparity_ellipse_px = t.left.ellipse_centre.x - t.right.ellipse_centre.x;
    t.disparity_centre_px = rig.disparity_px(t.centre_m.z);
    t.disparity_visible_px =
        t.visible_mean_depth_m > 0.0 ? rig.disparity_px(t.visible_mean_depth_m) : 0.0;
    t.in_front_of_background = t.centre_m.z + t.radius_m < background_depth_m;
    t.in_both_views = t.right.valid && t.left.valid && t.right.inside_image &&
                      t.left.inside_image && clear_of_border(t.right, right) &&
                      clear_of_border(t.left, left) && t.in_front_of_background;
    return t;
}

sequence::sequence(scenario s) : m_scenario(std::move(s)), m_renderer(m_scenario.scene) {}

std::vector<ball_truth> sequence::truth(int n) const {
    std::vector<ball_truth> out;
    for (const ball_desc& b : m_scenario.scene.balls) {
        out.push_back(ball_truth_at(m_scenario.scene.rig, b, time_of(n),
                                    m_scenario.scene.background.depth_m));
    }
    return out;
}

void sequence::render(int n, stereo_frame* out) const {
    out->index = n;
    out->time_s = time_of(n);
    out->light_gain = m_scenario.scene.light.gain_at(out->time_s);
    out->balls = truth(n);
    std::vector<ball_render_stats> stats;
    m_renderer.render(camera_id::left, out->time_s, &out->left, &out->coverage_left);
    m_renderer.render(camera_id::right, out->time_s, &out->right, &out->coverage_right, &stats);
    const int n2 = m_renderer.desc().supersampling * m_renderer.desc().supersampling;
    for (size_t k = 0; k < out->balls.size() && k < stats.size(); ++k) {
        out->balls[k].rendered_subsamples = stats[k].visible_subsamples;
        out->balls[k].rendered_area_px = static_cast<double>(stats[k].visible_subsamples) / n2;
        out->balls[k].rendered_mean_depth_m = stats[k].mean_depth_m();
    }
}

stereo_frame sequence::render(int n) const {
    stereo_frame f;
    render(n, &f);
    return f;
}

scenario default_scenario(int still_frames) {
    scenario s;
    s.scene.background = background_desc::procedural_plane(procedural_texture_params{}, 5.0);
    ball_desc ball;
    ball.radius_m = 0.05;
    ball.path = thrown_ball_path(2.6, ball.radius_m, /*speed=*/1.0,
                                 motion_start_s(still_frames, s.frame_period_s));
    s.scene.balls.push_back(ball);
    s.frame_count = 100;
    return s;
}

}  // namespace scene
