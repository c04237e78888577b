// The bounds a tracked box is judged by on rendered pairs (docs/firmware.md,
// "The box's sides judged"): tests/dsp/test_box_on_motion.cpp and
// tests/dsp/test_box_on_return.cpp.
#pragma once

#include <algorithm>

namespace test_support {

constexpr int untracked_start_pairs = 2;  // tracked pairs before the bounds apply
constexpr double max_mean_box_error_px = 3.0;
constexpr double max_box_error_px = 6.0;
constexpr double max_depth_error_pct = 1.0;
constexpr double max_side_error = 0.20;  // of the object's side (side_error_allowed_px)
constexpr double min_side_error_px = 3.0;
constexpr double frame_period_ms = 24.5;  // docs/design-brief.md

// A box on the object covers it: each side within a fifth of the object's
// (3 px for a small one) of the pixels the object's ellipse touches. The
// centre and depth bounds alone passed a box reported at three quarters of
// its size about its centre (docs/firmware.md, "The box's sides judged").
inline double side_error_allowed_px(int object_side_px) {
    return std::max(min_side_error_px, max_side_error * object_side_px);
}

}  // namespace test_support
