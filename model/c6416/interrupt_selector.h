// The C6416 interrupt selector (model/c6416/c6416_regs.h irq::; [DS] Table 26):
// MUXL / MUXH route one of 32 interrupt events to each maskable CPU
// interrupt INT4..INT15; EXTPOL sets the active edge of EXT_INT4..7.
// Plain C++ (no SystemC): the c6416 module feeds it pin levels and events.
#pragma once

#include <cstdint>

namespace c6416 {

class interrupt_selector {
  public:
    interrupt_selector() { reset(); }

    void reset();

    // Register access at its address (muxh, muxl, extpol); false if not one.
    bool read(uint32_t address, uint32_t& value) const;
    bool write(uint32_t address, uint32_t value);

    // CPU interrupts (bit n = INTn, n in 4..15) an event (selector code, e.g.
    // irq::sel_gpint4) is routed to; 0 if none.
    uint32_t cpu_interrupts_for(uint32_t event_code) const;
    // The event code CPU interrupt n (4..15) selects.
    uint32_t selected_event(int cpu_int) const;

    // EXT_INT(4 + n) changed from `was` to `now`: true on its active edge
    // (rising when EXTPOL bit n is 0, falling when it is 1).
    bool active_edge(int n, bool was, bool now) const;

    uint32_t muxh() const { return m_muxh; }
    uint32_t muxl() const { return m_muxl; }
    uint32_t extpol() const { return m_extpol; }

  private:
    uint32_t m_muxh = 0;
    uint32_t m_muxl = 0;
    uint32_t m_extpol = 0;
};

}  // namespace c6416
