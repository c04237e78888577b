// RGB to 8-bit gray with the paper's weights Y = 0.299 R + 0.587 G + 0.114 B,
// as integers (the C6416 has no FPU).
//
// Computes: Y = (R * 4899 + G * 9617 + B * 1868 + 8192) >> 14 (Q14 weights
//   summing to 16384, the weights OpenCV uses for COLOR_RGB2GRAY).
// Assumes: out has in's size.
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

constexpr uint32_t gray_weight_r_q14 = 4899;
constexpr uint32_t gray_weight_g_q14 = 9617;
constexpr uint32_t gray_weight_b_q14 = 1868;

inline uint8_t gray_of(rgb8 p) {
    return static_cast<uint8_t>((p.r * gray_weight_r_q14 + p.g * gray_weight_g_q14 +
                                 p.b * gray_weight_b_q14 + (1u << 13)) >>
                                14);
}

void rgb_to_gray(rgb_cplane in, gray_plane out);
void rgb_row_to_gray(const rgb8* in, int width, uint8_t* out);

}  // namespace dsp
