#include "tb/platform/arrangements/pins/pins_island.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "model/emif/ardy_glue.h"
#include "model/emif/emif_pins_sc.h"
#include "model/emif/emif_tlm_target_sc.h"
#include "model/sensor/sensor_sc.h"
#include "model/time/sc_ticks.h"

// verilated.h, seeing SystemC, expects sc_time_stamp in the global namespace.
using sc_core::sc_time_stamp;
#include "Vcard_sc.h"
#include "Vcard_sc___024root.h"

namespace pins {

namespace {

using simtime::ticks;
using sig_bool = sc_core::sc_signal<bool>;
using sig_u32 = sc_core::sc_signal<uint32_t>;

using platform::pack_dsp_pins;
using platform::pin_group_card_out;
using platform::pin_group_emif_dsp;

sc_core::sc_time time_of(ticks t) {
    return simtime::sc_time_of(t);
}

// The sensor's pins as one word (sensor::pin_word).
struct sensor_wires {
    sig_bool pclk, vsync, href, valid;
    sig_u32 data;
    sig_u32 card_data;  // after the board wire (wire_fault), when one is modelled
    explicit sensor_wires(const std::string& p)
        : pclk((p + "_pclk").c_str()),
          vsync((p + "_vsync").c_str()),
          href((p + "_href").c_str()),
          valid((p + "_valid").c_str()),
          data((p + "_data").c_str()),
          card_data((p + "_card_data").c_str()) {}
    uint16_t word() const {
        return static_cast<uint16_t>((data.read() & sensor::pin_word::data_mask) |
                                     (href.read() ? sensor::pin_word::href_bit : 0) |
                                     (vsync.read() ? sensor::pin_word::vsync_bit : 0) |
                                     (valid.read() ? sensor::pin_word::valid_bit : 0));
    }
};

class pins_island : public platform::island {
  public:
    SC_HAS_PROCESS(pins_island);
    pins_island(sc_core::sc_module_name name, const platform::island_config& config,
                sensor::frame_source& source, emif::emif_async_master& engine,
                platform::timeline& events)
        : platform::island(name, config, engine, events, observers_only{}),
          m_mclk("mclk"),
          m_eclk("eclkout"),
          m_rst_n("rst_n"),
          m_oe("sensor_oe"),
          m_oe_right("sensor_oe_right"),
          m_wires{sensor_wires("l"), sensor_wires("r")},
          m_ce{sig_bool("ce0_n"), sig_bool("ce1_n"), sig_bool("ce2_n"), sig_bool("ce3_n")},
          m_ea("ea"),
          m_be_n("be_n"),
          m_dsp_ed("dsp_ed"),
          m_dsp_ed_oe("dsp_ed_oe"),
          m_aoe_n("aoe_n"),
          m_are_n("are_n"),
          m_awe_n("awe_n"),
          m_card_ed("card_ed"),
          m_card_ed_oe("card_ed_oe"),
          m_card_ardy("card_ardy"),
          m_bus_ed("bus_ed"),
          m_bus_ardy("bus_ardy"),
          m_glue_edges("glue_edges") {
        m_rst_n.write(true);
        m_dsp_seen = pack_dsp_pins(engine.pins());
        for (int c = 0; c < 2; ++c) {
            for (const sensor::fault& f : config.faults[c]) {
                if (f.kind == sensor::fault_kind::pclk_drift)
                    SC_REPORT_ERROR(this->name(),
                                    "the pin-level arrangement does not model pclk_drift");
            }
        }
        build(source);
        if (config.trace) trace_declare();
    }

    ~pins_island() override {
        if (m_card) m_card->final();
    }

