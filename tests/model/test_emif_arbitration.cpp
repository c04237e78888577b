// Arbitration on EMIFA between the CPU (single words), the EDMA (bursts) and
// SDRAM (refresh, and CPU/EDMA traffic to CE0 at transaction level), with
// waiting times counted exactly in ECLK edges (docs/emif.md, "Arbitration"):
//   fixed priority at every word boundary: refresh due > CPU > EDMA;
//   a burst yields between words and resumes after the winner;
//   TA idle cycles whenever an async word is next to a different CE space
//   or direction (SDRAM and refresh included);
//   an SDRAM burst moves in chunks of 32 words, 2 words per ECLK, plus 7
//   cycles to open a row unless it directly continues its own last chunk.
// Every schedule is worked out by hand in the comments (CECTL 0x22A28A22 on
// CE2/CE3: 14 ECLK per word, TA 2) and the protocol checker must stay silent.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "model/emif/emif_async_master.h"
#include "model/emif/emif_checker.h"
#include "model/emif/emif_pin_loop.h"
#include "tests/support/emif/async_sram_slave.h"

using namespace emif;

namespace {

struct rig {
    emif_config cfg;
    emif_async_master engine;
    async_sram_slave ce2, ce3;
    emif_checker checker;
    emif_pin_loop loop;
    std::vector<uint8_t> sdram;

    static emif_config make(uint32_t refresh_period) {
        emif_config c;
        c.sdram.refresh_period = refresh_period;
        return c;
    }
    explicit rig(uint32_t refresh_period = 0)
        : cfg(make(refresh_period)),
          engine(cfg),
          ce2(sram_config{2, 1024, 2, true}),
          ce3(sram_config{3, 1024, 2, true}),
          checker(cfg.cectl),
          loop(engine),
          sdram(1 << 16) {
        engine.set_observer(&checker);
        loop.attach(2, &ce2);
        loop.attach(3, &ce3);
        for (uint32_t i = 0; i < 1024; ++i) {
            ce2.word(i) = 0x22000000u | i;
            ce3.word(i) = 0x33000000u | i;
        }
        for (size_t i = 0; i < sdram.size(); ++i) sdram[i] = static_cast<uint8_t>(i * 7 + 1);
        engine.set_sdram_storage(sdram.data(), sdram.size());
    }
    // Steps until the next edge to be stepped is `edge`.
    void run_to(uint64_t edge) {
        while (engine.next_edge() < edge) loop.step();
    }
};

struct request {
    std::vector<uint8_t> data;
    emif_access a;
    request(requester who, bool write, uint32_t address, uint32_t words, bool increment = true)
        : data(4 * words) {
        a.who = who;
        a.write = write;
        a.address = address;
        a.words = words;
        a.increment = increment;
        a.data = data.data();
    }
    uint32_t word(size_t i) const {
        return data[4 * i] | data[4 * i + 1] << 8 | data[4 * i + 2] << 16 |
               uint32_t(data[4 * i + 3]) << 24;
    }
};

}  // namespace

TEST(emif_arbitration, cpu_word_waits_for_the_edma_word_boundary_then_the_burst_resumes) {
    rig r;
    request dma(requester::edma, false, 0xB0000000, 10, false);
    ASSERT_TRUE(r.engine.submit(dma.a));  // eligible at edge 0: words end at 14, 28, ...
    r.run_to(20);
    request cpu(requester::cpu, false, 0xA0000008, 1);
    ASSERT_TRUE(r.engine.submit(cpu.a));  // eligible at edge 20, mid word 1
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    // Word 1 ends at 28: the CPU wins, TA (CE3 -> CE2) 28..30, its read 30..44;
    // TA 44..46, the burst's 8 remaining words 46..158.
    EXPECT_EQ(cpu.a.eligible_edge, 20u);
    EXPECT_EQ(cpu.a.grant_edge, 28u);
    EXPECT_EQ(cpu.a.turnaround_cycles, 2u);
    EXPECT_EQ(cpu.a.done_edge, 44u);
    EXPECT_EQ(dma.a.grant_edge, 0u);
    EXPECT_EQ(dma.a.done_edge, 158u);
    EXPECT_EQ(dma.a.done_edge - 10 * 14, 14u + 2 * 2);  // the burst lost one word and two TAs
    EXPECT_EQ(cpu.word(0), 0x22000002u);
    for (size_t i = 0; i < 10; ++i) EXPECT_EQ(dma.word(i), 0x33000000u);
    EXPECT_EQ(r.checker.total(), 0u);
    std::printf(
        "CPU read behind an EDMA burst: waited %llu ECLK (8 to the word boundary + TA 2 + 14), "
        "burst +%llu ECLK\n",
        (unsigned long long)(cpu.a.done_edge - cpu.a.eligible_edge),
        (unsigned long long)(dma.a.done_edge - 140));
}

