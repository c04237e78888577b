#include "model/sensor/truth.h"

#include "model/sensor/fault.h"

namespace sensor {

uint32_t timing_fault_mask() {
    return fault_bit(fault_kind::dropped_line) | fault_bit(fault_kind::dropped_frame) |
           fault_bit(fault_kind::vsync_glitch) | fault_bit(fault_kind::href_glitch);
}

bool pair_in_step(const frame_truth& a, const frame_truth& b, simtime::rational_ticks pclk) {
    if (!a.complete || !b.complete || a.dropped || b.dropped) return false;
    if (!a.have_active || !b.have_active) return false;
    if (a.scene_frame != b.scene_frame) return false;
    if (((a.faults | b.faults) & timing_fault_mask()) != 0) return false;
    const auto within_one_clock = [&](simtime::ticks x, simtime::ticks y) {
        const simtime::ticks d = x > y ? x - y : y - x;
        return static_cast<__int128>(d) * pclk.den < pclk.num;
    };
    return within_one_clock(a.first_active_tick, b.first_active_tick) &&
           within_one_clock(a.last_active_tick, b.last_active_tick);
}

}  // namespace sensor