    void finish() override {
        if (m_pending_tick >= 0) observe(m_pending_tick);
        m_pending_tick = -1;
        // sc_start(T) stops before the processes of time T run, while the
        // fast island steps its edges up to and including T: account for
        // those edges as it does (edge counts, the period that closes at T).
        // No pin can change there from SystemC's side: the run is over.
        if (!m_finished) {
            m_finished = true;
            for (;;) {
                const ticks t = std::min(m_pclk_cursor.tick(), m_eclk_cursor.tick());
                if (t > m_config.end) break;
                while (t >= m_next_boundary) close_period();
                if (m_pclk_cursor.tick() == t) {
                    if ((m_pclk_cursor.index() & 1u) == 0) ++m_stats.pclk_edges;
                    m_pclk_cursor.advance();
                }
                if (m_eclk_cursor.tick() == t) {
                    if ((m_eclk_cursor.index() & 1u) == 0) ++m_stats.eclk_edges;
                    m_eclk_cursor.advance();
                }
            }
        }
        if (m_trace) {
            // The firmware's remaining events, then the base closes the trace
            // (its own firmware cursor is moved past what is traced here).
            trace_firmware_through(INT64_MAX);
            m_timeline_traced = m_events.events().size();
        }
        platform::island::finish();
    }

  private:
    void build(sensor::frame_source& source) {
        const platform::island_config& config = m_config;
        // Sensors on the master clock; OE from the card (the right one through
        // a one-pclk flop when the test switch asks for a difference).
        for (int c = 0; c < 2; ++c) {
            const char* name = c == 0 ? "sensor_l" : "sensor_r";
            m_sensor_sc[c] = std::make_unique<sensor::sensor_sc>(
                name, config.profile, c == 0 ? scene::camera_id::left : scene::camera_id::right,
                source, config.sensor[c]);
            sensor::sensor_sc& s = *m_sensor_sc[c];
            for (const sensor::fault& f : config.faults[c]) s.core().add_fault(f);
            attach_sensor(c, s.core());
            sensor_wires& w = m_wires[c];
            s.mclk.bind(m_mclk);
            s.oe.bind(c == 1 && config.test_delay_right_oe ? m_oe_right : m_oe);
            s.pclk.bind(w.pclk);
            s.vsync.bind(w.vsync);
            s.href.bind(w.href);
            s.valid.bind(w.valid);
            s.data.bind(w.data);
        }
        m_emif = std::make_unique<emif::emif_pins_sc>("emif", m_engine);
        emif::emif_pins_sc& e = *m_emif;
        e.eclkout.bind(m_eclk);
        e.ce0_n.bind(m_ce[0]);
        e.ce1_n.bind(m_ce[1]);
        e.ce2_n.bind(m_ce[2]);
        e.ce3_n.bind(m_ce[3]);
        e.ea.bind(m_ea);
        e.be_n.bind(m_be_n);
        e.ed_out.bind(m_dsp_ed);
        e.ed_oe.bind(m_dsp_ed_oe);
        e.aoe_n.bind(m_aoe_n);
        e.are_n.bind(m_are_n);
        e.awe_n.bind(m_awe_n);
        e.ed_in.bind(m_bus_ed);
        e.ardy.bind(m_bus_ardy);

        m_card = std::make_unique<Vcard_sc>("card");
        Vcard_sc& d = *m_card;
        d.rst_n.bind(m_rst_n);
        d.pclk.bind(m_mclk);
        d.sensor_oe.bind(m_oe);
        const bool wire[2] = {config.wire.enabled && config.wire.camera == 0,
                              config.wire.enabled && config.wire.camera == 1};
        d.l_vsync.bind(m_wires[0].vsync);
        d.l_href.bind(m_wires[0].href);
        d.l_valid.bind(m_wires[0].valid);
        d.l_data.bind(wire[0] ? m_wires[0].card_data : m_wires[0].data);
        d.r_vsync.bind(m_wires[1].vsync);
        d.r_href.bind(m_wires[1].href);
        d.r_valid.bind(m_wires[1].valid);
        d.r_data.bind(wire[1] ? m_wires[1].card_data : m_wires[1].data);
        d.eclk.bind(m_eclk);
        d.ce2_n.bind(m_ce[2]);
        d.ce3_n.bind(m_ce[3]);
        d.aoe_n.bind(m_aoe_n);
        d.are_n.bind(m_are_n);
        d.awe_n.bind(m_awe_n);
        d.ea.bind(m_ea);
        d.be_n.bind(m_be_n);
        d.ed_in.bind(m_dsp_ed);
        d.ed_out.bind(m_card_ed);
        d.ed_oe.bind(m_card_ed_oe);
        d.ardy.bind(m_card_ardy);
        d.ext_int4.bind(ext_int4);  // the island's ports, bound by the platform to the DSP
        d.ext_int5.bind(ext_int5);
        d.ext_int6.bind(ext_int6);

        for (const emif::ardy_fault& f : config.ardy_faults) m_glue.add(f);
        SC_METHOD(drive_bus);
        sensitive << m_ce[0] << m_ce[1] << m_ce[2] << m_ce[3] << m_card_ed << m_card_ed_oe
                  << m_card_ardy << m_are_n << m_awe_n << m_glue_edges;
        if (!m_glue.empty()) {
            SC_METHOD(clock_glue);
            sensitive << m_eclk.posedge_event();
            dont_initialize();
        }
        for (int c = 0; c < 2; ++c) {
            if (!wire[c]) continue;
            m_wire_camera = c;
            SC_METHOD(drive_wire);
            sensitive << m_wires[c].pclk << m_wires[c].data;
        }
        if (config.test_delay_right_oe) {
            SC_METHOD(delay_right_oe);
            sensitive << m_mclk.posedge_event();
            dont_initialize();
        }
        SC_THREAD(run);
    }

