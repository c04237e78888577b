#include "tb/platform/island_sc.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>

#include "model/emif/emif_tlm_target_sc.h"
#include "model/time/sc_ticks.h"

// verilated.h, seeing SystemC, expects sc_time_stamp in the global namespace
// (where <systemc.h> would put it). The card is --cc: it never calls it.
using sc_core::sc_time_stamp;
#include "Vcard.h"
#include "Vcard___024root.h"
#include "verilated.h"

namespace platform {

namespace {

// The card's EMIF inputs (CE2/CE3, strobes, EA, BE, ED) as the engine drives them.
inline void drive_card_emif_inputs(Vcard& d, const emif::emif_pins& p) {
    d.ce2_n = p.ce_n[2];
    d.ce3_n = p.ce_n[3];
    d.aoe_n = p.aoe_n;
    d.are_n = p.are_n;
    d.awe_n = p.awe_n;
    d.ea = p.ea;
    d.be_n = p.be_n;
    d.ed_in = p.ed_out;
}

}  // namespace

namespace {

using simtime::ticks;

// The card's outputs as the pin hash packs them (pin_hash.h).
uint64_t card_outputs_of(const Vcard& d) {
    return platform::pack_card_outputs(d.sensor_oe, d.ardy, d.ed_oe, d.ext_int4, d.ext_int5,
                                       d.ext_int6, d.ed_out);
}

// Before the window the edges make no trace calls, except in a warm-up of
// 16 periods of the slower of the card's two clocks (a drift fault moves a
// sensor's clock off the master by ppm, not by periods): the fast island
// sets every sensor pin at each sensor pixel clock and every card and EMIF
// signal at each card edge, the pin-level one every signal at each tick, so
// each holds its value at the window start by then. The firmware signals
// come from the timeline events, still read from the start (per sync, not
// per edge). A window after the run's end gets the values at the end.
ticks trace_edges_from(const island_config& config, const simtime::tick_clock& eclk) {
    const ticks pclk_period = config.pclk.period_num() / config.pclk.period_den() + 1;
    const ticks eclk_period = eclk.period_num() / eclk.period_den() + 1;
    const ticks warmup = 16 * std::max(pclk_period, eclk_period);
    const ticks from = std::min(config.trace_window.from, config.end);
    return from > warmup ? from - warmup : 0;
}

}  // namespace

island::island(sc_core::sc_module_name name, const island_config& config,
               sensor::frame_source& source, emif::emif_async_master& engine, timeline& events)
    : sc_core::sc_module(name),
      ext_int4("ext_int4"),
      ext_int5("ext_int5"),
      ext_int6("ext_int6"),
      m_config(config),
      m_engine(engine),
      m_events(events),
      m_context(std::make_unique<VerilatedContext>()),
      m_pclk(config.pclk),
      m_eclk(engine.config().eclk),
      m_trace_edges_from(trace_edges_from(config, engine.config().eclk)) {
    m_card = std::make_unique<Vcard>(m_context.get(), "card");
    for (const emif::ardy_fault& f : config.ardy_faults) m_glue.add(f);
    for (int c = 0; c < 2; ++c) {
        m_sensor[c] = std::make_unique<sensor::sensor_core>(
            config.profile, c == 0 ? scene::camera_id::left : scene::camera_id::right, source,
            config.sensor[c]);
        for (const sensor::fault& f : config.faults[c]) m_sensor[c]->add_fault(f);
        m_core[c] = m_sensor[c].get();
        const size_t bytes = static_cast<size_t>(config.profile.active_cols) *
                             static_cast<size_t>(config.profile.active_rows);
        m_ring[c].assign(static_cast<size_t>(std::max(2, config.frame_ring)),
                         std::vector<uint8_t>(bytes, 0));
        m_ring_owner[c].assign(m_ring[c].size(), UINT64_MAX);
    }
    // The engine must be at its first edge: the island owns its stepping.
    m_eclk.reset(engine.config().eclk, 2 * engine.next_edge());
    m_next_boundary = config.period;
    reset_card();
    if (config.trace) {
        m_trace = config.trace;
        for (int i = 0; i < trace_pin_count; ++i)
            m_trace_id[i] = m_trace->declare(trace_pin_signal(static_cast<trace_pin>(i)));
        // The values before the first edge (tick -1: before any window).
        for (int c = 0; c < 2; ++c) {
            const int base = c == 0 ? 0 : static_cast<int>(trace_pin::r_pclk);
            for (int k = 0; k < 5; ++k) trace_set(-1, static_cast<trace_pin>(base + k), 0);
        }
        trace_set(-1, trace_pin::card_pclk, 0);
        trace_set(-1, trace_pin::eclkout, 0);
        trace_emif(-1, engine.pins());
        trace_card(-1);
        trace_set(-1, trace_pin::irq_taken, 0);
        trace_set(-1, trace_pin::cpu_asleep, 0);
        trace_set(-1, trace_pin::fw_stage, stage_idle);
        trace_set(-1, trace_pin::fw_tracker, 0);
    }
    SC_THREAD(run);
}

island::island(sc_core::sc_module_name name, const island_config& config,
               emif::emif_async_master& engine, timeline& events, observers_only)
    : sc_core::sc_module(name),
      ext_int4("ext_int4"),
      ext_int5("ext_int5"),
      ext_int6("ext_int6"),
      m_config(config),
      m_engine(engine),
      m_events(events),
      m_pclk(config.pclk),
      m_eclk(engine.config().eclk),
      m_trace_edges_from(trace_edges_from(config, engine.config().eclk)) {
    for (int c = 0; c < 2; ++c) {
        const size_t bytes = static_cast<size_t>(config.profile.active_cols) *
                             static_cast<size_t>(config.profile.active_rows);
        m_ring[c].assign(static_cast<size_t>(std::max(2, config.frame_ring)),
                         std::vector<uint8_t>(bytes, 0));
        m_ring_owner[c].assign(m_ring[c].size(), UINT64_MAX);
    }
    m_next_boundary = config.period;
    m_pins_seen = engine.pins();
    m_pin_hasher.set_initial(pin_group_emif_dsp, pack_dsp_pins(m_pins_seen));
}

island::~island() {
    if (m_card) m_card->final();
}

void island::reset_card() {
    Vcard& d = *m_card;
    d.pclk = 0;
    d.eclk = 0;
    d.rst_n = 1;
    const emif::emif_pins& p = m_engine.pins();
    drive_card_emif_inputs(d, p);
    d.eval();
    d.rst_n = 0;  // a falling edge: the asynchronous resets act
    d.eval();
    d.rst_n = 1;
    d.eval();
    m_pins_seen = p;
    m_card_out_seen = card_outputs_of(d);
    m_pin_hasher.set_initial(pin_group_emif_dsp, pack_dsp_pins(p));
    m_pin_hasher.set_initial(pin_group_card_out, m_card_out_seen);
}

// ---- the SystemC side ------------------------------------------------------------------------
void island::run() {
    const sc_core::sc_time quantum = simtime::sc_time_of(m_config.quantum);
    for (;;) {
        // Everything else at this time acts first: its bus requests are then
        // queued before any edge after now is stepped.
        while (sc_core::sc_pending_activity_at_current_time()) sc_core::wait(sc_core::SC_ZERO_TIME);
        const sc_core::sc_time now = sc_core::sc_time_stamp();
        const sc_core::sc_time ahead = std::min(quantum, sc_core::sc_time_to_pending_activity());
        const ticks limit = std::min(m_config.end, simtime::tick_at_or_before(now + ahead));
        if (limit < 0 || (m_last_tick >= m_config.end && limit == m_config.end)) {
            sc_core::wait();  // past the end of the run: nothing more to step
            continue;
        }

        const auto wall0 = std::chrono::steady_clock::now();
        bool stopped = false;
        const ticks last = advance(limit, &stopped);
        m_stats.wall_s +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

        const sc_core::sc_time wake = simtime::sc_time_of(stopped ? last : limit);
        ++m_stats.syncs;
        sc_core::wait(wake > now ? wake - now : sc_core::SC_ZERO_TIME);
        if (m_irq != m_irq_written) {
            ext_int4.write((m_irq & 1) != 0);
            ext_int5.write((m_irq & 2) != 0);
            ext_int6.write((m_irq & 4) != 0);
            m_irq_written = m_irq;
        }
    }
}

// ---- the C++ island --------------------------------------------------------------------------
ticks island::advance(ticks limit, bool* stopped) {
    Vcard& d = *m_card;
    emif::emif_async_master& engine = m_engine;
    sensor::sensor_core& left = *m_sensor[0];
    sensor::sensor_core& right = *m_sensor[1];
    const emif::emif_stats& bus = engine.stats();
    auto& root = *d.rootp;
    simtime::clock_cursor pclk = m_pclk;
    simtime::clock_cursor eclk = m_eclk;
    ticks last = m_last_tick;
    const bool hash = m_config.hash_pins;
    const bool trace_on = m_trace != nullptr;
    // The firmware's events up to now come before any edge after now.
    if (trace_on) trace_firmware();

    for (;;) {
        const ticks tp = pclk.tick();
        const ticks te = eclk.tick();
        const ticks tl = left.next_rise_tick();
        const ticks tr = right.next_rise_tick();
        const ticks t = std::min(std::min(tp, te), std::min(tl, tr));
        if (t > limit) break;
        const bool pe = tp == t, ee = te == t;
        const bool trace = trace_on && trace_edges_at(t);
        while (t >= m_next_boundary) close_period();
        if (trace) trace_flush(t);

        // 1. Every core samples its inputs as they were before the tick.
        emif::emif_inputs in;
        if (ee) {
            const emif::emif_pins& before = engine.pins();
            const int ce = before.active_ce();
            // ARDY through the board glue (emif-wait, model/emif/ardy_glue.h).
            in.ardy = m_glue.bus_ardy(before, d.ardy != 0, engine);
            if (ce == 2 || ce == 3) in.ed_in = d.ed_oe ? d.ed_out : 0u;
            m_glue.clock(before, t);
        }
        const bool oe_before = d.sensor_oe != 0;
        if (pe) d.pclk = 1;
        if (ee) d.eclk = 1;
        if (pe || ee) d.eval();
        if (tl == t) step_sensor(0, oe_before);
        if (tr == t) step_sensor(1, oe_before);
        if (trace) {
            if (tl == t) trace_sensor(0, t);
            if (tr == t) trace_sensor(1, t);
        }

        // 2. Then the outputs of this tick.
        bool stop = false;
        if (pe) {
            ++m_stats.pclk_edges;
            const bool oe = d.sensor_oe != 0;
            if (oe != m_oe) {
                m_oe = oe;
                m_events.add(t, event_kind::oe, oe ? 1 : 0);
            }
            const uint32_t level[2] = {root.card_top__DOT__l_wr_level_unused,
                                       root.card_top__DOT__r_wr_level_unused};
            for (int c = 0; c < 2; ++c) {
                if (level[c] > m_current.fifo_peak_words[c])
                    m_current.fifo_peak_words[c] = level[c];
            }
            const bool overflow[2] = {root.card_top__DOT__l_overflow != 0,
                                      root.card_top__DOT__r_overflow != 0};
            for (int c = 0; c < 2; ++c) {
                if (overflow[c] && !m_fifo_overflow_seen[c]) m_current.fifo_overflow[c] = true;
                m_fifo_overflow_seen[c] = overflow[c];
            }
        }
        if (ee) {
            ++m_stats.eclk_edges;
            const uint8_t irq = static_cast<uint8_t>((d.ext_int4 ? 1 : 0) | (d.ext_int5 ? 2 : 0) |
                                                     (d.ext_int6 ? 4 : 0));
            if (irq != m_irq) {
                const unsigned rose = irq & ~m_irq & 7u;
                const unsigned fell = m_irq & ~irq & 7u;
                for (int n = 0; n < 3; ++n) {
                    if ((rose >> n) & 1u) {
                        m_irq_rises[n].push_back(t);
                        m_events.add(t, event_kind::irq, static_cast<uint8_t>(4 + n), 1);
                    } else if ((fell >> n) & 1u) {
                        m_events.add(t, event_kind::irq, static_cast<uint8_t>(4 + n), 0);
                    }
                }
                m_irq = irq;
                stop = true;
                ++m_stats.stops_irq;
            }
            const uint64_t cpu_done = bus.accesses[0], edma_done = bus.accesses[1];
            engine.step(in);
            if (bus.accesses[0] != cpu_done || bus.accesses[1] != edma_done) {
                if (bus.accesses[1] != edma_done) m_edma_done.push_back(t);
                stop = true;
                ++m_stats.stops_bus;
            }
            const emif::emif_pins& p = engine.pins();
            drive_card_emif_inputs(d, p);
            if (hash && p != m_pins_seen) {
                m_pins_seen = p;
                mix_pin(t, pin_group_emif_dsp, pack_dsp_pins(p));
            }
            eclk.advance();
            if (trace) {
                trace_set(t, trace_pin::eclkout, 1);
                trace_defer(eclk.tick(), trace_pin::eclkout, 0);
                trace_emif(t, p);
            }
            eclk.advance();
        }
        if (pe) {
            pclk.advance();
            if (trace) {
                trace_set(t, trace_pin::card_pclk, 1);
                trace_defer(pclk.tick(), trace_pin::card_pclk, 0);
            }
            pclk.advance();
        }
        // A sensor word reaches the card's inputs if its falling edge comes
        // before the card's next rising edge (always, on the master clock).
        for (int c = 0; c < 2; ++c) {
            pending_word& w = m_pending[c];
            if (!w.applied && w.fall < pclk.tick()) {
                apply_sensor_word(c, w.bits);
                w.applied = true;
            }
        }
        if (pe || ee) {
            d.pclk = 0;
            d.eclk = 0;
            d.eval();
            if (hash) {
                const uint64_t out = card_outputs_of(d);
                if (out != m_card_out_seen) {
                    m_card_out_seen = out;
                    mix_pin(t, pin_group_card_out, out);
                }
            }
            if (trace) trace_card(t);
        }
        last = t;
        if (stop) {
            *stopped = true;
            break;
        }
    }
    m_pclk = pclk;
    m_eclk = eclk;
    m_last_tick = last;
    // Every change still to come is at a later tick (a sensor's word at its
    // fall after a later rise, other pins at later edges).
    m_pin_hasher.flush_before(last + 1);
    // Nothing else can report a change before the time the island waits for.
    if (trace_on) trace_flush(*stopped ? last : limit);
    return last;
}

void island::step_sensor(int c, bool oe) {
    sensor::sensor_core& s = *m_sensor[c];
    const uint16_t bits = s.step(oe).bits;
    pending_word& w = m_pending[c];
    w.bits = bits;
    w.fall = s.last_fall_tick();
    w.applied = false;
    record_sensor_word(c, bits, w.fall);
}

void island::record_sensor_word(int c, uint16_t bits, ticks fall) {
    if (m_config.hash_pins && bits != m_word_seen[c]) {
        m_word_seen[c] = bits;
        mix_pin(fall, c == 0 ? pin_group_sensor_left : pin_group_sensor_right, bits);
    }

    // Record the active pixels as driven (docs/platform.md, "Data path integrity").
    recorder& r = m_rec[c];
    const sensor::pin_word word{bits};
    const bool vsync = word.vsync();
    if (vsync && !r.vsync) start_frame(c);
    r.vsync = vsync;
    const bool href = word.href() && word.valid();
    if (href) {
        const sensor::sensor_profile& p = m_config.profile;
        const int x = r.col - p.active_col0();
        const int y = r.row - p.active_row0();
        if (r.frame && static_cast<unsigned>(x) < static_cast<unsigned>(p.active_cols) &&
            static_cast<unsigned>(y) < static_cast<unsigned>(p.active_rows)) {
            r.frame[static_cast<size_t>(y) * p.active_cols + x] = word.data();
            ++r.pixels;
        }
        ++r.col;
    } else if (r.href) {
        ++r.row;
        r.col = 0;
    }
    r.href = href;
}

void island::apply_sensor_word(int c, uint16_t bits) {
    Vcard& d = *m_card;
    const sensor::pin_word w{bits};
    uint8_t data = w.data();
    const wire_fault& f = m_config.wire;
    if (f.enabled && f.camera == c && m_pending[c].fall >= f.from_tick) {
        const uint8_t mask = static_cast<uint8_t>(1u << f.bit);
        data = f.value ? static_cast<uint8_t>(data | mask) : static_cast<uint8_t>(data & ~mask);
    }
    if (c == 0) {
        d.l_vsync = w.vsync();
        d.l_href = w.href();
        d.l_valid = w.valid();
        d.l_data = data;
    } else {
        d.r_vsync = w.vsync();
        d.r_href = w.href();
        d.r_valid = w.valid();
        d.r_data = data;
    }
}

void island::start_frame(int c) {
    recorder& r = m_rec[c];
    const sensor::sensor_core& s = *m_core[c];
    if (s.truth().empty()) return;
    const uint64_t index = s.truth().size() - 1;
    if (index == r.truth_index) return;  // a VSYNC glitch inside the frame
    if (r.truth_index != UINT64_MAX) m_frames[c][r.truth_index].pixels = r.pixels;
    const size_t slot = static_cast<size_t>(index % m_ring[c].size());
    if (m_ring_owner[c][slot] != UINT64_MAX) {
        finalize(c, m_ring_owner[c][slot]);
        m_frames[c][m_ring_owner[c][slot]].slot = -1;
    }
    std::vector<uint8_t>& buffer = m_ring[c][slot];
    std::memset(buffer.data(), 0, buffer.size());
    m_ring_owner[c][slot] = index;
    if (m_frames[c].size() <= index) m_frames[c].resize(index + 1);
    m_frames[c][index].slot = static_cast<int>(slot);
    r.truth_index = index;
    r.frame = buffer.data();
    r.pixels = 0;
    r.row = 0;
    r.col = 0;
    m_events.add_pin_event(s.truth()[index].start_tick, event_kind::sensor_frame,
                           static_cast<uint8_t>(c), static_cast<uint32_t>(index));
}

void island::finalize(int c, uint64_t index) {
    frame_info& f = m_frames[c][index];
    if (f.have_checksum || f.slot < 0) return;
    if (m_rec[c].truth_index == index) f.pixels = m_rec[c].pixels;
    const std::vector<uint8_t>& buffer = m_ring[c][static_cast<size_t>(f.slot)];
    f.checksum = fnv1a(buffer.data(), buffer.size());
    f.have_checksum = true;
}

const uint8_t* island::frame_pixels(int c, uint64_t index) const {
    if (index >= m_frames[c].size() || m_frames[c][index].slot < 0) return nullptr;
    return m_ring[c][static_cast<size_t>(m_frames[c][index].slot)].data();
}

bool island::frame_checksum(int c, uint64_t index, uint64_t* checksum) {
    if (index >= m_frames[c].size()) return false;
    finalize(c, index);
    if (!m_frames[c][index].have_checksum) return false;
    *checksum = m_frames[c][index].checksum;
    return true;
}

void island::close_period() {
    const uint64_t busy = m_engine.stats().busy_edges;
    m_current.emif_busy_edges = busy - m_busy_at_boundary;
    m_busy_at_boundary = busy;
    const uint64_t cpu_words = m_engine.stats().words[static_cast<int>(emif::requester::cpu)];
    m_current.cpu_words = cpu_words - m_cpu_words_at_boundary;
    m_cpu_words_at_boundary = cpu_words;
    for (int c = 0; c < 2; ++c) {
        if (m_current.fifo_peak_words[c] > m_fifo_peak_run[c])
            m_fifo_peak_run[c] = m_current.fifo_peak_words[c];
    }
    m_current.eclk_edges = m_stats.eclk_edges - m_eclk_at_boundary;
    m_eclk_at_boundary = m_stats.eclk_edges;
    m_periods.push_back(m_current);
    m_current = period_sample{};
    m_next_boundary += m_config.period;
}

void island::finish() {
    m_pin_hasher.finish();
    m_stats.pin_changes = m_pin_hasher.changes();
    for (int c = 0; c < 2; ++c) {
        if (m_rec[c].truth_index != UINT64_MAX)
            m_frames[c][m_rec[c].truth_index].pixels = m_rec[c].pixels;
    }
    if (m_trace && !m_trace_finished) {
        trace_firmware();
        const ticks end = std::min(m_config.end, m_config.trace_window.to);
        trace_flush(end);
        // A window that no edge reached still gets its snapshot.
        if (!m_trace_open && m_config.trace_window.from <= end) trace_open();
        m_trace->finish(end);
        m_trace_finished = true;
    }
}

// ---- pin trace -------------------------------------------------------------------------------
void island::trace_set(ticks t, trace_pin pin, uint64_t value) {
    const tick_window& window = m_config.trace_window;
    if (t >= window.to || m_trace_finished) return;
    if (t >= window.from && !m_trace_open) trace_open();
    const int i = static_cast<int>(pin);
    if (m_trace_state[i] == 1 && m_trace_value[i] == value) return;
    m_trace_state[i] = 1;
    m_trace_value[i] = value;
    if (t >= window.from) m_trace->change(t, m_trace_id[i], value);
}

// The snapshot: every signal as the edges before the window left it.
void island::trace_open() {
    m_trace_open = true;
    const ticks from = m_config.trace_window.from;
    for (int i = 0; i < trace_pin_count; ++i) {
        if (m_trace_state[i] == 1) m_trace->change(from, m_trace_id[i], m_trace_value[i]);
        if (m_trace_state[i] == 2) m_trace->release(from, m_trace_id[i]);
    }
}

void island::trace_release(ticks t, trace_pin pin) {
    const int i = static_cast<int>(pin);
    if (m_trace_state[i] == 2) return;
    const tick_window& window = m_config.trace_window;
    if (t >= window.to || m_trace_finished) return;
    if (t >= window.from && !m_trace_open) trace_open();
    m_trace_state[i] = 2;
    if (t >= window.from) m_trace->release(t, m_trace_id[i]);
}

void island::trace_defer(ticks t, trace_pin pin, uint64_t value) {
    if (m_deferred_count == static_cast<int>(sizeof m_deferred / sizeof m_deferred[0])) {
        trace_flush(t);  // cannot happen with 4 clocks (at most 12 pending); keeps order anyway
    }
    m_deferred[m_deferred_count++] = {t, pin, value};
}

void island::trace_flush(ticks upto) {
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
        trace_set(c.t, c.pin, c.value);
    }
}

