// Ticks <-> SystemC time, the one conversion every SystemC module of the
// model uses (ticks.h is the plain C++ side).
//
// SystemC must run at a 1 fs resolution (tests/support/sc_test_main.cpp):
// a tick's time is to_fs(tick), rounded once from the exact tick count, so
// the fast island and the pin arrangement place every edge at the same
// femtosecond. Header-only so that plain C++ libraries need no SystemC.
#pragma once

#include <systemc>

#include "model/time/ticks.h"

namespace simtime {

// SystemC time of a tick (rounded once, from the exact tick count).
inline sc_core::sc_time sc_time_of(ticks t) {
    return sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(to_fs(t)));
}

// The last tick whose time is at or before t.
inline ticks tick_at_or_before(const sc_core::sc_time& t) {
    const int64_t fs = static_cast<int64_t>(t.value());
    // An estimate without overflow, then onto the last tick not later than fs.
    ticks tick = fs / fs_per_ns * ticks_per_ns + (fs % fs_per_ns) * ticks_per_ns / fs_per_ns;
    while (to_fs(tick + 1) <= fs) ++tick;
    while (tick > 0 && to_fs(tick) > fs) --tick;
    return tick;
}

// The first tick whose time is at or after t.
inline ticks tick_at_or_after(const sc_core::sc_time& t) {
    return tick_at_or_after_fs(static_cast<int64_t>(t.value()));
}

}  // namespace simtime
