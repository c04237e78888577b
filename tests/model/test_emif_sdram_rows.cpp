// SDRAM rows on CE0 (docs/emif.md "SDRAM on CE0"): a chunk pays the row
// access (7 ECLK) unless the op right before it left the SAME SDRAM row
// (2 KB of consecutive addresses) open. The open row is a real row of the
// byte address, not the request object: emif_tlm_target reuses one
// emif_access object for every CPU transfer, and the engine once took that
// object's address for "the row is open" (consecutive 128-byte line
// transfers anywhere in SDRAM paid 16 instead of 23 ECLK).
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "model/emif/emif_access.h"
#include "model/emif/emif_async_master.h"
#include "model/emif/emif_pin_loop.h"

using namespace emif;

namespace {

struct line_rig {
    emif_config cfg;  // refresh on at the DSK's period, but no run here reaches it
    emif_async_master engine{cfg};
    emif_pin_loop loop{engine};
    std::vector<uint8_t> sdram = std::vector<uint8_t>(1 << 16);
    std::vector<uint8_t> buffer = std::vector<uint8_t>(128);
    emif_access reused;  // one object for every transfer, as emif_tlm_target does

    line_rig() {
        for (size_t i = 0; i < sdram.size(); ++i) sdram[i] = static_cast<uint8_t>(i * 3 + 1);
        engine.set_sdram_storage(sdram.data(), sdram.size());
    }
    // One 128-byte L2 line (32 words) from the CPU at `address`; returns its ECLK
    // on the bus.
    uint64_t line(uint32_t address, bool write = false, uint32_t words = 32) {
        reused = emif_access{};
        reused.who = requester::cpu;
        reused.write = write;
        reused.address = address;
        reused.words = words;
        reused.data = buffer.data();
        const uint64_t start = engine.next_edge();
        EXPECT_TRUE(engine.submit(reused));
        EXPECT_TRUE(loop.run_until_idle(10000));
        EXPECT_EQ(reused.status, access_status::ok);
        return reused.done_edge - start;
    }
};

constexpr uint32_t sdram_base = 0x80000000;

TEST(emif_sdram_rows, same_row_pays_no_row_access_another_row_does) {
    line_rig r;
    ASSERT_EQ(r.cfg.sdram.row_bytes, 2048u);
    // First line: the row is closed: 7 + 32 / 2 = 23 ECLK.
    EXPECT_EQ(r.line(sdram_base + 0x000), 23u);
    // Next lines in the same 2 KB row: 16 ECLK each, read or write.
    EXPECT_EQ(r.line(sdram_base + 0x080), 16u);
    EXPECT_EQ(r.line(sdram_base + 0x780, true), 16u);
    // The next row (bank 1 of the same row number, or any other row): 23.
    EXPECT_EQ(r.line(sdram_base + 0x800), 23u);
    // Back to the first row: closed by the one in between: 23 again.
    EXPECT_EQ(r.line(sdram_base + 0x100), 23u);
    // Far away (another row of the same bank): 23.
    EXPECT_EQ(r.line(sdram_base + 0x2000 + 0x100), 23u);
    // The data is still right.
    for (int i = 0; i < 128; ++i) ASSERT_EQ(r.buffer[i], r.sdram[0x2100 + i]) << i;
    std::printf("SDRAM lines: closed row 23 ECLK, same row 16, other row 23\n");
}

// The reused-object case of the old bug, in one sequence: lines 2 KB apart
// (each in a new row) all pay the row access, whatever object carries them.
TEST(emif_sdram_rows, consecutive_lines_in_different_rows_each_pay_the_row_access) {
    line_rig r;
    uint64_t total = 0;
    for (uint32_t k = 0; k < 10; ++k) total += r.line(sdram_base + k * 0x800);
    EXPECT_EQ(total, 10u * 23);
    // Sequential lines fill a row: 16 lines per 2 KB row, the first pays 7.
    line_rig s;
    uint64_t sequential = 0;
    for (uint32_t k = 0; k < 32; ++k) sequential += s.line(sdram_base + 0x4000 + k * 128);
    EXPECT_EQ(sequential, 2u * 7 + 32u * 16);
    std::printf(
        "10 lines in 10 rows: %llu ECLK; 32 sequential lines (2 rows): "
        "%llu ECLK\n",
        static_cast<unsigned long long>(total), static_cast<unsigned long long>(sequential));
}

// A chunk that crosses a row boundary pays a second row access there.
TEST(emif_sdram_rows, a_chunk_crossing_a_row_boundary_pays_it) {
    line_rig r;
    // 32 words from offset 0x7C0: words 0..15 in row 0, 16..31 in row 1.
    EXPECT_EQ(r.line(sdram_base + 0x7C0), 7u + 7 + 16);
    for (int i = 0; i < 128; ++i) ASSERT_EQ(r.buffer[i], r.sdram[0x7C0 + i]) << i;
    // Row 1 is now open: a line in it pays none.
    EXPECT_EQ(r.line(sdram_base + 0x840), 16u);
}

}  // namespace
