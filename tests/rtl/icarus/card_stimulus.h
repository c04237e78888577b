// A recorded pin stimulus of the card (rtl/card_top.v) and its replay into a
// verilated card, for the Icarus Verilog reference (docs/arrangements.md
// "Icarus reference"): the same file is replayed under vvp by
// tests/rtl/icarus/card_replay_tb.v and into the verilated model here, and the two
// output sequences must be equal, line by line.
//
// One clock event = the clocks of `edges` rise with the inputs unchanged
// (phase 1), then the event's new inputs are applied and both clocks fall
// (phase 2): the two evals per event of the C++ drivers (tests/rtl/rtl_sim.h,
// tb/platform/arrangements/fast/fast_island.cpp). The outputs after each phase are compared.
// Times: simtime::to_fs(tick) + replay_offset_fs, one rounding per edge.
//
// Cost: the replay is two evals per event; the file is ~70 bytes per event.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "model/time/ticks.h"

namespace icarus_ref {

// The card's inputs other than the clocks (card_top.v's port order).
struct card_inputs {
    uint8_t rst_n = 1;
    uint8_t l_vsync = 0, l_href = 0, l_valid = 0, l_data = 0, l_fodd = 0;
    uint8_t r_vsync = 0, r_href = 0, r_valid = 0, r_data = 0, r_fodd = 0;
    uint8_t ce2_n = 1, ce3_n = 1, aoe_n = 1, are_n = 1, awe_n = 1;
    uint32_t ea = 0;  // EA[21:2]
    uint8_t be_n = 0xF;
    uint32_t ed_in = 0;
};

struct card_outputs {
    uint8_t sensor_oe = 0, ed_oe = 0, ardy = 0;
    uint32_t ed_out = 0;
    uint8_t ext_int4 = 0, ext_int5 = 0, ext_int6 = 0;
};

inline constexpr uint8_t edge_pclk = 1, edge_eclk = 2;

struct clock_event {
    simtime::ticks tick = 0;
    uint8_t edges = 0;
    card_inputs in;  // applied at phase 2
};

// Reset takes 0..20 fs; events start after it.
inline constexpr int64_t replay_offset_fs = 1000000;

template <class Model>
card_inputs read_inputs(const Model& d) {
    card_inputs i;
    i.rst_n = d.rst_n;
    i.l_vsync = d.l_vsync;
    i.l_href = d.l_href;
    i.l_valid = d.l_valid;
    i.l_data = d.l_data;
    i.l_fodd = d.l_fodd;
    i.r_vsync = d.r_vsync;
    i.r_href = d.r_href;
    i.r_valid = d.r_valid;
    i.r_data = d.r_data;
    i.r_fodd = d.r_fodd;
    i.ce2_n = d.ce2_n;
    i.ce3_n = d.ce3_n;
    i.aoe_n = d.aoe_n;
    i.are_n = d.are_n;
    i.awe_n = d.awe_n;
    i.ea = d.ea;
    i.be_n = d.be_n;
    i.ed_in = d.ed_in;
    return i;
}

template <class Model>
void apply_inputs(Model& d, const card_inputs& i) {
    d.rst_n = i.rst_n;
    d.l_vsync = i.l_vsync;
    d.l_href = i.l_href;
    d.l_valid = i.l_valid;
    d.l_data = i.l_data;
    d.l_fodd = i.l_fodd;
    d.r_vsync = i.r_vsync;
    d.r_href = i.r_href;
    d.r_valid = i.r_valid;
    d.r_data = i.r_data;
    d.r_fodd = i.r_fodd;
    d.ce2_n = i.ce2_n;
    d.ce3_n = i.ce3_n;
    d.aoe_n = i.aoe_n;
    d.are_n = i.are_n;
    d.awe_n = i.awe_n;
    d.ea = i.ea;
    d.be_n = i.be_n;
    d.ed_in = i.ed_in;
}

template <class Model>
card_outputs read_outputs(const Model& d) {
    card_outputs o;
    o.sensor_oe = d.sensor_oe;
    o.ed_oe = d.ed_oe;
    o.ardy = d.ardy;
    o.ed_out = d.ed_out;
    o.ext_int4 = d.ext_int4;
    o.ext_int5 = d.ext_int5;
    o.ext_int6 = d.ext_int6;
    return o;
}

// As card_replay_tb.v's $fwrite "%h %h %h %h %h %h %h" (%h pads to the width).
inline std::string format_outputs(const card_outputs& o) {
    char text[48];
    std::snprintf(text, sizeof text, "%x %x %x %08x %x %x %x", o.sensor_oe, o.ed_oe, o.ardy,
                  o.ed_out, o.ext_int4, o.ext_int5, o.ext_int6);
    return text;
}

inline void print_inputs(std::FILE* f, const card_inputs& i) {
    std::fprintf(f, "%x %x %x %x %02x %x %x %x %x %02x %x %x %x %x %x %x %05x %x %08x\n", i.rst_n,
                 i.l_vsync, i.l_href, i.l_valid, i.l_data, i.l_fodd, i.r_vsync, i.r_href, i.r_valid,
                 i.r_data, i.r_fodd, i.ce2_n, i.ce3_n, i.aoe_n, i.are_n, i.awe_n, i.ea, i.be_n,
                 i.ed_in);
}

inline bool write_stimulus(const std::string& path, const card_inputs& before_reset,
                           const std::vector<clock_event>& events) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) return false;
    print_inputs(f, before_reset);
    for (const clock_event& e : events) {
        std::fprintf(f, "%lld %x ",
                     static_cast<long long>(simtime::to_fs(e.tick) + replay_offset_fs), e.edges);
        print_inputs(f, e.in);
    }
    return std::fclose(f) == 0;
}

// Replays into a fresh verilated card: reset as card_replay_tb.v does, then
// per event the two phases; returns one line per event, as the testbench writes.
template <class Model>
std::vector<std::string> replay(Model& d, const card_inputs& before_reset,
                                const std::vector<clock_event>& events) {
    d.pclk = 0;
    d.eclk = 0;
    apply_inputs(d, before_reset);
    d.rst_n = 1;
    d.eval();
    d.rst_n = 0;  // a falling edge: the asynchronous resets act
    d.eval();
    d.rst_n = 1;
    d.eval();
    std::vector<std::string> lines;
    lines.reserve(events.size());
    for (const clock_event& e : events) {
        if (e.edges & edge_pclk) d.pclk = 1;
        if (e.edges & edge_eclk) d.eclk = 1;
        d.eval();
        std::string line = format_outputs(read_outputs(d));
        apply_inputs(d, e.in);
        d.pclk = 0;
        d.eclk = 0;
        d.eval();
        line += ' ';
        line += format_outputs(read_outputs(d));
        lines.push_back(std::move(line));
    }
    return lines;
}

}  // namespace icarus_ref