    // The DSP's AED/ARDY inputs (the board): the card drives them only while
    // CE2/CE3 is selected (ARDY has a pull-up; idle ED reads as 0), as the
    // fast island feeds the engine (docs/emif.md).
    void drive_bus() {
        int ce = -1;
        for (int i = 0; i < emif::ce_count && ce < 0; ++i)
            if (!m_ce[i].read()) ce = i;
        const bool card = ce == 2 || ce == 3;
        m_bus_ardy.write(m_glue.bus_ardy(strobe_pins(), m_card_ardy.read(), m_engine));
        m_bus_ed.write(card && m_card_ed_oe.read() ? m_card_ed.read() : 0u);
    }

    // The DSP's pins the board glue looks at, as the signals carry them now.
    emif::emif_pins strobe_pins() const {
        emif::emif_pins p;
        for (int i = 0; i < emif::ce_count; ++i) p.ce_n[i] = m_ce[i].read();
        p.are_n = m_are_n.read();
        p.awe_n = m_awe_n.read();
        return p;
    }

    // The glue's register at each ECLK rise, from the pins before it (the
    // EMIF's writes of this edge land a delta later); its count as a signal
    // so that drive_bus sees the change.
    void clock_glue() {
        m_glue.clock(strobe_pins(), simtime::tick_at_or_before(sc_core::sc_time_stamp()));
        m_glue_edges.write(m_glue_edges.read() + 1);
    }

    // A stuck DATA bit on the wire to the card (platform::wire_fault), from
    // the first word a falling edge at or after from_tick drives.
    void drive_wire() {
        const sensor_wires& w = m_wires[m_wire_camera];
        const platform::wire_fault& f = m_config.wire;
        uint32_t data = w.data.read();
        if (simtime::tick_at_or_before(sc_core::sc_time_stamp()) >= f.from_tick) {
            const uint32_t mask = 1u << f.bit;
            data = f.value ? (data | mask) : (data & ~mask);
        }
        m_wires[m_wire_camera].card_data.write(data);
    }

    // Test only: the right sensor samples OE one pixel clock late.
    void delay_right_oe() { m_oe_right.write(m_oe.read()); }

