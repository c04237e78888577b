// ARDY wait states and the fault hook, counted in ECLK edges.
//
// The sample point (ASSUMED, as the card expects it): the strobe ends at the
// first edge E >= S + RST at which ARDY sampled at edge E - ardy_lead was
// high. A slave whose read data is ready `L` edges after the first edge that
// sees ARE low (counting that one) releases ARDY after edge S + L, so the
// closed form is strobe = max(RST, L + 1 + ardy_lead); the test sweeps L,
// ardy_lead and RST. The fault hook holds ARDY low N more cycles on one CE
// space, from an access count or from a time: exactly N more edges per
// affected word, none elsewhere. The checker stays silent (a longer strobe
// is legal).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "model/emif/emif_async_master.h"
#include "model/emif/emif_checker.h"
#include "model/emif/emif_pin_loop.h"
#include "tests/support/emif/async_sram_slave.h"

using namespace emif;

namespace {

// CECTL with RS = RH = WS = WH = 2, TA 2, ASYNC32 and the given read strobe.
uint32_t cectl_with_read_strobe(uint32_t rst) {
    cectl_fields f = cectl_unpack(cectl_dsk_v1);
    f.rdstrb = rst;
    return cectl_pack(f);
}

// Per-word strobe lengths seen at the pins.
struct strobe_meter : emif_pin_observer {
    emif_checker* checker = nullptr;
    std::vector<uint64_t> strobe_lengths, strobe_starts;
    bool low = false;
    uint64_t start = 0;
    void observe(uint64_t e, const emif_pins& p, const emif_inputs& in) override {
        const bool now_low = !p.are_n || !p.awe_n;
        if (now_low && !low) start = e;
        if (!now_low && low) {
            strobe_lengths.push_back(e - start);
            strobe_starts.push_back(start);
        }
        low = now_low;
        if (checker) checker->observe(e, p, in);
    }
};

struct rig {
    emif_config cfg;
    emif_async_master engine;
    async_sram_slave ce2, ce3;
    emif_checker checker;
    strobe_meter meter;
    emif_pin_loop loop;

    static emif_config make(uint32_t cectl, uint32_t lead) {
        emif_config c;
        c.cectl[2] = c.cectl[3] = cectl;
        c.ardy_lead = lead;
        c.sdram.refresh_period = 0;
        return c;
    }
    rig(uint32_t cectl, uint32_t lead, uint32_t latency)
        : cfg(make(cectl, lead)),
          engine(cfg),
          ce2(sram_config{2, 1024, latency, true}),
          ce3(sram_config{3, 1024, latency, true}),
          checker(cfg.cectl),
          loop(engine) {
        meter.checker = &checker;
        engine.set_observer(&meter);
        loop.attach(2, &ce2);
        loop.attach(3, &ce3);
        for (uint32_t i = 0; i < 1024; ++i) ce2.word(i) = ce3.word(i) = 0xA5000000u | i;
    }
};

uint32_t word_at(const std::vector<uint8_t>& d, size_t i) {
    return d[4 * i] | d[4 * i + 1] << 8 | d[4 * i + 2] << 16 | uint32_t(d[4 * i + 3]) << 24;
}

emif_access burst(uint32_t address, uint32_t words, std::vector<uint8_t>& data,
                  requester who = requester::edma) {
    data.assign(4 * words, 0);
    emif_access a;
    a.who = who;
    a.address = address;
    a.words = words;
    a.data = data.data();
    return a;
}

}  // namespace

TEST(emif_ardy, strobe_is_max_of_programmed_and_slave_ready_plus_sample_lead) {
    int cases = 0;
    for (uint32_t latency = 1; latency <= 3; ++latency) {
        for (uint32_t lead = 0; lead <= 2; ++lead) {
            for (uint32_t rst = 1; rst <= 7; ++rst) {
                rig r(cectl_with_read_strobe(rst), lead, latency);
                std::vector<uint8_t> data;
                emif_access a = burst(0xA0000040, 3, data);
                ASSERT_TRUE(r.engine.submit(a));
                ASSERT_TRUE(r.loop.run_until_idle(1000));
                const uint32_t expected = std::max(rst, latency + 1 + lead);
                ASSERT_EQ(r.meter.strobe_lengths.size(), 3u);
                for (uint64_t len : r.meter.strobe_lengths)
                    EXPECT_EQ(len, expected)
                        << "L=" << latency << " lead=" << lead << " RST=" << rst;
                EXPECT_EQ(a.wait_cycles, 3 * (expected - rst));
                EXPECT_EQ(a.done_edge - a.grant_edge, 3ull * (2 + expected + 2));
                for (uint32_t i = 0; i < 3; ++i) EXPECT_EQ(word_at(data, i), 0xA5000010u + i);
                EXPECT_EQ(r.checker.total(), 0u);
                ++cases;
            }
        }
    }
    // The card's case (L = 2, lead 1): strobes of 1..3 cycles stretch to 4.
    std::printf("%d (latency, lead, RST) cases; card-like slave (L=2, lead 1): min strobe 4 ECLK\n",
                cases);
}

