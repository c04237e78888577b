// How a tracked box is judged on rendered pairs (docs/firmware.md, "The box's
// sides judged"): the bounds, and the errors of a track's scored pairs
// against them (tests/dsp/test_box_on_motion.cpp, test_box_on_return.cpp).
#pragma once

#include <string>

#include "tb/platform/scoring/error_metrics.h"
#include "tests/support/host/stereo_runner.h"

namespace host {

constexpr int untracked_start_pairs = 2;  // tracked pairs before the bounds apply
constexpr int min_judged_pairs = 5;       // a verdict on fewer judges too little
constexpr double max_mean_box_error_px = 3.0;
constexpr double max_box_error_px = 6.0;
constexpr double max_depth_error_pct = 1.0;
constexpr double max_side_error = 0.20;  // of the object's side (side_error_allowed_px)
constexpr double min_side_error_px = 3.0;
constexpr double frame_period_ms = 24.5;  // docs/design-brief.md

// A box on the object covers it: each side within a fifth of the object's
// (3 px for a small one) of the pixels the object's ellipse touches. The
// centre and depth bounds alone passed a box reported at three quarters of
// its size about its centre.
double side_error_allowed_px(int object_side_px);

// The firmware's processing time of a pair, all stages, at 600 MHz.
double processing_ms(const host_record& rec);

// A track's scored pairs: box centre error, |depth| error, and its box's
// sides against the object's (`sides`: " index:(w,h px)" box side less the
// object's, each pair).
struct box_errors {
    int scored = 0;
    double box_sum_px = 0.0, box_max_px = 0.0, depth_max_pct = 0.0;
    double side_max_pct = 0.0;   // the most a side is off, of the object's
    double side_over_px = -1.0;  // by how much more than the bound allows
    std::string sides;

    void score(const host_record& rec, const platform::frame_errors& e);
    double box_mean_px() const { return scored > 0 ? box_sum_px / scored : 0.0; }
};

}  // namespace host
