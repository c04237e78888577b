// The card's event counters past their low half: an unbroken run of good
// pairs longer than 2^16 (on 128-pclk frames, 8.4 M pixel clocks, 9 s),
// every pair read by the DSP model as it would. Every count register is
// 32 bits wide (docs/card-registers.md); a counter that drops or mixes a bit
// above the ones the short tests reach (at most a few hundred events) shows
// here from bit 16 down. The golden values are the test sensors' own frame
// counts and the pairs the DSP model read, not the card's.
#include <gtest/gtest.h>

#include <cstdio>

#include "Vcard_small.h"
#include "tests/rtl/card_bench.h"

namespace {

using bench = rtl_test::card_bench<Vcard_small>;
namespace regs = dsp::card_regs;

TEST(CardCounters, MoreThanSixtyFiveThousandPairsAreCountedExactly) {
    rtl_test::bench_options o;
    o.layout = rtl_test::tiny_layout();
    o.design = "card_small";
    bench b(o);
    b.configure_layout(b.opt.layout);
    b.reader_enabled = true;
    b.enable(true);
    constexpr uint32_t frames = (1u << 16) + 64;
    b.run_frames(frames + 0.5);
    b.enable(false);  // the counters stop; a pair in flight is finished
    b.run_frames(1.0);

    const uint32_t pairs_ok = b.read_reg(regs::pairs_ok);
    const uint32_t frames_l = b.read_reg(regs::frames_l);
    const uint32_t frames_r = b.read_reg(regs::frames_r);
    std::printf(
        "%u pairs good, %zu read; FRAMES_L %u, FRAMES_R %u; sensors drove %zu / %zu frames\n",
        pairs_ok, b.pairs.size(), frames_l, frames_r, b.left.frames().size(),
        b.right.frames().size());
    EXPECT_GT(pairs_ok, 1u << 16);
    EXPECT_EQ(pairs_ok, b.pairs.size()) << "PAIRS_OK against the pairs the DSP model read";
    EXPECT_EQ(frames_l, b.left.frames().size()) << "FRAMES_L against the left sensor's frames";
    EXPECT_EQ(frames_r, b.right.frames().size()) << "FRAMES_R against the right sensor's frames";
    size_t bad_pairs = 0;
    for (const auto& p : b.pairs) bad_pairs += p.bad_words != 0 || p.serial_l != p.serial_r;
    EXPECT_EQ(bad_pairs, 0u) << "every pair read whole, of one frame of both sensors";
    EXPECT_EQ(b.read_reg(regs::mismatches), 0u);
    EXPECT_EQ(b.read_reg(regs::skipped), 0u);
    EXPECT_EQ(b.read_reg(regs::overflows), 0u);
    EXPECT_EQ(b.read_reg(regs::underflows), 0u);
    EXPECT_EQ(b.context().errorCount(), 0);
}

}  // namespace
