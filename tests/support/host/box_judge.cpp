#include "tests/support/host/box_judge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace host {

double side_error_allowed_px(int object_side_px) {
    return std::max(min_side_error_px, max_side_error * object_side_px);
}

double processing_ms(const host_record& rec) {
    uint64_t cycles = 0;
    for (uint64_t stage : rec.firmware.stage_cycles) cycles += stage;
    return platform::cycles_to_ms(cycles);
}

void box_errors::score(const host_record& rec, const platform::frame_errors& e) {
    ++scored;
    box_sum_px += e.box_centre_err_px;
    box_max_px = std::max(box_max_px, e.box_centre_err_px);
    depth_max_pct = std::max(depth_max_pct, std::fabs(e.depth_err_pct));
    const stereosim_box& b = rec.out.box_right;
    const dsp::box& o = rec.truth.right.pixel_box;
    const int off_w = b.w - o.width, off_h = b.h - o.height;
    char text[48];
    std::snprintf(text, sizeof text, " %d:(%+d,%+d)", rec.index, off_w, off_h);
    sides += text;
    side_max_pct = std::max(
        {side_max_pct, 100.0 * std::abs(off_w) / o.width, 100.0 * std::abs(off_h) / o.height});
    side_over_px = std::max({side_over_px, std::abs(off_w) - side_error_allowed_px(o.width),
                             std::abs(off_h) - side_error_allowed_px(o.height)});
}

}  // namespace host
