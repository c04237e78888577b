// Sum of absolute differences (paper eq. 5) and the exhaustive SAD search
// used by tracking and by stereo matching.
//
//   SAD(x, y) = sum_ij |image(x + i, y + j) - pattern(i, j)|
//
// Computes: sad_search evaluates every top-left position in `positions`
//   (clipped so the pattern stays inside the image) and returns the minimum;
//   ties go to the first position in raster order (smallest y, then smallest
//   x), the same rule as the brute-force reference in the tests.
// Assumes: 8-bit gray planes, any width and stride (no alignment, no
//   multiple-of-8 size: a row is summed 16 and 8 pixels per step and its
//   last width % 8 pixels singly); pattern area * 255 < 2^32 (any pattern
//   up to 4096 x 4096).
// Costs (C64x, hand-scheduled in the manner of IMGLIB's IMG_mad_16x16):
//   dsp::cost::sad_search_cycles(pattern_w, pattern_h, positions): per
//   pattern row and 8 pixels LDNDW image + LDDW pattern (.D), two SUBABS4
//   (.L), two DOTPU4 against 0x01010101 (.M) summing the bytes; a 40x40
//   position costs 258 cycles (0.16 cycles/pixel). IMG_mad_16x16 publishes
//   38 cycles per 256-pixel position (docs/hardware-facts.md section 5).
//   No early exit: the cost is fixed by the sizes, not by the data. The host
//   code's fixed-count 16- and 8-pixel steps become the compiler's SIMD
//   (PSADBW on x86).
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

// SAD of the pattern placed with its top-left pixel at (x, y); the caller
// keeps the pattern inside the image.
uint32_t sad_at(gray_cplane image, int x, int y, gray_cplane pattern);

struct sad_result {
    bool valid = false;  // false when no position fits inside the image
    int x = 0;
    int y = 0;
    uint32_t sad = 0;
    int positions = 0;  // positions evaluated (for the cost model)
};

// positions: x in [positions.x, positions.right()), y in [positions.y,
// positions.bottom()), clipped to x in [0, image.width - pattern.width], y in
// [0, image.height - pattern.height].
sad_result sad_search(gray_cplane image, gray_cplane pattern, box positions);

// `positions` clipped as sad_search clips it (empty when nothing fits).
box clip_positions(box positions, int image_width, int image_height, int pattern_width,
                   int pattern_height);

}  // namespace dsp
