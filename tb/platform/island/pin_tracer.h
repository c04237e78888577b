// The pin trace of an island (pin_trace.h, --vcd): every traced signal's
// value per tick, reduced to its changes inside the window, sent to the
// run's sink. Both arrangements feed it the same values: the fast island at
// each edge it steps (a change at a later tick, a clock's fall or a
// sensor's word at its falling edge, is deferred until the loop passes it),
// the pin-level one from the settled signals of each tick.
//
// Before the window the edges make no trace calls, except in a warm-up of
// 16 periods of the slower of the card's two clocks (a drift fault moves a
// sensor's clock off the master by ppm, not by periods): by then every
// per-edge signal holds its value at the window start. The firmware's
// signals come from the timeline, read from the start. A window after the
// run's end gets the values at the end.
#pragma once

#include <cstdint>

#include "model/emif/emif_pins.h"
#include "model/time/ticks.h"
#include "tb/platform/island/card_signals.h"
#include "tb/platform/island/event_order.h"
#include "tb/platform/island/island_config.h"
#include "tb/platform/island/pin_trace.h"
#include "tb/platform/island/timeline.h"

namespace platform {

class pin_tracer {
  public:
    // Inactive (every call returns at once) without config.trace.
    pin_tracer(const island_config& config, const simtime::tick_clock& eclk, const timeline& events,
               event_order order);

    bool active() const { return m_sink != nullptr; }
    // Whether the edges of tick t make trace calls: from the warm-up before
    // the window until the window ends.
    bool edges_at(simtime::ticks t) const { return t >= m_edges_from && t < m_window.to; }

    // Declares every signal and sets the values before the first edge.
    void begin(const emif::emif_pins& dsp);

    void set(simtime::ticks t, trace_pin pin, uint64_t value);
    void release(simtime::ticks t, trace_pin pin);
    // A change at a later tick than the edge being stepped, held until flush.
    void defer(simtime::ticks t, trace_pin pin, uint64_t value);
    void flush(simtime::ticks upto);  // deferred changes at ticks <= upto, in tick order
    // Before an edge at tick t that may change the card: every change before
    // t reaches the sink and is sealed (pin_trace::seal_before), so a sink
    // that reads the card (--waves) writes those times with the card's
    // values there; at the window's end the sink finishes.
    void before_card_edge(simtime::ticks t);

    // A sensor's rising edge at `rise` and the word it drives from `fall`.
    void sensor_edge(int camera, simtime::ticks rise, uint16_t bits, simtime::ticks fall);
    // A sensor's pins as settled at tick t.
    void sensor_pins(int camera, simtime::ticks t, bool pclk, uint16_t bits);
    void emif(simtime::ticks t, const emif::emif_pins& dsp);
    // The card's outputs and internals, and the DSP's ARDY input after the board glue.
    void card(simtime::ticks t, const card_signals& card, bool bus_ardy,
              const emif::emif_pins& dsp);
    // The firmware's timeline events up to tick `upto` (an appending
    // arrangement takes every event added so far).
    void firmware_up_to(simtime::ticks upto);
    // The rest of the firmware, the deferred changes and the snapshot of a
    // window no edge reached; then the sink's finish.
    void finish(simtime::ticks end);

  private:
    struct deferred_change {
        simtime::ticks t = 0;
        trace_pin pin = trace_pin::l_pclk;
        uint64_t value = 0;
    };
    void open();  // the snapshot at the window start
    void firmware_event(const timeline_event& e);

    pin_trace* m_sink = nullptr;
    tick_window m_window;
    simtime::ticks m_edges_from = 0;  // window.from less the warm-up
    const timeline& m_events;
    event_order m_order;
    trace_id m_id[trace_pin_count] = {};
    uint64_t m_value[trace_pin_count] = {};
    uint8_t m_state[trace_pin_count] = {};  // 0 unknown, 1 driven, 2 released
    bool m_open = false;                    // the snapshot at window.from was sent
    bool m_finished = false;
    deferred_change m_deferred[32];
    int m_deferred_count = 0;
    size_t m_firmware_index = 0;        // appended: events looked at
    simtime::ticks m_firmware_to = -1;  // placed: events through this tick are traced
};

}  // namespace platform
