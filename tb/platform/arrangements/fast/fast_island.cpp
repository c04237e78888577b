#include "tb/platform/arrangements/fast/fast_island.h"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "model/emif/ardy_glue.h"
#include "model/sensor/sensor_core.h"
#include "model/time/sc_ticks.h"
#include "tb/platform/arrangements/fast/card_eval.h"
#include "tb/platform/island/card_signals.h"

// verilated.h, seeing SystemC, expects sc_time_stamp in the global namespace
// (where <systemc.h> would put it). The card is --cc: it never calls it.
using sc_core::sc_time_stamp;
#include "Vcard.h"
#include "Vcard___024root.h"
#include "Vcard_fst.h"
#include "Vcard_fst___024root.h"
#include "Vcard_vcd.h"
#include "Vcard_vcd___024root.h"
#include "tb/platform/island/card_waves.h"
#include "verilated.h"
#include "verilated_fst_c.h"
#include "verilated_vcd_c.h"
#ifdef STEREOSIM_COVERAGE_DIR
#include <unistd.h>

#include <string>

#include "verilated_cov.h"
#endif

namespace fast {

namespace {

using platform::card_signals;
using simtime::ticks;

// Writes one of the card's input ports; true if its value changed.
template <typename Port, typename Value>
bool drive(Port& port, Value value) {
    const Port v = static_cast<Port>(value);
    if (port == v) return false;
    port = v;
    return true;
}

// The card's EMIF inputs (CE2/CE3, strobes, EA, BE, ED) as the engine drives
// them; true if any of them changed.
template <class card_model>
bool drive_card_emif_inputs(card_model& d, const emif::emif_pins& p) {
    bool changed = drive(d.ce2_n, p.ce_n[2]);
    changed |= drive(d.ce3_n, p.ce_n[3]);
    changed |= drive(d.aoe_n, p.aoe_n);
    changed |= drive(d.are_n, p.are_n);
    changed |= drive(d.awe_n, p.awe_n);
    changed |= drive(d.ea, p.ea);
    changed |= drive(d.be_n, p.be_n);
    changed |= drive(d.ed_in, p.ed_out);
    return changed;
}

// The falling half of the clocks when no input of the card changed since its
// last eval: that eval would only record the clocks' low level for edge
// detection (the card has no negedge logic and reads its clocks nowhere but
// in its triggers; its input-driven logic was settled by the last eval, in
// its ico and nba regions alike), so record it without one. The names are
// Verilator 5's trigger bookkeeping: a later Verilator that renames them
// fails to compile here rather than running wrong.
template <class card_model>
void lower_clocks_without_eval(card_model& d) {
    d.pclk = 0;
    d.eclk = 0;
    d.rootp->__Vtrigrprev__TOP__pclk = 0;
    d.rootp->__Vtrigrprev__TOP__eclk = 0;
}

// One clock's fall the same way, at its own tick (a traced card, below).
template <class card_model>
void lower_clock_without_eval(card_model& d, bool eclk) {
    if (eclk) {
        d.eclk = 0;
        d.rootp->__Vtrigrprev__TOP__eclk = 0;
    } else {
        d.pclk = 0;
        d.rootp->__Vtrigrprev__TOP__pclk = 0;
    }
}

template <class card_model>
card_signals card_signals_of(const card_model& d) {
    card_signals s;
    s.sensor_oe = d.sensor_oe != 0;
    s.ext_int[0] = d.ext_int4 != 0;
    s.ext_int[1] = d.ext_int5 != 0;
    s.ext_int[2] = d.ext_int6 != 0;
    s.slave_ardy = d.ardy != 0;
    s.slave_ed_oe = d.ed_oe != 0;
    s.slave_ed = d.ed_out;
    s.fifo_level[0] = d.dbg_fifo_level_l;
    s.fifo_level[1] = d.dbg_fifo_level_r;
    platform::read_card_internals(d, &s);
    return s;
}

// The card's outputs as the pin hash packs them (pin_hash.h).
template <class card_model>
uint64_t card_outputs_of(const card_model& d) {
    return platform::pack_card_outputs(d.sensor_oe, d.ardy, d.ed_oe, d.ext_int4, d.ext_int5,
                                       d.ext_int6, d.ed_out);
}

// card_model: Vcard, or Vcard_fst / Vcard_vcd (the same RTL traced) when the
// run writes waves.
//
// A traced card sees its inputs at their own ticks, as the pin-level
// arrangement's does, so that its waveform is the pins' (docs/waveforms.md):
// each clock falls at its falling half-edge and a sensor's word reaches the
// card at the sensor's falling edge (pass_falls_before), and the edge's
// settling eval runs with the clocks still high; each such tick gets an eval
// of its own (the tracer sees only what an eval touched). None changes the
// card's state: it has no negedge logic, reads its clocks only in its
// triggers and registers its sensor pins at the pixel clock.
template <class card_model>
class fast_island final : public platform::island {
  public:
    SC_HAS_PROCESS(fast_island);
    fast_island(sc_core::sc_module_name name, const platform::island_config& config,
                sensor::frame_source& source, emif::emif_async_master& engine,
                platform::timeline& events);
    ~fast_island() override { m_card->final(); }
    void finish() override;
    void add_late_faults(const std::vector<sensor::fault> (&sensor_faults)[2],
                         const std::vector<emif::ardy_fault>& ardy_faults) override;

