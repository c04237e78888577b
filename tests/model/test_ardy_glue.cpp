// The board glue's wait states (model/emif/ardy_glue.h, the emif-wait fault)
// against the real EMIF engine and an SRAM slave on CE2 / CE3: the DSP's
// ARDY is held low on the pins for exactly N ECLK at the end of every strobe
// on the faulted space, from the arming time on, and the engine stretches
// each word by exactly N edges. The golden is the engine's own closed form
// (RST + N per word, docs/emif.md) and, independently, the engine's internal
// wait-state hook: both must give the same edge for every word.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "model/emif/ardy_glue.h"
#include "model/emif/cectl.h"
#include "model/emif/emif_async_master.h"
#include "tests/support/emif/async_sram_slave.h"

using namespace emif;

namespace {

struct glue_rig {
    emif_config cfg;
    emif_async_master engine;
    async_sram_slave ce2, ce3;
    ardy_glue glue;
    uint64_t edges = 0, ardy_low_edges = 0, card_ardy_low_edges = 0;

    static emif_config make() {
        emif_config c;
        c.cectl[2] = c.cectl[3] = cectl_dsk_v1;  // RS 2, RST 10, RH 2: 14 ECLK a word
        c.ardy_lead = 1;
        c.sdram.refresh_period = 0;
        return c;
    }
    glue_rig()
        : cfg(make()),
          engine(cfg),
          ce2(sram_config{2, 1024, 2, true}),
          ce3(sram_config{3, 1024, 2, true}) {
        for (uint32_t i = 0; i < 1024; ++i) ce2.word(i) = ce3.word(i) = 0xC0DE0000u | i;
    }
    // One edge in the islands' order: the slave's outputs before the edge,
    // ARDY through the glue, then the glue's and slave's flops, then the engine.
    void step() {
        const emif_pins pins = engine.pins();
        const int ce = pins.active_ce();
        async_sram_slave* slave = ce == 2 ? &ce2 : ce == 3 ? &ce3 : nullptr;
        emif_inputs in;
        if (slave) in = slave->outputs(pins);
        const bool card_ardy = in.ardy;
        in.ardy = glue.bus_ardy(pins, card_ardy, engine);
        ardy_low_edges += !in.ardy;
        card_ardy_low_edges += !card_ardy;
        glue.clock(pins, engine.edge_tick(engine.next_edge()));
        ce2.eclk_edge(pins);
        ce3.eclk_edge(pins);
        engine.step(in);
        ++edges;
    }
    void run_until_idle() {
        for (int n = 0; n < 100000 && !engine.idle(); ++n) step();
    }
};

emif_access burst(uint32_t address, uint32_t words, std::vector<uint8_t>& data) {
    data.assign(4 * words, 0);
    emif_access a;
    a.who = requester::edma;
    a.address = address;
    a.words = words;
    a.data = data.data();
    return a;
}

}  // namespace

TEST(ardy_glue, holds_ardy_low_n_cycles_per_word_on_the_faulted_space_only) {
    for (uint32_t extra : {1u, 3u, 40u}) {
        glue_rig r;
        ardy_fault f;
        f.ce = 3;
        f.extra_cycles = extra;
        r.glue.add(f);
        std::vector<uint8_t> d3, d2;
        emif_access a = burst(0xB0000000, 10, d3);
        ASSERT_TRUE(r.engine.submit(a));
        r.run_until_idle();
        EXPECT_EQ(a.done_edge - a.grant_edge, 10u * (14 + extra)) << extra;
        EXPECT_EQ(a.wait_cycles, 10u * extra);
        // The DSP saw ARDY low exactly N edges a word; the slave's own ARDY
        // (data ready 2 edges into a 10-edge strobe) never stretched it.
        EXPECT_EQ(r.ardy_low_edges - r.card_ardy_low_edges, 10u * extra);
        for (uint32_t i = 0; i < 10; ++i)
            EXPECT_EQ(d3[4 * i] | d3[4 * i + 1] << 8, static_cast<int>(i));
        // CE2 (registers) is untouched.
        emif_access b = burst(0xA0000000, 4, d2);
        ASSERT_TRUE(r.engine.submit(b));
        r.run_until_idle();
        EXPECT_EQ(b.wait_cycles, 0u);
    }
}

TEST(ardy_glue, equals_the_engine_hook_edge_for_edge) {
    // Reference: the engine's internal hook, the same N on the same space.
    const uint32_t extra = 5;
    glue_rig hook, glued;
    ardy_fault f;
    f.ce = 3;
    f.extra_cycles = extra;
    hook.engine.set_ardy_fault(f);
    glued.glue.add(f);
    std::vector<uint8_t> d1, d2;
    emif_access a = burst(0xB0000000, 30, d1), b = burst(0xB0000000, 30, d2);
    ASSERT_TRUE(hook.engine.submit(a));
    ASSERT_TRUE(glued.engine.submit(b));
    hook.run_until_idle();
    glued.run_until_idle();
    EXPECT_EQ(a.done_edge, b.done_edge);
    EXPECT_EQ(a.wait_cycles, b.wait_cycles);
    EXPECT_EQ(b.wait_cycles, 30u * extra);
}

TEST(ardy_glue, arms_at_its_time) {
    const uint32_t extra = 5;
    glue_rig r;
    ardy_fault f;
    f.ce = 3;
    f.extra_cycles = extra;
    f.from_tick = r.engine.edge_tick(200);
    r.glue.add(f);
    std::vector<uint8_t> d;
    emif_access a = burst(0xB0000000, 30, d);
    ASSERT_TRUE(r.engine.submit(a));
    r.run_until_idle();
    // Words whose strobe ended by edge ~200 ran at 14 ECLK (200 / 14 = 14
    // words), every later one at 14 + 5.
    EXPECT_EQ(a.wait_cycles % extra, 0u);
    const uint64_t slowed = a.wait_cycles / extra;
    EXPECT_GE(slowed, 15u);
    EXPECT_LE(slowed, 16u);
    std::printf("30 words, +%u from edge 200: %llu words slowed, done at edge %llu\n", extra,
                (unsigned long long)slowed, (unsigned long long)a.done_edge);
}
