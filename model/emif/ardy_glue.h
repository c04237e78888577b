// The board between the card's ARDY and the DSP's (docs/faults.md,
// emif-wait): a wait-state generator on one CE space that, from a time on,
// holds the DSP's ARDY low for `extra_cycles` ECLK more at the end of each
// access's programmed strobe, whatever the card drives. The access is
// stretched on the pins, as a slow card or a faulty glue would stretch it,
// and the waveform shows the DSP's ARDY low (emif.ARDY) while the card's
// own (card.emif_slave.ARDY) is high.
//
// A tiny synchronous circuit, so both arrangements compute the same ARDY:
// a register counts the consecutive ECLK edges that sampled the glue's CE
// selected with ARE or AWE low (the strobe so far), and the hold is
// combinational on the pins and that count. With the strobe starting at
// edge S0 (ARE low from just after it), the EMIF ends it at the first edge
// E >= S0 + strobe whose ARDY sampled at E - ardy_lead was high
// (emif_async_master), so holding ARDY low for counts
// [strobe - lead, strobe - lead + extra) adds exactly `extra` edges.
#pragma once

#include <cstdint>

#include "model/emif/emif_async_master.h"
#include "model/emif/emif_pins.h"

namespace emif {

class ardy_glue {
  public:
    // One fault per CE space (extra_cycles 0: none); from_tick arms it.
    void add(const ardy_fault& fault);
    bool empty() const;

    // Whether the glue holds ARDY low before the coming ECLK edge, given the
    // DSP's pins now (combinational).
    bool holds(const emif_pins& pins, const emif_async_master& master) const;
    // The ECLK edge at tick `t`, with the pins as they were before it.
    void clock(const emif_pins& pins, simtime::ticks t);
    // The DSP's ARDY input: the card's while it is selected (CE2/CE3, less
    // the glue's hold), the pull-up's otherwise.
    bool bus_ardy(const emif_pins& pins, bool card_ardy, const emif_async_master& master) const;

  private:
    uint32_t count_after(const emif_pins& pins) const;
    int fault_ce(const emif_pins& pins) const;

    ardy_fault m_fault[ce_count];
    bool m_armed[ce_count] = {};
    int m_unarmed = 0;            // faults whose from_tick has not come yet
    uint32_t m_strobe_edges = 0;  // the register: strobe edges so far on a faulted CE
};

}  // namespace emif
