// The sensor's pixel pipeline, plain C++: for each readout column of a row,
// the scene image's colour under the CFA (model/scene/bayer_mosaic.h), times
// gain x exposure, plus the black level and noise, clamped to 8 bits; dark
// columns and rows read the dark level. The border's outermost 2x2 CFA cell
// repeats, so every position keeps its colour.
#pragma once

#include <cstdint>
#include <vector>

#include "dsp/image.h"
#include "model/sensor/pixel_noise.h"
#include "model/sensor/profile.h"
#include "model/sensor/sensor_config.h"

namespace sensor {

class pixel_pipeline {
  public:
    pixel_pipeline(const sensor_profile& profile, const sensor_config& config);

    // Gain x exposure ratio, Q16 (65536 = 1.0).
    void set_gain_q16(int64_t gain_q16) { m_gain_q16 = gain_q16; }
    // The image the next rows are read from, the scene frame it shows.
    void hold_image(const dsp::rgb_cplane& image, uint64_t scene_frame);
    bool holds_image_of(uint64_t scene_frame) const {
        return m_have_image && m_image_scene_frame == scene_frame;
    }

    // Readout columns [from_col, readout_cols) of readout row `row` as pin
    // words (valid, HREF, data) into out[from_col...]; dark pixels read
    // dark_level (plus noise).
    void read_row(int row, int from_col, int dark_level, uint16_t* out);

  private:
    int pixel_value(int x, int y);

    sensor_profile m_profile;
    int64_t m_gain_q16 = 65536;
    pixel_noise m_noise;
    // Image x (y) of each readout column (row), -1 for dark.
    std::vector<int> m_col_image_x;
    std::vector<int> m_row_image_y;
    dsp::rgb_cplane m_image{};
    bool m_have_image = false;
    uint64_t m_image_scene_frame = 0;
};

}  // namespace sensor
