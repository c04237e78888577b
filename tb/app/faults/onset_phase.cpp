// Where in the design's cycle a fault took effect (docs/fault-contract.md,
// "Coverage"): the line of the sensor frame it acted on, and what the card
// and the bus were doing then. The campaign's fault-space coverage counts
// these per kind, sensor and mode.
#include <algorithm>

#include "tb/app/faults/observe.h"
#include "tb/app/faults/recovery_rule.h"

namespace faults {

namespace {

// A line of the sensor's frame: its readout rows are dark or active
// (border rows count as active), the rest is vertical blanking.
const char* line_phase(const sensor::sensor_profile& p, int64_t line) {
    const int64_t first = p.first_row_line, row = line - first;
    if (row < 0 || row >= p.readout_rows()) return "vertical_blanking";
    if (row < p.dark_rows_top || row >= p.readout_rows() - p.dark_rows_bottom) return "dark_rows";
    return "active_rows";
}

// The frame of `truth` under tick t, or nullptr before the first.
const sensor::frame_truth* frame_at(const std::vector<sensor::frame_truth>& truth,
                                    simtime::ticks t) {
    const sensor::frame_truth* found = nullptr;
    for (const sensor::frame_truth& f : truth) {
        if (f.start_tick > t) break;
        found = &f;
    }
    return found;
}

}  // namespace

std::vector<std::string> onset_phases(const platform::platform_top& top, const fault_spec& s,
                                      simtime::ticks onset, bool frame_cut) {
    std::vector<std::string> phases;
    const platform::platform_config& config = top.config();
    const sensor::sensor_profile& p = config.profile;
    const simtime::rational_ticks pclk = p.mclk_period;
    const simtime::ticks line_ticks = p.line_pclks * pclk.num / pclk.den;
    const platform::island& isl = top.cycle_island();
    const int camera = is_sensor_fault(s.type) ? s.camera : 0;
    const sensor::frame_truth* frame = frame_at(isl.sensor(camera).truth(), onset);
    // (A dropped line's onset is its line's HREF: find_onset in observe.cpp.)
    if (frame != nullptr && line_ticks > 0) {
        phases.push_back(line_phase(p, (onset - frame->start_tick) / line_ticks));
    } else {
        phases.push_back("vertical_blanking");
    }
    // The card's OE controller just before: restarting (OE low), or waiting
    // for or running the first frame of a start (before its first check). A
    // dead sensor acts at an OE rise: the state before it is the restart's.
    uint8_t state = 0;
    simtime::ticks since = 0;
    for (const platform::card_state_change& c : isl.card_states()) {
        if (c.tick >= onset) break;
        state = c.state;
        since = c.tick;
    }
    const auto is = [&](card_state st) { return state == static_cast<uint8_t>(st); };
    const simtime::ticks card_frame = line_ticks * p.frame_lines;
    if (frame_cut || is(card_state::oe_low) || is(card_state::idle) || is(card_state::hard_error))
        phases.push_back("oe_restart");
    else if (is(card_state::wait_vsync) || (is(card_state::run) && onset - since < card_frame))
        phases.push_back("first_check");
    // A pixel-port burst of the EDMA ends within a line's read (160 words)
    // after the onset: the bus was reading the card.
    const std::vector<simtime::ticks>& bursts = isl.edma_completions();
    const auto next = std::lower_bound(bursts.begin(), bursts.end(), onset);
    if (next != bursts.end() && *next - onset <= 25000 * simtime::ticks_per_ns)
        phases.push_back("bus_burst");
    return phases;
}

}  // namespace faults
