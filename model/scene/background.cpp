#include "model/scene/background.h"

#include <algorithm>
#include <utility>

namespace scene {

background_desc background_desc::uniform(vec3 radiance, double depth_m) {
    background_desc b;
    b.type = kind::uniform;
    b.uniform_radiance = radiance;
    b.depth_m = depth_m;
    return b;
}

background_desc background_desc::procedural_plane(const procedural_texture_params& params,
                                                  double depth_m) {
    background_desc b;
    b.type = kind::procedural;
    b.procedural = params;
    b.depth_m = depth_m;
    return b;
}

background_desc background_desc::image_plane(std::shared_ptr<const texture_image> image,
                                             const stereo_rig& rig, double depth_m) {
    background_desc b;
    b.type = kind::image;
    b.depth_m = depth_m;
    // Plane footprint of one pixel at this depth; the two views together
    // span width pixels plus the baseline horizontally.
    const double step = depth_m / rig.focal_px();
    const pinhole_camera l = rig.left(), r = rig.right();
    const double x_min =
        std::min(l.centre.x + (-0.5 - l.cx) * step, r.centre.x + (-0.5 - r.cx) * step);
    const double x_max = std::max(l.centre.x + (rig.width - 0.5 - l.cx) * step,
                                  r.centre.x + (rig.width - 0.5 - r.cx) * step);
    const double y_min = std::min((-0.5 - l.cy) * step, (-0.5 - r.cy) * step);
    const double y_max =
        std::max((rig.height - 0.5 - l.cy) * step, (rig.height - 0.5 - r.cy) * step);
    b.image_centre_m = {0.5 * (x_min + x_max), 0.5 * (y_min + y_max)};
    if (image && image->width > 0 && image->height > 0) {
        b.texel_size_m = std::max((x_max - x_min) / image->width, (y_max - y_min) / image->height);
    }
    b.image = std::move(image);
    return b;
}

void render_background(const background_desc& background, const pinhole_camera& camera,
                       int supersampling, std::vector<float>* rgb) {
    const size_t w = static_cast<size_t>(camera.width), h = static_cast<size_t>(camera.height);
    // Plane size of one pixel; pixel i's footprint is centred at
    // centre.x + (i - cx) * step.
    const double step = (background.depth_m - camera.centre.z) / camera.focal_px;
    const double x0 = camera.centre.x - camera.cx * step;
    const double y0 = camera.centre.y - camera.cy * step;

    switch (background.type) {
        case background_desc::kind::uniform: {
            rgb->resize(3 * w * h);
            for (size_t p = 0; p < w * h; ++p) {
                (*rgb)[3 * p + 0] = static_cast<float>(background.uniform_radiance.x);
                (*rgb)[3 * p + 1] = static_cast<float>(background.uniform_radiance.y);
                (*rgb)[3 * p + 2] = static_cast<float>(background.uniform_radiance.z);
            }
            return;
        }
        case background_desc::kind::procedural: {
            plane_texture(background.procedural)
                .grid_box_means(x0, y0, step, camera.width, camera.height, rgb);
            return;
        }
        case background_desc::kind::image: {
            rgb->assign(3 * w * h, 0.0f);
            if (!background.image) return;
            const texture_image& img = *background.image;
            const int n = std::max(1, supersampling);
            // Texel coordinates of every sub-sample column and row (separable).
            std::vector<double> us(w * n), vs(h * n);
            const double inv_texel = 1.0 / background.texel_size_m;
            for (size_t i = 0; i < w * n; ++i) {
                const double x = -0.5 + (static_cast<double>(i) + 0.5) / n;  // pixel-index units
                us[i] = (x0 + x * step - background.image_centre_m.x) * inv_texel +
                        0.5 * (img.width - 1);
            }
            for (size_t j = 0; j < h * n; ++j) {
                const double y = -0.5 + (static_cast<double>(j) + 0.5) / n;
                vs[j] = (y0 + y * step - background.image_centre_m.y) * inv_texel +
                        0.5 * (img.height - 1);
            }
            const double norm = 1.0 / (n * n);
            for (size_t j = 0; j < h; ++j) {
                for (size_t i = 0; i < w; ++i) {
                    vec3 sum;
                    for (int b = 0; b < n; ++b) {
                        for (int a = 0; a < n; ++a) {
                            sum = sum + img.sample(us[i * n + a], vs[j * n + b]);
                        }
                    }
                    float* out = rgb->data() + 3 * (j * w + i);
                    out[0] = static_cast<float>(sum.x * norm);
                    out[1] = static_cast<float>(sum.y * norm);
                    out[2] = static_cast<float>(sum.z * norm);
                }
            }
            return;
        }
    }
}

}  // namespace scene
