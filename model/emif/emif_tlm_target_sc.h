// The EMIF's TLM-2.0 side: the DSP's masters (CPU through L2, EDMA) call
// b_transport on a target socket; the access runs on the cycle engine
// (emif_async_master) and b_transport returns at the simulated time the
// engine completed it.
//
// As libsystemctlm-soc's bridges do, b_transport first consumes the
// initiator's accumulated loosely-timed delay (wait(delay); delay = 0), so
// the pins move at the right simulated time, then queues the access (made at
// that tick: eligible from the first ECLK edge strictly after it) and waits
// for the engine's completion. An EDMA burst is ONE b_transport (length =
// words * 4) that the engine runs word by word at the pins; streaming width 4
// means a fixed address (a FIFO port), streaming width >= length an
// incrementing one. Byte enables (a 4-byte pattern, repeated) apply to writes.
//
// The engine is stepped by someone else: emif_pins_sc (pin-level, one
// SC_METHOD per ECLK edge), the platform's fast island (tb/platform) or, in
// tests, emif_cycle_driver (tests/support/emif). Requires
// 1 fs time resolution (tests/support/sc_test_main.cpp): tick edges are placed with
// simtime::sc_time_of (model/time/sc_ticks.h).
#pragma once

#include <tlm_utils/simple_target_socket.h>
#include <systemc>
#include <tlm>

#include "model/emif/emif_async_master.h"

namespace emif {

class emif_tlm_target : public sc_core::sc_module {
  public:
    tlm_utils::simple_target_socket<emif_tlm_target> cpu;   // single accesses
    tlm_utils::simple_target_socket<emif_tlm_target> edma;  // bursts

    // Installs itself as the engine's completion handler.
    emif_tlm_target(sc_core::sc_module_name name, emif_async_master& engine);

    emif_async_master& engine() { return m_engine; }
    // Notified (delta) whenever an access is queued: a driver sleeping over
    // an idle bus wakes on it.
    const sc_core::sc_event& work_event() const { return m_work; }
    uint64_t transactions() const { return m_transactions; }

  private:
    void b_transport_cpu(tlm::tlm_generic_payload& p, sc_core::sc_time& delay);
    void b_transport_edma(tlm::tlm_generic_payload& p, sc_core::sc_time& delay);
    void transport(requester who, tlm::tlm_generic_payload& p, sc_core::sc_time& delay);
    static void on_complete(void* self, emif_access& a);

    emif_async_master& m_engine;
    sc_core::sc_event m_work;
    uint64_t m_transactions = 0;
};

}  // namespace emif