void island::trace_sensor(int c, ticks rise) {
    const int base = c == 0 ? 0 : static_cast<int>(trace_pin::r_pclk);
    const pending_word& w = m_pending[c];
    const sensor::pin_word word{w.bits};
    trace_set(rise, static_cast<trace_pin>(base), 1);
    // The sensor drives its new pins from its falling edge (docs/sensor.md).
    trace_defer(w.fall, static_cast<trace_pin>(base), 0);
    trace_defer(w.fall, static_cast<trace_pin>(base + 1), word.vsync() ? 1 : 0);
    trace_defer(w.fall, static_cast<trace_pin>(base + 2), word.href() ? 1 : 0);
    trace_defer(w.fall, static_cast<trace_pin>(base + 3), word.valid() ? 1 : 0);
    trace_defer(w.fall, static_cast<trace_pin>(base + 4), word.data());
}

void island::trace_emif(ticks t, const emif::emif_pins& p) {
    trace_set(t, trace_pin::ce0_n, p.ce_n[0]);
    trace_set(t, trace_pin::ce2_n, p.ce_n[2]);
    trace_set(t, trace_pin::ce3_n, p.ce_n[3]);
    trace_set(t, trace_pin::ea, p.ea & 0xFFFFF);
    trace_set(t, trace_pin::be_n, p.be_n & 0xF);
    trace_set(t, trace_pin::aoe_n, p.aoe_n);
    trace_set(t, trace_pin::are_n, p.are_n);
    trace_set(t, trace_pin::awe_n, p.awe_n);
    // The card's register the access names: EA[7:2] while CE2 is selected.
    if (!p.ce_n[2]) {
        trace_set(t, trace_pin::slave_register, p.ea & 0x3F);
    } else {
        trace_release(t, trace_pin::slave_register);
    }
}

