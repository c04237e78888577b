// 3x3 Sobel edge magnitude, IMG_sobel semantics (hardware-facts.md section 5):
//   H = -i00 - 2 i01 - i02 + i20 + 2 i21 + i22   (vertical gradient)
//   V = -i00 + i02 - 2 i10 + 2 i12 - i20 + i22   (horizontal gradient)
//   out = min(255, |H| + |V|)
// Assumes: out has in's size, width and height >= 3.
// Border: the outermost rows and columns are set to 0 (IMG_sobel leaves them
//   undefined; we define them).
#pragma once

#include "dsp/image.h"

namespace dsp {

void sobel_3x3(gray_cplane in, gray_plane out);

// Only rows [y0, y1) of the output (a band around the epipolar line), for
// the edge stereo method; other rows are not touched.
void sobel_3x3_rows(gray_cplane in, int y0, int y1, gray_plane out);

}  // namespace dsp
