// The card's configuration registers over their range, not only at the
// values the other tests and the platform use (DARK_THRESHOLD 32, even
// H_START): every bit of DARK_THRESHOLD decides a dark pixel exactly at the
// threshold, odd window offsets and line totals check as cleanly as even
// ones, and every bit of a window register moves the window. Golden values:
// the register map's definitions (docs/card-registers.md), checked against
// the test sensors' own layout. Written for the RTL mutants
// (docs/mutants.md): a comparator input with one bit flipped only when
// another bit of the register is set survives every test that keeps the
// register at one value.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "Vcard_small.h"
#include "tests/rtl/card_bench.h"

namespace {

using bench = rtl_test::card_bench<Vcard_small>;
namespace regs = dsp::card_regs;

rtl_test::bench_options small_options(const rtl_test::sensor_layout& layout) {
    rtl_test::bench_options o;
    o.layout = layout;
    o.design = "card_small";
    return o;
}

struct dark_run {
    uint32_t mismatches = 0;
    uint32_t verdict_causes = 0;
    uint32_t pairs_ok = 0;
    uint32_t mismatch_pos = 0;
};

struct register_write {
    uint32_t offset, value;
};

// Readout pixel (row, col) of the left sensor's frame 1 reads `value`;
// `writes` follow the layout's registers.
dark_run run_with_left_pixel(const rtl_test::sensor_layout& layout, uint32_t threshold, int row,
                             int col, uint8_t value,
                             const std::vector<register_write>& writes = {}) {
    bench b(small_options(layout));
    b.configure_layout(b.opt.layout);
    for (const register_write& w : writes) b.write_reg(w.offset, w.value);
    b.write_reg(regs::dark_threshold, threshold);
    b.left.poke_pixel(1, row, col, value);
    b.enable(true);
    b.run_frames(3.5);
    dark_run r;
    r.mismatches = b.read_reg(regs::mismatches);
    r.verdict_causes = b.read_reg(regs::verdict) & 0xFFu;
    r.pairs_ok = b.read_reg(regs::pairs_ok);
    r.mismatch_pos = b.read_reg(regs::mismatch_pos);
    EXPECT_EQ(b.context().errorCount(), 0);
    return r;
}

// A left dark-column pixel of frame 1 reads `value` under DARK_THRESHOLD `threshold`.
dark_run run_with_dark_pixel(uint32_t threshold, uint8_t value) {
    return run_with_left_pixel(rtl_test::small_layout(), threshold, 8, 1, value);
}

// The test sensors' dark pixels read 12..15 (rtl_test::test_black_level), so
// thresholds start at 16; together they set each of bits 3..7, alone and mixed.
TEST(CardConfig, EveryDarkThresholdFlagsAPixelAtItAndNotBelowIt) {
    for (uint32_t threshold : {16u, 24u, 40u, 48u, 72u, 96u, 130u, 200u, 255u}) {
        const dark_run below = run_with_dark_pixel(threshold, static_cast<uint8_t>(threshold - 1));
        EXPECT_EQ(below.mismatches, 0u) << "threshold " << threshold << ", pixel one below";
        EXPECT_GE(below.pairs_ok, 3u) << "threshold " << threshold;
        const dark_run at = run_with_dark_pixel(threshold, static_cast<uint8_t>(threshold));
        EXPECT_EQ(at.mismatches, 1u) << "threshold " << threshold << ", pixel at it";
        EXPECT_EQ(at.verdict_causes, regs::verdict_l_dark_mask)
            << "threshold " << threshold << ": only L_DARK";
    }
}

// Aligned streams with the window placed at odd columns and lines, and lines
// of an odd number of pixel clocks (49 and 51 around the small layout's 50):
// no mismatch, and every word the DSP model reads is the active pixels.
TEST(CardConfig, OddWindowOffsetsPassAndForwardTheActivePixels) {
    struct offsets {
        int h_start, v_start, dark_left, dark_top, line_total;
    };
    for (const offsets o :
         {offsets{1, 1, 4, 2, 50}, offsets{3, 3, 3, 1, 49}, offsets{5, 2, 1, 3, 51}}) {
        rtl_test::sensor_layout layout = rtl_test::small_layout();
        layout.h_start = o.h_start;
        layout.v_start = o.v_start;
        layout.dark_left = o.dark_left;
        layout.dark_top = o.dark_top;
        layout.line_total = o.line_total;
        const std::string name = "H_START " + std::to_string(o.h_start) + ", V_START " +
                                 std::to_string(o.v_start) + ", LINE_TOTAL " +
                                 std::to_string(o.line_total);
        ASSERT_LE(layout.h_start + layout.readout_cols(), layout.line_total) << name;
        ASSERT_LE(layout.v_start + layout.readout_rows(), layout.frame_lines) << name;
        {  // one card model alive at a time: with two, a model's
            // destructor hung in Verilator 5.006's scope teardown
            bench b(small_options(layout));
            b.configure_layout(layout);
            b.reader_enabled = true;
            b.enable(true);
            b.run_frames(5.3);
            EXPECT_EQ(b.read_reg(regs::mismatches), 0u)
                << name << ": first mismatch at 0x" << std::hex << b.read_reg(regs::mismatch_pos);
            EXPECT_GE(b.read_reg(regs::pairs_ok), 4u) << name;
            ASSERT_GE(b.pairs.size(), 3u) << name;
            for (size_t i = 0; i < b.pairs.size(); ++i) {
                EXPECT_EQ(b.pairs[i].bad_words, 0u) << name << ", pair " << i;
                EXPECT_EQ(b.pairs[i].serial_l, i) << name;
                EXPECT_EQ(b.pairs[i].serial_r, i) << name;
            }
            EXPECT_EQ(b.context().errorCount(), 0) << name;
        }

        // Each dark region is still checked there: a leak in it is flagged.
        const int mid_row = layout.dark_top + layout.border_top + 3;
        const int mid_col = layout.dark_left + layout.border_left + 5;
        struct leak {
            const char* where;
            int row, col;
        };
        for (const leak l : {leak{"top dark row", 0, mid_col},
                             leak{"bottom dark row", layout.readout_rows() - 1, mid_col},
                             leak{"left dark column", mid_row, 0},
                             leak{"right dark column", mid_row, layout.readout_cols() - 1}}) {
            const dark_run r = run_with_left_pixel(layout, 32, l.row, l.col, 200);
            EXPECT_EQ(r.mismatches, 1u) << name << ": leak in the " << l.where;
            EXPECT_EQ(r.verdict_causes, regs::verdict_l_dark_mask) << name << ", " << l.where;
            // MISMATCH_POS: the leak's line and pixel clock in the common frame
            // (VSYNC rises at line 0 column 0; readout row r is line V_START + r,
            // readout column c pixel clock H_START + c).
            const uint32_t line = static_cast<uint32_t>(layout.v_start + l.row);
            const uint32_t col = static_cast<uint32_t>(layout.h_start + l.col);
            EXPECT_EQ(r.mismatch_pos, line << 16 | col)
                << name << ", " << l.where << ": MISMATCH_POS 0x" << std::hex << r.mismatch_pos;
        }
    }
}

// Every RW configuration register resets to its documented value and keeps
// exactly its field's bits (rtl/card_regs.csv, through the generated
// dsp/card_regs.h; the RTL's write masks are written by hand).
TEST(CardConfig, EveryConfigRegisterResetsAndReadsBackItsFieldBits) {
    struct rw_register {
        const char* name;
        uint32_t offset, reset, mask;
    };
    const rw_register registers[] = {
        {"IRQ_ENABLE", regs::irq_enable, regs::irq_enable_reset,
         regs::irq_enable_frame_ready_mask | regs::irq_enable_sync_error_mask |
             regs::irq_enable_overflow_mask},
        {"DARK_THRESHOLD", regs::dark_threshold, regs::dark_threshold_reset,
         regs::dark_threshold_value_mask},
        {"H_START", regs::h_start, regs::h_start_reset, regs::h_start_value_mask},
        {"DARK_COLS_LEFT", regs::dark_cols_left, regs::dark_cols_left_reset,
         regs::dark_cols_left_value_mask},
        {"BORDER_COLS_LEFT", regs::border_cols_left, regs::border_cols_left_reset,
         regs::border_cols_left_value_mask},
        {"ACTIVE_COLS", regs::active_cols, regs::active_cols_reset, regs::active_cols_value_mask},
        {"BORDER_COLS_RIGHT", regs::border_cols_right, regs::border_cols_right_reset,
         regs::border_cols_right_value_mask},
        {"DARK_COLS_RIGHT", regs::dark_cols_right, regs::dark_cols_right_reset,
         regs::dark_cols_right_value_mask},
        {"LINE_TOTAL", regs::line_total, regs::line_total_reset, regs::line_total_value_mask},
        {"V_START", regs::v_start, regs::v_start_reset, regs::v_start_value_mask},
        {"DARK_ROWS_TOP", regs::dark_rows_top, regs::dark_rows_top_reset,
         regs::dark_rows_top_value_mask},
        {"BORDER_ROWS_TOP", regs::border_rows_top, regs::border_rows_top_reset,
         regs::border_rows_top_value_mask},
        {"ACTIVE_ROWS", regs::active_rows, regs::active_rows_reset, regs::active_rows_value_mask},
        {"BORDER_ROWS_BOTTOM", regs::border_rows_bottom, regs::border_rows_bottom_reset,
         regs::border_rows_bottom_value_mask},
        {"DARK_ROWS_BOTTOM", regs::dark_rows_bottom, regs::dark_rows_bottom_reset,
         regs::dark_rows_bottom_value_mask},
        {"FRAME_LINES", regs::frame_lines, regs::frame_lines_reset, regs::frame_lines_value_mask},
        {"RETRY_LIMIT", regs::retry_limit, regs::retry_limit_reset, regs::retry_limit_value_mask},
        {"OE_LOW_CYCLES", regs::oe_low_cycles, regs::oe_low_cycles_reset,
         regs::oe_low_cycles_value_mask},
        {"START_TIMEOUT", regs::start_timeout, regs::start_timeout_reset,
         regs::start_timeout_value_mask},
        {"CHECKS", regs::checks, regs::checks_reset, regs::checks_frame_id_mask},
    };
    bench b(small_options(rtl_test::small_layout()));
    for (const rw_register& r : registers) {
        EXPECT_EQ(b.read_reg(r.offset), r.reset) << r.name << " after reset";
        for (uint32_t pattern : {0xFFFFFFFFu, 0xA5A5A5A5u, 0x5A5A5A5Au, 0u}) {
            b.write_reg(r.offset, pattern);
            // Read at three bus-clock phases: a register holds between writes.
            for (uint64_t idle_eclk = 0; idle_eclk < 3; ++idle_eclk) {
                b.run_ticks(idle_eclk * b.opt.eclk_ticks);
                EXPECT_EQ(b.read_reg(r.offset), pattern & r.mask)
                    << r.name << " written 0x" << std::hex << pattern << ", read after "
                    << idle_eclk << " idle ECLK";
            }
        }
        // A write with one byte lane enabled (BE_n active low) changes that
        // byte alone: the other three keep what they held.
        for (uint32_t lane = 0; lane < 4; ++lane) {
            const uint32_t lane_bits = 0xFFu << (8 * lane);
            b.write_reg(r.offset, 0xFFFFFFFFu);
            b.write_reg(r.offset, 0x5A5A5A5Au, static_cast<uint8_t>(0xFu & ~(1u << lane)));
            EXPECT_EQ(b.read_reg(r.offset),
                      ((0xFFFFFFFFu & ~lane_bits) | (0x5A5A5A5Au & lane_bits)) & r.mask)
                << r.name << ": byte lane " << lane << " alone written over all ones";
        }
        b.write_reg(r.offset, 0u);
    }
    EXPECT_EQ(b.context().errorCount(), 0);
}

// The window registers are 16-bit counts (docs/card-registers.md): any
// high bit of one moves the window the card expects past the small layout's
// 50 x 25 pclk frame (bits 6-15 of a column count, 5-15 of a line count),
// so both streams' HREF disagree with it: a window mismatch on each (a
// dark region grown over the active pixels flags them dark too).
TEST(CardConfig, EveryBitOfTheWindowRegistersMovesTheWindow) {
    const rtl_test::sensor_layout layout = rtl_test::small_layout();
    struct window_register {
        const char* name;
        uint32_t offset;
        int base;
        bool column;
    };
    const window_register window[] = {
        {"H_START", regs::h_start, layout.h_start, true},
        {"DARK_COLS_LEFT", regs::dark_cols_left, layout.dark_left, true},
        {"BORDER_COLS_LEFT", regs::border_cols_left, layout.border_left, true},
        {"ACTIVE_COLS", regs::active_cols, layout.active_cols, true},
        {"BORDER_COLS_RIGHT", regs::border_cols_right, layout.border_right, true},
        {"DARK_COLS_RIGHT", regs::dark_cols_right, layout.dark_right, true},
        {"V_START", regs::v_start, layout.v_start, false},
        {"DARK_ROWS_TOP", regs::dark_rows_top, layout.dark_top, false},
        {"BORDER_ROWS_TOP", regs::border_rows_top, layout.border_top, false},
        {"ACTIVE_ROWS", regs::active_rows, layout.active_rows, false},
        {"BORDER_ROWS_BOTTOM", regs::border_rows_bottom, layout.border_bottom, false},
        {"DARK_ROWS_BOTTOM", regs::dark_rows_bottom, layout.dark_bottom, false},
    };
    const uint32_t both_windows = regs::verdict_l_window_mask | regs::verdict_r_window_mask;
    for (const window_register& w : window) {
        for (int bit = w.column ? 6 : 5; bit < 16; ++bit) {
            const uint32_t value = static_cast<uint32_t>(w.base) + (1u << bit);
            const dark_run moved = run_with_left_pixel(layout, 32, 0, 0, rtl_test::test_black_level,
                                                       {register_write{w.offset, value}});
            const std::string name = std::string(w.name) + " = " + std::to_string(value);
            EXPECT_GE(moved.mismatches, 1u) << name;
            EXPECT_EQ(moved.verdict_causes & both_windows, both_windows) << name;
        }
    }
}

}  // namespace