  private:
    // The clocks that rise at the next tick.
    struct edges {
        ticks t = 0;
        bool pclk = false, eclk = false, sensor[2] = {};
    };
    // A sensor's word, held from its rising edge until it reaches the card.
    struct pending_word {
        uint16_t bits = 0;
        ticks fall = 0;
        bool applied = true;
    };

    void run();
    void reset_card();
    // Steps every edge at or before `limit`; stops after an edge where a bus
    // access completed or an interrupt pin changed (*stopped set). Returns
    // the tick of the last edge stepped.
    ticks advance(ticks limit, bool* stopped);
    edges next_edges() const;
    // 1. Every core samples its inputs as they were before the tick.
    emif::emif_inputs sample_bus(const edges& e);
    void clock_rising(const edges& e, bool trace);
    // 2. Then the outputs of this tick.
    void card_pclk_outputs(ticks t);
    bool eclk_outputs(ticks t, const emif::emif_inputs& in, bool trace);
    void advance_pclk(bool trace);
    void deliver_sensor_words();
    // A traced card: the clock falls and sensor words before tick `limit`.
    void pass_falls_before(ticks limit);
    void settle_card(ticks t, bool trace);
    void eval_card();
    void step_sensor(int camera, bool oe);
    void apply_sensor_word(int camera, const pending_word& w);
    void trace_card(ticks t);

    emif::ardy_glue m_glue;  // the board between the card's ARDY and the DSP's
    std::unique_ptr<VerilatedContext> m_context;
    std::unique_ptr<card_model> m_card;
    std::unique_ptr<sensor::sensor_core> m_sensor[2];
    platform::pin_tracer& m_tracer;
    bool m_tracing;

