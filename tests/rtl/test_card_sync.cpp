// The card (rtl/card_top.v with 512-word FIFOs and the metastability model)
// driven cycle by cycle with two test sensors on small 32x16 frames: the
// dark-pixel sync check, OE restarts and the retry limit, forwarding of
// active pixels only, rejected frames removed from the FIFOs, overflow.
//
// Exact expectations: a fault is reported by the verdict of the common frame
// in which it begins (VERDICT.FRAME), with the documented cause bits, and the
// SYNC_ERROR interrupt rises after that frame's last pixel clock and within a
// few clocks of it, never earlier; every word the DSP model reads is the
// expected pixel word of a good frame (byte order: pixel 4k+n in bits 8n+7..8n).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "Vcard_small.h"
#include "tests/rtl/card_bench.h"

namespace {

using bench = rtl_test::card_bench<Vcard_small>;
namespace regs = dsp::card_regs;
using rtl_test::small_layout;

constexpr uint32_t oe_low_cycles = 60;
constexpr uint32_t start_timeout_lines = 100;

// Verdict latency bound: the counter is registered (1 pclk), the status
// snapshot needs at most one handshake round trip plus one transfer (2 pclk +
// 6 eclk), the event and the pin are registered (2 eclk), and the monitor
// samples the pin at the next edge (1 eclk).
uint64_t verdict_latency_bound(const rtl_test::bench_options& o) {
    return 4 * o.pclk_ticks + 12 * o.eclk_ticks;
}

rtl_test::bench_options small_options(const char* design = "card_small") {
    rtl_test::bench_options o;
    o.layout = small_layout();
    o.design = design;
    return o;
}

void setup(bench& b) {
    b.configure_layout(b.opt.layout);
    b.write_reg(regs::oe_low_cycles, oe_low_cycles);
    b.write_reg(regs::start_timeout, start_timeout_lines);
}

// Tick at which the card samples the last pixel clock of common frame `k` of
// OE start `start`: the common frame begins with the first VSYNC of either sensor.
uint64_t common_frame_end(bench& b, unsigned start, uint64_t k) {
    uint64_t c0 = UINT64_MAX;
    for (const auto* s : {&b.left, &b.right})
        for (const auto& f : s->frames())
            if (f.start == start) {
                c0 = std::min(c0, f.start_cycle);
                break;
            }
    const uint64_t last = c0 + (k + 1) * b.opt.layout.frame_pclks() - 1;
    return b.sample_tick(last);
}

void expect_clean_protocol(bench& b) {
    EXPECT_EQ(b.ed_conflicts, 0u);
    EXPECT_EQ(b.ed_outside_ce, 0u);
    EXPECT_EQ(b.ardy_outside_ce, 0u);
    EXPECT_EQ(b.ed_hold_errors, 0u);
    EXPECT_EQ(b.timeouts, 0u);
    EXPECT_EQ(b.context().errorCount(), 0);
}

// Every pair read is a whole good frame of both sensors, frames in order.
void expect_pairs_intact(bench& b) {
    uint32_t last = 0;
    for (size_t i = 0; i < b.pairs.size(); ++i) {
        const auto& p = b.pairs[i];
        EXPECT_EQ(p.bad_words, 0u) << "pair " << i;
        EXPECT_EQ(p.serial_l, p.serial_r) << "pair " << i << " mixes frames of the two sensors";
        if (i > 0) {
            EXPECT_GT(p.serial_l, last) << "pair " << i;
        }
        last = p.serial_l;
    }
}

TEST(CardSync, AlignedStreamsPassAndEveryForwardedWordIsTheActivePixels) {
    bench b(small_options());
    setup(b);
    b.reader_enabled = true;
    b.enable(true);
    b.run_frames(8.3);

    const uint32_t pairs_ok = b.read_reg(regs::pairs_ok);
    EXPECT_EQ(b.read_reg(regs::mismatches), 0u);
    EXPECT_EQ(b.read_reg(regs::retries), 0u);
    EXPECT_EQ(b.read_reg(regs::underflows), 0u);
    EXPECT_EQ(b.read_reg(regs::discarded), 0u);
    EXPECT_EQ(b.read_reg(regs::frames_l), b.read_reg(regs::frames_r));
    EXPECT_EQ(b.read_reg(regs::status) & regs::status_state_mask, 3u) << "RUN";
    EXPECT_GE(pairs_ok, 7u);
    const uint32_t verdict = b.read_reg(regs::verdict);
    EXPECT_EQ(verdict & 0x3FFu, 0u) << "no cause in the last verdict; first mismatch at 0x"
                                    << std::hex << b.read_reg(regs::mismatch_pos);
    EXPECT_EQ(verdict >> regs::verdict_frame_shift, pairs_ok - 1) << "last verdict = last frame";

    ASSERT_GE(b.pairs.size(), pairs_ok - 1);
    expect_pairs_intact(b);
    for (size_t i = 0; i < b.pairs.size(); ++i) EXPECT_EQ(b.pairs[i].serial_l, i);

    // FRAME_READY rises after each frame's end, within the bound.
    uint64_t worst = 0;
    for (size_t k = 0; k < b.int4.rise_ticks.size(); ++k) {
        const uint64_t end = common_frame_end(b, 0, k);
        const uint64_t irq = b.int4.rise_ticks[k];
        ASSERT_GT(irq, end) << "pair " << k << " announced before its frame ended";
        worst = std::max(worst, irq - end);
    }
    EXPECT_LE(worst, verdict_latency_bound(b.opt));
    std::printf(
        "%u pairs checked, %llu words read and matched; FRAME_READY %.1f ns after the "
        "frame's last pixel clock at worst\n",
        pairs_ok, (unsigned long long)b.words_read, worst * rtl_test::ns_per_tick);
    // Pulses: 4 ECLK high, >= 4 low (docs/card.md, "Interrupts").
    EXPECT_EQ(b.int4.min_high, 4u);
    EXPECT_EQ(b.int5.rise_ticks.size(), 0u);
    EXPECT_EQ(b.int6.rise_ticks.size(), 0u);
    expect_clean_protocol(b);
}

// One fault, the frame it begins in, the causes the verdict must show.
struct fault_case {
    const char* name;
    void (*inject)(bench&);
    uint64_t frame;      // common frame (of OE start 0) where it begins
    uint32_t causes;     // VERDICT bits that must be set
    uint32_t forbidden;  // VERDICT bits that must stay clear
    bool words_written;  // the bad frame had forwarded words to discard
};

constexpr uint32_t l_win = regs::verdict_l_window_mask, r_win = regs::verdict_r_window_mask;
constexpr uint32_t l_dark = regs::verdict_l_dark_mask, r_dark = regs::verdict_r_dark_mask;
constexpr uint32_t l_vs = regs::verdict_l_vsync_mask, r_vs = regs::verdict_r_vsync_mask;
constexpr uint32_t l_id = regs::verdict_l_frame_id_mask, r_id = regs::verdict_r_frame_id_mask;
constexpr uint32_t all_l = l_win | l_dark | l_vs | l_id, all_r = r_win | r_dark | r_vs | r_id;

const fault_case fault_cases[] = {
    {"right starts 1 pclk late", [](bench& b) { b.right.set_start_extra({1}); }, 0, r_win | r_vs,
     all_l, false},
    {"left starts 1 pclk late", [](bench& b) { b.left.set_start_extra({1}); }, 0, l_win | l_vs,
     all_r, false},
    {"right starts 1 line late", [](bench& b) { b.right.set_start_extra({50}); }, 0, r_win | r_vs,
     all_l, false},
    {"right starts 3 lines late", [](bench& b) { b.right.set_start_extra({150}); }, 0, r_win | r_vs,
     all_l, false},
    {"right drops active row 4 of frame 2", [](bench& b) { b.right.drop_line(2, 7); }, 2, r_win,
     all_l | r_vs | r_dark, true},
    {"right drops dark row 0 of frame 1", [](bench& b) { b.right.drop_line(1, 0); }, 1, r_win,
     all_l | r_vs | r_dark, false},
    {"extra VSYNC in the right stream, frame 3 line 10",
     [](bench& b) { b.right.extra_vsync(3, 10, 5); }, 3, r_vs, all_l | r_win | r_dark, true},
    {"left slips 1 pclk before frame 2", [](bench& b) { b.left.slip_before_frame(2, 1); }, 2,
     l_win | l_vs, all_r, false},
    {"left slips 2 lines before frame 1", [](bench& b) { b.left.slip_before_frame(1, 100); }, 1,
     l_win | l_vs, all_r, false},
    {"light leak: left dark column pixel reads 200 in frame 1",
     [](bench& b) { b.left.poke_pixel(1, 8, 1, 200); }, 1, l_dark, all_r | l_win | l_vs, true},
    {"light leak: right bottom dark row pixel reads 32 in frame 2",
     [](bench& b) { b.right.poke_pixel(2, 20, 20, 32); }, 2, r_dark, all_l | r_win | r_vs, true},
    // A frame sent twice keeps every pin's timing and dark pixel: only its
    // FODD, unchanged from the frame before, shows it. Seen at the frame's
    // VSYNC rise, so none of its words is forwarded.
    {"right sends frame 2 twice", [](bench& b) { b.right.repeat_frame(2); }, 3, r_id,
     all_l | r_win | r_dark | r_vs, false},
    {"left sends frame 0 twice", [](bench& b) { b.left.repeat_frame(0); }, 1, l_id,
     all_r | l_win | l_dark | l_vs, false},
};

class CardSyncFault : public ::testing::TestWithParam<fault_case> {};

TEST_P(CardSyncFault, DetectedByTheVerdictOfTheFrameWhereItBeginsThenOeRestarts) {
    const fault_case& fc = GetParam();
    bench b(small_options());
    setup(b);
    fc.inject(b);
    b.reader_enabled = true;
    b.enable(true);
    ASSERT_TRUE(b.run_until([&] { return !b.int5.rise_ticks.empty(); },
                            (fc.frame + 3) * b.opt.layout.frame_pclks() * b.opt.pclk_ticks));
    const uint64_t end = common_frame_end(b, 0, fc.frame);
    const uint64_t irq = b.int5.rise_ticks.front();
    EXPECT_GT(irq, end) << "reported before the frame ended";
    EXPECT_LE(irq - end, verdict_latency_bound(b.opt)) << "reported late";
    if (fc.frame > 0) {
        EXPECT_GT(irq, common_frame_end(b, 0, fc.frame - 1) + verdict_latency_bound(b.opt))
            << "reported in an earlier frame's verdict";
    }

    const uint32_t verdict = b.read_reg(regs::verdict);
    const uint32_t pos = b.read_reg(regs::mismatch_pos);
    EXPECT_EQ(verdict >> regs::verdict_frame_shift, fc.frame);
    EXPECT_EQ(verdict & fc.causes, fc.causes) << std::hex << "verdict 0x" << verdict;
    EXPECT_EQ(verdict & fc.forbidden, 0u) << std::hex << "verdict 0x" << verdict;
    EXPECT_EQ(b.read_reg(regs::mismatches), 1u);
    EXPECT_EQ(b.read_reg(regs::pairs_ok), fc.frame) << "the frames before it passed";
    std::printf(
        "%s: verdict of frame %u causes 0x%03x, first mismatch line %u col %u, "
        "SYNC_ERROR %.1f ns after the frame end\n",
        fc.name, verdict >> 16, verdict & 0x3FF, pos >> 16, pos & 0xFFFF,
        (irq - end) * rtl_test::ns_per_tick);

    // OE restart: low for exactly OE_LOW_CYCLES pixel clocks, then the
    // (now healthy) sensors pass and pairs flow again.
    b.run_frames(4.5);
    ASSERT_GE(b.oe_fall_edges.size(), 1u);
    ASSERT_GE(b.oe_rise_edges.size(), 2u);
    EXPECT_EQ(b.oe_rise_edges[1] - b.oe_fall_edges[0], oe_low_cycles);
    EXPECT_EQ(b.read_reg(regs::retries), 1u);
    EXPECT_EQ(b.read_reg(regs::mismatches), 1u);
    EXPECT_EQ(b.read_reg(regs::discarded), fc.words_written ? 1u : 0u);
    EXPECT_GE(b.read_reg(regs::pairs_ok), fc.frame + 3);
    EXPECT_EQ(b.int5.rise_ticks.size(), 1u);
    EXPECT_GE(b.int5.min_low, 4u);
    expect_pairs_intact(b);  // the rejected frame's words never reach the DSP
    EXPECT_GE(b.pairs.size(), fc.frame + 2);
    expect_clean_protocol(b);
}

INSTANTIATE_TEST_SUITE_P(Faults, CardSyncFault, ::testing::ValuesIn(fault_cases),
                         [](const ::testing::TestParamInfo<fault_case>& info) {
                             std::string n = info.param.name;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

// CHECKS.FRAME_ID = 0 is the paper's card: the repeat passes the dark-pixel
// check and its pair, two frames a period apart, reaches the DSP.
TEST(CardSync, WithTheFrameIdCheckOffARepeatedFrameIsForwarded) {
    bench b(small_options());
    setup(b);
    b.write_reg(regs::checks, 0);
    EXPECT_EQ(b.read_reg(regs::checks), 0u);
    b.right.repeat_frame(2);
    b.reader_enabled = true;
    b.enable(true);
    b.run_frames(6.5);
    EXPECT_EQ(b.read_reg(regs::mismatches), 0u);
    EXPECT_EQ(b.read_reg(regs::retries), 0u);
    ASSERT_GE(b.pairs.size(), 5u);
    // Pair 3 is left frame 3 with right frame 2 again; then right is one behind.
    EXPECT_EQ(b.pairs[3].serial_l, 3u);
    EXPECT_EQ(b.pairs[3].serial_r, 2u);
    EXPECT_EQ(b.pairs[4].serial_r + 1, b.pairs[4].serial_l);
    expect_clean_protocol(b);
}

// A sensor whose frame count is one off the other's (FODD inverted) fails
// the first frame after every OE start, both streams flagged (no history
// says which one is off), until the retry limit; the check off lets it pass.
TEST(CardSync, FrameIdentitiesThatDifferAtTheStartFailEveryStartUntilTheRetryLimit) {
    for (const bool check : {true, false}) {
        bench b(small_options());
        setup(b);
        b.write_reg(regs::retry_limit, 2);
        if (!check) b.write_reg(regs::checks, 0);
        b.right.invert_fodd();
        b.reader_enabled = true;
        b.enable(true);
        b.run_frames(8);
        if (check) {
            EXPECT_EQ(b.read_reg(regs::mismatches), 3u);
            EXPECT_EQ(b.read_reg(regs::retries), 2u);
            EXPECT_EQ(b.read_reg(regs::pairs_ok), 0u);
            EXPECT_NE(b.read_reg(regs::status) & regs::status_hard_error_mask, 0u);
            const uint32_t verdict = b.read_reg(regs::verdict);
            EXPECT_EQ(verdict & 0x3FFu, l_id | r_id) << std::hex << "verdict 0x" << verdict;
            EXPECT_EQ(verdict >> regs::verdict_frame_shift, 0u);
        } else {
            EXPECT_EQ(b.read_reg(regs::mismatches), 0u);
            EXPECT_GE(b.read_reg(regs::pairs_ok), 7u);
        }
        expect_clean_protocol(b);
    }
}

TEST(CardSync, DarkPixelJustBelowTheThresholdPasses) {
    bench b(small_options());
    setup(b);
    b.left.poke_pixel(1, 8, 1, 31);  // threshold 32: 31 is still dark
    b.write_reg(regs::dark_threshold, 32);
    b.enable(true);
    b.run_frames(3.5);
    EXPECT_EQ(b.read_reg(regs::mismatches), 0u);
    EXPECT_GE(b.read_reg(regs::pairs_ok), 3u);
    expect_clean_protocol(b);
}

// OE_LOW_CYCLES 0 acts as 1 (docs/card-registers.md): each restart holds OE
// low for exactly one pixel clock, not for none and not for more.
TEST(CardSync, OeLowCyclesZeroHoldsOeLowOnePixelClock) {
    bench b(small_options());
    setup(b);
    b.write_reg(regs::oe_low_cycles, 0);
    b.write_reg(regs::retry_limit, 3);
    b.right.set_start_extra_always(2);  // out of step on every start: 3 restarts
    b.enable(true);
    b.run_frames(10);
    ASSERT_EQ(b.oe_rise_edges.size(), 4u);
    for (size_t i = 1; i < b.oe_rise_edges.size(); ++i)
        EXPECT_EQ(b.oe_rise_edges[i] - b.oe_fall_edges[i - 1], 1u) << "restart " << i;
    expect_clean_protocol(b);
}

TEST(CardSync, RetryLimitStopsWithAHardSyncErrorThenEnableRecovers) {
    bench b(small_options());
    setup(b);
    b.write_reg(regs::retry_limit, 3);
    b.right.set_start_extra_always(2);  // out of step on every start
    b.enable(true);
    b.run_frames(10);

    EXPECT_EQ(b.read_reg(regs::retries), 3u) << "exactly RETRY_LIMIT restarts";
    EXPECT_EQ(b.read_reg(regs::mismatches), 4u) << "first attempt plus 3 retries";
    const uint32_t status = b.read_reg(regs::status);
    EXPECT_EQ(status & regs::status_state_mask, 4u) << "HARD_ERROR";
    EXPECT_NE(status & regs::status_hard_error_mask, 0u);
    EXPECT_EQ(status & regs::status_oe_mask, 0u);
    EXPECT_EQ(b.oe_rise_edges.size(), 4u);
    EXPECT_EQ(b.oe_fall_edges.size(), 4u);
    for (size_t i = 1; i < b.oe_rise_edges.size(); ++i)
        EXPECT_EQ(b.oe_rise_edges[i] - b.oe_fall_edges[i - 1], oe_low_cycles);
    EXPECT_EQ(b.int5.rise_ticks.size(), 4u) << "one SYNC_ERROR pulse per failed check";
    EXPECT_EQ(b.read_reg(regs::pairs_ok), 0u);
    EXPECT_NE(b.read_reg(regs::irq_status) & regs::irq_status_sync_error_mask, 0u);
    // OE stays low: no more starts.
    const size_t rises = b.oe_rise_edges.size();
    b.run_frames(3);
    EXPECT_EQ(b.oe_rise_edges.size(), rises);
    std::printf("hard sync error after %zu OE starts; OE low between them %u pclk\n", rises,
                oe_low_cycles);

    // ENABLE low clears it; with a healthy sensor the next run works.
    b.enable(false);
    b.run_ticks(20 * b.opt.pclk_ticks);
    EXPECT_EQ(b.read_reg(regs::status) & (regs::status_state_mask | regs::status_hard_error_mask),
              0u);
    b.right.set_start_extra_always(0);
    b.enable(true);
    b.run_frames(3.5);
    EXPECT_GE(b.read_reg(regs::pairs_ok), 2u);
    EXPECT_EQ(b.read_reg(regs::mismatches), 4u);
    // W1C: clearing SYNC_ERROR leaves the others.
    b.write_reg(regs::irq_status, regs::irq_status_sync_error_mask);
    const uint32_t irqs = b.read_reg(regs::irq_status);
    EXPECT_EQ(irqs & regs::irq_status_sync_error_mask, 0u);
    EXPECT_NE(irqs & regs::irq_status_frame_ready_mask, 0u);
    expect_clean_protocol(b);
}

TEST(CardSync, OneSensorNeverStartingIsAMismatchBothSilentIsAStartTimeout) {
    {
        bench b(small_options());
        setup(b);
        b.write_reg(regs::retry_limit, 0);
        b.right.never_start();
        b.enable(true);
        b.run_frames(2.5);
        EXPECT_EQ(b.read_reg(regs::mismatches), 1u);
        const uint32_t verdict = b.read_reg(regs::verdict);
        EXPECT_EQ(verdict & (r_win | r_vs), r_win | r_vs);
        EXPECT_EQ(verdict & all_l, 0u);
        EXPECT_EQ(b.read_reg(regs::status) & regs::status_state_mask, 4u);
        expect_clean_protocol(b);
    }
    {
        bench b(small_options());
        setup(b);
        b.write_reg(regs::retry_limit, 1);
        b.left.never_start();
        b.right.never_start();
        b.enable(true);
        const uint64_t timeout_ticks =
            uint64_t{start_timeout_lines} * b.opt.layout.line_total * b.opt.pclk_ticks;
        b.run_ticks(3 * timeout_ticks);
        EXPECT_EQ(b.read_reg(regs::mismatches), 2u);
        EXPECT_EQ(b.read_reg(regs::retries), 1u);
        EXPECT_EQ(b.read_reg(regs::verdict), regs::verdict_start_timeout_mask);
        ASSERT_EQ(b.oe_fall_edges.size(), 2u);
        // OE high for exactly START_TIMEOUT lines (+1 clock to decide) before each restart.
        EXPECT_EQ(b.oe_fall_edges[0] - b.oe_rise_edges[0],
                  uint64_t{start_timeout_lines} * b.opt.layout.line_total + 1);
        EXPECT_EQ(b.int5.rise_ticks.size(), 2u);
        expect_clean_protocol(b);
    }
}

// docs/design-brief.md's start-up model: each sensor starts after a fixed latency plus,
// with probability 0.25, an extra 1 pclk .. 2 lines. Over many starts the
// verdict of the first frame must be "in step" exactly when both sensors
// drew the same extra delay: no false alarm, no missed skew.
TEST(CardSync, RandomStartSkewsAreJudgedExactlyOverManyStarts) {
    bench b(small_options());
    setup(b);
    b.write_reg(regs::retry_limit, 0);  // judge each start once
    std::mt19937 rng(2024);
    const int starts = 200 / static_cast<int>(rtl_test::stress_divisor) + 6;
    std::vector<int> extra_l, extra_r;
    for (int i = 0; i < starts; ++i) {
        const auto draw = [&] {
            return rng() % 4 == 0 ? 1 + static_cast<int>(rng() % (2 * 50)) : 0;
        };
        extra_l.push_back(draw());
        extra_r.push_back(i % 3 == 0 ? extra_l.back() : draw());  // many equal pairs too
    }
    b.left.set_start_extra(extra_l);
    b.right.set_start_extra(extra_r);
    b.reader_enabled = true;  // pairs must be drained, or a pending discard blocks forwarding
    int false_alarms = 0, missed = 0, in_step = 0;
    const uint64_t limit = 3 * b.opt.layout.frame_pclks() * b.opt.pclk_ticks;
    for (int i = 0; i < starts; ++i) {
        const size_t ok0 = b.int4.rise_ticks.size(), bad0 = b.int5.rise_ticks.size();
        b.enable(true);
        ASSERT_TRUE(b.run_until(
            [&] { return b.int4.rise_ticks.size() > ok0 || b.int5.rise_ticks.size() > bad0; },
            limit));
        const bool passed = b.int4.rise_ticks.size() > ok0;
        const bool same = extra_l[i] == extra_r[i];
        in_step += same;
        false_alarms += same && !passed;
        missed += !same && passed;
        b.enable(false);
        b.run_ticks(30 * b.opt.pclk_ticks);
    }
    std::printf("%d starts (%d in step): %d false alarms, %d missed skews\n", starts, in_step,
                false_alarms, missed);
    EXPECT_EQ(false_alarms, 0);
    EXPECT_EQ(missed, 0);
    EXPECT_EQ(b.read_reg(regs::mismatches), static_cast<uint32_t>(starts - in_step));
    expect_clean_protocol(b);
}

// ENABLE cleared while OE is held low for a restart, or while waiting for the
// first VSYNC, returns to IDLE at once (OE stays low, nothing counted).
TEST(CardSync, DisableDuringTheRestartGapOrTheWaitForVsyncGoesIdle) {
    bench b(small_options());
    setup(b);
    b.write_reg(regs::oe_low_cycles, 5000);
    b.right.set_start_extra({1});
    b.enable(true);
    ASSERT_TRUE(b.run_until([&] { return !b.int5.rise_ticks.empty(); },
                            3 * b.opt.layout.frame_pclks() * b.opt.pclk_ticks));
    EXPECT_EQ(b.read_reg(regs::status) & regs::status_state_mask, 1u) << "OE_LOW";
    b.enable(false);
    b.run_ticks(20 * b.opt.pclk_ticks);
    EXPECT_EQ(b.read_reg(regs::status) & regs::status_state_mask, 0u) << "IDLE";
    EXPECT_EQ(b.oe_rise_edges.size(), 1u) << "no restart after ENABLE went low";

    b.left.never_start();
    b.right.never_start();
    b.enable(true);
    b.run_ticks(300 * b.opt.pclk_ticks);
    EXPECT_EQ(b.read_reg(regs::status) & regs::status_state_mask, 2u) << "WAIT_VSYNC";
    b.enable(false);
    b.run_ticks(20 * b.opt.pclk_ticks);
    const uint32_t status = b.read_reg(regs::status);
    EXPECT_EQ(status & (regs::status_state_mask | regs::status_oe_mask), 0u) << "IDLE, OE low";
    EXPECT_EQ(b.read_reg(regs::mismatches), 1u);
    expect_clean_protocol(b);
}

// Interrupt events faster than the pin can pulse: with a pixel clock faster
// than ECLK and a 1-line start timeout on a 4-clock line, silent sensors fail
// a check every few ECLK cycles. The pin keeps its 4-high / 4-low shape and
// merges events into fewer pulses; MISMATCHES and RETRIES stay exact.
TEST(CardIrq, EventsFasterThanThePulseMergeAndTheCountersStayExact) {
    rtl_test::bench_options o = small_options();
    o.pclk_ticks = 60;  // 300 MHz against the 100 MHz ECLK
    bench b(o);
    b.write_reg(regs::line_total, 4);
    b.write_reg(regs::start_timeout, 1);
    b.write_reg(regs::oe_low_cycles, 1);
    b.write_reg(regs::retry_limit, 200);
    b.left.never_start();
    b.right.never_start();
    b.enable(true);
    b.run_ticks(4000 * o.pclk_ticks);
    EXPECT_EQ(b.read_reg(regs::status) & regs::status_state_mask, 4u) << "HARD_ERROR";
    EXPECT_EQ(b.read_reg(regs::mismatches), 201u);
    EXPECT_EQ(b.read_reg(regs::retries), 200u);
    EXPECT_EQ(b.oe_rise_edges.size(), 201u);
    const size_t pulses = b.int5.rise_ticks.size();
    EXPECT_GT(pulses, 10u);
    EXPECT_LT(pulses, 201u) << "events closer than a pulse merge";
    EXPECT_EQ(b.int5.min_high, 4u);
    EXPECT_GE(b.int5.min_low, 4u);
    std::printf("201 failed checks in %.1f us -> %zu EXT_INT5 pulses (4 ECLK high, >= %llu low)\n",
                b.now() * rtl_test::ns_per_tick / 1000.0, pulses,
                (unsigned long long)b.int5.min_low);
    expect_clean_protocol(b);
}

// The DSP is late: the FIFOs (512 words = 4 pairs of 32x16) fill, the next
// frames overflow and are dropped (OVERFLOW interrupt); a partial frame that
// overflowed half-way is removed from the FIFOs; once the DSP catches up,
// pairs flow again and every word read belongs to a whole good frame.
TEST(CardSync, OverflowDropsThePairAndRemovesItsWordsFromTheFifos) {
    bench b(small_options());
    setup(b);
    b.enable(true);
    ASSERT_TRUE(b.run_until([&] { return !b.int6.rise_ticks.empty(); },
                            8 * b.opt.layout.frame_pclks() * b.opt.pclk_ticks));
    EXPECT_EQ(b.read_reg(regs::pairs_ok), 4u) << "4 pairs fill 512 words";
    EXPECT_EQ(b.read_reg(regs::overflows), 1u);
    const uint32_t status = b.read_reg(regs::status);
    EXPECT_NE(status & regs::status_overflow_l_mask, 0u);
    EXPECT_NE(status & regs::status_overflow_r_mask, 0u);
    EXPECT_EQ(b.read_reg(regs::level_l), 512u);
    EXPECT_EQ(b.read_reg(regs::peak_l), 512u);

    // The DSP reads 40 words (L 24, R 16), then stalls: the next frame writes
    // 17 words to L and 16 to R before R overflows.
    b.reader_enabled = true;
    b.reader_budget = 40;
    ASSERT_TRUE(b.run_until([&] { return b.int6.rise_ticks.size() >= 2; },
                            3 * b.opt.layout.frame_pclks() * b.opt.pclk_ticks));
    b.run_frames(1.8);
    EXPECT_EQ(b.read_reg(regs::overflows), 2u);
    EXPECT_EQ(b.read_reg(regs::discarded), 1u);
    EXPECT_EQ(b.read_reg(regs::verdict) & regs::verdict_overflow_mask, 0u)
        << "the frame after it was not forwarded (discard pending): no overflow";
    EXPECT_EQ(b.read_reg(regs::mismatches), 0u) << "an overflow is not a sync error";
    EXPECT_NE(b.read_reg(regs::status) & regs::status_discard_busy_mask, 0u);

    b.reader_budget = UINT64_MAX;
    b.run_frames(8);
    EXPECT_EQ(b.read_reg(regs::status) & regs::status_discard_busy_mask, 0u);
    EXPECT_GE(b.read_reg(regs::skipped), 1u) << "good frames skipped while the discard ran";
    EXPECT_GE(b.pairs.size(), 8u);
    expect_pairs_intact(b);
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(b.pairs[i].serial_l, i);
    EXPECT_GT(b.pairs[4].serial_l, 5u) << "frames 4 and 5 were dropped";
    EXPECT_EQ(b.read_reg(regs::underflows), 0u);
    std::printf("after the overflow the DSP read pairs of frames");
    for (const auto& p : b.pairs) std::printf(" %u", p.serial_l);
    std::printf("\n");
    // Every sensor frame up to the last one read that the DSP did not get
    // was dropped by an overflow or skipped while the discard ran: SKIPPED
    // is exactly the rest (counted from what the DSP model read).
    const uint32_t unread = b.pairs.back().serial_l + 1 - static_cast<uint32_t>(b.pairs.size());
    // Read a few times, a few pixel clocks apart: the counter holds between events.
    for (int read = 0; read < 4; ++read)
        EXPECT_EQ(b.read_reg(regs::skipped), unread - b.read_reg(regs::overflows))
            << unread << " frames unread, read " << read;
    expect_clean_protocol(b);
}

TEST(CardSync, DisablingMidFrameDropsThePartialFrameAndRestartsCleanly) {
    bench b(small_options());
    setup(b);
    b.reader_enabled = true;
    b.enable(true);
    // Two pairs, then stop in the middle of the third frame's active rows.
    ASSERT_TRUE(b.run_until([&] { return b.int4.rise_ticks.size() >= 2; },
                            4 * b.opt.layout.frame_pclks() * b.opt.pclk_ticks));
    b.run_ticks(b.opt.layout.frame_pclks() * b.opt.pclk_ticks / 2);
    b.enable(false);
    b.run_frames(1);
    EXPECT_EQ(b.read_reg(regs::status) & regs::status_state_mask, 0u) << "IDLE";
    EXPECT_EQ(b.read_reg(regs::discarded), 1u);
    b.enable(true);
    b.run_frames(4);
    EXPECT_EQ(b.read_reg(regs::mismatches), 0u);
    EXPECT_GE(b.pairs.size(), 4u);
    expect_pairs_intact(b);
    EXPECT_EQ(b.read_reg(regs::level_l), b.read_reg(regs::level_r));
    expect_clean_protocol(b);
}

}  // namespace
