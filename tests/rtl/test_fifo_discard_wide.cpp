// fifo_discard alone with the platform's FIFO width (AW = 17, card_top's
// default): a VGA frame's 76,800 words dropped from start pointers around
// the pointer wrap, the reader at and before the region. Long regions reach
// the offset bits (>= 2^13) that the small-FIFO tests never set.
#include <gtest/gtest.h>

#include "Vfifo_discard.h"
#include "tests/rtl/fifo_discard_bench.h"

namespace {

constexpr unsigned aw = 17;
using bench = rtl_test::fifo_discard_bench<Vfifo_discard, aw>;
constexpr uint64_t vga_frame_words = 640 * 480 / 4;  // 4 pixels a 32-bit word

TEST(FifoDiscardWide, DropsAVgaFrameExactly) {
    bench discard;
    for (uint64_t begin : {uint64_t{0}, uint64_t{8}, uint64_t{12345}, uint64_t{1} << aw,
                           bench::pointer_mask - 100}) {
        for (uint64_t behind : {0u, 3u, 9u}) {
            const rtl_test::discard_outcome out = discard.drop(begin, vga_frame_words, behind, 1);
            ASSERT_EQ(out.first_error, "")
                << "region at " << begin << ", reader " << behind << " word(s) behind";
            EXPECT_EQ(out.region_pops, vga_frame_words);
        }
    }
}

}  // namespace