    simtime::clock_cursor m_pclk;  // on the next rising half-edge
    simtime::clock_cursor m_eclk;
    ticks m_last_tick = -1;
    pending_word m_pending[2];
    uint8_t m_irq = 0;  // EXT_INT4..6 as bits 0..2, as last stepped
    uint8_t m_irq_written = 0;
    bool m_inputs_changed = false;         // an EMIF input, since the card's last eval
    bool m_sensor_inputs_changed = false;  // a sensor's pins, likewise
    static constexpr bool traced = platform::is_traced_card<card_model>;
    ticks m_clock_fall[2] = {-1, -1};  // a traced card's pending pclk / eclk fall
};

template <class card_model>
fast_island<card_model>::fast_island(sc_core::sc_module_name name,
                                     const platform::island_config& config,
                                     sensor::frame_source& source, emif::emif_async_master& engine,
                                     platform::timeline& events)
    : platform::island(name, config, engine, events, platform::event_order::appended),
      m_context(std::make_unique<VerilatedContext>()),
      m_tracer(m_observer.tracer()),
      m_tracing(m_tracer.active()),
      m_pclk(config.pclk),
      m_eclk(engine.config().eclk) {
    platform::card_waves* waves = config.trace ? config.trace->card_file() : nullptr;
    if (waves) m_context->traceEverOn(true);
    m_card = std::make_unique<card_model>(m_context.get(), "card");
    if (waves) platform::trace_card_into(*m_card, *waves);
    for (const emif::ardy_fault& f : config.ardy_faults) m_glue.add(f);
    for (int c = 0; c < 2; ++c) {
        m_sensor[c] = std::make_unique<sensor::sensor_core>(
            config.profile, c == 0 ? scene::camera_id::left : scene::camera_id::right, source,
            config.sensor[c]);
        for (const sensor::fault& f : config.faults[c]) m_sensor[c]->add_fault(f);
        m_observer.frames().attach(c, *m_sensor[c]);
    }
    // The engine must be at its first edge: the island owns its stepping.
    m_eclk.reset(engine.config().eclk, 2 * engine.next_edge());
    reset_card();
    m_tracer.begin(engine.pins());
    if (m_tracing) trace_card(-1);
    SC_THREAD(run);
}

#ifdef STEREOSIM_COVERAGE_DIR
// Coverage builds (make coverage, docs/fault-contract.md "Coverage"): the
// card's line, toggle and functional coverage of this run, a file per run so
// that a campaign's forked runs each leave theirs.
void write_card_coverage(VerilatedContext& context) {
    std::error_code ignored;  // a run that cannot write says so below
    std::filesystem::create_directories(STEREOSIM_COVERAGE_DIR, ignored);
    static int runs = 0;
    const std::string path = std::string(STEREOSIM_COVERAGE_DIR) + "/card-" +
                             std::to_string(::getpid()) + "-" + std::to_string(runs++) + ".dat";
    context.coveragep()->write(path.c_str());
}
#endif

template <class card_model>
void fast_island<card_model>::finish() {
    m_observer.finish();
#ifdef STEREOSIM_COVERAGE_DIR
    if constexpr (!traced) write_card_coverage(*m_context);
#endif
}

template <class card_model>
void fast_island<card_model>::add_late_faults(const std::vector<sensor::fault> (&sensor_faults)[2],
                                              const std::vector<emif::ardy_fault>& ardy_faults) {
    // Both the sensor core and the glue look their faults up lazily, at the
    // frame, line, pixel clock or bus edge where each may start.
    for (int c = 0; c < 2; ++c) {
        for (const sensor::fault& f : sensor_faults[c]) {
            m_sensor[c]->add_fault(f);
            m_config.faults[c].push_back(f);
        }
    }
    for (const emif::ardy_fault& f : ardy_faults) {
        m_glue.add(f);
        m_config.ardy_faults.push_back(f);
    }
}

template <class card_model>
void fast_island<card_model>::reset_card() {
    card_model& d = *m_card;
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
    // (The DSP's pins before the first edge: the observer took them from the engine.)
    m_observer.set_initial_card_outputs(card_outputs_of(d));
}

// ---- the SystemC side ------------------------------------------------------------------------
template <class card_model>
void fast_island<card_model>::run() {
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
        m_observer.stats().wall_s +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();

        const sc_core::sc_time wake = simtime::sc_time_of(stopped ? last : limit);
        ++m_observer.stats().syncs;
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
template <class card_model>
ticks fast_island<card_model>::advance(ticks limit, bool* stopped) {
    // The firmware's events up to now come before any edge after now.
    if (m_tracing) m_tracer.firmware_up_to(INT64_MAX);
    for (;;) {
        const edges e = next_edges();
        if (e.t > limit) break;
        const bool trace = m_tracing && m_tracer.edges_at(e.t);
        m_observer.close_periods_through(e.t);
        if constexpr (traced) pass_falls_before(e.t);
        if (m_tracing) m_tracer.before_card_edge(e.t);

        const emif::emif_inputs in = sample_bus(e);
        clock_rising(e, trace);
        bool stop = false;
        if (e.pclk) card_pclk_outputs(e.t);
        if (e.eclk) stop = eclk_outputs(e.t, in, trace);
        if (e.pclk) advance_pclk(trace);
        deliver_sensor_words();
        if (e.pclk || e.eclk) settle_card(e.t, trace);
        m_last_tick = e.t;
        if (stop) {
            *stopped = true;
            break;
        }
    }
    if constexpr (traced) pass_falls_before((*stopped ? m_last_tick : limit) + 1);
    // Every change still to come is at a later tick (a sensor's word at its
    // fall after a later rise, other pins at later edges).
    m_observer.flush_hash_before(m_last_tick + 1);
    // Nothing else can report a change before the time the island waits for.
    if (m_tracing) m_tracer.flush(*stopped ? m_last_tick : limit);
    return m_last_tick;
}

template <class card_model>
typename fast_island<card_model>::edges fast_island<card_model>::next_edges() const {
    const ticks tp = m_pclk.tick();
    const ticks te = m_eclk.tick();
    const ticks tl = m_sensor[0]->next_rise_tick();
    const ticks tr = m_sensor[1]->next_rise_tick();
    edges e;
    e.t = std::min(std::min(tp, te), std::min(tl, tr));
    e.pclk = tp == e.t;
    e.eclk = te == e.t;
    e.sensor[0] = tl == e.t;
    e.sensor[1] = tr == e.t;
    return e;
}

// The engine's ED and ARDY inputs before an ECLK edge: ARDY through the
// board glue (emif-wait, model/emif/ardy_glue.h), ED from the card.
template <class card_model>
emif::emif_inputs fast_island<card_model>::sample_bus(const edges& e) {
    emif::emif_inputs in;
    if (!e.eclk) return in;
    const card_model& d = *m_card;
    const emif::emif_pins& before = m_engine.pins();
    in.ardy = m_glue.bus_ardy(before, d.ardy != 0, m_engine);
    in.ed_in = platform::bus_ed_from_card(before.active_ce(), d.ed_oe != 0, d.ed_out);
    m_glue.clock(before, e.t);
    return in;
}

// The card's flops of both domains sample in one eval; the sensors sample OE.
template <class card_model>
void fast_island<card_model>::clock_rising(const edges& e, bool trace) {
    card_model& d = *m_card;
    const bool oe_before = d.sensor_oe != 0;
    if (e.pclk) d.pclk = 1;
    if (e.eclk) d.eclk = 1;
    if (e.pclk || e.eclk) eval_card();
    for (int c = 0; c < 2; ++c) {
        if (!e.sensor[c]) continue;
        step_sensor(c, oe_before);
        if (trace) m_tracer.sensor_edge(c, e.t, m_pending[c].bits, m_pending[c].fall);
    }
}

template <class card_model>
void fast_island<card_model>::card_pclk_outputs(ticks t) {
    const card_model& d = *m_card;
    const auto& root = *d.rootp;
    const uint32_t level[2] = {d.dbg_fifo_level_l, d.dbg_fifo_level_r};
    const bool overflow[2] = {root.card_top__DOT__l_overflow != 0,
                              root.card_top__DOT__r_overflow != 0};
    m_observer.pclk_rise(t, d.sensor_oe != 0,
                         root.card_top__DOT__u_capture__DOT__u_oe__DOT__state_q, level, overflow);
}

// Interrupt pins, the engine's step, the card's new EMIF inputs; true to
// stop after this edge.
template <class card_model>
bool fast_island<card_model>::eclk_outputs(ticks t, const emif::emif_inputs& in, bool trace) {
    card_model& d = *m_card;
    m_irq =
        static_cast<uint8_t>((d.ext_int4 ? 1 : 0) | (d.ext_int5 ? 2 : 0) | (d.ext_int6 ? 4 : 0));
    bool stop = m_observer.eclk_rise(t, m_irq);
    m_engine.step(in);
    if (m_observer.bus_completed(t)) stop = true;
    const emif::emif_pins& p = m_engine.pins();
    m_inputs_changed |= drive_card_emif_inputs(d, p);
    m_observer.dsp_pins(t, p);
    m_eclk.advance();
    if constexpr (traced) m_clock_fall[1] = m_eclk.tick();
    if (trace) {
        m_tracer.set(t, platform::trace_pin::eclkout, 1);
        m_tracer.defer(m_eclk.tick(), platform::trace_pin::eclkout, 0);
        m_tracer.emif(t, p);
    }
    m_eclk.advance();
    return stop;
}

template <class card_model>
void fast_island<card_model>::advance_pclk(bool trace) {
    const ticks t = m_pclk.tick();
    m_pclk.advance();
    if constexpr (traced) m_clock_fall[0] = m_pclk.tick();
    if (trace) {
        m_tracer.set(t, platform::trace_pin::card_pclk, 1);
        m_tracer.defer(m_pclk.tick(), platform::trace_pin::card_pclk, 0);
    }
    m_pclk.advance();
}

// A sensor word reaches the card's inputs if its falling edge comes before
// the card's next rising edge (always, on the master clock).
template <class card_model>
void fast_island<card_model>::deliver_sensor_words() {
    if constexpr (traced) return;  // at their own ticks: pass_falls_before
    for (int c = 0; c < 2; ++c) {
        pending_word& w = m_pending[c];
        if (!w.applied && w.fall < m_pclk.tick()) {
            apply_sensor_word(c, w);
            w.applied = true;
        }
    }
}

// The falling half of the card's clocks: its combinational outputs settle.
template <class card_model>
void fast_island<card_model>::settle_card(ticks t, bool trace) {
    card_model& d = *m_card;
    if constexpr (traced) {
        if (m_inputs_changed) eval_card();  // the clocks fall at their own ticks
    } else if (m_inputs_changed) {
        d.pclk = 0;
        d.eclk = 0;
        eval_card();
    } else {
        lower_clocks_without_eval(d);
    }
    m_observer.card_outputs(t, card_outputs_of(d));
    if (trace) trace_card(t);
}

template <class card_model>
void fast_island<card_model>::pass_falls_before(ticks limit) {
    for (;;) {
        ticks f = limit;
        for (int k = 0; k < 2; ++k)
            if (m_clock_fall[k] >= 0 && m_clock_fall[k] < f) f = m_clock_fall[k];
        for (int c = 0; c < 2; ++c)
            if (!m_pending[c].applied && m_pending[c].fall < f) f = m_pending[c].fall;
        if (f >= limit) return;
        // The card's values before f are written before it moves.
        if (m_tracing) m_tracer.before_card_edge(f);
        for (int k = 0; k < 2; ++k) {
            if (m_clock_fall[k] != f) continue;
            lower_clock_without_eval(*m_card, k == 1);
            m_clock_fall[k] = -1;
        }
        for (int c = 0; c < 2; ++c) {
            pending_word& w = m_pending[c];
            if (w.applied || w.fall != f) continue;
            apply_sensor_word(c, w);
            w.applied = true;
        }
        // Verilator's tracer compares only what an eval marked active: an
        // eval with no clock rising, which changes no state (not counted).
        m_card->eval();
    }
}

template <class card_model>
void fast_island<card_model>::eval_card() {
    card_eval(*m_card, m_inputs_changed || m_sensor_inputs_changed);
    m_inputs_changed = false;
    m_sensor_inputs_changed = false;
    ++m_observer.stats().card_evals;
}

template <class card_model>
void fast_island<card_model>::step_sensor(int c, bool oe) {
    sensor::sensor_core& s = *m_sensor[c];
    const uint16_t bits = s.step(oe).bits;
    pending_word& w = m_pending[c];
    w.bits = bits;
    w.fall = s.last_fall_tick();
    w.applied = false;
    m_observer.sensor_word(c, bits, w.fall);
}

template <class card_model>
void fast_island<card_model>::apply_sensor_word(int c, const pending_word& w) {
    card_model& d = *m_card;
    const sensor::pin_word word{w.bits};
    const uint8_t data = m_config.wire.on_wire(c, word.data(), w.fall);
    m_sensor_inputs_changed = true;
    // No eval for a new word: the card registers its sensor inputs at its
    // pixel clock before any logic reads them (rtl/sync_check.v, "input
    // sampling"), so no signal settles on them between edges; the next
    // rising eval samples the word.
    if (c == 0) {
        d.l_vsync = word.vsync();
        d.l_href = word.href();
        d.l_valid = word.valid();
        d.l_data = data;
        d.l_fodd = word.fodd();
    } else {
        d.r_vsync = word.vsync();
        d.r_href = word.href();
        d.r_valid = word.valid();
        d.r_data = data;
        d.r_fodd = word.fodd();
    }
}

template <class card_model>
void fast_island<card_model>::trace_card(ticks t) {
    const card_model& d = *m_card;
    const emif::emif_pins& p = m_engine.pins();
    m_tracer.card(t, card_signals_of(d), m_glue.bus_ardy(p, d.ardy != 0, m_engine), p);
}

}  // namespace

std::unique_ptr<platform::island> make_fast_island(const char* name,
                                                   const platform::island_config& config,
                                                   sensor::frame_source& source,
                                                   emif::emif_async_master& engine,
                                                   platform::timeline& events) {
    platform::card_waves* waves = config.trace ? config.trace->card_file() : nullptr;
    if (waves && waves->fst_writer())
        return std::make_unique<fast_island<Vcard_fst>>(name, config, source, engine, events);
    if (waves && waves->vcd_writer())
        return std::make_unique<fast_island<Vcard_vcd>>(name, config, source, engine, events);
    return std::make_unique<fast_island<Vcard>>(name, config, source, engine, events);
}

}  // namespace fast
