// Deterministic, seeded, band-limited textures: one for the background plane,
// one fixed to a ball's surface, and a real image mapped on the plane.
// Radiance is in 8-bit levels (0..255) before the lighting gain.
//
// Randomness comes from splitmix64 with our own double conversion (not the
// std distributions, whose output is implementation-defined), so a seed
// gives the same texture on every platform and library.
#pragma once

#include <cstdint>
#include <vector>

#include "dsp/image.h"
#include "model/scene/geometry.h"

namespace scene {

// splitmix64: a tiny, well-mixed, reproducible generator.
class random_stream {
  public:
    explicit random_stream(uint64_t seed) : m_state(seed) {}
    uint64_t next();
    double uniform();  // [0, 1), 53-bit
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  private:
    uint64_t m_state;
};

// A sum of plane waves on the background plane (X, Y in metres):
//   L(X, Y) = mean + sum_n a_n cos(kx_n X + ky_n Y + phase_n)   per channel
// with random directions, wavelengths log-uniform in [min, max], amplitudes
// growing with the wavelength (see amplitude_exponent: cloudy, not busy) and
// per-channel amplitudes around a common one (mostly luminance texture with
// some colour). No energy above
// 2 pi / min_wavelength: band-limited, so SAD and edges see clean structure,
// and the average over any rectangle is exact in closed form (a sinc factor
// per axis), which is how the renderer antialiases the plane.
struct procedural_texture_params {
    uint64_t seed = 1;
    int components = 64;
    double min_wavelength_m = 0.03;  // ~4.7 px at 5 m with the default rig
    double max_wavelength_m = 0.8;
    double mean_level = 110.0;      // mean radiance, levels
    double contrast = 35.0;         // standard deviation of the luminance, levels
    double colour_variation = 0.4;  // relative spread of the per-channel amplitudes
    // Amplitude of a component proportional to wavelength^exponent: 0 puts
    // equal energy in every octave (a 1/f^2 power spectrum, like natural
    // images); > 0 weakens the fine scales (a smoother, less busy texture).
    double amplitude_exponent = 0.5;
};

class plane_texture {
  public:
    explicit plane_texture(const procedural_texture_params& params);

    // Radiance at a plane point.
    vec3 radiance(double x_m, double y_m) const;
    // Exact mean radiance over the rectangle [x +- w/2] x [y +- h/2].
    vec3 box_mean(double x_m, double y_m, double w_m, double h_m) const;

    // Box means for a grid of equal rectangles: column i centred at
    // x0 + i * step, row j at y0 + j * step, each step x step (a
    // fronto-parallel plane seen by a pinhole camera). Writes width x height
    // RGB float triples, row-major. Separable: O(components) per pixel.
    void grid_box_means(double x0_m, double y0_m, double step_m, int width, int height,
                        std::vector<float>* rgb) const;

  private:
    struct component {
        double kx, ky, phase;
        double amplitude[3];
    };
    std::vector<component> m_components;
    double m_mean;
};

// A texture fixed to a sphere, a function of the unit normal n in the ball's
// own frame: factor(n) = 1 + contrast * clamp(s(n), -2.5, 2.5), where s is a
// unit-variance sum of cos(k_m . n + phase_m), |k_m| in [min, max] radians
// per radius (features of about a quarter to a half of the radius).
struct sphere_texture_params {
    uint64_t seed = 7;
    int components = 10;
    double contrast = 0.25;  // relative standard deviation of the albedo
    double min_wave_number = 3.0;
    double max_wave_number = 9.0;
};

class sphere_texture {
  public:
    explicit sphere_texture(const sphere_texture_params& params);
    double factor(vec3 n_body) const;

  private:
    struct component {
        vec3 k;
        double phase;
    };
    std::vector<component> m_components;
    double m_scale = 0.0;  // contrast / standard deviation of the raw sum
    double m_clamp = 0.0;  // 2.5 standard deviations of the factor
};

// A real image to map on the background plane (the caller loads it; the scene
// library reads no files). Sampled bilinearly with mirrored repetition, so
// the plane is covered however far it extends.
struct texture_image {
    int width = 0;
    int height = 0;
    std::vector<dsp::rgb8> pixels;  // row-major

    // Bilinear sample at continuous texel coordinates (texel (i, j) centred
    // at (i, j), the pixel-index convention), mirrored outside.
    vec3 sample(double u, double v) const;
};

}  // namespace scene
