#include "tb/platform/arrangements/pins/pins_island.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "model/emif/ardy_glue.h"
#include "model/emif/emif_pins_sc.h"
#include "model/sensor/sensor_sc.h"
#include "model/time/sc_ticks.h"
#include "tb/platform/island/card_signals.h"

// verilated.h, seeing SystemC, expects sc_time_stamp in the global namespace.
using sc_core::sc_time_stamp;
#include "Vcard_sc.h"
#include "Vcard_sc___024root.h"
#include "Vcard_sc_fst.h"
#include "Vcard_sc_fst___024root.h"
#include "Vcard_sc_vcd.h"
#include "Vcard_sc_vcd___024root.h"
#include "tb/platform/island/card_waves.h"
#include "verilated_fst_c.h"
#include "verilated_vcd_c.h"

namespace pins {

namespace {

using simtime::ticks;
using sig_bool = sc_core::sc_signal<bool>;
using sig_u32 = sc_core::sc_signal<uint32_t>;

using platform::card_signals;
using platform::trace_pin;

// The sensor's pins as one word (sensor::pin_word).
struct sensor_wires {
    sig_bool pclk, vsync, href, valid, fodd;
    sig_u32 data;
    sig_u32 card_data;  // after the board wire (wire_fault), when one is modelled
    explicit sensor_wires(const std::string& p)
        : pclk((p + "_pclk").c_str()),
          vsync((p + "_vsync").c_str()),
          href((p + "_href").c_str()),
          valid((p + "_valid").c_str()),
          fodd((p + "_fodd").c_str()),
          data((p + "_data").c_str()),
          card_data((p + "_card_data").c_str()) {}
    uint16_t word() const {
        return static_cast<uint16_t>((data.read() & sensor::pin_word::data_mask) |
                                     (href.read() ? sensor::pin_word::href_bit : 0) |
                                     (vsync.read() ? sensor::pin_word::vsync_bit : 0) |
                                     (valid.read() ? sensor::pin_word::valid_bit : 0) |
                                     (fodd.read() ? sensor::pin_word::fodd_bit : 0));
    }
};

// card_model: Vcard_sc, or Vcard_sc_fst / Vcard_sc_vcd (the same RTL traced)
// when the run writes waves. The card is a top-level module named "card"
// (made before the island, make_pins_island): its waveform scope is then
// platform.card, as the fast island's.
template <class card_model>
class pins_island : public platform::island {
  public:
    SC_HAS_PROCESS(pins_island);
    pins_island(sc_core::sc_module_name name, std::unique_ptr<card_model> card,
                const platform::island_config& config, sensor::frame_source& source,
                emif::emif_async_master& engine, platform::timeline& events)
        : platform::island(name, config, engine, events, platform::event_order::placed),
          m_tracer(m_observer.tracer()),
          m_mclk("mclk"),
          m_eclk("eclkout"),
          m_rst_n("rst_n"),
          m_oe("sensor_oe"),
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
          m_glue_edges("glue_edges"),
          m_fifo_level{sig_u32("fifo_level_l"), sig_u32("fifo_level_r")},
          m_card(std::move(card)) {
        m_rst_n.write(true);
        for (int c = 0; c < 2; ++c) {
            for (const sensor::fault& f : config.faults[c]) {
                if (f.kind == sensor::fault_kind::pclk_drift)
                    SC_REPORT_ERROR(this->name(),
                                    "the pin-level arrangement does not model pclk_drift");
            }
        }
        build(source);
        m_tracer.begin(engine.pins());
    }

    // A --sc model registers with a trace file only after elaboration.
    void start_of_simulation() override {
        if (platform::card_waves* waves = m_config.trace ? m_config.trace->card_file() : nullptr)
            platform::trace_card_into(*m_card, *waves);
    }

    ~pins_island() override {
        if (m_card) m_card->final();
    }

