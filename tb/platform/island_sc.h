// The cycle-accurate island (DESIGN.md "How it is clocked"; docs/platform.md):
// both sensor cores, the verilated card (verilator --cc) and the EMIF cycle
// engine, stepped edge by edge from plain C++ inside ONE SystemC thread.
//
// Edges. Every edge is derived from tick counts (1/18 ns): the card's master
// pixel clock (also the sensors' clock unless a drift fault moves one off
// it), ECLKOUT, and each sensor's own rising edges. At a tick where several
// clocks rise, every core first samples its inputs as they were before the
// tick (the engine samples ED/ARDY, the card's flops of both domains sample
// in one eval, the sensors sample OE), then all outputs update. A sensor's
// pins of cycle n change at its falling edge; the card sees them at its next
// rising edge after that (docs/sensor.md, docs/card.md, docs/emif.md).
//
// Syncing with SystemC. The island runs ahead of SystemC time, but never
// past the next activity of any other process (sc_time_to_pending_activity)
// and never more than a quantum; it stops early at an edge where a bus
// access completes (the EMIF target wakes its initiator there) or an
// interrupt pin changes (the pin is written at that edge's exact time).
// Before running ahead it lets every process at the current time act, so a
// bus request made at time t is queued before the island steps any edge
// after t; the engine takes it from the first edge strictly after t (rule 5
// of docs/emif.md). Hence the quantum changes only the number of syncs,
// never a result (tests/system/test_quantum_invariance_sc.cpp).
//
// Observers (no effect on the simulation): the pin hash (every pin change
// with its tick, hashed in a defined order), the pin trace (every traced
// signal's change with its tick to a pin_trace sink, pin_trace.h), a copy of every sensor frame's
// active pixels as driven on its pins (data path integrity), the card's
// FIFO write levels and the EMIF's busy edges per sync period (budget), the
// interrupt and OE edges (timeline).
//
// Cost per edge: one or two Verilator evals, the engine's switch, a sensor
// step, a few compares; the loop's state lives in locals between syncs.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <systemc>
#include <vector>

#include "model/emif/ardy_glue.h"
#include "model/emif/emif_async_master.h"
#include "model/sensor/frame_source.h"
#include "model/sensor/sensor_core.h"
#include "tb/platform/pin_hash.h"
#include "tb/platform/pin_trace.h"
#include "tb/platform/platform_config.h"
#include "tb/platform/timeline.h"

class Vcard;
class VerilatedContext;

namespace platform {

// Words in each of the card's FIFOs: rtl_card is card_top with its default
// FIFO_AW = 17 (docs/card.md).
inline constexpr uint32_t card_fifo_words = 1u << 17;

struct island_config {
    sensor::sensor_profile profile;
    sensor::sensor_config sensor[2];  // left, right
    std::vector<sensor::fault> faults[2];
    wire_fault wire;
    std::vector<emif::ardy_fault> ardy_faults;  // the board glue's wait states (emif-wait)
    simtime::tick_clock pclk;                   // the card's master pixel clock
    simtime::ticks quantum = 0;
    simtime::ticks end = INT64_MAX;          // the island never steps an edge after this tick
    simtime::ticks period = period_24_5_ms;  // for the per-period samples
    bool hash_pins = true;
    int frame_ring = 8;                // sensor frames whose pixels are kept (per sensor)
    bool test_delay_right_oe = false;  // pins arrangement only (platform_config)
    pin_trace* trace = nullptr;        // every traced signal's change in `trace_window`
    tick_window trace_window;
};

// What happened in one sync period [k P, (k+1) P).
struct period_sample {
    uint64_t eclk_edges = 0;
    uint64_t emif_busy_edges = 0;      // engine: bus in use or turning around
    uint64_t cpu_words = 0;            // engine: words the CPU moved (SDRAM lines, registers)
    uint32_t fifo_peak_words[2] = {};  // card FIFO write-side level, maximum
    bool fifo_overflow[2] = {};        // the card's sticky overflow flag rose in the period
};

struct island_stats {
    uint64_t pclk_edges = 0;
    uint64_t eclk_edges = 0;
    uint64_t syncs = 0;        // waits of the island thread
    uint64_t stops_bus = 0;    // early stops at a bus completion
    uint64_t stops_irq = 0;    // early stops at an interrupt pin change
    uint64_t pin_changes = 0;  // pin changes folded into the hash
    double wall_s = 0.0;       // host time spent stepping (sensors and scene included)
};

// One sensor frame as the island saw it on the sensor's pins.
struct frame_info {
    int slot = -1;        // ring slot holding its pixels, -1 if evicted / none
    uint64_t pixels = 0;  // active pixels recorded
    bool have_checksum = false;
    uint64_t checksum = 0;  // FNV-1a 64 of the active pixels in raster order
};

class island : public sc_core::sc_module {
  public:
    sc_core::sc_out<bool> ext_int4;  // FRAME_READY
    sc_core::sc_out<bool> ext_int5;  // SYNC_ERROR
    sc_core::sc_out<bool> ext_int6;  // OVERFLOW

