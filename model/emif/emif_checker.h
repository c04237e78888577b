// Protocol checker on the EMIFA async pins (plain C++, apart from the model it
// checks, as libsystemctlm-soc keeps its checkers). It observes the pins once
// per ECLK cycle and compares every async access with the CECTL timing
// programmed for its CE space (docs/emif.md, "Protocol checker").
//
// Rules (cycles = ECLK cycles; "select" = CE, EA, BE, AOE and the DSP's ED
// drive and value, the signals [DS] requires valid before and after a strobe):
//   setup_short      select changed less than RS / WS cycles before the strobe fell;
//   strobe_short     ARE / AWE low for fewer than RST / WST cycles (ARDY may
//                    only lengthen it);
//   hold_short       select changed less than RH / WH cycles after the strobe rose;
//   hold_setup_short two strobes on one CE with no select change between them
//                    (same address, CE held low) closer than hold + setup;
//   select_in_strobe select changed while the strobe was low;
//   are_awe_both_low ARE and AWE low together;
//   ed_in_read       the DSP drives ED while AOE or ARE is low;
//   ce_turnaround    a different CE space selected fewer than TA idle cycles
//                    after the last one (TA as the engine applies it: the
//                    larger of the async spaces involved; SDRAM spaces have none);
//   dir_turnaround   on one CE, the DSP drives ED fewer than TA cycles after
//                    AOE was low, or AOE falls fewer than TA cycles after it drove ED;
//   multiple_ce      more than one CE low;
//   strobe_no_ce     a strobe with no async CE space selected.
// Cost: a few comparisons per cycle; violations are stored (first 4096) and counted.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "model/emif/cectl.h"
#include "model/emif/emif_pins.h"

namespace emif {

enum class violation_kind : uint8_t {
    setup_short,
    strobe_short,
    hold_short,
    hold_setup_short,
    select_in_strobe,
    are_awe_both_low,
    ed_in_read,
    ce_turnaround,
    dir_turnaround,
    multiple_ce,
    strobe_no_ce,
};
inline constexpr int violation_kind_count = 11;
const char* violation_name(violation_kind k);

struct violation {
    uint64_t cycle = 0;  // the observed cycle (edge index) where it was seen
    violation_kind kind = violation_kind::setup_short;
    int ce = -1;
    uint32_t required = 0;  // cycles programmed / required
    uint32_t actual = 0;    // cycles seen
};
std::string to_string(const violation& v);

class emif_checker : public emif_pin_observer {
  public:
    explicit emif_checker(const uint32_t (&cectl)[ce_count]);
    // The firmware reprogrammed CECTLn (applies to accesses after it).
    void set_cectl(int ce, uint32_t value) { m_timing[ce] = decode_cectl(value); }

    // The pins driven during cycle `cycle` (from edge `cycle` to the next).
    // Cycles must be observed in increasing order; a gap counts as cycles of
    // unchanged pins.
    void observe(uint64_t cycle, const emif_pins& pins);
    void observe(uint64_t edge, const emif_pins& pins, const emif_inputs&) override {
        observe(edge, pins);
    }

    uint64_t count(violation_kind k) const { return m_counts[static_cast<int>(k)]; }
    uint64_t total() const;
    const std::vector<violation>& violations() const { return m_violations; }
    uint64_t cycles_observed() const { return m_observed; }
    uint64_t strobes_checked() const { return m_strobes; }

  private:
    struct select {
        int ce = -1;
        uint32_t ea = 0;
        uint8_t be_n = 0xF;
        bool aoe_n = true, ed_oe = false;
        uint32_t ed = 0;
        bool operator==(const select& o) const {
            return ce == o.ce && ea == o.ea && be_n == o.be_n && aoe_n == o.aoe_n &&
                   ed_oe == o.ed_oe && ed == o.ed;
        }
    };
    void flag(uint64_t cycle, violation_kind k, int ce, uint32_t required, uint32_t actual);
    void check_turnarounds(uint64_t c, int active, bool reading, bool driving);
    void check_async_cycle(uint64_t c, const emif_pins& p, int active, bool read_strobe,
                           bool write_strobe);
    void strobe_rose(uint64_t c);
    void strobe_fell(uint64_t c, int active, bool write_strobe);
    bool async_space(int ce) const { return ce >= 0 && is_async(m_timing[ce].type); }
    uint32_t turnaround(int a, int b) const;

    async_timing m_timing[ce_count];
    bool m_have_prev = false;
    uint64_t m_observed = 0, m_strobes = 0;
    select m_sel;
    uint64_t m_sel_since = 0;  // cycle where the current select began
    bool m_prev_strobe = false;
    bool m_in_strobe = false, m_strobe_write = false;
    int m_strobe_ce = -1;
    uint64_t m_strobe_start = 0;
    bool m_hold_pending = false;
    uint32_t m_hold_required = 0;
    uint64_t m_strobe_end = 0;
    int m_prev_ce = -1;
    int m_last_ce = -1;  // last CE seen low, and the last cycle it was
    uint64_t m_last_ce_cycle = 0;
    bool m_prev_read = false, m_prev_drive = false;
    int m_read_ce = -1, m_drive_ce = -1;
    uint64_t m_last_read_cycle = 0, m_last_drive_cycle = 0;
    bool m_have_read = false, m_have_drive = false;
    uint64_t m_counts[violation_kind_count] = {};
    std::vector<violation> m_violations;
};

}  // namespace emif
