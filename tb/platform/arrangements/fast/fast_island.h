// The fast arrangement of the cycle-accurate island (docs/design-brief.md "How it is
// clocked"; docs/platform.md): both sensor cores, the verilated card
// (verilator --cc) and the EMIF cycle engine, stepped edge by edge from
// plain C++ inside ONE SystemC thread.
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
// Observers: the island's observer (tb/platform/island/island_observer.h),
// fed at each edge in the order it documents.
//
// Cost per edge: one Verilator eval at the rising edge; a second one at the
// falling half only when the engine changed one of the card's EMIF inputs
// (the only inputs with logic that settles between edges: a sensor word is
// registered at the card's pixel clock before anything reads it), otherwise
// the clocks' low level is recorded without an eval; then the engine's
// switch, a sensor step, a few compares. The untraced card is evaluated
// without the parts of Verilator's loop that change nothing on it
// (card_eval.h: the input region only after an input changed). The loop's
// state lives in members between syncs. docs/performance.md has the figures.
#pragma once

#include <memory>

#include "model/emif/emif_async_master.h"
#include "model/sensor/frame_source.h"
#include "tb/platform/island/island.h"

namespace fast {

// The fast arrangement behind platform_config::arrangement == fast.
std::unique_ptr<platform::island> make_fast_island(const char* name,
                                                   const platform::island_config& config,
                                                   sensor::frame_source& source,
                                                   emif::emif_async_master& engine,
                                                   platform::timeline& events);

}  // namespace fast
