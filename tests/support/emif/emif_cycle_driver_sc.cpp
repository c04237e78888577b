#include "tests/support/emif/emif_cycle_driver_sc.h"

#include <algorithm>

#include "model/time/sc_ticks.h"

namespace emif {

emif_cycle_driver::emif_cycle_driver(sc_core::sc_module_name name, emif_async_master& engine,
                                     const sc_core::sc_event& work, emif_pin_slave& slave)
    : sc_core::sc_module(name), m_engine(engine), m_work(work), m_slave(slave) {
    SC_HAS_PROCESS(emif_cycle_driver);
    SC_THREAD(run);
}

void emif_cycle_driver::run() {
    const simtime::tick_clock& eclk = m_engine.config().eclk;
    for (;;) {
        if (m_engine.idle()) {
            while (m_engine.idle()) wait(m_work);
            // Requests made at this time start at the first edge after it.
            const simtime::ticks now = simtime::tick_at_or_before(sc_core::sc_time_stamp());
            m_engine.skip_idle_to(
                std::max(m_engine.next_edge(), eclk.first_rise_at_or_after(now + 1)));
            continue;
        }
        if (m_engine.arbitrates_at_next_edge()) {
            const sc_core::sc_time at =
                simtime::sc_time_of(m_engine.edge_tick(m_engine.next_edge()));
            if (at > sc_core::sc_time_stamp()) {
                wait(at - sc_core::sc_time_stamp());
                ++m_syncs;
            }
        }
        const emif_pins pins = m_engine.pins();
        const emif_inputs in = m_slave.outputs(pins);
        m_slave.eclk_edge(pins);
        m_engine.step(in);
    }
}

}  // namespace emif