    // Snapshots are the fast arrangement's (faults are wired into the
    // sensors' modules and the glue's process at elaboration here).
    void add_late_faults(const std::vector<sensor::fault> (&)[2],
                         const std::vector<emif::ardy_fault>&) override {
        throw std::logic_error("faults added to a running island need the fast arrangement");
    }
    void finish() override {
        if (m_pending_tick >= 0) observe(m_pending_tick, m_config.end + 1);
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
                m_observer.close_periods_through(t);
                platform::island_stats& stats = m_observer.stats();
                if (m_pclk_cursor.tick() == t) {
                    if ((m_pclk_cursor.index() & 1u) == 0) ++stats.pclk_edges;
                    m_pclk_cursor.advance();
                }
                if (m_eclk_cursor.tick() == t) {
                    if ((m_eclk_cursor.index() & 1u) == 0) ++stats.eclk_edges;
                    m_eclk_cursor.advance();
                }
            }
        }
        m_observer.finish();
    }

  private:
    void build(sensor::frame_source& source) {
        build_sensors(source);
        build_emif();
        build_card();
        build_board();
    }

    void build_sensors(sensor::frame_source& source) {
        const platform::island_config& config = m_config;
        // Sensors on the master clock; OE from the card.
        for (int c = 0; c < 2; ++c) {
            const char* name = c == 0 ? "sensor_l" : "sensor_r";
            m_sensor_sc[c] = std::make_unique<sensor::sensor_sc>(
                name, config.profile, c == 0 ? scene::camera_id::left : scene::camera_id::right,
                source, config.sensor[c]);
            sensor::sensor_sc& s = *m_sensor_sc[c];
            for (const sensor::fault& f : config.faults[c]) s.core().add_fault(f);
            m_observer.frames().attach(c, s.core());
            sensor_wires& w = m_wires[c];
            s.mclk.bind(m_mclk);
            s.oe.bind(m_oe);
            s.pclk.bind(w.pclk);
            s.vsync.bind(w.vsync);
            s.href.bind(w.href);
            s.valid.bind(w.valid);
            s.fodd.bind(w.fodd);
            s.data.bind(w.data);
        }
    }

    void build_emif() {
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
    }

    // The card's pins, the sensors' DATA through the wire fault where one is modelled.
    void build_card() {
        const platform::island_config& config = m_config;
        card_model& d = *m_card;
        d.rst_n.bind(m_rst_n);
        d.pclk.bind(m_mclk);
        d.sensor_oe.bind(m_oe);
        const bool wire[2] = {config.wire.enabled && config.wire.camera == 0,
                              config.wire.enabled && config.wire.camera == 1};
        d.l_vsync.bind(m_wires[0].vsync);
        d.l_href.bind(m_wires[0].href);
        d.l_valid.bind(m_wires[0].valid);
        d.l_data.bind(wire[0] ? m_wires[0].card_data : m_wires[0].data);
        d.l_fodd.bind(m_wires[0].fodd);
        d.r_vsync.bind(m_wires[1].vsync);
        d.r_href.bind(m_wires[1].href);
        d.r_valid.bind(m_wires[1].valid);
        d.r_data.bind(wire[1] ? m_wires[1].card_data : m_wires[1].data);
        d.r_fodd.bind(m_wires[1].fodd);
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
        d.dbg_fifo_level_l.bind(m_fifo_level[0]);
        d.dbg_fifo_level_r.bind(m_fifo_level[1]);
    }

