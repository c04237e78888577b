// The larger and the smaller of two ints, an int's magnitude and an integer
// square root: the box arithmetic of the firmware's rules (dsp/box_refit.*,
// dsp/extent_window.*, dsp/round_box.*, the outline's ellipse, the
// controller), which keeps to plain integer code as the DSP build would.
#pragma once

#include <cstdint>

namespace dsp {

inline int max_int(int a, int b) {
    return a > b ? a : b;
}
inline int min_int(int a, int b) {
    return a < b ? a : b;
}
inline int abs_int(int a) {
    return a < 0 ? -a : a;
}
// floor(sqrt(v)) for 0 <= v < 2^62, by bits (31 steps).
inline int64_t isqrt64(int64_t v) {
    int64_t r = 0;
    for (int64_t bit = int64_t{1} << 30; bit > 0; bit >>= 1)
        if ((r + bit) * (r + bit) <= v) r += bit;
    return r;
}

}  // namespace dsp
