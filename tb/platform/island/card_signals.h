// The daughter card's signals an island observes after each edge, the same
// fields from either arrangement: the fast island reads them from the
// verilated --cc model, the pin-level one from its sc_signals and the --sc
// model. The internals come from the card's debug outputs (the FIFO levels)
// and the verilated root (same RTL names in --cc and --sc).
#pragma once

#include <cstdint>

#include "tb/platform/island/pin_hash.h"

namespace platform {

struct card_signals {
    bool sensor_oe = false;
    bool ext_int[3] = {};  // EXT_INT4..6
    bool slave_ardy = false;
    bool slave_ed_oe = false;
    uint32_t slave_ed = 0;
    // Internals (docs/card.md): OE controller state, causes so far, last
    // verdict, FIFO write-side levels and sticky overflow flags.
    uint32_t oe_state = 0;
    uint32_t sync_causes = 0;
    uint32_t verdict = 0;
    uint32_t fifo_level[2] = {};
    bool fifo_overflow[2] = {};

    uint8_t irq_bits() const {
        return static_cast<uint8_t>((ext_int[0] ? 1 : 0) | (ext_int[1] ? 2 : 0) |
                                    (ext_int[2] ? 4 : 0));
    }
    // As the pin hash packs them (pin_hash.h).
    uint64_t packed_outputs() const {
        return pack_card_outputs(sensor_oe, slave_ardy, slave_ed_oe, ext_int[0], ext_int[1],
                                 ext_int[2], slave_ed);
    }
};

// The internals from a verilated card (Vcard or Vcard_sc) and its root.
template <class card_model>
void read_card_internals(const card_model& card, card_signals* s) {
    const auto& root = *card.rootp;
    s->oe_state = root.card_top__DOT__u_capture__DOT__u_oe__DOT__state_q;
    // In VERDICT's bit order: the frame-identity causes are its bits 9..8.
    const uint32_t causes = root.card_top__DOT__u_capture__DOT__u_check__DOT__causes_q;
    s->sync_causes = (causes & 0x3Fu) | ((causes >> 6) & 3u) << 8;
    s->verdict = root.card_top__DOT__p_verdict_causes;
    s->fifo_overflow[0] = root.card_top__DOT__l_overflow != 0;
    s->fifo_overflow[1] = root.card_top__DOT__r_overflow != 0;
}

// AED as the DSP reads it: the card drives it only while CE2 / CE3 is
// selected and its ED_OE is high; an idle bus reads 0 (docs/emif.md).
inline uint32_t bus_ed_from_card(int active_ce, bool card_ed_oe, uint32_t card_ed) {
    return (active_ce == 2 || active_ce == 3) && card_ed_oe ? card_ed : 0u;
}

}  // namespace platform
