// The card as the platform uses it (rtl_card: default parameters, 2^17-word
// FIFOs, reset values = docs/design-brief.md's default VGA profile) with VGA sensors on
// the real clocks (120/7 MHz pixel clock, 100 MHz ECLK, CECTL 0x22A28A22):
// the DSP model reads each pair after FRAME_READY, 14 ECLK per word back to
// back, and every word is checked.
//
// Buffering (docs/design-brief.md "Buffering"): reading L and R interleaved line by line
// keeps the peak FIFO occupancy near one frame (76,800 words); reading all of
// L, then all of R lets R gather ~30k words of the next frame on top of a
// full frame, more than a 384 KB (98,304-word) FIFO holds. Both peaks are read
// from the card's PEAK registers; both must stay inside the card's 131,072
// words (1.7 frames).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "Vcard.h"
#include "tests/rtl/card_bench.h"

namespace {

using bench = rtl_test::card_bench<Vcard>;
namespace regs = dsp::card_regs;

struct vga_run {
    uint32_t peak_l = 0, peak_r = 0, depth = 0, overflows = 0, mismatches = 0, pairs_ok = 0;
    size_t pairs_read = 0;
    uint64_t bad_words = 0;
    double pair_read_ms = 0.0;  // FRAME_READY to the pair's last word
    double seconds = 0.0;
};

// Runs until `pairs` pairs were read completely.
vga_run run_vga(rtl_test::read_order order, size_t pairs) {
    rtl_test::bench_options o;
    o.layout = rtl_test::vga_layout();
    o.sensor_latency = 2 * 800;  // model/sensor's default: 2 lines
    o.design = "card";
    const auto wall = std::chrono::steady_clock::now();
    bench b(o);
    b.reader_enabled = true;
    b.order = order;
    b.enable(true);  // the reset values are the VGA layout: nothing else to set
    const uint64_t frame_ticks = o.layout.frame_pclks() * o.pclk_ticks;
    const bool done = b.run_until(
        [&] {
            return b.pairs.size() > pairs ||
                   (b.pairs.size() == pairs && b.reads_pending() == 0 &&
                    b.words_read == 2ull * pairs * o.layout.words_per_frame());
        },
        (pairs + 2) * frame_ticks);
    EXPECT_TRUE(done);
    vga_run r;
    r.peak_l = b.read_reg(regs::peak_l);
    r.peak_r = b.read_reg(regs::peak_r);
    r.depth = b.read_reg(regs::fifo_depth);
    r.overflows = b.read_reg(regs::overflows);
    r.mismatches = b.read_reg(regs::mismatches);
    r.pairs_ok = b.read_reg(regs::pairs_ok);
    r.pairs_read = b.pairs.size();
    for (const auto& p : b.pairs) r.bad_words += p.bad_words;
    if (!b.pairs.empty())
        r.pair_read_ms =
            (b.pairs[0].last_read_tick - b.pairs[0].irq_tick) * rtl_test::ns_per_tick * 1e-6;
    EXPECT_EQ(b.ed_conflicts, 0u);
    EXPECT_EQ(b.ed_outside_ce, 0u);
    EXPECT_EQ(b.ed_hold_errors, 0u);
    EXPECT_EQ(b.context().errorCount(), 0);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count();
    return r;
}

TEST(CardVga, PeakOccupancyUnderTheDocumentedReadOrderStaysInsideTheFifo) {
    const vga_run r = run_vga(rtl_test::read_order::interleaved_lines, 1);
    std::printf(
        "interleaved L/R lines: peak %u / %u words of %u (%.2f frames), pair read in "
        "%.2f ms, %zu pair(s) read, %.1f s wall\n",
        r.peak_l, r.peak_r, r.depth, r.peak_r / 76800.0, r.pair_read_ms, r.pairs_read, r.seconds);
    EXPECT_EQ(r.depth, 131072u);
    EXPECT_EQ(r.overflows, 0u);
    EXPECT_EQ(r.mismatches, 0u);
    EXPECT_EQ(r.bad_words, 0u);
    EXPECT_GE(r.pairs_read, 1u);
    EXPECT_GE(r.peak_l, 76800u) << "a whole frame waits for its verdict";
    EXPECT_LT(r.peak_l, 76800u + 2 * 160u) << "interleaved draining keeps it near one frame";
    EXPECT_LT(r.peak_r, 76800u + 2 * 160u);
    // 153,600 words at 14 ECLK = 21.5 ms (docs/design-brief.md), inside the 24.5 ms frame.
    EXPECT_NEAR(r.pair_read_ms, 21.5, 0.1);
    RecordProperty("peak_words_interleaved", std::to_string(std::max(r.peak_l, r.peak_r)));
}

TEST(CardVga, ReadingAllOfLeftThenRightNeedsMoreThanA384KbFifo) {
    const vga_run r = run_vga(rtl_test::read_order::left_then_right, 1);
    std::printf(
        "L then R: peak %u / %u words of %u (%.2f frames), pair read in %.2f ms, %.1f s "
        "wall\n",
        r.peak_l, r.peak_r, r.depth, r.peak_r / 76800.0, r.pair_read_ms, r.seconds);
    EXPECT_EQ(r.overflows, 0u) << "1.7 frames of FIFO still hold it";
    EXPECT_EQ(r.bad_words, 0u);
    EXPECT_GT(r.peak_r, 98304u) << "R gathers more than a 384 KB FIFO holds (docs/design-brief.md)";
    EXPECT_LT(r.peak_r, r.depth);
    RecordProperty("peak_words_left_then_right", std::to_string(r.peak_r));
}

}  // namespace