    // ---- the clocks and the observers -----------------------------------------------------
    void run() {
        // Reset as the fast island does before its first edge: clocks low,
        // rst_n 1 -> 0 -> 1 (asynchronous), everything settled.
        sc_core::wait(sc_core::SC_ZERO_TIME);
        m_rst_n.write(false);
        for (int i = 0; i < 3; ++i) sc_core::wait(sc_core::SC_ZERO_TIME);
        m_rst_n.write(true);
        for (int i = 0; i < 3; ++i) sc_core::wait(sc_core::SC_ZERO_TIME);
        m_card_out_seen = card_outputs();
        m_pin_hasher.set_initial(pin_group_card_out, m_card_out_seen);
        if (m_trace) trace_card_pins(-1);  // the values before the first edge, as the fast island
        m_access_seen[0] = m_engine.stats().accesses[0];
        m_access_seen[1] = m_engine.stats().accesses[1];

        simtime::clock_cursor& pclk = m_pclk_cursor;
        simtime::clock_cursor& eclk = m_eclk_cursor;
        pclk.reset(m_config.pclk);
        eclk.reset(m_engine.config().eclk, 2 * m_engine.next_edge());
        for (;;) {
            const ticks t = std::min(pclk.tick(), eclk.tick());
            if (t > m_config.end) break;
            const sc_core::sc_time at = time_of(t);
            const sc_core::sc_time now = sc_core::sc_time_stamp();
            if (at > now) sc_core::wait(at - now);
            // Every delta of the previous tick has run: observe it.
            if (m_pending_tick >= 0) observe(m_pending_tick);
            while (t >= m_next_boundary) close_period();

            m_edges = 0;
            if (pclk.tick() == t) {
                const bool rise = (pclk.index() & 1u) == 0;
                m_mclk.write(rise);
                m_edges |= rise ? pclk_rise : pclk_fall;
                pclk.advance();
            }
            if (eclk.tick() == t) {
                const bool rise = (eclk.index() & 1u) == 0;
                m_eclk.write(rise);
                if (rise) m_edges |= eclk_rise;
                eclk.advance();
            }
            m_pending_tick = t;
        }
        if (m_pending_tick >= 0) {
            sc_core::wait(sc_core::SC_ZERO_TIME);  // let the last tick settle (finish() observes)
        }
    }

    uint64_t card_outputs() const {
        return platform::pack_card_outputs(m_oe.read(), m_card_ardy.read(), m_card_ed_oe.read(),
                                           ext_int4.read(), ext_int5.read(), ext_int6.read(),
                                           m_card_ed.read());
    }

    emif::emif_pins dsp_pins() const {
        emif::emif_pins p;
        for (int i = 0; i < emif::ce_count; ++i) p.ce_n[i] = m_ce[i].read();
        p.ea = m_ea.read();
        p.be_n = static_cast<uint8_t>(m_be_n.read());
        p.ed_out = m_dsp_ed.read();
        p.ed_oe = m_dsp_ed_oe.read();
        p.aoe_n = m_aoe_n.read();
        p.are_n = m_are_n.read();
        p.awe_n = m_awe_n.read();
        return p;
    }

