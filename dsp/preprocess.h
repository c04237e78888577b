// Pre-processing (paper step 2), fused line by line as a DSP engineer would
// write it so no full-frame RGB image is ever stored: Bayer raw -> bilinear
// RGB row (line_scratch) -> gray row (out), then brightness compensation.
//
// Brightness compensation (documented method): a global gain towards a
//   target mean. The sum of the gray frame is accumulated while the rows are
//   produced; with mean = gray_sum / pixel_count (exact, not rounded),
//   gain_q8 = round(256 * target_mean / mean)
//           = (256 * target_mean * pixel_count + gray_sum / 2) / gray_sum
//   in 64-bit integers (one division per frame), clamped to
//   [min_gain_q8, max_gain_q8]; a black frame (sum 0) gets max_gain_q8 and a
//   disabled compensation gain 256. Then every pixel
//   p -> min(255, (p * gain_q8 + 128) >> 8), applied through a 256-entry
//   lookup table built once per frame (a gain of exactly 256 is the identity
//   and skips the pass). A multiplicative global lighting change is
//   cancelled up to rounding, so it does not look like motion to the
//   temporal differencing.
// Assumes: raw and out have the same size; width and height even and >= 4
//   (bayer_demosaic.h); line_scratch holds raw.width rgb8. With a size
//   mismatch or a too small raw nothing is written and the result is the
//   default (mean 0, gain 256).
// Cost (C reference): demosaic row + gray row (see bayer_demosaic.h,
//   gray_convert.h) + 1 addition per pixel for the sum; then 256 LUT entries
//   and 1 load, 1 table lookup, 1 store per pixel. Modelled C64x cycles:
//   cost::demosaic_gray_cycles and cost::brightness_cycles (dsp/kernel_costs.h).
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
    uint32_t mean_before = 0;  // mean gray level before compensation (rounded half up)
    uint16_t gain_q8 = 256;    // gain applied (256 = 1.0)
};

// Gain for a measured mean (sum of gray levels over pixel_count pixels).
uint16_t brightness_gain_q8(uint64_t gray_sum, uint32_t pixel_count,
                            const brightness_params& params);

// In place: p -> min(255, (p * gain_q8 + 128) >> 8) via a lookup table.
void apply_gain(gray_plane image, uint16_t gain_q8);

// Fused raw Bayer -> gray with brightness compensation. Equals
// demosaic_bilinear -> rgb_to_gray -> brightness_gain_q8 (of the gray sum)
// -> apply_gain done one after the other, exactly.
preprocess_result preprocess_raw_to_gray(gray_cplane raw, cfa_order order,
                                         const brightness_params& params, rgb8* line_scratch,
                                         gray_plane out);

}  // namespace dsp