    SC_HAS_PROCESS(island);
    island(sc_core::sc_module_name name, const island_config& config, sensor::frame_source& source,
           emif::emif_async_master& engine, timeline& events);
    ~island() override;

    const sensor::sensor_core& sensor(int camera) const { return *m_core[camera]; }
    int frame_width() const { return m_config.profile.active_cols; }
    int frame_height() const { return m_config.profile.active_rows; }
    // Active pixels of the sensor's frame `truth_index` as driven on its
    // pins (nullptr once evicted from the ring or never recorded).
    const uint8_t* frame_pixels(int camera, uint64_t truth_index) const;
    // Checksum of that frame (computed now if still in the ring); false if unknown.
    bool frame_checksum(int camera, uint64_t truth_index, uint64_t* checksum);
    const std::vector<frame_info>& frames(int camera) const { return m_frames[camera]; }

    // Rising edges of EXT_INT4..6 (index 0..2), ticks.
    const std::vector<simtime::ticks>& irq_rises(int index) const { return m_irq_rises[index]; }
    // Ticks of the ECLK edges where an EDMA access (one burst) completed.
    const std::vector<simtime::ticks>& edma_completions() const { return m_edma_done; }
    const std::vector<period_sample>& periods() const { return m_periods; }
    uint32_t fifo_peak_words(int camera) const { return m_fifo_peak_run[camera]; }
    // Complete after finish() (pin_hash.h: changes are folded in canonical order).
    uint64_t pin_hash() const { return m_pin_hasher.value(); }
    // Keep the hashed pin changes of ticks [from, to) (set before the run).
    void log_pin_changes(simtime::ticks from, simtime::ticks to) {
        m_pin_hasher.log_window(from, to);
    }
    const std::vector<pin_change>& logged_pin_changes() const { return m_pin_hasher.logged(); }
    const island_stats& stats() const { return m_stats; }
    // The tick up to which every edge has been stepped.
    simtime::ticks stepped_to() const { return m_last_tick; }
    // Closes the period in progress (end of run).
    virtual void finish();

  protected:
    // For another arrangement of the same cores (tb/platform/arrangements/pins/pins_island.h):
    // the observers only; no card, no sensor cores, no stepping thread. The
    // derived module steps the pins, calls attach_sensor for both cameras
    // and feeds the observers below exactly as advance() does.
    struct observers_only {};
    island(sc_core::sc_module_name name, const island_config& config,
           emif::emif_async_master& engine, timeline& events, observers_only);
    void attach_sensor(int camera, const sensor::sensor_core& core) { m_core[camera] = &core; }
    // A sensor's word of one pixel clock as driven at its falling edge `fall`:
    // pin hash and the frame recorder (data path integrity).
    void record_sensor_word(int camera, uint16_t bits, simtime::ticks fall);

    struct pending_word {
        uint16_t bits = 0;
        simtime::ticks fall = 0;
        bool applied = true;
    };
    struct recorder {
        bool href = false;
        bool vsync = false;
        int col = 0;
        int row = 0;
        uint8_t* frame = nullptr;  // active pixels of the frame being recorded
        uint64_t truth_index = UINT64_MAX;
        uint64_t pixels = 0;
    };

