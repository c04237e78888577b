#include "model/scene/texture.h"

#include <algorithm>
#include <cmath>

#include "model/scene/cosine.h"

namespace scene {
namespace {

constexpr double two_pi = 6.28318530717958647692;

// sin(z) / z, exact limit at 0.
double sinc(double z) {
    return std::fabs(z) < 1e-8 ? 1.0 - z * z / 6.0 : std::sin(z) / z;
}

// Continuous mirrored repetition of [0, n - 1].
double mirror(double u, int n) {
    if (n <= 1) return 0.0;
    const double period = 2.0 * (n - 1);
    u = std::fmod(u, period);
    if (u < 0.0) u += period;
    return u > n - 1 ? period - u : u;
}

}  // namespace

uint64_t random_stream::next() {
    uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double random_stream::uniform() {
    return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

plane_texture::plane_texture(const procedural_texture_params& params) : m_mean(params.mean_level) {
    random_stream rng(params.seed);
    const int n = std::max(0, params.components);
    const double log_min = std::log(params.min_wavelength_m);
    const double log_max = std::log(params.max_wavelength_m);
    m_components.reserve(static_cast<size_t>(n));
    std::vector<double> weight;  // relative amplitude of each component
    for (int i = 0; i < n; ++i) {
        component c{};
        const double angle = rng.uniform(0.0, two_pi);
        const double wavelength = std::exp(rng.uniform(log_min, log_max));
        const double k = two_pi / wavelength;
        c.kx = k * std::cos(angle);
        c.ky = k * std::sin(angle);
        c.phase = rng.uniform(0.0, two_pi);
        for (double& amp : c.amplitude) {
            amp = 1.0 + params.colour_variation * rng.uniform(-1.0, 1.0);
        }
        weight.push_back(std::pow(wavelength / params.max_wavelength_m, params.amplitude_exponent));
        m_components.push_back(c);
    }
    // Each cosine has variance a^2 / 2: scale so the sum has the requested
    // standard deviation.
    double variance = 0.0;
    for (double w : weight) variance += 0.5 * w * w;
    const double scale = variance > 0.0 ? params.contrast / std::sqrt(variance) : 0.0;
    for (size_t i = 0; i < m_components.size(); ++i) {
        for (double& amp : m_components[i].amplitude) amp *= scale * weight[i];
    }
}

vec3 plane_texture::radiance(double x_m, double y_m) const {
    return box_mean(x_m, y_m, 0.0, 0.0);
}

vec3 plane_texture::box_mean(double x_m, double y_m, double w_m, double h_m) const {
    double out[3] = {m_mean, m_mean, m_mean};
    for (const component& c : m_components) {
        const double s = std::cos(c.kx * x_m + c.ky * y_m + c.phase) * sinc(0.5 * c.kx * w_m) *
                         sinc(0.5 * c.ky * h_m);
        for (int ch = 0; ch < 3; ++ch) out[ch] += c.amplitude[ch] * s;
    }
    return {out[0], out[1], out[2]};
}

void plane_texture::grid_box_means(double x0_m, double y0_m, double step_m, int width, int height,
                                   std::vector<float>* rgb) const {
    const size_t w = static_cast<size_t>(width), h = static_cast<size_t>(height);
    const size_t n = m_components.size();
    // cos(A + B) = cos A cos B - sin A sin B with A along the row, B down the
    // column: per-component tables make each pixel a few multiply-adds.
    std::vector<double> col_cos(n * w), col_sin(n * w), row_cos(n * h), row_sin(n * h);
    for (size_t k = 0; k < n; ++k) {
        const component& c = m_components[k];
        const double sx = sinc(0.5 * c.kx * step_m), sy = sinc(0.5 * c.ky * step_m);
        for (size_t i = 0; i < w; ++i) {
            const double a = c.kx * (x0_m + static_cast<double>(i) * step_m) + c.phase;
            col_cos[k * w + i] = std::cos(a) * sx;
            col_sin[k * w + i] = std::sin(a) * sx;
        }
        for (size_t j = 0; j < h; ++j) {
            const double b = c.ky * (y0_m + static_cast<double>(j) * step_m);
            row_cos[k * h + j] = std::cos(b) * sy;
            row_sin[k * h + j] = std::sin(b) * sy;
        }
    }
    rgb->assign(3 * w * h, 0.0f);
    std::vector<double> acc(3 * w);
    for (size_t j = 0; j < h; ++j) {
        std::fill(acc.begin(), acc.end(), m_mean);
        for (size_t k = 0; k < n; ++k) {
            const component& c = m_components[k];
            const double cb = row_cos[k * h + j], sb = row_sin[k * h + j];
            const double* ca = &col_cos[k * w];
            const double* sa = &col_sin[k * w];
            for (size_t i = 0; i < w; ++i) {
                const double s = ca[i] * cb - sa[i] * sb;
                acc[3 * i + 0] += c.amplitude[0] * s;
                acc[3 * i + 1] += c.amplitude[1] * s;
                acc[3 * i + 2] += c.amplitude[2] * s;
            }
        }
        float* out = rgb->data() + 3 * w * j;
        for (size_t i = 0; i < 3 * w; ++i) out[i] = static_cast<float>(acc[i]);
    }
}

sphere_texture::sphere_texture(const sphere_texture_params& params) {
    random_stream rng(params.seed);
    const int n = std::max(0, params.components);
    m_scale = n > 0 ? params.contrast / std::sqrt(0.5 * n) : 0.0;
    for (int i = 0; i < n; ++i) {
        // Uniform direction on the sphere, then a magnitude in [min, max].
        const double z = rng.uniform(-1.0, 1.0);
        const double phi = rng.uniform(0.0, two_pi);
        const double rxy = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double k = rng.uniform(params.min_wave_number, params.max_wave_number);
        component c{{k * rxy * std::cos(phi), k * rxy * std::sin(phi), k * z},
                    rng.uniform(0.0, two_pi)};
        m_components.push_back(c);
    }
    if (params.contrast > 0.0) m_clamp = 2.5 * params.contrast;
}

double sphere_texture::factor(vec3 n_body) const {
    double s = 0.0;
    for (const component& c : m_components) s += cosine(dot(c.k, n_body) + c.phase);
    return 1.0 + std::clamp(m_scale * s, -m_clamp, m_clamp);
}

vec3 texture_image::sample(double u, double v) const {
    if (width <= 0 || height <= 0) return {};
    u = mirror(u, width);
    v = mirror(v, height);
    const int i0 = std::min(static_cast<int>(u), width - 1);
    const int j0 = std::min(static_cast<int>(v), height - 1);
    const int i1 = std::min(i0 + 1, width - 1);
    const int j1 = std::min(j0 + 1, height - 1);
    const double fx = u - i0, fy = v - j0;
    auto px = [&](int i, int j) {
        const dsp::rgb8 p = pixels[static_cast<size_t>(j) * static_cast<size_t>(width) + i];
        return vec3{double(p.r), double(p.g), double(p.b)};
    };
    const vec3 top = px(i0, j0) * (1.0 - fx) + px(i1, j0) * fx;
    const vec3 bottom = px(i0, j1) * (1.0 - fx) + px(i1, j1) * fx;
    return top * (1.0 - fy) + bottom * fy;
}

}  // namespace scene
