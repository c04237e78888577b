// The reporting protocol's inputs (report_protocol.h) from a finished
// platform run: the firmware's reports and results, the DSP's CTRL writes on
// the bus, the processed pairs whose frames were never named, and whether
// the frame loop returned without being asked to.
#include "dsp/card_regs.h"
#include "tb/app/faults/observe.h"
#include "tb/app/faults/report_protocol.h"

namespace faults {

namespace {

// VERDICT's cause bits: a pair with any of them set is not to be used.
constexpr uint32_t verdict_causes =
    dsp::card_regs::verdict_l_window_mask | dsp::card_regs::verdict_r_window_mask |
    dsp::card_regs::verdict_l_dark_mask | dsp::card_regs::verdict_r_dark_mask |
    dsp::card_regs::verdict_l_vsync_mask | dsp::card_regs::verdict_r_vsync_mask |
    dsp::card_regs::verdict_start_timeout_mask | dsp::card_regs::verdict_overflow_mask;

}  // namespace

protocol_inputs gather_protocol_inputs(const platform::platform_top& top,
                                       const std::vector<platform::fw_event>& events,
                                       simtime::ticks window, simtime::ticks until) {
    protocol_inputs p;
    p.events = events;
    if (top.firmware_started()) {
        const platform::probe_hal& probe = top.probe();
        for (const platform::fw_result& r : probe.results()) p.result_pairs.push_back(r.pair);
        for (const platform::register_write& w : probe.card_control_writes())
            p.enable_writes.push_back({w.tick, w.value & dsp::card_regs::ctrl_enable_mask});
        // A loop that ended on the platform's stop request owes no reason.
        if (probe.halted_at() >= 0 && !probe.halted_on_request()) p.returned = probe.halted_at();
    }
    for (const platform::used_pair& u : top.used_pairs())
        if (!u.reported) p.unnamed_used_pairs.push_back(u.pair);
    p.until = until;
    p.window = window;
    p.verdict_causes = verdict_causes;
    return p;
}

}  // namespace faults
