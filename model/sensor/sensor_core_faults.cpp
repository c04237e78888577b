// sensor_core's fault triggers: when each added fault fires, at its own
// granularity (frame, line, pixel clock; fault.h). What a pixel fault then
// does to the pins is fault_effects'; the drifting oscillator is the core's.
#include <algorithm>
#include <stdexcept>

#include "model/sensor/sensor_core.h"

namespace sensor {

namespace {

bool is_pixel_fault(fault_kind k) {
    return k != fault_kind::start_skew && k != fault_kind::dropped_frame &&
           k != fault_kind::extra_frame && k != fault_kind::dropped_line;
}

bool is_glitch(fault_kind k) {
    return k == fault_kind::vsync_glitch || k == fault_kind::href_glitch;
}

}  // namespace

void sensor_core::add_fault(const fault& f) {
    if (f.kind == fault_kind::stuck_data_bit && (f.bit < 0 || f.bit > 7))
        throw std::invalid_argument("stuck_data_bit: bit must be 0..7");
    if (is_glitch(f.kind) && f.width_pclks < 1)
        throw std::invalid_argument("glitch width must be >= 1 pclk");
    if (f.kind == fault_kind::start_skew && f.skew_pclks < 0)
        throw std::invalid_argument("start_skew must be >= 0 pclk");
    if (f.kind == fault_kind::pclk_drift && (f.drift_ppm <= -1000000 || f.drift_ppm >= 1000000))
        throw std::invalid_argument("pclk_drift: |ppm| must be < 1e6");
    m_pending.push_back({f, false});
    // A pixel fault may now start inside the current segment.
    limit_segment();
}

// ---- frame and line faults -------------------------------------------------------------------

// dropped_frame and extra_frame faults reached at the start of frame t.
void sensor_core::take_frame_faults(frame_truth& t) {
    m_extra_after = false;
    m_frame_dropped = false;
    for (pending& p : m_pending) {
        if (p.fired) continue;
        if (p.f.kind != fault_kind::dropped_frame && p.f.kind != fault_kind::extra_frame) continue;
        if (!frame_fault_reached(p.f, t.index, m_cycle)) continue;
        p.fired = true;
        if (p.f.kind == fault_kind::dropped_frame) {
            m_frame_dropped = true;
            t.dropped = true;
            t.faults |= fault_bit(fault_kind::dropped_frame);
        } else {
            m_extra_after = true;
        }
    }
}

// Whether a dropped_line fault takes the readout line starting now.
bool sensor_core::take_dropped_line() {
    bool dropped = false;
    for (pending& p : m_pending) {
        if (p.fired || p.f.kind != fault_kind::dropped_line) continue;
        const bool reached = p.f.when.by_time
                                 ? p.f.when.tick <= rise_of(m_cycle)
                                 : position_reached(p.f.when, m_truth.back().index, m_line, 0);
        if (!reached) continue;
        p.fired = true;
        dropped = true;
        m_truth.back().faults |= fault_bit(fault_kind::dropped_line);
    }
    return dropped;
}

bool sensor_core::position_reached(const fault_trigger& t, uint64_t frame, int line,
                                   int col) const {
    if (t.frame != frame) return t.frame < frame;
    if (t.line != line) return t.line < line;
    return t.col <= col;
}

bool sensor_core::frame_fault_reached(const fault& f, uint64_t frame_index,
                                      uint64_t start_cycle) const {
    if (f.when.by_time) return f.when.tick <= rise_of(start_cycle);
    return position_reached(f.when, frame_index, 0, 0);
}

// ---- pixel faults ----------------------------------------------------------------------------

uint64_t sensor_core::onset_cycle(const fault& f) const {
    if (f.when.by_time) {
        const uint64_t n = m_clock_origin_cycle + m_clock.first_rise_at_or_after(f.when.tick);
        return std::max(n, m_cycle);
    }
    if (m_phase != phase::frame) return never;  // positions do not advance between frames
    const uint64_t current = m_truth.back().index;
    if (f.when.frame < current) return m_cycle;
    if (f.when.frame > current) return never;
    const uint64_t at = m_frame_start_cycle +
                        static_cast<uint64_t>(f.when.line) * m_profile.line_pclks +
                        static_cast<uint64_t>(f.when.col);
    return std::max(at, m_cycle);
}

uint64_t sensor_core::next_pixel_fault_onset() const {
    uint64_t next = never;
    for (const pending& p : m_pending)
        if (!p.fired && is_pixel_fault(p.f.kind)) next = std::min(next, onset_cycle(p.f));
    return next;
}

bool sensor_core::activate_due_faults() {
    bool any = false;
    // Index loop: activate() never adds to m_pending.
    for (size_t i = 0; i < m_pending.size(); ++i) {
        pending& p = m_pending[i];
        if (p.fired || !is_pixel_fault(p.f.kind)) continue;
        if (onset_cycle(p.f) > m_cycle) continue;
        p.fired = true;
        activate(p.f);
        any = true;
    }
    if (any) {
        // Re-derive the rest of the current segment with the new fault state.
        if (m_phase == phase::frame) {
            build_line(m_col);
        } else {
            std::fill(m_words.begin() + m_col, m_words.begin() + m_seg_natural_end, const_word());
            m_effects.apply(m_words.data(), m_col, m_seg_natural_end, m_seg_start_cycle);
        }
    }
    return any;
}

void sensor_core::activate(const fault& f) {
    const uint32_t bit = fault_bit(f.kind);
    if (f.kind == fault_kind::pclk_drift) {
        switch_to_own_oscillator(f.drift_ppm);
    } else if (!m_effects.activate(f, m_cycle)) {
        return;
    }
    // A glitch is over after its window; the others stay from now on.
    if (!is_glitch(f.kind)) m_persistent_faults |= bit;
    if (m_phase == phase::frame) m_truth.back().faults |= bit;
}

// The new oscillator's first edge is this cycle's rising edge, as the master
// clock would have placed it (m_cursor is on it).
void sensor_core::switch_to_own_oscillator(int32_t drift_ppm) {
    const simtime::ticks origin = m_cursor.tick();
    m_clock = simtime::tick_clock(m_profile.pclk_period(), origin, drift_ppm);
    m_clock_origin_cycle = m_cycle;
    m_cursor.reset(m_clock);
    m_on_master_clock = false;
}

}  // namespace sensor