    // The board (the DSP's ED / ARDY inputs, the ARDY glue, the wire fault)
    // and the clock thread.
    void build_board() {
        const platform::island_config& config = m_config;
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
            if (!config.wire.enabled || config.wire.camera != c) continue;
            m_wire_camera = c;
            SC_METHOD(drive_wire);
            sensitive << m_wires[c].pclk.negedge_event() << m_wires[c].data;
        }
        SC_THREAD(run);
    }

    // The DSP's AED/ARDY inputs (the board): the card drives them only while
    // CE2/CE3 is selected (ARDY has a pull-up; idle ED reads as 0), as the
    // fast island feeds the engine (docs/emif.md).
    void drive_bus() {
        const emif::emif_pins strobes = strobe_pins();
        m_bus_ardy.write(m_glue.bus_ardy(strobes, m_card_ardy.read(), m_engine));
        m_bus_ed.write(
            platform::bus_ed_from_card(strobes.active_ce(), m_card_ed_oe.read(), m_card_ed.read()));
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

    // A stuck DATA bit on the wire to the card (platform::wire_fault): the
    // sensor drives DATA at its falling edge, so the tick of a fall or a
    // DATA change is the tick the word was driven.
    void drive_wire() {
        const sensor_wires& w = m_wires[m_wire_camera];
        const uint8_t data = static_cast<uint8_t>(w.data.read() & sensor::pin_word::data_mask);
        const simtime::ticks driven = simtime::tick_at_or_before(sc_core::sc_time_stamp());
        m_wires[m_wire_camera].card_data.write(m_config.wire.on_wire(m_wire_camera, data, driven));
    }

    // ---- the clocks and the observer --------------------------------------------------------
    void run() {
        // Reset as the fast island does before its first edge: clocks low,
        // rst_n 1 -> 0 -> 1 (asynchronous), everything settled.
        sc_core::wait(sc_core::SC_ZERO_TIME);
        m_rst_n.write(false);
        for (int i = 0; i < 3; ++i) sc_core::wait(sc_core::SC_ZERO_TIME);
        m_rst_n.write(true);
        for (int i = 0; i < 3; ++i) sc_core::wait(sc_core::SC_ZERO_TIME);
        m_observer.set_initial_card_outputs(card().packed_outputs());
        // The values before the first edge, as the fast island's.
        if (m_tracer.active()) {
            card_signals settled = card();
            platform::read_card_internals(*m_card, &settled);
            m_tracer.card(-1, settled, m_bus_ardy.read(), dsp_pins());
        }

        simtime::clock_cursor& pclk = m_pclk_cursor;
        simtime::clock_cursor& eclk = m_eclk_cursor;
        pclk.reset(m_config.pclk);
        eclk.reset(m_engine.config().eclk, 2 * m_engine.next_edge());
        for (;;) {
            const ticks t = std::min(pclk.tick(), eclk.tick());
            if (t > m_config.end) break;
            const sc_core::sc_time at = simtime::sc_time_of(t);
            const sc_core::sc_time now = sc_core::sc_time_stamp();
            if (at > now) sc_core::wait(at - now);
            // Every delta of the previous tick has run: observe it (the
            // card moves again at t).
            if (m_pending_tick >= 0) observe(m_pending_tick, t);
            m_observer.close_periods_through(t);

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

    // The card's pins and debug outputs as settled now (the internals from
    // the verilated root only where they are looked at: read_card_internals).
    card_signals card() const {
        card_signals s;
        s.sensor_oe = m_oe.read();
        s.ext_int[0] = ext_int4.read();
        s.ext_int[1] = ext_int5.read();
        s.ext_int[2] = ext_int6.read();
        s.slave_ardy = m_card_ardy.read();
        s.slave_ed_oe = m_card_ed_oe.read();
        s.slave_ed = m_card_ed.read();
        s.fifo_level[0] = m_fifo_level[0].read();
        s.fifo_level[1] = m_fifo_level[1].read();
        return s;
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

    // The settled pins of tick t, fed to the observer in the fast island's
    // order; the card's next edge is at `next`.
    void observe(ticks t, ticks next) {
        card_signals settled = card();
        const emif::emif_pins dsp = dsp_pins();
        const bool trace = m_tracer.active() && m_tracer.edges_at(t);
        if (trace || (m_edges & pclk_rise)) platform::read_card_internals(*m_card, &settled);
        if (trace) trace_tick(t, settled, dsp);
        if (m_tracer.active()) m_tracer.before_card_edge(next);
        if (m_edges & pclk_fall) {
            for (int c = 0; c < 2; ++c) m_observer.sensor_word(c, m_wires[c].word(), t);
        }
        if (m_edges & pclk_rise) {
            m_observer.pclk_rise(t, settled.sensor_oe, static_cast<uint8_t>(settled.oe_state),
                                 settled.fifo_level, settled.fifo_overflow);
        }
        if (m_edges & eclk_rise) {
            m_observer.eclk_rise(t, settled.irq_bits());
            m_observer.bus_completed(t);
        }
        m_observer.dsp_pins(t, dsp);
        m_observer.card_outputs(t, settled.packed_outputs());
        m_observer.flush_hash_before(t + 1);
    }

    // ---- pin trace: every signal's settled value per observed tick (the
    // tracer drops repeats), so each change is reported at the tick it
    // settled, as the fast island reports it.
    void trace_tick(ticks t, const card_signals& card, const emif::emif_pins& dsp) {
        // Every firmware event up to t exists: the CPU added them at or before time t.
        m_tracer.firmware_up_to(t);
        for (int c = 0; c < 2; ++c)
            m_tracer.sensor_pins(c, t, m_wires[c].pclk.read(), m_wires[c].word());
        m_tracer.set(t, trace_pin::card_pclk, m_mclk.read());
        m_tracer.set(t, trace_pin::eclkout, m_eclk.read());
        m_tracer.emif(t, dsp);
        m_tracer.card(t, card, m_bus_ardy.read(), dsp);
    }

    static constexpr uint8_t pclk_rise = 1, pclk_fall = 2, eclk_rise = 4;

    platform::pin_tracer& m_tracer;
    sig_bool m_mclk, m_eclk, m_rst_n;
    sig_bool m_oe;
    sensor_wires m_wires[2];
    sig_bool m_ce[emif::ce_count];
    sig_u32 m_ea, m_be_n, m_dsp_ed;
    sig_bool m_dsp_ed_oe, m_aoe_n, m_are_n, m_awe_n;
    sig_u32 m_card_ed;
    sig_bool m_card_ed_oe, m_card_ardy;
    sig_u32 m_bus_ed;
    sig_bool m_bus_ardy;
    emif::ardy_glue m_glue;   // the board between the card's ARDY and the DSP's
    sig_u32 m_glue_edges;     // ECLK rises the glue clocked
    sig_u32 m_fifo_level[2];  // the card's debug outputs

    std::unique_ptr<sensor::sensor_sc> m_sensor_sc[2];
    std::unique_ptr<emif::emif_pins_sc> m_emif;
    std::unique_ptr<card_model> m_card;
    int m_wire_camera = 0;

    simtime::clock_cursor m_pclk_cursor, m_eclk_cursor;  // the next half-edge of each clock
    bool m_finished = false;
    ticks m_pending_tick = -1;  // the tick whose edges were written last, not yet observed
    uint8_t m_edges = 0;        // which edges that tick had
};

template <class card_model>
std::unique_ptr<platform::island> make(const char* name, const platform::island_config& config,
                                       sensor::frame_source& source,
                                       emif::emif_async_master& engine,
                                       platform::timeline& events) {
    auto card = std::make_unique<card_model>("card");
    return std::make_unique<pins_island<card_model>>(name, std::move(card), config, source, engine,
                                                     events);
}

}  // namespace

std::unique_ptr<platform::island> make_pins_island(const char* name,
                                                   const platform::island_config& config,
                                                   sensor::frame_source& source,
                                                   emif::emif_async_master& engine,
                                                   platform::timeline& events) {
    platform::card_waves* waves = config.trace ? config.trace->card_file() : nullptr;
    if (waves) Verilated::traceEverOn(true);  // before the model exists
    if (waves && waves->fst_writer())
        return make<Vcard_sc_fst>(name, config, source, engine, events);
    if (waves && waves->vcd_writer())
        return make<Vcard_sc_vcd>(name, config, source, engine, events);
    return make<Vcard_sc>(name, config, source, engine, events);
}

}  // namespace pins
