// fifo_discard alone with the unit tests' FIFO width (AW = 9, rtl_card_small):
// every region start pointer, a reader behind, at and past the region's
// start, the DSP reading the words before it slowly. The golden is the
// module's specification (tests/rtl/fifo_discard_bench.h).
#include <gtest/gtest.h>

#include "Vfifo_discard_small.h"
#include "tests/rtl/fifo_discard_bench.h"

namespace {

constexpr unsigned aw = 9;
using bench = rtl_test::fifo_discard_bench<Vfifo_discard_small, aw>;

// A rejected frame's region published while the DSP still reads the last
// words of the good frame before it: none of those words may be dropped,
// whatever the region's start pointer (every value, wrap included).
TEST(FifoDiscard, NeverDropsAWordBeforeItsRegion) {
    bench discard;
    for (uint64_t begin = 0; begin <= bench::pointer_mask; ++begin) {
        for (uint64_t behind : {1u, 2u, 3u, 5u, 8u, 9u, 16u, 100u}) {
            const rtl_test::discard_outcome out = discard.drop(begin, 37, behind, 3);
            ASSERT_EQ(out.first_error, "")
                << "region at " << begin << ", reader " << behind << " word(s) behind";
        }
    }
}

TEST(FifoDiscard, DropsExactlyItsRegionFromAnyStart) {
    bench discard;
    for (uint64_t begin = 0; begin <= bench::pointer_mask; begin += 7) {
        for (uint64_t length : {1u, 2u, 100u, 1u << aw}) {
            const rtl_test::discard_outcome out = discard.drop(begin, length, 0, 0);
            ASSERT_EQ(out.first_error, "") << "region at " << begin << ", " << length << " words";
            EXPECT_EQ(out.region_pops, length);
            EXPECT_EQ(out.early_pops + out.late_pops, 0u);
        }
    }
}

}  // namespace