TEST(emif_arbitration, cpu_before_edma_when_both_ask_at_the_same_edge) {
    rig r;
    request dma(requester::edma, false, 0xB0000000, 3);
    request cpu(requester::cpu, true, 0xA0000010, 1);
    ASSERT_TRUE(r.engine.submit(dma.a));  // submitted first, still loses
    ASSERT_TRUE(r.engine.submit(cpu.a));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    EXPECT_EQ(cpu.a.grant_edge, 0u);
    EXPECT_EQ(cpu.a.done_edge, 14u);
    EXPECT_EQ(dma.a.grant_edge, 14u);
    EXPECT_EQ(dma.a.done_edge, 14u + 2 + 3 * 14);
    EXPECT_EQ(r.checker.total(), 0u);
}

TEST(emif_arbitration, edma_bursts_run_in_submission_order) {
    rig r;
    request first(requester::edma, false, 0xB0000000, 3);
    request second(requester::edma, false, 0xB0000100, 2);
    ASSERT_TRUE(r.engine.submit(first.a));
    ASSERT_TRUE(r.engine.submit(second.a));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    EXPECT_EQ(first.a.done_edge, 42u);
    EXPECT_EQ(second.a.grant_edge, 42u);  // same CE and direction: no TA
    EXPECT_EQ(second.a.done_edge, 70u);
    EXPECT_EQ(second.word(1), 0x33000041u);
}

TEST(emif_arbitration, refresh_takes_the_bus_at_the_next_word_boundary) {
    // Refresh every 100 ECLK (due at 100, 200, 300), 7 cycles each.
    rig r(100);
    request dma(requester::edma, false, 0xB0000000, 20);
    ASSERT_TRUE(r.engine.submit(dma.a));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    // Due at 100, word 7 ends at 112: TA 112..114, refresh 114..121, TA, word 8 at 123.
    // Due at 200, word 13 ends at 207: TA, refresh 209..216, TA, word 14 at 218;
    // words 14..19 end at 218 + 6 x 14 = 302, then the third refresh 304..311.
    EXPECT_EQ(dma.a.done_edge, 302u);
    EXPECT_EQ(dma.a.done_edge, 20u * 14 + 2 * (2 + 7 + 2));
    EXPECT_EQ(r.engine.stats().refreshes, 3u);
    EXPECT_EQ(r.engine.next_edge(), 312u);  // idle right after the third refresh
    for (uint32_t i = 0; i < 20; ++i) EXPECT_EQ(dma.word(i), 0x33000000u + i);
    EXPECT_EQ(r.checker.total(), 0u);
}

TEST(emif_arbitration, refresh_wins_over_a_waiting_cpu_word) {
    rig r(100);
    request dma(requester::edma, false, 0xB0000000, 20);
    ASSERT_TRUE(r.engine.submit(dma.a));
    r.run_to(100);
    request cpu(requester::cpu, false, 0xA0000000, 1);
    ASSERT_TRUE(r.engine.submit(cpu.a));  // eligible at 100, with the refresh
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    // Word 7 ends at 112: refresh 114..121 (after TA); the CPU wins at 121:
    // TA, read 123..137; TA, burst word 8 at 139.
    EXPECT_EQ(cpu.a.grant_edge, 121u);
    EXPECT_EQ(cpu.a.done_edge, 137u);
    EXPECT_EQ(cpu.a.done_edge - cpu.a.eligible_edge, 12u + 2 + 7 + 2 + 14);
    // Words 8..12 from 139 end at 209; the refresh due at 200 goes at 209:
    // TA, 211..218, TA, words 13..18 from 220 end at 304, where the refresh
    // due at 300 goes (+11); word 19 ends at 304 + 11 + 14 = 329.
    EXPECT_EQ(dma.a.done_edge, 329u);
    EXPECT_EQ(r.checker.total(), 0u);
}

