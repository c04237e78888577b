// The cycle-accurate island (docs/design-brief.md "How it is clocked"; docs/platform.md,
// docs/arrangements.md): both sensors, the daughter card's RTL and the EMIF
// engine, clocked from tick counts (1/18 ns), beside the C6416 model. Two
// arrangements step the same cores (tb/platform/arrangements/): fast (plain
// C++ cores in one SystemC thread) and pins (SystemC modules wired with
// sc_signals, the literal reference). Each one only steps and wires its
// cores; what the platform reads after the run comes from the observer they
// both hold (island_observer.h), so scoreboard, budget and report read
// either arrangement the same way.
#pragma once

#include <cstdint>
#include <systemc>
#include <vector>

#include "model/emif/emif_async_master.h"
#include "model/sensor/sensor_core.h"
#include "tb/platform/island/island_config.h"
#include "tb/platform/island/island_observer.h"
#include "tb/platform/island/timeline.h"

namespace platform {

class island : public sc_core::sc_module {
  public:
    sc_core::sc_out<bool> ext_int4;  // FRAME_READY
    sc_core::sc_out<bool> ext_int5;  // SYNC_ERROR
    sc_core::sc_out<bool> ext_int6;  // OVERFLOW

    const sensor::sensor_core& sensor(int camera) const {
        return m_observer.frames().sensor(camera);
    }
    int frame_width() const { return m_config.profile.active_cols; }
    int frame_height() const { return m_config.profile.active_rows; }
    // Active pixels of the sensor's frame `truth_index` as driven on its
    // pins (nullptr once evicted from the ring or never recorded).
    const uint8_t* frame_pixels(int camera, uint64_t truth_index) const {
        return m_observer.frames().pixels(camera, truth_index);
    }
    // Checksum of that frame (computed now if still in the ring); false if unknown.
    bool frame_checksum(int camera, uint64_t truth_index, uint64_t* checksum) {
        return m_observer.frames().checksum(camera, truth_index, checksum);
    }
    const std::vector<frame_info>& frames(int camera) const {
        return m_observer.frames().frames(camera);
    }

    // Rising edges of EXT_INT4..6 (index 0..2), ticks.
    const std::vector<simtime::ticks>& irq_rises(int index) const {
        return m_observer.irq_rises(index);
    }
    // The card's OE controller state after each change (STATUS.STATE).
    const std::vector<card_state_change>& card_states() const { return m_observer.card_states(); }
    // Ticks of the ECLK edges where an EDMA access (one burst) completed.
    const std::vector<simtime::ticks>& edma_completions() const {
        return m_observer.edma_completions();
    }
    const std::vector<period_sample>& periods() const { return m_observer.periods(); }
    uint32_t fifo_peak_words(int camera) const { return m_observer.fifo_peak_words(camera); }
    // Complete after finish() (pin_hash.h: changes are folded in canonical order).
    uint64_t pin_hash() const { return m_observer.pin_hash().value(); }
    // Keep the hashed pin changes of ticks [from, to) (set before the run).
    void log_pin_changes(simtime::ticks from, simtime::ticks to) {
        m_observer.pin_hash().log_window(from, to);
    }
    const std::vector<pin_change>& logged_pin_changes() const {
        return m_observer.pin_hash().logged();
    }
    const island_stats& stats() const { return m_observer.stats(); }
    // Closes the period in progress, the hash, the frames and the trace (end of run).
    virtual void finish() = 0;
    // Adds faults to an island that is already running (a fault campaign's
    // snapshot, docs/performance.md): each must start after every edge
    // stepped so far, so the run goes on as if it had had them from the
    // start. The fast arrangement takes them; the pin-level one throws
    // std::logic_error.
    virtual void add_late_faults(const std::vector<sensor::fault> (&sensor_faults)[2],
                                 const std::vector<emif::ardy_fault>& ardy_faults) = 0;

  protected:
    island(sc_core::sc_module_name name, const island_config& config,
           emif::emif_async_master& engine, timeline& events, event_order order)
        : sc_core::sc_module(name),
          ext_int4("ext_int4"),
          ext_int5("ext_int5"),
          ext_int6("ext_int6"),
          m_config(config),
          m_engine(engine),
          m_events(events),
          m_observer(config, engine, events, order) {}

    island_config m_config;
    emif::emif_async_master& m_engine;
    timeline& m_events;
    island_observer m_observer;
};

}  // namespace platform
