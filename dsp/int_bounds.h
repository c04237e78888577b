// The larger and the smaller of two ints, and an int's magnitude: the box arithmetic of the
// firmware's rules (dsp/box_refit.*, dsp/extent_window.*, the controller),
// which keeps to plain integer code as the DSP build would.
#pragma once

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

}  // namespace dsp
