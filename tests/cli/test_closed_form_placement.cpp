// Where the capture's closed form puts the frames (tb/platform/closed_form.h,
// docs/budget.md): the first PAIR_CAPTURED that names two frames in SDRAM,
// else the reference's pair buffer. The SDRAM row crossings of each
// placement, counted by hand for VGA frames and 2 KB rows: 300 a pair with
// the reference's 64-byte header, 240 for frames at a row start (of the 149
// row boundaries inside each 300 KB frame the 29 at a multiple of 10 KB fall
// between two lines).
#include <gtest/gtest.h>

#include <vector>

#include "model/c6416/c6416_regs.h"
#include "model/emif/emif_async_master.h"
#include "tb/platform/closed_form.h"

namespace {

constexpr int cols = 640, rows = 480;
constexpr uint32_t frame_bytes = cols * rows;

platform::fw_event captured(uint32_t left, uint32_t right) {
    platform::fw_event e;
    e.event.kind = STEREOSIM_EV_PAIR_CAPTURED;
    e.event.left = left;
    e.event.right = right;
    return e;
}

uint64_t crossings(const platform::frame_placement& frames) {
    emif::emif_config emif;  // the DSK's SDRAM: 2 KB rows
    return platform::capture(cols, rows, c6416::emifa::dsk_cectl_card_v1, emif, frames)
        .row_crossings;
}

TEST(ClosedFormPlacement, TheFirmwaresReportedFramesElseTheReferences) {
    const platform::frame_placement reference = platform::reference_placement(cols, rows);
    EXPECT_EQ(reference.left, 64u);
    EXPECT_EQ(reference.right, 64u + frame_bytes);
    EXPECT_EQ(crossings(reference), 300u);

    const uint32_t at_row = c6416::sdram_base + 0x10000u;
    const std::vector<platform::fw_event> aligned = {captured(at_row, at_row + frame_bytes),
                                                     captured(at_row + 64, at_row + 128)};
    const platform::frame_placement first = platform::reported_placement(aligned, cols, rows);
    EXPECT_EQ(first.left, at_row);  // the first report, not a later one
    EXPECT_EQ(first.right, at_row + frame_bytes);
    EXPECT_EQ(crossings(first), 240u);

    // No frames named (both at one address), frames in L2, no capture at all:
    // the reference's buffer.
    const std::vector<platform::fw_event> unnamed = {
        captured(0, 0), captured(at_row + 64, at_row + 64), captured(0x1000, 0x60000)};
    const platform::frame_placement fallback = platform::reported_placement(unnamed, cols, rows);
    EXPECT_EQ(fallback.left, reference.left);
    EXPECT_EQ(fallback.right, reference.right);
    EXPECT_EQ(platform::reported_placement({}, cols, rows).left, reference.left);
}

}  // namespace
