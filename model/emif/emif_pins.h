// The EMIFA asynchronous interface at the pins, as the DSP drives and
// samples it (docs/hardware-facts.md section 3; J4 connector of the DSK), and the
// C++ interfaces of things clocked on ECLKOUT beside the EMIF engine.
//
// One emif_pins value is what the DSP drives from one ECLKOUT rising edge to
// the next; emif_inputs is what a pin slave drives back, sampled by the DSP
// just before an edge. Two-state model: ED is split into ed_out + ed_oe
// (DSP side) and the slave's value + its own enable.
#pragma once

#include <cstdint>

namespace emif {

inline constexpr int ce_count = 4;

struct emif_pins {
    bool ce_n[ce_count] = {true, true, true, true};  // ACE0..ACE3, active low
    uint32_t ea = 0;      // word address AEA[21:2] of J4: (byte address >> 2) & 0xFFFFF
    uint8_t be_n = 0xF;   // ABE3..ABE0, active low
    uint32_t ed_out = 0;  // AED[31:0] as driven by the DSP ...
    bool ed_oe = false;   // ... when it drives them (writes)
    bool aoe_n = true;    // AAOE: output enable of the selected async device (reads)
    bool are_n = true;    // AARE: read strobe
    bool awe_n = true;    // AAWE: write strobe

    // The CE space selected, or -1 (several low at once is a protocol error
    // the checker reports; this returns the lowest).
    int active_ce() const {
        for (int i = 0; i < ce_count; ++i)
            if (!ce_n[i]) return i;
        return -1;
    }
};

bool operator==(const emif_pins& a, const emif_pins& b);
inline bool operator!=(const emif_pins& a, const emif_pins& b) {
    return !(a == b);
}

struct emif_inputs {
    uint32_t ed_in = 0;  // AED[31:0] as driven by the slave
    bool ardy = true;    // AARDY (the pin has an internal pull-up: idle high)
};

// Sees the pins after every ECLK edge the engine steps (tests, checkers, traces).
class emif_pin_observer {
  public:
    virtual ~emif_pin_observer() = default;
    // edge: index of the ECLK edge just stepped; pins: driven until the next
    // edge; sampled: the slave's outputs the engine sampled at this edge.
    virtual void observe(uint64_t edge, const emif_pins& pins, const emif_inputs& sampled) = 0;
};

// A device on the bus clocked by ECLKOUT, stepped by the same C++ loop as the
// engine (the card's EMIF slave, an SRAM model). Per edge the loop does:
//   in = slave.outputs(engine.pins());  // what the slave drives just before the edge
//   slave.eclk_edge(engine.pins());     // the slave's flops sample the pins
//   engine.step(in);                    // the engine samples `in`, drives new pins
// so both sides sample the other's pre-edge values (non-blocking semantics).
class emif_pin_slave {
  public:
    virtual ~emif_pin_slave() = default;
    // Outputs as a function of the slave's state and the pins driven now
    // (ED enable and ARDY may be combinational in the pins, as on the card).
    virtual emif_inputs outputs(const emif_pins& pins) const = 0;
    virtual void eclk_edge(const emif_pins& pins) = 0;
};

}  // namespace emif
