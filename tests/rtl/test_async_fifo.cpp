// rtl/async_fifo.v (16 words, Gray pointers, metastability model on) driven
// cycle by cycle on two unrelated clocks: millions of words in random bursts,
// with exact expectations on data, flags, levels, overflow and peak
// (tests/rtl/fifo_stress.h), plus the synchronizer's random extra cycle
// measured and the empty-read assertion shown to fire.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "Vasync_fifo.h"
#include "tests/rtl/fifo_stress.h"

namespace {

using rtl_test::fifo_stress_config;
using rtl_test::fifo_stress_result;

constexpr int fifo_aw = 4;  // rtl/CMakeLists.txt verilates rtl_async_fifo with -GAW=4

void expect_clean(const fifo_stress_result& r, const char* what) {
    std::printf(
        "%s: %llu words written, %llu read, %llu writes dropped on full, %llu/%llu write/read "
        "edges (%llu full, %llu empty), %llu held-value checks, %.2f s wall\n",
        what, (unsigned long long)r.accepted, (unsigned long long)r.read,
        (unsigned long long)r.dropped, (unsigned long long)r.write_edges,
        (unsigned long long)r.read_edges, (unsigned long long)r.full_edges,
        (unsigned long long)r.empty_edges, (unsigned long long)r.held_checks, r.seconds);
    EXPECT_EQ(r.data_errors, 0u) << what << ": lost, duplicated or reordered words";
    EXPECT_EQ(r.flag_errors, 0u) << what << ": full/empty/overflow/peak not exact";
    EXPECT_EQ(r.bound_errors, 0u) << what << ": a level on the unsafe side of the occupancy";
    EXPECT_EQ(r.held_violations, 0u) << what << ": a synchronized pointer never held";
    EXPECT_EQ(r.window_too_wide, 0u) << what << ": test window wider than the pointer range";
    EXPECT_EQ(r.rtl_errors, 0u) << what << ": RTL assertion failures";
    // The run must really have exercised both extremes and the overflow path
    // (the shortened sanitizer run only both extremes).
    EXPECT_GT(r.full_edges, 1000u / rtl_test::stress_divisor) << what;
    EXPECT_GT(r.empty_edges, 1000u / rtl_test::stress_divisor) << what;
    if (rtl_test::stress_divisor == 1) {
        EXPECT_GT(r.dropped, 100u) << what;
    }
    EXPECT_LE(r.accepted - r.read, 16u) << what << ": more words in flight than the FIFO holds";
}

struct ratio_case {
    const char* name;
    uint64_t write_period, read_period;
};

// Periods in ticks of 1/18 ns: the card's 35:6 (pixel clock writes, 100 MHz
// ECLK reads), its inverse, two nearly equal clocks whose phase walks through
// every alignment, and 125 MHz against 120 MHz (24:25).
const ratio_case ratio_cases[] = {
    {"pclk 120/7 MHz -> eclk 100 MHz (35:6)", rtl_test::ticks_pclk_default,
     rtl_test::ticks_eclk_v1},
    {"eclk 100 MHz -> pclk 120/7 MHz (6:35)", rtl_test::ticks_eclk_v1,
     rtl_test::ticks_pclk_default},
    {"1000 ticks -> 1013 ticks (phase walk)", 1000, 1013},
    {"125 MHz -> 120 MHz (24:25)", rtl_test::ticks_eclk_v3, rtl_test::ticks_eclk_v2},
};

TEST(AsyncFifo, MillionsOfWordsInRandomBurstsArriveExactlyOnceInOrderWithExactFlags) {
    uint64_t total = 0;
    uint64_t seed = 11;
    for (const ratio_case& rc : ratio_cases) {
        fifo_stress_config cfg;
        cfg.write_period = rc.write_period;
        cfg.read_period = rc.read_period;
        cfg.write_phase = 37;  // no common start edge
        cfg.read_phase = 0;
        cfg.words = 600000 / rtl_test::stress_divisor;
        cfg.seed = seed++;
        const fifo_stress_result r = rtl_test::run_fifo_stress<Vasync_fifo>(cfg, fifo_aw);
        expect_clean(r, rc.name);
        total += r.read;
    }
    std::printf("total words moved: %llu\n", (unsigned long long)total);
    RecordProperty("words_moved", std::to_string(total));
    EXPECT_GE(total, 2400000u / rtl_test::stress_divisor);
}

// The metastability model: a pointer bit that toggled in the source's last
// cycle reaches the synchronizer output 0 or 1 destination cycle late, at
// random. One isolated write into an empty FIFO must therefore become
// visible (rd_empty low after the edge) exactly 2 or 3 read edges after the
// write edge, and both must occur.
TEST(AsyncFifo, SynchronizerAddsZeroOrOneRandomCycle) {
    auto context = std::make_unique<VerilatedContext>();
    context->randSeed(5);
    auto dut = std::make_unique<Vasync_fifo>(context.get(), "fifo");
    dut->wclk = dut->rclk = 0;
    dut->wrst_n = dut->rrst_n = 0;
    dut->wr_en = dut->rd_en = dut->wr_clear = 0;
    dut->eval();
    dut->wrst_n = dut->rrst_n = 1;
    dut->eval();

    rtl_test::two_clocks clocks(rtl_test::ticks_pclk_default, rtl_test::ticks_eclk_v1, 11, 0);
    std::map<int, int> latency_histogram;
    int trials = 0;
    int gap = 1;          // write edges to wait before the next single write
    int read_edges = -1;  // read edges since the write edge; -1: no write in flight
    bool write_driven = false;
    while (trials < 400) {
        const unsigned edges = clocks.advance();
        const bool w = edges & rtl_test::two_clocks::edge_a;
        const bool r = edges & rtl_test::two_clocks::edge_b;
        if (w) dut->wclk = 1;
        if (r) dut->rclk = 1;
        dut->eval();
        if (w && write_driven) {
            read_edges = 0;  // the write happened at this edge
        } else if (r && read_edges >= 0) {
            ++read_edges;
            if (!dut->rd_empty) {
                ++latency_histogram[read_edges];
                ++trials;
                read_edges = -1;
                gap = 1 + trials % 4;
            }
        }
        if (w) {
            write_driven = false;
            // Next single write once the word was read and the writer saw it go.
            if (read_edges < 0 && dut->wr_level == 0 && --gap <= 0) write_driven = true;
            dut->wr_en = write_driven;
        }
        if (r) dut->rd_en = !dut->rd_empty;  // drain it again
        dut->wclk = 0;
        dut->rclk = 0;
        dut->eval();
    }
    for (const auto& [latency, count] : latency_histogram)
        std::printf("write visible to the reader after %d read edges: %d times\n", latency, count);
    EXPECT_EQ(latency_histogram.size(), 2u);
    EXPECT_GT(latency_histogram[2], 40);
    EXPECT_GT(latency_histogram[3], 40);
    dut->final();
    rtl_test::write_coverage(*context, "async_fifo");
}

// Assertions are compiled in (--assert): a read of an empty FIFO is reported
// once, and does nothing.
TEST(AsyncFifo, ReadingAnEmptyFifoTripsTheAssertionAndChangesNothing) {
    auto context = std::make_unique<VerilatedContext>();
    context->errorLimit(1000);  // count instead of aborting
    auto dut = std::make_unique<Vasync_fifo>(context.get(), "fifo");
    dut->wclk = dut->rclk = 0;
    dut->wrst_n = dut->rrst_n = 0;
    dut->wr_en = dut->rd_en = dut->wr_clear = 0;
    dut->eval();
    dut->wrst_n = dut->rrst_n = 1;
    dut->eval();
    ASSERT_TRUE(dut->rd_empty);
    dut->rd_en = 1;
    {
        rtl_test::stdout_muted quiet;
        dut->rclk = 1;
        dut->eval();
        dut->rd_en = 0;
        dut->rclk = 0;
        dut->eval();
    }
    EXPECT_EQ(context->errorCount(), 1);
    EXPECT_EQ(dut->rd_ptr, 0u) << "the read pointer must not move";
    EXPECT_EQ(dut->rd_level, 0u);
    dut->final();
    rtl_test::write_coverage(*context, "async_fifo");
}

}  // namespace
