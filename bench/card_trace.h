// The verilated card's evaluations in a platform run, recorded and replayed
// alone (bench_card_replay; issue 14, docs/performance.md "The card alone").
//
// A record is one evaluation of the fast island's card: its inputs as the
// island set them, Verilator's previous values of the two clocks (the island
// lowers the clocks without an eval by writing those: fast_island.cpp,
// lower_clocks_without_eval), which kind of evaluation it was (Verilator's
// own eval, or card_eval with or without the input region) and the card's
// outputs just before it (the outputs of the evaluation before). Replaying
// the records into a fresh card repeats the run's evaluations one for one;
// the replay checks every output against the record, so a replay that left
// the run's path fails rather than timing something else.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tb/platform/arrangements/fast/card_eval.h"

namespace card_trace {

// The bits of record::bits: the 1-bit inputs, the clocks' previous values
// and the kind of evaluation.
enum record_bit : uint32_t {
    bit_rst_n = 1u << 0,
    bit_pclk = 1u << 1,
    bit_eclk = 1u << 2,
    bit_l_vsync = 1u << 3,
    bit_l_href = 1u << 4,
    bit_l_valid = 1u << 5,
    bit_r_vsync = 1u << 6,
    bit_r_href = 1u << 7,
    bit_r_valid = 1u << 8,
    bit_ce2_n = 1u << 9,
    bit_ce3_n = 1u << 10,
    bit_aoe_n = 1u << 11,
    bit_are_n = 1u << 12,
    bit_awe_n = 1u << 13,
    bit_prev_pclk = 1u << 14,  // __Vtrigrprev__TOP__pclk before the evaluation
    bit_prev_eclk = 1u << 15,
    bit_full_eval = 1u << 16,     // Verilator's own eval (the reset and the first evaluation)
    bit_input_region = 1u << 17,  // card_eval ran the input-combinational region
    bit_end_of_run = 1u << 18,    // no evaluation: the card's outputs after the last one
    bit_l_fodd = 1u << 19,
    bit_r_fodd = 1u << 20,
};

struct record {
    uint32_t ea = 0, ed_in = 0;
    uint32_t bits = 0;  // record_bit
    uint8_t l_data = 0, r_data = 0, be_n = 0;
    uint8_t outputs = 0;  // sensor_oe, ed_oe, ardy, ext_int4..6 (bits 0..5)
    uint32_t ed_out = 0, level_l = 0, level_r = 0;
};
static_assert(sizeof(record) == 28, "the trace's size per evaluation, as documented");

inline uint8_t output_bits(const Vcard& d) {
    return static_cast<uint8_t>(d.sensor_oe | d.ed_oe << 1 | d.ardy << 2 | d.ext_int4 << 3 |
                                d.ext_int5 << 4 | d.ext_int6 << 5);
}

// The card's inputs and outputs at the start of an evaluation of `kind`
// (bit_full_eval, bit_input_region, 0 for card_eval without the input region,
// or bit_end_of_run after the last evaluation).
inline record record_of(const Vcard& d, uint32_t kind) {
    const Vcard___024root& root = *d.rootp;
    const auto bit = [](uint8_t v, uint32_t b) { return v ? b : 0u; };
    record r;
    r.ea = d.ea;
    r.ed_in = d.ed_in;
    r.bits = kind | bit(d.rst_n, bit_rst_n) | bit(d.pclk, bit_pclk) | bit(d.eclk, bit_eclk) |
             bit(d.l_vsync, bit_l_vsync) | bit(d.l_href, bit_l_href) | bit(d.l_valid, bit_l_valid) |
             bit(d.r_vsync, bit_r_vsync) | bit(d.r_href, bit_r_href) | bit(d.r_valid, bit_r_valid) |
             bit(d.ce2_n, bit_ce2_n) | bit(d.ce3_n, bit_ce3_n) | bit(d.aoe_n, bit_aoe_n) |
             bit(d.are_n, bit_are_n) | bit(d.awe_n, bit_awe_n) | bit(d.l_fodd, bit_l_fodd) |
             bit(d.r_fodd, bit_r_fodd) | bit(root.__Vtrigrprev__TOP__pclk, bit_prev_pclk) |
             bit(root.__Vtrigrprev__TOP__eclk, bit_prev_eclk);
    r.l_data = d.l_data;
    r.r_data = d.r_data;
    r.be_n = d.be_n;
    r.outputs = output_bits(d);
    r.ed_out = d.ed_out;
    r.level_l = d.dbg_fifo_level_l;
    r.level_r = d.dbg_fifo_level_r;
    return r;
}

inline bool outputs_match(const Vcard& d, const record& r) {
    return output_bits(d) == r.outputs && d.ed_out == r.ed_out && d.dbg_fifo_level_l == r.level_l &&
           d.dbg_fifo_level_r == r.level_r;
}

// Every input port and the two clocks' previous values, as recorded.
inline void apply(Vcard& d, const record& r) {
    const auto on = [&r](uint32_t b) -> uint8_t { return (r.bits & b) ? 1 : 0; };
    d.rst_n = on(bit_rst_n);
    d.pclk = on(bit_pclk);
    d.eclk = on(bit_eclk);
    d.l_vsync = on(bit_l_vsync);
    d.l_href = on(bit_l_href);
    d.l_valid = on(bit_l_valid);
    d.l_data = r.l_data;
    d.l_fodd = on(bit_l_fodd);
    d.r_vsync = on(bit_r_vsync);
    d.r_href = on(bit_r_href);
    d.r_valid = on(bit_r_valid);
    d.r_data = r.r_data;
    d.r_fodd = on(bit_r_fodd);
    d.ce2_n = on(bit_ce2_n);
    d.ce3_n = on(bit_ce3_n);
    d.aoe_n = on(bit_aoe_n);
    d.are_n = on(bit_are_n);
    d.awe_n = on(bit_awe_n);
    d.be_n = r.be_n;
    d.ea = r.ea;
    d.ed_in = r.ed_in;
    d.rootp->__Vtrigrprev__TOP__pclk = on(bit_prev_pclk);
    d.rootp->__Vtrigrprev__TOP__eclk = on(bit_prev_eclk);
}

enum class replay_mode {
    verify,       // check every output against the record
    timed,        // evaluate only
    inputs_only,  // write the inputs, evaluate nothing: the replay's own cost
};

// Replays `trace` into `d` (fresh). verify: returns the index of the first
// record whose outputs the card does not show (trace.size() if none).
template <replay_mode mode>
size_t replay(Vcard& d, const std::vector<record>& trace) {
    for (size_t i = 0; i < trace.size(); ++i) {
        const record& r = trace[i];
        if constexpr (mode == replay_mode::verify) {
            if (!outputs_match(d, r)) return i;
        }
        if (r.bits & bit_end_of_run) break;
        apply(d, r);
        if constexpr (mode == replay_mode::inputs_only) {
            asm volatile("" ::: "memory");  // every record's stores happen
        } else if (r.bits & bit_full_eval) {
            d.eval();
        } else {
            fast::card_eval(d, (r.bits & bit_input_region) != 0);
        }
    }
    return trace.size();
}

}  // namespace card_trace
