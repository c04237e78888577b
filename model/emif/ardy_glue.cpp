#include "model/emif/ardy_glue.h"

namespace emif {

void ardy_glue::add(const ardy_fault& fault) {
    if (fault.ce < 0 || fault.ce >= ce_count) return;
    m_fault[fault.ce] = fault;
    m_armed[fault.ce] = false;
    m_unarmed = 0;
    for (int ce = 0; ce < ce_count; ++ce)
        m_unarmed += m_fault[ce].extra_cycles != 0 && !m_armed[ce];
}

bool ardy_glue::empty() const {
    for (const ardy_fault& f : m_fault)
        if (f.extra_cycles != 0) return false;
    return true;
}

// The CE space selected with a strobe low, if the glue has a fault there.
int ardy_glue::fault_ce(const emif_pins& pins) const {
    const int ce = pins.active_ce();
    if (ce < 0 || m_fault[ce].extra_cycles == 0) return -1;
    return pins.are_n && pins.awe_n ? -1 : ce;
}

uint32_t ardy_glue::count_after(const emif_pins& pins) const {
    return fault_ce(pins) >= 0 ? m_strobe_edges + 1 : 0;
}

bool ardy_glue::holds(const emif_pins& pins, const emif_async_master& master) const {
    const int ce = fault_ce(pins);
    if (ce < 0 || !m_armed[ce]) return false;
    const async_timing& t = master.timing(ce);
    const uint32_t strobe = pins.awe_n ? t.read_strobe : t.write_strobe;
    const uint32_t lead = master.config().ardy_lead;
    const uint32_t first = strobe > lead ? strobe - lead : 1;
    const uint32_t k = count_after(pins);
    return k >= first && k < first + m_fault[ce].extra_cycles;
}

void ardy_glue::clock(const emif_pins& pins, simtime::ticks t) {
    m_strobe_edges = count_after(pins);
    if (m_unarmed == 0) return;  // every ECLK edge calls this: nothing left to arm
    for (int ce = 0; ce < ce_count; ++ce) {
        if (m_fault[ce].extra_cycles == 0 || m_armed[ce] || t < m_fault[ce].from_tick) continue;
        m_armed[ce] = true;
        --m_unarmed;
    }
}

bool ardy_glue::bus_ardy(const emif_pins& pins, bool card_ardy,
                         const emif_async_master& master) const {
    const int ce = pins.active_ce();
    if (ce != 2 && ce != 3) return true;
    return card_ardy && !holds(pins, master);
}

}  // namespace emif