    void run();
    // Steps every edge at or before `limit`; stops after an edge where a bus
    // access completed or an interrupt pin changed (*stopped set). Returns
    // the tick of the last edge stepped.
    simtime::ticks advance(simtime::ticks limit, bool* stopped);
    void reset_card();
    void step_sensor(int camera, bool oe);
    void apply_sensor_word(int camera, uint16_t bits);
    void start_frame(int camera);
    void finalize(int camera, uint64_t truth_index);
    void close_period();
    // ---- pin trace (pin_trace.h); only called with a sink attached ----
    void trace_set(simtime::ticks t, trace_pin pin, uint64_t value);
    void trace_release(simtime::ticks t, trace_pin pin);
    // The card's internals every arrangement traces (sync check, verdict,
    // FIFO levels and overflow flags), read from the verilated model's root
    // (--cc or --sc: the same RTL names).
    template <class card_root>
    void trace_card_internals(simtime::ticks t, const card_root& root) {
        trace_set(t, trace_pin::oe_state, root.card_top__DOT__u_capture__DOT__u_oe__DOT__state_q);
        trace_set(t, trace_pin::sync_causes,
                  root.card_top__DOT__u_capture__DOT__u_check__DOT__causes_q);
        trace_set(t, trace_pin::verdict, root.card_top__DOT__p_verdict_causes);
        trace_set(t, trace_pin::fifo_level_l, root.card_top__DOT__l_wr_level_unused);
        trace_set(t, trace_pin::fifo_level_r, root.card_top__DOT__r_wr_level_unused);
        trace_set(t, trace_pin::fifo_overflow_l, root.card_top__DOT__l_overflow);
        trace_set(t, trace_pin::fifo_overflow_r, root.card_top__DOT__r_overflow);
    }
    void trace_open();  // sends the snapshot at trace_window.from
    // A change at a later tick than the edge being stepped (a clock's fall,
    // a sensor's word at its falling edge): held until the loop passes it.
    void trace_defer(simtime::ticks t, trace_pin pin, uint64_t value);
    void trace_flush(simtime::ticks upto);  // deferred changes at ticks <= upto, in tick order
    void trace_sensor(int camera, simtime::ticks rise);
    void trace_emif(simtime::ticks t, const emif::emif_pins& p);
    void trace_card(simtime::ticks t);
    void trace_firmware();  // timeline events the firmware added since the last call
    void trace_firmware_event(const timeline_event& e);  // one event's firmware signals
    // Whether the edges of tick t make trace calls (pin_trace.h): only from
    // a warm-up before the window (every per-edge signal is refreshed in it,
    // so its value at the window start is exact) until the window ends.
    bool trace_edges_at(simtime::ticks t) const {
        return t >= m_trace_edges_from && t < m_config.trace_window.to;
    }
    void mix_pin(simtime::ticks t, uint32_t group, uint64_t value) {
        m_pin_hasher.add(t, group, value);
    }

    island_config m_config;
    emif::emif_async_master& m_engine;
    emif::ardy_glue m_glue;  // the board between the card's ARDY and the DSP's
    timeline& m_events;
    std::unique_ptr<VerilatedContext> m_context;
    std::unique_ptr<Vcard> m_card;
    std::unique_ptr<sensor::sensor_core> m_sensor[2];
    const sensor::sensor_core* m_core[2] =
        {};  // the sensors observed (owned here or by a derived arrangement)

    simtime::clock_cursor m_pclk;  // on the next rising half-edge
    simtime::clock_cursor m_eclk;
    simtime::ticks m_last_tick = -1;
    pending_word m_pending[2];
    uint16_t m_word_seen[2] = {};  // last sensor words (hash)
    bool m_oe = false;
    uint8_t m_irq = 0;  // EXT_INT4..6 as bits 0..2, as last stepped
    uint8_t m_irq_written = 0;
    emif::emif_pins m_pins_seen;
    uint64_t m_card_out_seen = 0;
    canonical_pin_hash m_pin_hasher;  // pin_hash.h: canonical order, both arrangements

    recorder m_rec[2];
    std::vector<std::vector<uint8_t>> m_ring[2];
    std::vector<uint64_t> m_ring_owner[2];
    std::vector<frame_info> m_frames[2];

    std::vector<simtime::ticks> m_irq_rises[3];
    std::vector<simtime::ticks> m_edma_done;
    std::vector<period_sample> m_periods;
    period_sample m_current;
    simtime::ticks m_next_boundary = 0;
    uint64_t m_busy_at_boundary = 0;
    uint64_t m_cpu_words_at_boundary = 0;
    uint64_t m_eclk_at_boundary = 0;
    uint32_t m_fifo_peak_run[2] = {};
    bool m_fifo_overflow_seen[2] = {};
    island_stats m_stats;

    struct deferred_change {
        simtime::ticks t = 0;
        trace_pin pin = trace_pin::l_pclk;
        uint64_t value = 0;
    };
    pin_trace* m_trace = nullptr;
    trace_id m_trace_id[trace_pin_count] = {};
    uint64_t m_trace_value[trace_pin_count] = {};
    uint8_t m_trace_state[trace_pin_count] = {};  // 0 unknown, 1 driven, 2 released
    bool m_trace_open = false;                    // the snapshot at window.from was sent
    bool m_trace_finished = false;
    simtime::ticks m_trace_edges_from = 0;  // trace_window.from less the warm-up
    deferred_change m_deferred[32];
    int m_deferred_count = 0;
    size_t m_timeline_traced = 0;  // timeline events looked at for the firmware signals
};

}  // namespace platform
