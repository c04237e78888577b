// RGB to 8-bit gray with the paper's weights Y = 0.299 R + 0.587 G + 0.114 B,
// as integers (the C6416 has no FPU).
//
// Computes: Y = (R * 9798 + G * 19235 + B * 3735 + 16384) >> 15: Q15 weights
//   (round(32768 * w), summing to 32768) rounded half up. These are the
//   weights and the rounding of OpenCV 4.x's cv::cvtColor(COLOR_RGB2GRAY) on
//   8-bit data (gray_shift = 15), so the result equals OpenCV's on all 2^24
//   colours (tests/dsp/test_gray.cpp). The older Q14 weights
//   (4899, 9617, 1868; OpenCV 2.x/3.x) differ from it by 1 on 43,864 colours.
//   The weighted sum is at most 255 * 32768 + 16384 < 2^24: 32-bit unsigned
//   arithmetic never overflows and no clamp is needed.
// Assumes: out has in's size.
// Cost (C reference, per pixel): 3 byte loads, 3 multiplications, 3 additions,
//   1 shift, 1 store. The weights fit 16 bits, so on the C64x the products
//   run in 16-bit lanes (DOTP2 / MPYU2, two pixels' worth per .M unit);
//   the modelled cycles of the fused path are cost::demosaic_gray_cycles
//   (dsp/kernel_costs.h).
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

constexpr uint32_t gray_weight_r_q15 = 9798;
constexpr uint32_t gray_weight_g_q15 = 19235;
constexpr uint32_t gray_weight_b_q15 = 3735;
static_assert(gray_weight_r_q15 + gray_weight_g_q15 + gray_weight_b_q15 == 1u << 15,
              "white must stay 255");

inline uint8_t gray_of(rgb8 p) {
    return static_cast<uint8_t>((p.r * gray_weight_r_q15 + p.g * gray_weight_g_q15 +
                                 p.b * gray_weight_b_q15 + (1u << 14)) >>
                                15);
}

void rgb_to_gray(rgb_cplane in, gray_plane out);
void rgb_row_to_gray(const rgb8* in, int width, uint8_t* out);

}  // namespace dsp
