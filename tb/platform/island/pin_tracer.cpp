#include "tb/platform/island/pin_tracer.h"

#include <algorithm>

#include "model/sensor/sensor_core.h"

namespace platform {

namespace {

using simtime::ticks;

// The warm-up's start (pin_tracer.h): 16 periods of the slower clock before the window.
ticks edges_from(const island_config& config, const simtime::tick_clock& eclk) {
    const ticks pclk_period = config.pclk.period_num() / config.pclk.period_den() + 1;
    const ticks eclk_period = eclk.period_num() / eclk.period_den() + 1;
    const ticks warmup = 16 * std::max(pclk_period, eclk_period);
    const ticks from = std::min(config.trace_window.from, config.end);
    return from > warmup ? from - warmup : 0;
}

// The first of a sensor's five traced pins (PCLK, VSYNC, HREF, VALID, DATA).
int sensor_base(int camera) {
    return camera == 0 ? 0 : static_cast<int>(trace_pin::r_pclk);
}

}  // namespace

pin_tracer::pin_tracer(const island_config& config, const simtime::tick_clock& eclk,
                       const timeline& events, event_order order)
    : m_sink(config.trace),
      m_window(config.trace_window),
      m_edges_from(edges_from(config, eclk)),
      m_events(events),
      m_order(order) {}

void pin_tracer::begin(const emif::emif_pins& dsp) {
    if (!m_sink) return;
    for (int i = 0; i < trace_pin_count; ++i)
        m_id[i] = m_sink->declare(trace_pin_signal(static_cast<trace_pin>(i)));
    // The values before the first edge (tick -1: before any window).
    for (int c = 0; c < 2; ++c) {
        for (int k = 0; k < 5; ++k) set(-1, static_cast<trace_pin>(sensor_base(c) + k), 0);
        set(-1, static_cast<trace_pin>(sensor_base(c) + 6), 0);  // FODD
    }
    set(-1, trace_pin::card_pclk, 0);
    set(-1, trace_pin::eclkout, 0);
    emif(-1, dsp);
    set(-1, trace_pin::irq_taken, 0);
    set(-1, trace_pin::cpu_asleep, 0);
    set(-1, trace_pin::fw_stage, stage_idle);
    set(-1, trace_pin::fw_tracker, 0);
}

void pin_tracer::set(ticks t, trace_pin pin, uint64_t value) {
    if (t >= m_window.to || m_finished) return;
    if (t >= m_window.from && !m_open) open();
    const int i = static_cast<int>(pin);
    if (m_state[i] == 1 && m_value[i] == value) return;
    m_state[i] = 1;
    m_value[i] = value;
    if (t >= m_window.from) m_sink->change(t, m_id[i], value);
}

// The snapshot: every signal as the edges before the window left it.
void pin_tracer::open() {
    m_open = true;
    for (int i = 0; i < trace_pin_count; ++i) {
        if (m_state[i] == 1) m_sink->change(m_window.from, m_id[i], m_value[i]);
        if (m_state[i] == 2) m_sink->release(m_window.from, m_id[i]);
    }
}

void pin_tracer::release(ticks t, trace_pin pin) {
    const int i = static_cast<int>(pin);
    if (m_state[i] == 2) return;
    if (t >= m_window.to || m_finished) return;
    if (t >= m_window.from && !m_open) open();
    m_state[i] = 2;
    if (t >= m_window.from) m_sink->release(t, m_id[i]);
}

void pin_tracer::defer(ticks t, trace_pin pin, uint64_t value) {
    if (m_deferred_count == static_cast<int>(sizeof m_deferred / sizeof m_deferred[0])) {
        flush(t);  // cannot happen with 4 clocks (at most 12 pending); keeps order anyway
    }
    m_deferred[m_deferred_count++] = {t, pin, value};
}

void pin_tracer::flush(ticks upto) {
    while (m_deferred_count > 0) {
        int first = -1;
        for (int i = 0; i < m_deferred_count; ++i) {
            if (m_deferred[i].t <= upto && (first < 0 || m_deferred[i].t < m_deferred[first].t))
                first = i;
        }
        if (first < 0) return;
        const deferred_change c = m_deferred[first];
        for (int i = first + 1; i < m_deferred_count; ++i) m_deferred[i - 1] = m_deferred[i];
        --m_deferred_count;
        set(c.t, c.pin, c.value);
    }
}

void pin_tracer::before_card_edge(ticks t) {
    if (!m_sink || m_finished || t < m_edges_from) return;
    if (t >= m_window.to) {
        finish(m_window.to);
        return;
    }
    // (A pin-level run may have placed firmware events before t since.)
    firmware_up_to(t - 1);
    flush(t);
    m_sink->seal_before(t);
}

void pin_tracer::sensor_edge(int c, ticks rise, uint16_t bits, ticks fall) {
    const int base = sensor_base(c);
    const sensor::pin_word word{bits};
    set(rise, static_cast<trace_pin>(base), 1);
    // The sensor drives its new pins from its falling edge (docs/sensor.md).
    defer(fall, static_cast<trace_pin>(base), 0);
    defer(fall, static_cast<trace_pin>(base + 1), word.vsync() ? 1 : 0);
    defer(fall, static_cast<trace_pin>(base + 2), word.href() ? 1 : 0);
    defer(fall, static_cast<trace_pin>(base + 3), word.valid() ? 1 : 0);
    defer(fall, static_cast<trace_pin>(base + 4), word.data());
    defer(fall, static_cast<trace_pin>(base + 6), word.fodd() ? 1 : 0);
}

void pin_tracer::sensor_pins(int c, ticks t, bool pclk, uint16_t bits) {
    const int base = sensor_base(c);
    const sensor::pin_word word{bits};
    set(t, static_cast<trace_pin>(base), pclk ? 1 : 0);
    set(t, static_cast<trace_pin>(base + 1), word.vsync() ? 1 : 0);
    set(t, static_cast<trace_pin>(base + 2), word.href() ? 1 : 0);
    set(t, static_cast<trace_pin>(base + 3), word.valid() ? 1 : 0);
    set(t, static_cast<trace_pin>(base + 4), word.data());
    set(t, static_cast<trace_pin>(base + 6), word.fodd() ? 1 : 0);
}

void pin_tracer::emif(ticks t, const emif::emif_pins& p) {
    set(t, trace_pin::ce0_n, p.ce_n[0]);
    set(t, trace_pin::ce2_n, p.ce_n[2]);
    set(t, trace_pin::ce3_n, p.ce_n[3]);
    set(t, trace_pin::ea, p.ea & 0xFFFFF);
    set(t, trace_pin::be_n, p.be_n & 0xF);
    set(t, trace_pin::aoe_n, p.aoe_n);
    set(t, trace_pin::are_n, p.are_n);
    set(t, trace_pin::awe_n, p.awe_n);
    // The card's register the access names: EA[7:2] while CE2 is selected.
    set(t, trace_pin::slave_register, !p.ce_n[2] ? p.ea & 0x3F : register_no_access);
}

void pin_tracer::card(ticks t, const card_signals& d, bool bus_ardy, const emif::emif_pins& dsp) {
    set(t, trace_pin::l_oe, d.sensor_oe);
    set(t, trace_pin::r_oe, d.sensor_oe);
    set(t, trace_pin::ext_int4, d.ext_int[0]);
    set(t, trace_pin::ext_int5, d.ext_int[1]);
    set(t, trace_pin::ext_int6, d.ext_int[2]);
    set(t, trace_pin::slave_ardy, d.slave_ardy);
    set(t, trace_pin::ardy, bus_ardy);
    set(t, trace_pin::slave_ed_oe, d.slave_ed_oe);
    if (d.slave_ed_oe) {
        set(t, trace_pin::slave_ed, d.slave_ed);
    } else {
        release(t, trace_pin::slave_ed);
    }
    // ED on the bus: the DSP's value while it drives (writes), the card's
    // while it drives (reads), else nobody (z).
    if (dsp.ed_oe) {
        set(t, trace_pin::ed, dsp.ed_out);
    } else if (d.slave_ed_oe) {
        set(t, trace_pin::ed, d.slave_ed);
    } else {
        release(t, trace_pin::ed);
    }
    set(t, trace_pin::oe_state, d.oe_state);
    set(t, trace_pin::sync_causes, d.sync_causes);
    set(t, trace_pin::verdict, d.verdict);
    set(t, trace_pin::fifo_level_l, d.fifo_level[0]);
    set(t, trace_pin::fifo_level_r, d.fifo_level[1]);
    set(t, trace_pin::fifo_overflow_l, d.fifo_overflow[0]);
    set(t, trace_pin::fifo_overflow_r, d.fifo_overflow[1]);
}

void pin_tracer::firmware_up_to(ticks upto) {
    if (!m_sink) return;
    const std::vector<timeline_event>& events = m_events.events();
    if (m_order == event_order::appended) {
        for (; m_firmware_index < events.size(); ++m_firmware_index)
            firmware_event(events[m_firmware_index]);
        return;
    }
    // By tick, not by index: pin events placed later (timeline::add_pin_event)
    // may land before events already traced.
    if (events.empty() || events.back().tick <= m_firmware_to) return;
    auto it = std::upper_bound(events.begin(), events.end(), m_firmware_to,
                               [](ticks t, const timeline_event& e) { return t < e.tick; });
    for (; it != events.end() && it->tick <= upto; ++it) firmware_event(*it);
    m_firmware_to = std::max(m_firmware_to, std::min(upto, events.back().tick));
}

void pin_tracer::firmware_event(const timeline_event& e) {
    switch (e.kind) {
        case event_kind::stage_begin:
            set(e.tick, trace_pin::fw_stage, e.a);
            break;
        case event_kind::stage_end:
            set(e.tick, trace_pin::fw_stage, stage_idle);
            break;
        case event_kind::cpu_sleep:
            set(e.tick, trace_pin::cpu_asleep, 1);
            break;
        case event_kind::cpu_wake:
            set(e.tick, trace_pin::cpu_asleep, 0);
            set(e.tick, trace_pin::irq_taken, e.a);
            break;
        case event_kind::result:
            set(e.tick, trace_pin::fw_tracker, e.a);
            break;
        default:  // the island's own events (pins) are traced where they happen
            break;
    }
}

void pin_tracer::finish(ticks end) {
    if (!m_sink || m_finished) return;
    firmware_up_to(INT64_MAX);
    const ticks last = std::min(end, m_window.to);
    flush(last);
    // A window that no edge reached still gets its snapshot.
    if (!m_open && m_window.from <= last) open();
    m_sink->finish(last);
    m_finished = true;
}

}  // namespace platform
