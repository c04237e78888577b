// Rule 11's inputs (recovery_rule.h) from a finished platform run: the card's
// pins and STATUS.STATE from the island's observer, the DSP's CTRL writes
// from the probe HAL, the sensors' VSYNC rises from their timing truth.
#include <algorithm>

#include "tb/app/faults/observe.h"
#include "tb/app/faults/recovery_rule.h"

namespace faults {

recovery_inputs gather_recovery_inputs(const platform::platform_top& top,
                                       const std::vector<fault_spec>& specs,
                                       const std::vector<simtime::ticks>& onsets) {
    const platform::platform_config& config = top.config();
    const platform::island& isl = top.cycle_island();
    recovery_inputs in;
    in.frame_readies = isl.irq_rises(0);
    in.sync_errors = isl.irq_rises(1);
    in.overflows = isl.irq_rises(2);
    for (const platform::timeline_event& e : top.events().events())
        if (e.kind == platform::event_kind::oe && e.a == 1) in.oe_rises.push_back(e.tick);
    for (int camera = 0; camera < 2; ++camera)
        for (const sensor::frame_truth& f : isl.sensor(camera).truth())
            in.vsync_rises.push_back(f.start_tick);
    std::sort(in.vsync_rises.begin(), in.vsync_rises.end());
    for (const platform::card_state_change& s : isl.card_states())
        in.card_states.push_back({s.tick, s.state});
    double slow = 1.0;
    if (top.firmware_started()) {
        for (const platform::register_write& w : top.probe().card_control_writes())
            in.enable_writes.push_back({w.tick, w.value});
        for (const platform::fw_event& e : top.probe().fw_events()) {
            if (e.event.kind == STEREOSIM_EV_WATCHDOG)
                in.watchdog_reports.push_back(e.tick);
            if (e.event.kind == STEREOSIM_EV_HARD_ERROR)
                in.give_up = std::min(in.give_up, e.tick);
        }
    }
    for (size_t i = 0; i < specs.size() && i < onsets.size(); ++i) {
        if (onsets[i] == no_tick) continue;
        in.fault_onsets.push_back(onsets[i]);
        if (specs[i].type == fault_type::emif_wait) in.bus_fault_onsets.push_back(onsets[i]);
        if (specs[i].type == fault_type::cpu_slow) slow = std::max(slow, specs[i].factor);
    }
    // The recovery policy the firmware under test declared for this run.
    const stereosim_fw_policy& policy = top.firmware_policy();
    in.retry_limit = config.card_retry_limit;
    const simtime::rational_ticks pclk = config.profile.mclk_period;
    in.card_frame = static_cast<simtime::ticks>(config.profile.line_pclks) *
                    config.profile.frame_lines * pclk.num / pclk.den;
    in.watchdog = static_cast<simtime::ticks>(policy.watchdog_ms) * 1000000 * simtime::ticks_per_ns;
    in.service = static_cast<simtime::ticks>((1.0 + slow) * static_cast<double>(config.period));
    in.rearm_on_overflow = policy.rearm_on_overflow != 0;
    in.rearm_on_every_sync_error = policy.rearm_on_every_sync_error != 0;
    in.end = top.end_tick();
    return in;
}

}  // namespace faults