    // The settled pins of tick t, observed as the fast island's advance() does.
    void observe(ticks t) {
        const bool hash = m_config.hash_pins;
        if (m_trace && trace_edges_at(t)) trace_tick(t);
        if (m_edges & pclk_fall) {
            for (int c = 0; c < 2; ++c) record_sensor_word(c, m_wires[c].word(), t);
        }
        if (m_edges & pclk_rise) {
            ++m_stats.pclk_edges;
            const bool oe = m_oe.read();
            if (oe != m_oe_level) {
                m_oe_level = oe;
                m_events.add_pin_event(t, platform::event_kind::oe, oe ? 1 : 0);
            }
            const auto& root = *m_card->rootp;
            const uint32_t level[2] = {root.card_top__DOT__l_wr_level_unused,
                                       root.card_top__DOT__r_wr_level_unused};
            const bool overflow[2] = {root.card_top__DOT__l_overflow != 0,
                                      root.card_top__DOT__r_overflow != 0};
            for (int c = 0; c < 2; ++c) {
                if (level[c] > m_current.fifo_peak_words[c])
                    m_current.fifo_peak_words[c] = level[c];
                if (overflow[c] && !m_fifo_overflow_seen[c]) m_current.fifo_overflow[c] = true;
                m_fifo_overflow_seen[c] = overflow[c];
            }
        }
        if (m_edges & eclk_rise) {
            ++m_stats.eclk_edges;
            const uint8_t irq = static_cast<uint8_t>(
                (ext_int4.read() ? 1 : 0) | (ext_int5.read() ? 2 : 0) | (ext_int6.read() ? 4 : 0));
            if (irq != m_irq) {
                const unsigned rose = irq & ~m_irq & 7u;
                const unsigned fell = m_irq & ~irq & 7u;
                for (int n = 0; n < 3; ++n) {
                    if ((rose >> n) & 1u) {
                        m_irq_rises[n].push_back(t);
                        m_events.add_pin_event(t, platform::event_kind::irq,
                                               static_cast<uint8_t>(4 + n), 1);
                    } else if ((fell >> n) & 1u) {
                        m_events.add_pin_event(t, platform::event_kind::irq,
                                               static_cast<uint8_t>(4 + n), 0);
                    }
                }
                m_irq = irq;
                ++m_stats.stops_irq;
            }
            const emif::emif_stats& bus = m_engine.stats();
            if (bus.accesses[0] != m_access_seen[0] || bus.accesses[1] != m_access_seen[1]) {
                if (bus.accesses[1] != m_access_seen[1]) m_edma_done.push_back(t);
                m_access_seen[0] = bus.accesses[0];
                m_access_seen[1] = bus.accesses[1];
                ++m_stats.stops_bus;
            }
        }
        if (hash) {
            const uint64_t dsp = pack_dsp_pins(dsp_pins());
            if (dsp != m_dsp_seen) {
                m_dsp_seen = dsp;
                mix_pin(t, pin_group_emif_dsp, dsp);
            }
            const uint64_t out = card_outputs();
            if (out != m_card_out_seen) {
                m_card_out_seen = out;
                mix_pin(t, pin_group_card_out, out);
            }
            m_pin_hasher.flush_before(t + 1);
        }
        m_last_tick = t;
    }

    // ---- pin trace (pin_trace.h): the fast island's signals, from the sc_signals ----------
    // The same declarations and values before the first edge as the fast
    // island (island_sc.cpp); then, per observed tick, every signal's
    // settled value (trace_set drops repeats), so each change is reported at
    // the tick it settled, as the fast island reports it.
    void trace_declare() {
        using platform::trace_pin;
        m_trace = m_config.trace;
        for (int i = 0; i < platform::trace_pin_count; ++i)
            m_trace_id[i] = m_trace->declare(platform::trace_pin_signal(static_cast<trace_pin>(i)));
        for (int c = 0; c < 2; ++c) {
            const int base = c == 0 ? 0 : static_cast<int>(trace_pin::r_pclk);
            for (int k = 0; k < 5; ++k) trace_set(-1, static_cast<trace_pin>(base + k), 0);
        }
        trace_set(-1, trace_pin::card_pclk, 0);
        trace_set(-1, trace_pin::eclkout, 0);
        trace_emif(-1, m_engine.pins());
        trace_set(-1, trace_pin::irq_taken, 0);
        trace_set(-1, trace_pin::cpu_asleep, 0);
        trace_set(-1, trace_pin::fw_stage, platform::stage_idle);
        trace_set(-1, trace_pin::fw_tracker, 0);
    }

    // The firmware's timeline events of ticks (m_fw_traced_to, upto], in
    // order. By tick, not by index: the pin events this arrangement inserts
    // (timeline::add_pin_event) may land before events already traced.
    void trace_firmware_through(ticks upto) {
        const std::vector<platform::timeline_event>& events = m_events.events();
        if (events.empty() || events.back().tick <= m_fw_traced_to) return;
        auto it =
            std::upper_bound(events.begin(), events.end(), m_fw_traced_to,
                             [](ticks t, const platform::timeline_event& e) { return t < e.tick; });
        for (; it != events.end() && it->tick <= upto; ++it) trace_firmware_event(*it);
        m_fw_traced_to = std::max(m_fw_traced_to, std::min(upto, events.back().tick));
    }

