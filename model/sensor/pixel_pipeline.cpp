#include "model/sensor/pixel_pipeline.h"

#include <algorithm>

#include "model/scene/bayer_mosaic.h"
#include "model/sensor/pin_word.h"

namespace sensor {

namespace {

// Image coordinate of a border pixel: the outermost 2x2 CFA cell repeats, so
// the colour (parity) of every position is kept.
int clamp_keep_parity(int v, int size) {
    if (v < 0) return v & 1;
    if (v >= size) return size - 2 + ((v - size) & 1);
    return v;
}

int clamp_u8(int v) {
    return v < 0 ? 0 : (v > 255 ? 255 : v);
}

constexpr uint64_t noise_stream_salt = 0x4E4F495345ull;  // "NOISE"

}  // namespace

pixel_pipeline::pixel_pipeline(const sensor_profile& profile, const sensor_config& config)
    : m_profile(profile) {
    m_noise.configure(config.noise, config.read_noise_dn, config.shot_noise_dn2_per_dn,
                      config.seed ^ noise_stream_salt);
    const int cols = m_profile.readout_cols();
    m_col_image_x.resize(cols);
    for (int i = 0; i < cols; ++i) {
        const bool dark = i < m_profile.dark_cols_left || i >= cols - m_profile.dark_cols_right;
        m_col_image_x[i] =
            dark ? -1 : clamp_keep_parity(i - m_profile.active_col0(), m_profile.active_cols);
    }
    const int rows = m_profile.readout_rows();
    m_row_image_y.resize(rows);
    for (int r = 0; r < rows; ++r) {
        const bool dark = r < m_profile.dark_rows_top || r >= rows - m_profile.dark_rows_bottom;
        m_row_image_y[r] =
            dark ? -1 : clamp_keep_parity(r - m_profile.active_row0(), m_profile.active_rows);
    }
}

void pixel_pipeline::hold_image(const dsp::rgb_cplane& image, uint64_t scene_frame) {
    m_image = image;
    m_have_image = true;
    m_image_scene_frame = scene_frame;
}

int pixel_pipeline::pixel_value(int x, int y) {
    const int s = scene::cfa_sample(m_image.at(x, y), scene::cfa_colour_at(m_profile.cfa, x, y));
    // 64-bit: gain x exposure ratio may exceed 2^15 / 255; the signal
    // saturates far above 255 (the clamp below) and the noise table's range.
    const int64_t scaled = (static_cast<int64_t>(s) * m_gain_q16 + 32768) >> 16;
    const int signal = static_cast<int>(std::min<int64_t>(scaled, 1 << 20));
    int v = m_profile.black_level + signal;
    if (m_noise.enabled()) v += m_noise.sample(signal);
    return clamp_u8(v);
}

void pixel_pipeline::read_row(int row, int from_col, int dark_level, uint16_t* out) {
    const int y = m_row_image_y[row];
    const int n = m_profile.readout_cols();
    for (int i = from_col; i < n; ++i) {
        const int x = m_col_image_x[i];
        int v;
        if (x < 0 || y < 0) {
            v = dark_level;
            if (m_noise.enabled()) v = clamp_u8(v + m_noise.sample(0));
        } else {
            v = pixel_value(x, y);
        }
        // The frame's FODD level, already in the word, stays.
        out[i] = static_cast<uint16_t>((out[i] & pin_word::fodd_bit) | pin_word::valid_bit |
                                       pin_word::href_bit | static_cast<uint16_t>(v));
    }
}

}  // namespace sensor
