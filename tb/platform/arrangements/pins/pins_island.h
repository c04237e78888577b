// The literal pin-level arrangement (docs/design-brief.md "How it is clocked";
// docs/arrangements.md): the same cores as the fast island, each in its
// SystemC pin wrapper, wired with sc_signals, as a SystemC user would build
// it first:
//
//   clocks (one thread, tick cursors) --mclk--> sensor_sc L, sensor_sc R --pins--> Vcard_sc
//                                     --eclk--> emif_pins_sc (engine) <--ED/ARDY-- (verilator --sc)
//
// Clocks. One thread drives the card's master pixel clock (mclk, which also
// feeds both sensors) and ECLKOUT from two simtime::clock_cursors on the
// same tick_clocks as the fast island; half-edge h of a clock is written at
// sc_time to_fs(tick) (1 tick = 1/18 ns, rounded once to the 1 fs
// resolution, never by adding rounded periods). Coincident edges of both
// clocks (every 350 ns at DSK v1) are written in ONE delta, so the card's
// two clock domains sample in one evaluation, as the fast island's single
// eval does. Rounding keeps the order: to_fs is monotonic and 1 tick is
// 55,555 fs, so distinct ticks never share a femtosecond.
//
// Edge order is SystemC's evaluate/update rule: at a rising edge every
// process (card, EMIF engine, sensors sampling OE) reads the signals as they
// were before it and its writes appear one delta later; sensors drive their
// pins at their falling edge; the EMIF engine's new pins reach the card a
// delta after the edge and the card's combinational ED/ARDY follow. That is
// the order the fast island implements in C++ (arrangements/fast/).
//
// Observers. The clock thread, woken for the next half-edge, first looks at
// the settled signals of the tick before (every delta of that tick has run)
// and feeds them to the island's observer (island/island_observer.h), the
// same component the fast island feeds: OE, interrupt and frame events are
// placed on the timeline where the fast island puts them
// (timeline::add_pin_event).
//
// Pin trace (pin_trace.h, --vcd): the same signals and values as the fast
// island, read from the settled signals of each tick by the same tracer,
// only for the ticks from the warm-up before the window to its end.
//
// Not supported: a pclk_drift fault (a sensor off the master clock has edges
// the clock thread does not visit); an SC_ERROR says so.
#pragma once

#include <memory>

#include "model/emif/emif_async_master.h"
#include "model/sensor/frame_source.h"
#include "tb/platform/island/island.h"

namespace pins {

// The pin-level arrangement behind platform_config::arrangement == pins.
std::unique_ptr<platform::island> make_pins_island(const char* name,
                                                   const platform::island_config& config,
                                                   sensor::frame_source& source,
                                                   emif::emif_async_master& engine,
                                                   platform::timeline& events);

}  // namespace pins