TEST(emif_arbitration, sdram_burst_in_chunks_and_a_cpu_word_between_them) {
    rig r;
    // 100 words to CE0 from SDRAM offset 0x400: chunks 32, 32, 32, 4.
    request dma(requester::edma, false, 0x80000400, 100);
    ASSERT_TRUE(r.engine.submit(dma.a));
    r.run_to(5);
    request cpu(requester::cpu, false, 0xA0000004, 1);
    ASSERT_TRUE(r.engine.submit(cpu.a));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    // Chunk 0: 7 + 16 = 0..23. CPU: TA 23..25, read 25..39. TA 39..41, chunk 1
    // reopens the row: 7 + 16 = 41..64; chunk 2 continues: 16 -> 80; chunk 3: 2 -> 82.
    EXPECT_EQ(cpu.a.grant_edge, 23u);
    EXPECT_EQ(cpu.a.done_edge, 39u);
    EXPECT_EQ(dma.a.done_edge, 82u);
    EXPECT_EQ(cpu.word(0), 0x22000001u);
    for (size_t i = 0; i < 400; ++i) ASSERT_EQ(dma.data[i], r.sdram[0x400 + i]) << i;
    // Alone, the same burst takes 7 + 50 = 57 ECLK.
    rig alone;
    request solo(requester::edma, false, 0x80000400, 100);
    ASSERT_TRUE(alone.engine.submit(solo.a));
    ASSERT_TRUE(alone.loop.run_until_idle(1000));
    EXPECT_EQ(solo.a.done_edge, 57u);
    EXPECT_EQ(r.checker.total(), 0u);
    std::printf("SDRAM 100-word burst: %llu ECLK alone, %llu with one CPU word in between\n",
                (unsigned long long)solo.a.done_edge, (unsigned long long)dma.a.done_edge);
}

TEST(emif_arbitration, sdram_write_lands_in_the_backing_store) {
    rig r;
    request w(requester::cpu, true, 0x80000010, 3);
    for (size_t i = 0; i < w.data.size(); ++i) w.data[i] = static_cast<uint8_t>(0xC0 + i);
    ASSERT_TRUE(r.engine.submit(w.a));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    EXPECT_EQ(w.a.done_edge, 7u + 2);  // ceil(3 / 2) data cycles
    for (size_t i = 0; i < w.data.size(); ++i) EXPECT_EQ(r.sdram[0x10 + i], 0xC0 + i);
}

TEST(emif_arbitration, busy_time_accounts_for_every_edge_of_a_mixed_load) {
    rig r(1560);  // the DSK's refresh period at 100 MHz
    request line_l(requester::edma, false, 0xB0000000, 160, false);  // one VGA line, left port
    request line_r(requester::edma, false, 0xB0100000, 160, false);  // and right port
    request store(requester::edma, true, 0x80001000, 320);           // both to SDRAM
    ASSERT_TRUE(r.engine.submit(line_l.a));
    ASSERT_TRUE(r.engine.submit(line_r.a));
    ASSERT_TRUE(r.engine.submit(store.a));
    ASSERT_TRUE(r.loop.run_until_idle(100000));
    const emif_stats& s = r.engine.stats();
    // 320 card words + TA to SDRAM + 10 chunks of 32 words (7 + 16, then 16 each)
    // + the refreshes due on the way, each with TA around it while on the card.
    EXPECT_EQ(s.words[1], 640u);
    EXPECT_EQ(s.accesses[1], 3u);
    EXPECT_EQ(s.refreshes, 2u);  // due at 1560 and 3120
    // Refresh at 1560: word 111 of line L ends at 1568: TA, 1570..1577, TA, resume at 1579.
    // Line L ends at 1579 + 48 x 14 = 2251; line R (other port, same CE3): 2251 + 2240 = 4491,
    // but the refresh due at 3120 goes at word boundary 3123: +11 -> 4502; TA, SDRAM
    // 4504 + 7 + 160 = 4671.
    EXPECT_EQ(line_l.a.done_edge, 2251u);
    EXPECT_EQ(line_r.a.done_edge, 4502u);
    EXPECT_EQ(store.a.done_edge, 4671u);
    EXPECT_EQ(s.busy_edges, 4671u);
    EXPECT_EQ(s.turnaround_edges, 5u * 2);
    EXPECT_EQ(r.checker.total(), 0u);
    std::printf(
        "two VGA lines from the card + store to SDRAM: %llu ECLK busy (%.2f us), "
        "%llu refreshes, %llu TA edges\n",
        (unsigned long long)s.busy_edges, s.busy_edges / 100.0, (unsigned long long)s.refreshes,
        (unsigned long long)s.turnaround_edges);
}
