// Sum of absolute differences (paper eq. 5) and the exhaustive SAD search
// used by tracking and by stereo matching.
//
//   SAD(x, y) = sum_ij |image(x + i, y + j) - pattern(i, j)|
//
// sad_search evaluates every top-left position in `positions` (clipped so
// the pattern stays inside the image) and returns the minimum; ties go to
// the first position in raster order (smallest y, then smallest x), the
// same rule as the brute-force reference in the tests.
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

uint32_t sad_at(gray_cplane image, int x, int y, gray_cplane pattern);

struct sad_result {
    bool valid = false;  // false when no position fits inside the image
    int x = 0;
    int y = 0;
    uint32_t sad = 0;
    int positions = 0;  // positions evaluated (for the cost model)
};

// positions: x in [positions.x, positions.right()), y in [positions.y, positions.bottom()).
sad_result sad_search(gray_cplane image, gray_cplane pattern, box positions);

}  // namespace dsp