    void trace_tick(ticks t) {
        using platform::trace_pin;
        // Every firmware event up to t exists: the CPU added them at or before time t.
        trace_firmware_through(t);
        for (int c = 0; c < 2; ++c) {
            const int base = c == 0 ? 0 : static_cast<int>(trace_pin::r_pclk);
            const sensor_wires& w = m_wires[c];
            trace_set(t, static_cast<trace_pin>(base), w.pclk.read());
            trace_set(t, static_cast<trace_pin>(base + 1), w.vsync.read());
            trace_set(t, static_cast<trace_pin>(base + 2), w.href.read());
            trace_set(t, static_cast<trace_pin>(base + 3), w.valid.read());
            trace_set(t, static_cast<trace_pin>(base + 4),
                      w.data.read() & sensor::pin_word::data_mask);
        }
        trace_set(t, trace_pin::card_pclk, m_mclk.read());
        trace_set(t, trace_pin::eclkout, m_eclk.read());
        trace_emif(t, dsp_pins());
        trace_card_pins(t);
    }

    // As island::trace_card, from the signals and the --sc card's internals.
    void trace_card_pins(ticks t) {
        using platform::trace_pin;
        const auto& root = *m_card->rootp;
        trace_set(t, trace_pin::l_oe, m_oe.read());
        trace_set(t, trace_pin::r_oe,
                  m_config.test_delay_right_oe ? m_oe_right.read() : m_oe.read());
        trace_set(t, trace_pin::ext_int4, ext_int4.read());
        trace_set(t, trace_pin::ext_int5, ext_int5.read());
        trace_set(t, trace_pin::ext_int6, ext_int6.read());
        trace_set(t, trace_pin::slave_ardy, m_card_ardy.read());
        trace_set(t, trace_pin::ardy, m_bus_ardy.read());
        trace_set(t, trace_pin::slave_ed_oe, m_card_ed_oe.read());
        if (m_card_ed_oe.read()) {
            trace_set(t, trace_pin::slave_ed, m_card_ed.read());
        } else {
            trace_release(t, trace_pin::slave_ed);
        }
        if (m_dsp_ed_oe.read()) {
            trace_set(t, trace_pin::ed, m_dsp_ed.read());
        } else if (m_card_ed_oe.read()) {
            trace_set(t, trace_pin::ed, m_card_ed.read());
        } else {
            trace_release(t, trace_pin::ed);
        }
        trace_card_internals(t, root);
    }

    static constexpr uint8_t pclk_rise = 1, pclk_fall = 2, eclk_rise = 4;

    sig_bool m_mclk, m_eclk, m_rst_n;
    sig_bool m_oe, m_oe_right;
    sensor_wires m_wires[2];
    sig_bool m_ce[emif::ce_count];
    sig_u32 m_ea, m_be_n, m_dsp_ed;
    sig_bool m_dsp_ed_oe, m_aoe_n, m_are_n, m_awe_n;
    sig_u32 m_card_ed;
    sig_bool m_card_ed_oe, m_card_ardy;
    sig_u32 m_bus_ed;
    sig_bool m_bus_ardy;
    emif::ardy_glue m_glue;  // the board between the card's ARDY and the DSP's
    sig_u32 m_glue_edges;    // ECLK rises the glue clocked

    std::unique_ptr<sensor::sensor_sc> m_sensor_sc[2];
    std::unique_ptr<emif::emif_pins_sc> m_emif;
    std::unique_ptr<Vcard_sc> m_card;
    int m_wire_camera = 0;

    simtime::clock_cursor m_pclk_cursor, m_eclk_cursor;  // the next half-edge of each clock
    bool m_finished = false;
    ticks m_pending_tick = -1;  // the tick whose edges were written last, not yet observed
    uint8_t m_edges = 0;        // which edges that tick had
    bool m_oe_level = false;
    uint64_t m_dsp_seen = 0;
    uint64_t m_access_seen[2] = {};
    ticks m_fw_traced_to = -1;  // firmware events through this tick are traced
};

}  // namespace

std::unique_ptr<platform::island> make_pins_island(const char* name,
                                                   const platform::island_config& config,
                                                   sensor::frame_source& source,
                                                   emif::emif_async_master& engine,
                                                   platform::timeline& events) {
    return std::make_unique<pins_island>(name, config, source, engine, events);
}

}  // namespace pins
