// The card's EMIF asynchronous slave (rtl/emif_slave.v in rtl/card_top.v)
// against the EMIF master model (tests/rtl/emif_master.h) at four CE space
// settings, cycle by cycle:
//   - read data is on ED (driven) at the edge where ARE rises, and stays
//     there through the hold;
//   - ED is driven only inside the card's CE with AOE low (never during a
//     write, never for a CE0 access), and released when the hold ends;
//   - ARDY is low from the read's setup until the data sits in the ED
//     register (2 edges after ARE fell), high after; it never stretches a
//     strobe of >= 3 + lead cycles, and adds exactly the documented wait
//     states to shorter ones; never low for another CE space;
//   - each access takes exactly RS + max(RST, 3 + lead) + RH (reads) or
//     WS + WST + WH (writes) cycles, back to back on the same CE;
//   - writes land in the registers with their byte enables; read-only,
//     unmapped and CE3 writes change nothing;
//   - pixel-port reads pop exactly one word, in order; an empty port reads 0
//     and counts an underflow; interrupt pulses are 4 ECLK high, >= 4 low.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "Vcard_small.h"
#include "tests/rtl/card_bench.h"

namespace {

using bench = rtl_test::card_bench<Vcard_small>;
namespace regs = dsp::card_regs;
using rtl_test::emif_access;

struct bus_setting {
    const char* name;
    uint32_t cectl;
    uint64_t eclk_ticks;
    int ardy_lead;
};

// The DSK's own values (v1 100 MHz, v2 120 MHz; docs/hardware-facts.md section 3),
// the fastest encodable async access at 125 MHz (all fields 1: the strobe is
// stretched by ARDY), a 1-cycle strobe with ARDY sampled two edges before the
// strobe end (then the card needs RS + RST >= 3 to be heard, docs/card.md),
// and the reset default (all fields maximal).
const bus_setting settings[] = {
    {"v1_0x22A28A22_100MHz", 0x22A28A22u, rtl_test::ticks_eclk_v1, 1},
    {"v2_0x23228C22_120MHz", 0x23228C22u, rtl_test::ticks_eclk_v2, 1},
    {"fastest_0x10514121_125MHz", 0x10514121u, rtl_test::ticks_eclk_v3, 1},
    {"rs2_rst1_ardy_lead2_125MHz", 0x10524121u, rtl_test::ticks_eclk_v3, 2},
    {"slowest_0xFFFFFF2F_100MHz", 0xFFFFFF2Fu, rtl_test::ticks_eclk_v1, 1},
};

class CardEmif : public ::testing::TestWithParam<bus_setting> {
  protected:
    static rtl_test::bench_options options(const bus_setting& s) {
        rtl_test::bench_options o;
        o.layout = rtl_test::small_layout();
        o.cectl = s.cectl;
        o.eclk_ticks = s.eclk_ticks;
        o.ardy_lead = s.ardy_lead;
        o.design = "card_small";
        return o;
    }
};

// Expected cycles of one access and the ARDY wait states (docs/card.md).
int expected_read_cycles(const rtl_test::emif_timing& t, int lead) {
    return t.rs + std::max(t.rst, 3 + lead) + t.rh;
}
int expected_read_waits(const rtl_test::emif_timing& t, int lead) {
    return std::max(0, 3 + lead - t.rst);
}

void expect_read_timing(bench& b, const emif_access& a, const char* what) {
    const rtl_test::emif_timing& t = b.master.timing();
    const int lead = b.opt.ardy_lead;
    EXPECT_TRUE(a.ed_driven_at_sample) << what << ": ED not driven where ARE rises";
    EXPECT_EQ(a.done_edge - a.setup_edge, static_cast<uint64_t>(expected_read_cycles(t, lead)))
        << what;
    EXPECT_EQ(a.strobe_edge - a.setup_edge, static_cast<uint64_t>(t.rs)) << what;
    EXPECT_EQ(a.wait_cycles, expected_read_waits(t, lead)) << what;
    // ARDY before edge n is ardy_trace[n - 1]: low from the first edge of the
    // setup to S + 2, high from S + 3 to E.
    const uint64_t s = a.strobe_edge;
    for (uint64_t n = a.setup_edge + 1; n <= a.end_edge; ++n) {
        const bool expect_high = n >= s + 3;
        EXPECT_EQ(b.ardy_trace.at(n - 1) != 0, expect_high)
            << what << ": ARDY at edge S" << static_cast<int64_t>(n - s);
    }
}

TEST_P(CardEmif, RegisterReadsAndWritesWithExactTiming) {
    const bus_setting& st = GetParam();
    bench b(options(st));
    b.trace_bus = true;
    const rtl_test::emif_timing& t = b.master.timing();

    emif_access rd;
    rd.k = emif_access::kind::read;
    rd.addr = regs::ce2_base + regs::id;
    const emif_access id = b.access(rd);
    EXPECT_EQ(id.data, regs::id_reset);
    expect_read_timing(b, id, "ID");

    // A full write, then byte-enabled partial writes (BE active low).
    emif_access wr;
    wr.k = emif_access::kind::write;
    wr.addr = regs::ce2_base + regs::h_start;
    wr.data = 0x12345678;
    const emif_access w1 = b.access(wr);
    EXPECT_EQ(w1.done_edge - w1.setup_edge, static_cast<uint64_t>(t.ws + t.wst + t.wh));
    EXPECT_EQ(w1.wait_cycles, 0);
    EXPECT_EQ(b.read_reg(regs::h_start), 0x5678u) << "16-bit register";
    b.write_reg(regs::h_start, 0xFFFFFFFF, 0xE);  // byte 0 only
    EXPECT_EQ(b.read_reg(regs::h_start), 0x56FFu);
    b.write_reg(regs::h_start, 0x0000AB00, 0xD);  // byte 1 only
    EXPECT_EQ(b.read_reg(regs::h_start), 0xABFFu);
    b.write_reg(regs::dark_threshold, 0x1234567F);
    EXPECT_EQ(b.read_reg(regs::dark_threshold), 0x7Fu);
    b.write_reg(regs::irq_enable, 0xFFFFFFFF);
    EXPECT_EQ(b.read_reg(regs::irq_enable), 0x7u);

    // Read-only, unmapped and CE3 writes change nothing.
    b.write_reg(regs::id, 0);
    b.write_reg(regs::pairs_ok, 0xFFFFFFFF);
    b.write_reg(regs::fifo_depth, 5);
    EXPECT_EQ(b.read_reg(regs::id), regs::id_reset);
    EXPECT_EQ(b.read_reg(regs::pairs_ok), 0u);
    EXPECT_EQ(b.read_reg(regs::fifo_depth), 512u) << "rtl_card_small: -GFIFO_AW=9";
    b.write_reg(0x100 + regs::dark_threshold, 0x11);  // beyond the register block
    EXPECT_EQ(b.read_reg(0x100 + regs::dark_threshold), 0u);
    EXPECT_EQ(b.read_reg(0xFC), 0u) << "unassigned register offset";
    emif_access w3 = wr;
    w3.addr = regs::ce3_base + regs::dark_threshold;  // CE3 is read-only pixel ports
    w3.data = 0x22;
    b.access(w3);
    EXPECT_EQ(b.read_reg(regs::dark_threshold), 0x7Fu);

    // Every read above: timing and ARDY exact.
    for (uint32_t off : {regs::ctrl, regs::status, regs::line_total, regs::start_timeout}) {
        rd.addr = regs::ce2_base + off;
        const emif_access a = b.access(rd);
        expect_read_timing(b, a, "register read");
    }
    EXPECT_EQ(b.ed_conflicts, 0u);
    EXPECT_EQ(b.ed_outside_ce, 0u);
    EXPECT_EQ(b.ardy_outside_ce, 0u);
    EXPECT_EQ(b.ed_hold_errors, 0u);
    EXPECT_EQ(b.timeouts, 0u);
    std::printf(
        "%s: RS %d RST %d RH %d WS %d WST %d WH %d TA %d: read %d ECLK (%d wait), write %d ECLK\n",
        st.name, t.rs, t.rst, t.rh, t.ws, t.wst, t.wh, t.ta, expected_read_cycles(t, st.ardy_lead),
        expected_read_waits(t, st.ardy_lead), t.ws + t.wst + t.wh);
}

TEST_P(CardEmif, PixelPortReadsPopOneWordEachInOrder) {
    const bus_setting& st = GetParam();
    bench b(options(st));
    b.trace_bus = true;
    b.configure_layout(b.opt.layout);
    b.enable(true);
    ASSERT_TRUE(b.run_until([&] { return !b.int4.rise_ticks.empty(); },
                            3 * b.opt.layout.frame_pclks() * b.opt.pclk_ticks));
    b.enable(false);  // no more frames: the FIFOs hold exactly one pair
    b.run_ticks(40 * b.opt.pclk_ticks);
    const uint32_t words = b.opt.layout.words_per_frame();
    ASSERT_EQ(b.read_reg(regs::level_l), words);
    ASSERT_EQ(b.read_reg(regs::level_r), words);

    // A CE0 (SDRAM-side) access with the card's CEs high must not pop or drive.
    emif_access foreign;
    foreign.k = emif_access::kind::foreign_read;
    foreign.addr = 0x80000000u;
    for (int i = 0; i < 3; ++i) b.access(foreign);
    // Outside both windows: reads 0, pops nothing.
    emif_access out;
    out.k = emif_access::kind::read;
    out.addr = regs::ce3_base + 2 * regs::data_window_bytes;
    EXPECT_EQ(b.access(out).data, 0u);
    EXPECT_EQ(b.read_reg(regs::level_l), words);

    // The pair, back to back on CE3 in the DSP's order (left line, right line).
    const uint32_t serial = b.left.frames().front().serial;
    const int wpl = b.opt.layout.words_per_line();
    uint64_t bad = 0, gaps = 0;
    for (int line = 0; line < b.opt.layout.active_rows; ++line) {
        for (int cam = 0; cam < 2; ++cam) {
            for (int w = 0; w < wpl; ++w) {
                emif_access a;
                a.k = emif_access::kind::read;
                a.addr = (cam ? regs::data_right : regs::data_left) + 4u * (line * wpl + w);
                a.tag = (uint64_t(cam) << 40) | (uint64_t(line) << 20) | w;
                b.master.push(a);
            }
        }
    }
    const size_t expected_reads = 2u * words;
    ASSERT_TRUE(b.run_until([&] { return b.master.done().size() >= expected_reads; },
                            uint64_t{expected_reads} * 200 * st.eclk_ticks));
    uint64_t prev_done = 0;
    for (const emif_access& a : b.master.done()) {
        const int cam = static_cast<int>(a.tag >> 40);
        const int line = static_cast<int>((a.tag >> 20) & 0xFFFFF);
        const int w = static_cast<int>(a.tag & 0xFFFFF);
        if (a.data != rtl_test::active_word(cam, serial, line, w)) ++bad;
        if (prev_done && a.setup_edge != prev_done) ++gaps;
        prev_done = a.done_edge;
        expect_read_timing(b, a, "pixel read");
    }
    b.master.done().clear();
    EXPECT_EQ(bad, 0u);
    EXPECT_EQ(gaps, 0u) << "back-to-back reads on one CE follow each other directly";
    EXPECT_EQ(b.read_reg(regs::level_l), 0u);
    EXPECT_EQ(b.read_reg(regs::level_r), 0u);
    EXPECT_EQ(b.read_reg(regs::underflows), 0u);

    // Empty: reads 0 and counts.
    emif_access empty_read;
    empty_read.k = emif_access::kind::read;
    empty_read.addr = regs::data_right;
    EXPECT_EQ(b.access(empty_read).data, 0u);
    EXPECT_EQ(b.read_reg(regs::underflows), 1u);
    // Every one counts, past the counter's low bits (a firmware polling an
    // empty port for a frame makes thousands).
    empty_read.addr = regs::data_left;
    for (int i = 0; i < 1100; ++i) b.access(empty_read);
    EXPECT_EQ(b.read_reg(regs::underflows), 1101u);

    EXPECT_EQ(b.ed_conflicts, 0u);
    EXPECT_EQ(b.ed_outside_ce, 0u);
    EXPECT_EQ(b.ardy_outside_ce, 0u);
    EXPECT_EQ(b.ed_hold_errors, 0u);
    EXPECT_EQ(b.timeouts, 0u);
    EXPECT_EQ(b.context().errorCount(), 0);
    const double ns = expected_read_cycles(b.master.timing(), st.ardy_lead) * st.eclk_ticks *
                      rtl_test::ns_per_tick;
    std::printf("%s: %zu pixel words read back to back, %.1f ns per word (%.1f MB/s)\n", st.name,
                expected_reads, ns, 4.0e3 / ns);
}

INSTANTIATE_TEST_SUITE_P(Settings, CardEmif, ::testing::ValuesIn(settings),
                         [](const ::testing::TestParamInfo<bus_setting>& info) {
                             return std::string(info.param.name);
                         });

// EXT_INT pulses: 4 ECLK high and at least 4 low (C64x needs >= 4 CPU cycles
// each: 8 ns at 500 MHz), IRQ_ENABLE gates the pin but not IRQ_STATUS.
TEST(CardIrq, PulseWidthsAndEnableMask) {
    rtl_test::bench_options o;
    o.layout = rtl_test::small_layout();
    o.design = "card_small";
    bench b(o);
    b.configure_layout(o.layout);
    b.reader_enabled = true;
    b.enable(true);
    b.run_frames(4.2);
    ASSERT_GE(b.int4.rise_ticks.size(), 3u);
    EXPECT_EQ(b.int4.min_high, 4u);
    EXPECT_GE(b.int4.min_low, 4u);
    const double high_ns = 4 * o.eclk_ticks * rtl_test::ns_per_tick;
    EXPECT_GE(high_ns, 4 * 2.0) << "4 CPU cycles at 500 MHz";
    std::printf("EXT_INT4 pulse %.0f ns high (>= 8 ns needed at 500 MHz, 4 ns at 1 GHz)\n",
                high_ns);

    b.write_reg(regs::irq_status, 0x7);  // clear all
    b.write_reg(regs::irq_enable, 0);    // pins off
    const size_t pulses = b.int4.rise_ticks.size();
    const uint32_t pairs = b.read_reg(regs::pairs_ok);
    b.run_frames(2);
    EXPECT_EQ(b.int4.rise_ticks.size(), pulses) << "masked: no pulse";
    EXPECT_GT(b.read_reg(regs::pairs_ok), pairs);
    EXPECT_EQ(b.read_reg(regs::irq_status), regs::irq_status_frame_ready_mask)
        << "IRQ_STATUS records the event anyway";
    b.write_reg(regs::irq_enable, regs::irq_enable_frame_ready_mask);
    b.run_frames(1.5);
    EXPECT_GT(b.int4.rise_ticks.size(), pulses);
    EXPECT_EQ(b.context().errorCount(), 0);
}

}  // namespace
