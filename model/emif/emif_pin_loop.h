// The C++ island order for the EMIF engine and the devices on its pins,
// stepped edge by edge from a plain loop (no SystemC): per ECLKOUT edge every
// slave's outputs are taken as they were before the edge, then the slaves'
// flops sample the pins, then the engine samples the slaves and drives new
// pins (emif_pins.h). Several slaves share the bus: the one whose CE space
// is selected drives ED and ARDY (a slave on an unselected space drives
// nothing, ARDY idles high).
#pragma once

#include <cstdint>

#include "model/emif/emif_async_master.h"

namespace emif {

class emif_pin_loop {
  public:
    explicit emif_pin_loop(emif_async_master& engine) : m_engine(engine) {}

    // The slave answering on CE space `ce` (nullptr: nothing there).
    void attach(int ce, emif_pin_slave* slave) { m_slave[ce] = slave; }

    void step() {
        const emif_pins& pins = m_engine.pins();
        const int ce = pins.active_ce();
        emif_inputs in;
        if (ce >= 0 && m_slave[ce]) in = m_slave[ce]->outputs(pins);
        for (emif_pin_slave* s : m_slave)
            if (s) s->eclk_edge(pins);
        m_engine.step(in);
    }

    // Steps until the engine is idle; returns false if that took more than max_edges.
    bool run_until_idle(uint64_t max_edges = 100000000) {
        for (uint64_t n = 0; n < max_edges; ++n) {
            if (m_engine.idle()) return true;
            step();
        }
        return m_engine.idle();
    }
    void run(uint64_t edges) {
        for (uint64_t n = 0; n < edges; ++n) step();
    }

  private:
    emif_async_master& m_engine;
    emif_pin_slave* m_slave[ce_count] = {};
};

}  // namespace emif
