#include "model/scene/renderer.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "model/scene/sphere_projection.h"

namespace scene {
namespace {

uint8_t quantize(double v) {
    const double r = std::floor(v + 0.5);
    return static_cast<uint8_t>(r < 0.0 ? 0.0 : (r > 255.0 ? 255.0 : r));
}

// A ball's state for one render.
struct ball_frame {
    vec3 centre;
    double radius;
    mat3 orientation;
    dsp::box box;  // pixels to ray cast (empty: not drawn)
};

bool contains(const dsp::box& b, int x, int y) {
    return x >= b.x && x < b.right() && y >= b.y && y < b.bottom();
}

// The balls at time t_s, each with the pixels its projection may cover.
std::vector<ball_frame> place_balls(const std::vector<ball_desc>& descs, const pinhole_camera& cam,
                                    double t_s) {
    const int w = cam.width, h = cam.height;
    std::vector<ball_frame> balls;
    for (const ball_desc& b : descs) {
        ball_frame f{b.path.position(t_s), b.radius_m, b.orientation(t_s), {}};
        const sphere_image si = project_sphere(cam, f.centre, f.radius);
        if (si.valid && !si.pixel_box.empty()) {
            // One pixel of margin against rounding at the closed-form edge.
            const int x0 = std::max(0, si.pixel_box.x - 1), y0 = std::max(0, si.pixel_box.y - 1);
            const int x1 = std::min(w, si.pixel_box.right() + 1);
            const int y1 = std::min(h, si.pixel_box.bottom() + 1);
            f.box = dsp::box{x0, y0, x1 - x0, y1 - y0};
        }
        balls.push_back(f);
    }
    return balls;
}

// Casts the n x n sub-sample rays of one pixel against the balls; a ray that
// misses them all (or meets the background plane first) adds nothing.
class ball_caster {
  public:
    ball_caster(const pinhole_camera& cam, const scene_desc& desc,
                const std::vector<sphere_texture>& textures, const std::vector<ball_frame>& balls,
                std::vector<ball_render_stats>* stats)
        : m_cam(cam),
          m_desc(desc),
          m_textures(textures),
          m_balls(balls),
          m_stats(stats),
          m_n(desc.supersampling),
          m_plane_t(desc.background.depth_m - cam.centre.z) {}  // rays have unit Z

    // The summed colour of the rays that hit a ball, and how many did.
    int cast(int x, int y, vec3* sum) const {
        int hits = 0;
        for (int b = 0; b < m_n; ++b) {
            for (int a = 0; a < m_n; ++a) {
                const vec3 d =
                    m_cam.ray_direction(x - 0.5 + (a + 0.5) / m_n, y - 0.5 + (b + 0.5) / m_n);
                if (shade_ray(d, sum)) ++hits;
            }
        }
        return hits;
    }

  private:
    bool shade_ray(const vec3& d, vec3* sum) const {
        double best_t = m_plane_t;
        int best = -1;
        for (size_t j = 0; j < m_balls.size(); ++j) {
            if (m_balls[j].box.empty()) continue;
            double t;
            if (intersect_sphere(m_cam.centre, d, m_balls[j].centre, m_balls[j].radius, &t) &&
                t < best_t) {
                best_t = t;
                best = static_cast<int>(j);
            }
        }
        if (best < 0) return false;
        const ball_frame& hit = m_balls[static_cast<size_t>(best)];
        const ball_desc& desc = m_desc.balls[static_cast<size_t>(best)];
        const lighting& light = m_desc.light;
        const vec3 p = m_cam.centre + d * best_t;
        const vec3 normal = (p - hit.centre) * (1.0 / hit.radius);
        double level = light.light_level * m_textures[static_cast<size_t>(best)].factor(
                                               hit.orientation.transposed_times(normal));
        if (desc.material.shaded) {
            level *= light.ambient +
                     (1.0 - light.ambient) * std::max(0.0, dot(normal, light.direction_to_light));
        }
        *sum = *sum + desc.material.albedo * level;
        if (m_stats) {
            ball_render_stats& s = (*m_stats)[static_cast<size_t>(best)];
            ++s.visible_subsamples;
            s.depth_sum_m += p.z;
        }
        return true;
    }

    const pinhole_camera& m_cam;
    const scene_desc& m_desc;
    const std::vector<sphere_texture>& m_textures;
    const std::vector<ball_frame>& m_balls;
    std::vector<ball_render_stats>* m_stats;
    int m_n;
    double m_plane_t;
};

}  // namespace

renderer::renderer(scene_desc desc) : m_desc(std::move(desc)) {
    m_desc.supersampling = std::max(1, m_desc.supersampling);
    for (const ball_desc& b : m_desc.balls) m_ball_textures.emplace_back(b.material.texture);
    for (camera_id id : {camera_id::left, camera_id::right}) {
        render_background(m_desc.background, m_desc.rig.camera(id), m_desc.supersampling,
                          &m_background[static_cast<size_t>(id)]);
    }
}

void renderer::render(camera_id id, double t_s, rgb_image* out, gray_image* coverage,
                      std::vector<ball_render_stats>* stats) const {
    const pinhole_camera cam = m_desc.rig.camera(id);
    const int w = cam.width, h = cam.height;
    const double gain = m_desc.light.gain_at(t_s);
    const std::vector<float>& bg = m_background[static_cast<size_t>(id)];

    out->resize(w, h);
    for (size_t p = 0; p < out->pixels.size(); ++p) {
        out->pixels[p] = dsp::rgb8{quantize(gain * bg[3 * p]), quantize(gain * bg[3 * p + 1]),
                                   quantize(gain * bg[3 * p + 2])};
    }
    if (coverage) coverage->resize(w, h);
    if (stats) stats->assign(m_desc.balls.size(), ball_render_stats{});

    const std::vector<ball_frame> balls = place_balls(m_desc.balls, cam, t_s);
    const ball_caster caster(cam, m_desc, m_ball_textures, balls, stats);
    const int n = m_desc.supersampling;
    const double inv_n2 = 1.0 / (n * n);
    for (size_t k = 0; k < balls.size(); ++k) {
        const dsp::box& box = balls[k].box;
        for (int y = box.y; y < box.bottom(); ++y) {
            for (int x = box.x; x < box.right(); ++x) {
                // A pixel in two boxes is cast once, with the first box.
                bool done = false;
                for (size_t j = 0; j < k; ++j) done = done || contains(balls[j].box, x, y);
                if (done) continue;

                vec3 sum;
                const int hits = caster.cast(x, y, &sum);
                if (hits == 0) continue;  // the background value is already there
                const size_t p = static_cast<size_t>(y) * static_cast<size_t>(w) + x;
                const double miss = (n * n - hits);
                const vec3 mean{(sum.x + miss * bg[3 * p]) * inv_n2,
                                (sum.y + miss * bg[3 * p + 1]) * inv_n2,
                                (sum.z + miss * bg[3 * p + 2]) * inv_n2};
                out->pixels[p] = dsp::rgb8{quantize(gain * mean.x), quantize(gain * mean.y),
                                           quantize(gain * mean.z)};
                if (coverage) coverage->pixels[p] = quantize(255.0 * hits * inv_n2);
            }
        }
    }
}

}  // namespace scene
