// 3x3 Sobel edge magnitude, IMG_sobel semantics (docs/hardware-facts.md section 5,
// the IMGLIB v1.03 C reference):
//   H = -i00 - 2 i01 - i02 + i20 + 2 i21 + i22   (vertical gradient, d/dy)
//   V = -i00 + i02 - 2 i10 + 2 i12 - i20 + i22   (horizontal gradient, d/dx)
//   out = min(255, |H| + |V|)
//   (irc = input at row r, column c of the 3x3 window). Integer only:
//   |H|, |V| <= 1020, the sum fits 16 bits. Equals saturate(|dx| + |dy|)
//   of cv::Sobel(CV_16S, ksize 3) on interior pixels, exactly
//   (tests/dsp/test_sobel.cpp).
// Assumes: out has in's size, width and height >= 3 (smaller images: nothing
//   is written).
// Border: the outermost rows and columns are set to 0 (IMG_sobel leaves them
//   undefined; we define them).
// Cost (C reference, per interior pixel): the column terms a + 2b + c and
//   c - a are computed once per column and reused by three outputs, so per
//   pixel 3 loads, 8 additions/subtractions/shifts, 2 absolute values,
//   1 saturation, 1 store. The C64x 8-bit IMG_sobel cycle formula is NOT
//   FOUND (docs/hardware-facts.md section 5; the C64x+ IMG_sobel_3x3_16 costs
//   15 * cols * (rows - 2) / 4 + 32). Modelled cycles: cost::sobel_cycles
//   (dsp/kernel_costs.h).
#pragma once

#include "dsp/image.h"

namespace dsp {

void sobel_3x3(gray_cplane in, gray_plane out);

// Only rows [y0, y1) of the output (a band around the epipolar line), for
// the edge stereo method; other rows are not touched. The band is clipped to
// [0, height); its rows equal the same rows of sobel_3x3 exactly (rows 0 and
// height-1 are 0).
void sobel_3x3_rows(gray_cplane in, int y0, int y1, gray_plane out);

}  // namespace dsp