TEST(emif_ardy, writes_are_not_stretched_by_a_read_only_ardy) {
    rig r(cectl_dsk_v1, 1, 3);
    std::vector<uint8_t> data(4 * 4, 0x5A);
    emif_access a;
    a.who = requester::edma;
    a.write = true;
    a.address = 0xA0000000;
    a.words = 4;
    a.data = data.data();
    ASSERT_TRUE(r.engine.submit(a));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    EXPECT_EQ(a.done_edge - a.grant_edge, 4u * 14);
    EXPECT_EQ(a.wait_cycles, 0u);
    EXPECT_EQ(r.ce2.word(3), 0x5A5A5A5Au);
}

TEST(emif_fault, extra_wait_states_from_the_nth_access_on_the_card_space) {
    rig r(cectl_dsk_v1, 1, 2);
    ardy_fault f;
    f.ce = 3;
    f.extra_cycles = 3;
    f.from_access = 5;
    r.engine.set_ardy_fault(f);
    std::vector<uint8_t> d3, d2;
    emif_access a = burst(0xB0000000, 10, d3);
    ASSERT_TRUE(r.engine.submit(a));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    // Words 0..4 take 14 ECLK, words 5..9 take 14 + 3.
    EXPECT_EQ(a.done_edge - a.grant_edge, 5u * 14 + 5u * 17);
    EXPECT_EQ(a.wait_cycles, 15u);
    for (size_t i = 0; i < 10; ++i) EXPECT_EQ(r.meter.strobe_lengths[i], i < 5 ? 10u : 13u) << i;
    for (uint32_t i = 0; i < 10; ++i) EXPECT_EQ(word_at(d3, i), 0xA5000000u + i);
    // CE2 is not affected. Queued one edge after the CE3 burst ended, so
    // 1 of the 2 TA cycles is still to run.
    emif_access b = burst(0xA0000000, 4, d2);
    ASSERT_TRUE(r.engine.submit(b));
    ASSERT_TRUE(r.loop.run_until_idle(1000));
    EXPECT_EQ(b.turnaround_cycles, 1u);
    EXPECT_EQ(b.done_edge - b.grant_edge, 1u + 4u * 14);
    EXPECT_EQ(b.wait_cycles, 0u);
    EXPECT_EQ(r.checker.total(), 0u);
    std::printf("fault +3 from access 5 on CE3: 10-word burst %llu ECLK (fault-free 140)\n",
                (unsigned long long)(a.done_edge - a.grant_edge));
}

TEST(emif_fault, limited_count_and_time_trigger) {
    {
        rig r(cectl_dsk_v1, 1, 2);
        ardy_fault f;
        f.ce = 3;
        f.extra_cycles = 6;
        f.from_access = 2;
        f.access_count = 2;  // words 2 and 3 only
        r.engine.set_ardy_fault(f);
        std::vector<uint8_t> d;
        emif_access a = burst(0xB0000000, 8, d);
        ASSERT_TRUE(r.engine.submit(a));
        ASSERT_TRUE(r.loop.run_until_idle(1000));
        EXPECT_EQ(a.done_edge - a.grant_edge, 8u * 14 + 2 * 6);
        EXPECT_EQ(r.meter.strobe_lengths[1], 10u);
        EXPECT_EQ(r.meter.strobe_lengths[2], 16u);
        EXPECT_EQ(r.meter.strobe_lengths[3], 16u);
        EXPECT_EQ(r.meter.strobe_lengths[4], 10u);
    }
    {
        // From a time: 100 MHz ECLK = 180 ticks per edge. A tick just after
        // edge 42 means the first word whose setup starts at edge >= 43: the
        // words start at 0, 14, 28, 42, 56, ... so words 4.. are slowed.
        rig r(cectl_dsk_v1, 1, 2);
        ardy_fault f;
        f.ce = 3;
        f.extra_cycles = 2;
        f.from_tick = 42 * 180 + 1;
        r.engine.set_ardy_fault(f);
        std::vector<uint8_t> d;
        emif_access a = burst(0xB0000000, 8, d);
        ASSERT_TRUE(r.engine.submit(a));
        ASSERT_TRUE(r.loop.run_until_idle(1000));
        EXPECT_EQ(a.done_edge - a.grant_edge, 8u * 14 + 4 * 2);
        for (size_t i = 0; i < 8; ++i) EXPECT_EQ(r.meter.strobe_lengths[i], i < 4 ? 10u : 12u) << i;
        r.engine.clear_ardy_faults();
        emif_access b = burst(0xB0000000, 2, d);
        ASSERT_TRUE(r.engine.submit(b));
        ASSERT_TRUE(r.loop.run_until_idle(1000));
        EXPECT_EQ(b.done_edge - b.grant_edge, 2u * 14);
        EXPECT_EQ(r.checker.total(), 0u);
    }
}