void island::trace_card(ticks t) {
    const Vcard& d = *m_card;
    const auto& root = *d.rootp;
    trace_set(t, trace_pin::l_oe, d.sensor_oe);
    trace_set(t, trace_pin::r_oe, d.sensor_oe);
    trace_set(t, trace_pin::ext_int4, d.ext_int4);
    trace_set(t, trace_pin::ext_int5, d.ext_int5);
    trace_set(t, trace_pin::ext_int6, d.ext_int6);
    trace_set(t, trace_pin::slave_ardy, d.ardy);
    trace_set(t, trace_pin::ardy, m_glue.bus_ardy(m_engine.pins(), d.ardy != 0, m_engine));
    trace_set(t, trace_pin::slave_ed_oe, d.ed_oe);
    if (d.ed_oe) {
        trace_set(t, trace_pin::slave_ed, d.ed_out);
    } else {
        trace_release(t, trace_pin::slave_ed);
    }
    // ED on the bus: the DSP's value while it drives (writes), the card's
    // while it drives (reads), else nobody (z).
    const emif::emif_pins& p = m_engine.pins();
    if (p.ed_oe) {
        trace_set(t, trace_pin::ed, p.ed_out);
    } else if (d.ed_oe) {
        trace_set(t, trace_pin::ed, d.ed_out);
    } else {
        trace_release(t, trace_pin::ed);
    }
    trace_card_internals(t, root);
}

void island::trace_firmware() {
    const std::vector<timeline_event>& events = m_events.events();
    for (; m_timeline_traced < events.size(); ++m_timeline_traced)
        trace_firmware_event(events[m_timeline_traced]);
}

void island::trace_firmware_event(const timeline_event& e) {
    switch (e.kind) {
        case event_kind::stage_begin:
            trace_set(e.tick, trace_pin::fw_stage, e.a);
            break;
        case event_kind::stage_end:
            trace_set(e.tick, trace_pin::fw_stage, stage_idle);
            break;
        case event_kind::cpu_sleep:
            trace_set(e.tick, trace_pin::cpu_asleep, 1);
            break;
        case event_kind::cpu_wake:
            trace_set(e.tick, trace_pin::cpu_asleep, 0);
            trace_set(e.tick, trace_pin::irq_taken, e.a);
            break;
        case event_kind::result:
            trace_set(e.tick, trace_pin::fw_tracker, e.a);
            break;
        default:  // the island's own events (pins) are traced where they happen
            break;
    }
}

}  // namespace platform
