// Pre-processing (paper step 2), fused line by line as a DSP engineer would
// write it so no full-frame RGB image is ever stored: Bayer raw -> bilinear
// RGB row -> gray row, then brightness compensation.
//
// Brightness compensation (documented method): a global gain towards a
//   target mean. The mean of the gray frame is measured while the rows are
//   produced; gain_q8 = round(256 * target_mean / mean), clamped to
//   [min_gain_q8, max_gain_q8]; then every pixel p -> min(255, (p * gain_q8
//   + 128) >> 8), applied through a 256-entry lookup table built once per
//   frame. A multiplicative global lighting change is cancelled up to
//   rounding, so it does not look like motion to the temporal differencing.
// Assumes: raw and out have the same size; width even and >= 4; line_scratch
//   holds raw.width rgb8.
#pragma once

#include <cstdint>

#include "dsp/bayer_demosaic.h"
#include "dsp/image.h"

namespace dsp {

struct brightness_params {
    bool enabled = true;
    uint8_t target_mean = 110;
    uint16_t min_gain_q8 = 64;    // 0.25x
    uint16_t max_gain_q8 = 1024;  // 4x
};

struct preprocess_result {
    uint32_t mean_before = 0;  // mean gray level before compensation (rounded)
    uint16_t gain_q8 = 256;    // gain applied (256 = 1.0)
};

// Gain for a measured mean (sum of gray levels over pixel_count pixels).
uint16_t brightness_gain_q8(uint64_t gray_sum, uint32_t pixel_count, const brightness_params& params);

// In place: p -> min(255, (p * gain_q8 + 128) >> 8) via a lookup table.
void apply_gain(gray_plane image, uint16_t gain_q8);

// Fused raw Bayer -> gray with brightness compensation.
preprocess_result preprocess_raw_to_gray(gray_cplane raw, cfa_order order,
                                         const brightness_params& params, rgb8* line_scratch,
                                         gray_plane out);

}  // namespace dsp
