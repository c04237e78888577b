// The CPU clock on SystemC time: cycle k's rising edge is at the exact tick
// of a simtime::tick_clock, converted once (model/time/sc_ticks.h), so no
// rounded period is ever accumulated.
#pragma once

#include <cstdint>
#include <systemc>

#include "model/time/sc_ticks.h"
#include "model/time/ticks.h"

namespace c6416 {

class cpu_clock_sc {
  public:
    explicit cpu_clock_sc(const simtime::tick_clock& clock) : m_clock(clock) {}

    const simtime::tick_clock& ticks() const { return m_clock; }
    // The CPU cycle (edge index) at or after t.
    uint64_t cycle_at_or_after(const sc_core::sc_time& t) const {
        return m_clock.first_rise_at_or_after(simtime::tick_at_or_after(t));
    }
    // The time of edge k.
    sc_core::sc_time time_of_cycle(uint64_t k) const {
        return simtime::sc_time_of(m_clock.rise(k));
    }
    // The cycle at or after the current simulation time.
    uint64_t current_cycle() const { return cycle_at_or_after(sc_core::sc_time_stamp()); }

  private:
    simtime::tick_clock m_clock;
};

}  // namespace c6416
