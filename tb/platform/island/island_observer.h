// What an island observes on its pins, the same for both arrangements
// (docs/arrangements.md): the pin hash in canonical order (pin_hash.h), the
// sensor frames as driven (frame_recorder.h), the card's FIFO peaks and
// overflows and the EMIF's busy edges per sync period (the budget), the
// interrupt and OE edges and the bus completions (timeline, scoreboard),
// and the pin trace (pin_tracer.h). No effect on the simulation.
//
// An arrangement calls it per tick in the order the fast island steps:
// close_periods_through(t), then the sensors' words, then pclk_rise /
// eclk_rise / bus_completed for the clocks that rose, then the pins for the
// hash; flush_hash_before once no change before a tick can come any more.
// The per-edge calls are inline: they run millions of times per period.
#pragma once

#include <cstdint>
#include <vector>

#include "model/emif/emif_async_master.h"
#include "tb/platform/island/event_order.h"
#include "tb/platform/island/frame_recorder.h"
#include "tb/platform/island/island_config.h"
#include "tb/platform/island/pin_hash.h"
#include "tb/platform/island/pin_tracer.h"
#include "tb/platform/island/timeline.h"

namespace platform {

class island_observer {
  public:
    island_observer(const island_config& config, emif::emif_async_master& engine, timeline& events,
                    event_order order);

    pin_tracer& tracer() { return m_tracer; }
    frame_recorder& frames() { return m_frames; }
    const frame_recorder& frames() const { return m_frames; }
    island_stats& stats() { return m_stats; }
    const island_stats& stats() const { return m_stats; }
    canonical_pin_hash& pin_hash() { return m_hash; }
    const canonical_pin_hash& pin_hash() const { return m_hash; }

    // The card's outputs before the first edge (a change is a difference
    // from these; the DSP's pins are the engine's at construction).
    void set_initial_card_outputs(uint64_t packed) {
        m_card_out_seen = packed;
        m_hash.set_initial(pin_group_card_out, packed);
    }

    // Closes every sync period that ends at or before tick t.
    void close_periods_through(simtime::ticks t) {
        while (t >= m_next_boundary) close_period();
    }
    // A sensor's word of one pixel clock as driven at its falling edge `fall`.
    void sensor_word(int camera, uint16_t bits, simtime::ticks fall) {
        if (m_hash_pins && bits != m_word_seen[camera]) {
            m_word_seen[camera] = bits;
            m_hash.add(fall, camera == 0 ? pin_group_sensor_left : pin_group_sensor_right, bits);
        }
        m_frames.record(camera, bits);
    }
    // The card's pixel clock rose at t: its OE, OE controller state
    // (STATUS.STATE) and FIFO write sides after it.
    void pclk_rise(simtime::ticks t, bool oe, uint8_t oe_state, const uint32_t fifo_level[2],
                   const bool fifo_overflow[2]) {
        ++m_stats.pclk_edges;
        if (oe != m_oe) {
            m_oe = oe;
            add_event(t, event_kind::oe, oe ? 1 : 0);
        }
        if (oe_state != m_oe_state) {
            m_oe_state = oe_state;
            m_card_states.push_back({t, oe_state});
        }
        for (int c = 0; c < 2; ++c) {
            if (fifo_level[c] > m_current.fifo_peak_words[c])
                m_current.fifo_peak_words[c] = fifo_level[c];
            if (fifo_overflow[c] && !m_fifo_overflow_seen[c]) m_current.fifo_overflow[c] = true;
            m_fifo_overflow_seen[c] = fifo_overflow[c];
        }
    }
    // ECLK rose at t with EXT_INT4..6 at `irq` (bits 0..2) before it; true
    // if an interrupt pin changed (the fast island stops there).
    bool eclk_rise(simtime::ticks t, uint8_t irq) {
        ++m_stats.eclk_edges;
        if (irq == m_irq) return false;
        interrupt_edges(t, irq);
        return true;
    }
    // After the engine's step of the ECLK edge at t: true if an access
    // completed there (the EMIF target wakes its initiator at that edge).
    bool bus_completed(simtime::ticks t) {
        const emif::emif_stats& bus = m_engine.stats();
        if (bus.accesses[0] == m_access_seen[0] && bus.accesses[1] == m_access_seen[1])
            return false;
        if (bus.accesses[1] != m_access_seen[1]) m_edma_done.push_back(t);
        m_access_seen[0] = bus.accesses[0];
        m_access_seen[1] = bus.accesses[1];
        ++m_stats.stops_bus;
        return true;
    }
    // The DSP's EMIF pins and the card's outputs as settled at t (pin hash).
    void dsp_pins(simtime::ticks t, const emif::emif_pins& p) {
        if (!m_hash_pins) return;
        const uint64_t packed = pack_dsp_pins(p);
        if (packed == m_dsp_seen) return;
        m_dsp_seen = packed;
        m_hash.add(t, pin_group_emif_dsp, packed);
    }
    void card_outputs(simtime::ticks t, uint64_t packed) {
        if (!m_hash_pins || packed == m_card_out_seen) return;
        m_card_out_seen = packed;
        m_hash.add(t, pin_group_card_out, packed);
    }
    // No pin can change before tick t any more.
    void flush_hash_before(simtime::ticks t) { m_hash.flush_before(t); }

    // Closes the hash, the frames and the trace (end of run).
    void finish();

    const std::vector<simtime::ticks>& irq_rises(int index) const { return m_irq_rises[index]; }
    const std::vector<card_state_change>& card_states() const { return m_card_states; }
    const std::vector<simtime::ticks>& edma_completions() const { return m_edma_done; }
    const std::vector<period_sample>& periods() const { return m_periods; }
    uint32_t fifo_peak_words(int camera) const { return m_fifo_peak_run[camera]; }

  private:
    void add_event(simtime::ticks t, event_kind kind, uint8_t a, uint32_t b = 0) {
        if (m_order == event_order::appended) {
            m_events.add(t, kind, a, b);
        } else {
            m_events.add_pin_event(t, kind, a, b);
        }
    }
    void interrupt_edges(simtime::ticks t, uint8_t irq);
    void close_period();

    emif::emif_async_master& m_engine;
    timeline& m_events;
    event_order m_order;
    bool m_hash_pins;
    simtime::ticks m_period;
    simtime::ticks m_end;
    canonical_pin_hash m_hash;
    frame_recorder m_frames;
    pin_tracer m_tracer;
    island_stats m_stats;

    uint16_t m_word_seen[2] = {};
    uint64_t m_dsp_seen = 0;
    uint64_t m_card_out_seen = 0;
    bool m_oe = false;
    uint8_t m_oe_state = 0;
    uint8_t m_irq = 0;
    uint64_t m_access_seen[2] = {};
    bool m_fifo_overflow_seen[2] = {};

    std::vector<simtime::ticks> m_irq_rises[3];
    std::vector<card_state_change> m_card_states;
    std::vector<simtime::ticks> m_edma_done;
    std::vector<period_sample> m_periods;
    period_sample m_current;
    simtime::ticks m_next_boundary = 0;
    uint64_t m_busy_at_boundary = 0;
    uint64_t m_cpu_words_at_boundary = 0;
    uint64_t m_eclk_at_boundary = 0;
    uint32_t m_fifo_peak_run[2] = {};
};

}  // namespace platform
