// Renders one camera's 8-bit RGB image of the scene at a time t.
//
// Pixel value = round(gain(t) * mean radiance over the pixel's area),
// clamped to 0..255 (linear, no gamma). The background's per-pixel mean is
// cached per camera at construction (the plane is static). Balls are ray
// cast at supersampling x supersampling regular sub-samples per pixel
// (offsets (k + 0.5) / n - 0.5), only inside each ball's closed-form
// projected bounding box; a sub-sample that misses every ball (or hits the
// plane first) takes the pixel's background mean. So the rendered ball's
// coverage, and hence its centroid, is accurate to the sub-sample grid.
// A ball whose sphere is not wholly in front of a camera (Z <= r) is not
// drawn in that camera.
#pragma once

#include <array>
#include <vector>

#include "model/scene/background.h"
#include "model/scene/ball.h"
#include "model/scene/camera.h"
#include "model/scene/images.h"
#include "model/scene/lighting.h"
#include "model/scene/texture.h"

namespace scene {

struct scene_desc {
    stereo_rig rig;
    background_desc background;
    std::vector<ball_desc> balls;
    lighting light;
    int supersampling = 4;  // per axis: 4 x 4 = 16 rays per pixel on a ball
};

// What one render saw of one ball: its visible (unoccluded, in-image)
// sub-samples and the sum of their world depths.
struct ball_render_stats {
    int visible_subsamples = 0;
    double depth_sum_m = 0.0;
    double mean_depth_m() const {
        return visible_subsamples > 0 ? depth_sum_m / visible_subsamples : 0.0;
    }
};

class renderer {
  public:
    explicit renderer(scene_desc desc);

    const scene_desc& desc() const { return m_desc; }

    // Renders camera `id` at time t_s into `out` (resized to the rig's image).
    // coverage (optional): per pixel, round(255 * fraction of sub-samples that
    //   see a ball). stats (optional): one entry per ball.
    void render(camera_id id, double t_s, rgb_image* out, gray_image* coverage = nullptr,
                std::vector<ball_render_stats>* stats = nullptr) const;

  private:
    scene_desc m_desc;
    std::vector<sphere_texture> m_ball_textures;
    std::array<std::vector<float>, 2> m_background;  // [camera_id]: RGB means per pixel
};

}  // namespace scene
