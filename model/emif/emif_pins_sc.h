// Thin SystemC pin wrapper around the EMIF engine, for the literal pin-level
// arrangement (docs/design-brief.md "How it is clocked"): ports named after the J4
// memory connector's pins, the engine stepped by an SC_METHOD at every
// rising edge of ECLKOUT. At an edge it reads ARDY and ED as they were
// before the edge (SystemC's evaluate/update rule) and writes the pins for
// the next cycle, which the slave sees one delta later: the same order as
// the C++ island (emif_pins.h). Port types follow verilator --sc (bool for
// one bit, uint32_t up to 32 bits), so a verilated card binds directly.
//
// Every edge must fall at the time the engine's own clock puts it
// (config().eclk, to the femtosecond), or it is an SC_ERROR: the ECLKOUT
// driver and the engine then agree on every edge.
#pragma once

#include <systemc>

#include "model/emif/emif_async_master.h"

namespace emif {

class emif_pins_sc : public sc_core::sc_module {
  public:
    sc_core::sc_in<bool> eclkout;
    sc_core::sc_out<bool> ce0_n, ce1_n, ce2_n, ce3_n;
    sc_core::sc_out<uint32_t> ea;  // AEA[21:2]
    sc_core::sc_out<uint32_t> be_n;
    sc_core::sc_out<uint32_t> ed_out;
    sc_core::sc_out<bool> ed_oe;
    sc_core::sc_out<bool> aoe_n, are_n, awe_n;
    sc_core::sc_in<uint32_t> ed_in;
    sc_core::sc_in<bool> ardy;

    emif_pins_sc(sc_core::sc_module_name name, emif_async_master& engine);

    emif_async_master& engine() { return m_engine; }

  private:
    void on_rising_edge();
    void drive(const emif_pins& p);

    emif_async_master& m_engine;
};

}  // namespace emif
