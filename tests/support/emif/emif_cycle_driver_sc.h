// Test support: the fast arrangement for the EMIF alone, one SystemC thread
// that steps the engine and a C++ pin slave (e.g. async_sram_slave) cycle by
// cycle, as the platform's RTL island does with the verilated card.
//
// It runs ahead of SystemC time through an access and syncs (wait) only
// before an edge where the engine may arbitrate (emif_async_master::
// arbitrates_at_next_edge), so every access queued before that edge's time
// takes part, exactly as in the pin-level arrangement. Completions happen
// at such edges, so b_transport returns at the exact edge time. Over an idle
// bus it sleeps on the target's work event and then skips the engine to the
// first edge after the request (refreshes due meanwhile are stepped, the
// slave is not: it must be a pure responder that needs no idle clocks).
// Cost: about two context switches per access, plus the engine and slave per edge.
#pragma once

#include <systemc>

#include "model/emif/emif_async_master.h"

namespace emif {

class emif_cycle_driver : public sc_core::sc_module {
  public:
    emif_cycle_driver(sc_core::sc_module_name name, emif_async_master& engine,
                      const sc_core::sc_event& work, emif_pin_slave& slave);

    uint64_t syncs() const { return m_syncs; }

  private:
    void run();

    emif_async_master& m_engine;
    const sc_core::sc_event& m_work;
    emif_pin_slave& m_slave;
    uint64_t m_syncs = 0;
};

}  // namespace emif
