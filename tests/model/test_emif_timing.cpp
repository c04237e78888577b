// The EMIF engine's async cycle, counted in ECLK edges against the closed
// form of the CECTL fields (docs/hardware-facts.md section 3): CECTL decoding of
// the DSK values, setup/strobe/hold at the pins, RS + RST + RH per read and
// WS + WST + WH per write, TA between directions and between CE spaces,
// back-to-back words, at 0x22A28A22 (DSK v1), 0x23228C22 (v2/v3), a value
// with every field different (WRHLDMSB set) and the all-zero fields (ASSUMED:
// 0 acts as 1). Every run also goes through the protocol checker, which must
// stay silent. Ends with one VGA frame read as one EDMA burst (10.752 ms).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "model/emif/emif_async_master.h"
#include "model/emif/emif_checker.h"
#include "model/emif/emif_pin_loop.h"
#include "tests/support/emif/async_sram_slave.h"

using namespace emif;

namespace {

// Hand-computed: WS=3 WST=5 WH=5 (WRHLD 01 + WRHLDMSB) RS=1 TA=3 RST=5 ASYNC32 RH=6.
constexpr uint32_t cectl_mixed = 0x3151C52E;
// Every timing field 0, MTYPE ASYNC32.
constexpr uint32_t cectl_zero = 0x00000020;

// Records the pins of every edge and forwards them to the checker.
struct recorder : emif_pin_observer {
    std::vector<emif_pins> at;
    emif_checker* checker = nullptr;
    void observe(uint64_t edge, const emif_pins& p, const emif_inputs& in) override {
        if (at.size() <= edge) at.resize(edge + 1);
        at[edge] = p;
        if (checker) checker->observe(edge, p, in);
    }
};

struct bus {
    emif_config cfg;
    emif_async_master engine;
    async_sram_slave ce2, ce3;
    emif_checker checker;
    recorder trace;
    emif_pin_loop loop;

    static emif_config make_config(uint32_t cectl) {
        emif_config c;
        c.cectl[2] = c.cectl[3] = cectl;
        c.sdram.refresh_period = 0;  // no refresh: pure async timing
        return c;
    }
    explicit bus(uint32_t cectl, uint32_t read_latency = 2)
        : cfg(make_config(cectl)),
          engine(cfg),
          ce2(sram_config{2, 4096, read_latency, true}),
          ce3(sram_config{3, 4096, read_latency, true}),
          checker(cfg.cectl),
          loop(engine) {
        trace.checker = &checker;
        engine.set_observer(&trace);
        loop.attach(2, &ce2);
        loop.attach(3, &ce3);
    }
};

// Phases of the access whose setup starts at or after edge `from` on CE `ce`,
// measured on the recorded pins.
struct phases {
    int64_t setup = -1, strobe = -1, hold = -1;
    uint64_t setup_edge = 0, end_edge = 0;
};
phases measure(const std::vector<emif_pins>& at, uint64_t from, int ce) {
    phases m;
    uint64_t c = from;
    while (c < at.size() && at[c].ce_n[ce]) ++c;
    // The select of a back-to-back word starts where the previous hold ended:
    // the caller passes that edge as `from` when CE stays low.
    m.setup_edge = c;
    uint64_t s = c;
    while (s < at.size() && at[s].are_n && at[s].awe_n) ++s;
    uint64_t r = s;
    while (r < at.size() && !(at[r].are_n && at[r].awe_n)) ++r;
    uint64_t h = r;
    const emif_pins& ref = at[r - 1];
    while (h < at.size() && !at[h].ce_n[ce] && at[h].ea == ref.ea && at[h].aoe_n == ref.aoe_n &&
           at[h].ed_oe == ref.ed_oe && at[h].are_n && at[h].awe_n)
        ++h;
    m.setup = static_cast<int64_t>(s - c);
    m.strobe = static_cast<int64_t>(r - s);
    m.hold = static_cast<int64_t>(h - r);
    m.end_edge = h;
    return m;
}

emif_access single(bool write, uint32_t address, uint8_t* data, requester who = requester::cpu) {
    emif_access a;
    a.who = who;
    a.write = write;
    a.address = address;
    a.words = 1;
    a.data = data;
    return a;
}

void expect_checker_clean(const emif_checker& c) {
    EXPECT_EQ(c.total(), 0u);
    for (const violation& v : c.violations()) ADD_FAILURE() << to_string(v);
}

}  // namespace

TEST(emif_cectl, decodes_the_dsk_values_as_the_fact_sheet_lists_them) {
    // docs/hardware-facts.md section 3: 0x22A28A22 = WS=2 WST=10 WH=2 RS=2 TA=2 RST=10 ASYNC32
    // RH=2.
    const async_timing v1 = decode_cectl(cectl_dsk_v1);
    EXPECT_EQ(v1.write_setup, 2u);
    EXPECT_EQ(v1.write_strobe, 10u);
    EXPECT_EQ(v1.write_hold, 2u);
    EXPECT_EQ(v1.read_setup, 2u);
    EXPECT_EQ(v1.turnaround, 2u);
    EXPECT_EQ(v1.read_strobe, 10u);
    EXPECT_EQ(v1.read_hold, 2u);
    EXPECT_EQ(v1.type, memory_type::async32);
    EXPECT_EQ(v1.read_cycles(), 14u);
    // 0x23228C22 = WS=2 WST=12 WH=2 RS=2 TA=2 RST=12 ASYNC32 RH=2.
    const async_timing v2 = decode_cectl(cectl_dsk_v2);
    EXPECT_EQ(v2.write_strobe, 12u);
    EXPECT_EQ(v2.read_strobe, 12u);
    EXPECT_EQ(v2.write_setup + v2.write_hold + v2.read_setup + v2.read_hold + v2.turnaround, 10u);
    EXPECT_EQ(v2.read_cycles(), 16u);
    // 0x02208800 (EMIFB CPLD/Flash at 100 MHz): WS=0 WST=8 WH=2 RS=0 TA=2 RST=8 ASYNC8 RH=0.
    const cectl_fields b = cectl_unpack(0x02208800);
    EXPECT_EQ(b.wrsetup, 0u);
    EXPECT_EQ(b.wrstrb, 8u);
    EXPECT_EQ(b.wrhld, 2u);
    EXPECT_EQ(b.rdsetup, 0u);
    EXPECT_EQ(b.ta, 2u);
    EXPECT_EQ(b.rdstrb, 8u);
    EXPECT_EQ(b.mtype, 0u);
    EXPECT_EQ(b.rdhld, 0u);
    EXPECT_EQ(decode_cectl(cectl_sdram_dsk).type, memory_type::sdram64);  // MTYPE 1101
    // The reset defaults of every field (0xF, 0x3F, 3, 0xF, 3, 0x3F, 0, 3).
    const cectl_fields r = cectl_unpack(cectl_reset);
    EXPECT_EQ(r.wrsetup, 15u);
    EXPECT_EQ(r.wrstrb, 63u);
    EXPECT_EQ(r.wrhld, 3u);
    EXPECT_EQ(r.rdsetup, 15u);
    EXPECT_EQ(r.ta, 3u);
    EXPECT_EQ(r.rdstrb, 63u);
    EXPECT_EQ(r.mtype, 0u);
    EXPECT_EQ(r.rdhld, 3u);
}

TEST(emif_cectl, wrhldmsb_is_the_third_hold_bit_and_zero_fields_act_as_one) {
    const async_timing m = decode_cectl(cectl_mixed);
    EXPECT_EQ(m.write_setup, 3u);
    EXPECT_EQ(m.write_strobe, 5u);
    EXPECT_EQ(m.write_hold, 5u);  // bits 21:20 = 01, bit 3 = 1
    EXPECT_EQ(m.read_setup, 1u);
    EXPECT_EQ(m.turnaround, 3u);
    EXPECT_EQ(m.read_strobe, 5u);
    EXPECT_EQ(m.read_hold, 6u);
    EXPECT_EQ(decode_cectl(cectl_mixed & ~0x8u).write_hold, 1u);
    const async_timing z = decode_cectl(cectl_zero);
    EXPECT_EQ(z.read_cycles(), 3u);
    EXPECT_EQ(z.write_cycles(), 3u);
    EXPECT_EQ(z.turnaround, 1u);
    // Every bit belongs to one field: pack(unpack(v)) == v.
    std::mt19937 rng(5);
    for (int i = 0; i < 10000; ++i) {
        const uint32_t v = rng();
        ASSERT_EQ(cectl_pack(cectl_unpack(v)), v) << std::hex << v;
    }
}

// RS + RST + RH per read, WS + WST + WH per write, each phase at the pins.
class emif_cycle_counts : public ::testing::TestWithParam<uint32_t> {};

TEST_P(emif_cycle_counts, single_read_and_single_write_take_setup_strobe_hold) {
    const uint32_t cectl = GetParam();
    const async_timing t = decode_cectl(cectl);
    bus b(cectl, cectl == cectl_zero ? 0 : 2);
    b.ce2.word(0x40) = 0xCAFEF00D;
    uint8_t rd[4] = {}, wr[4] = {0x11, 0x22, 0x33, 0x44};
    emif_access r = single(false, 0xA0000100, rd);
    ASSERT_TRUE(b.engine.submit(r));
    ASSERT_TRUE(b.loop.run_until_idle(1000));
    EXPECT_EQ(r.done_edge - r.grant_edge, t.read_cycles());
    EXPECT_EQ(r.wait_cycles, 0u);
    EXPECT_EQ(rd[0] | rd[1] << 8 | rd[2] << 16 | uint32_t(rd[3]) << 24, 0xCAFEF00Du);
    const phases pr = measure(b.trace.at, r.grant_edge, 2);
    EXPECT_EQ(pr.setup_edge, r.grant_edge);
    EXPECT_EQ(pr.setup, t.read_setup);
    EXPECT_EQ(pr.strobe, t.read_strobe);
    EXPECT_EQ(pr.hold, t.read_hold);
    EXPECT_EQ(b.trace.at[pr.setup_edge].ea, 0x40u);

    b.loop.run(10);  // idle longer than any TA: no turnaround
    emif_access w = single(true, 0xA0000104, wr);
    ASSERT_TRUE(b.engine.submit(w));
    ASSERT_TRUE(b.loop.run_until_idle(1000));
    EXPECT_EQ(w.done_edge - w.grant_edge, t.write_cycles());
    EXPECT_EQ(w.turnaround_cycles, 0u);
    const phases pw = measure(b.trace.at, w.grant_edge, 2);
    EXPECT_EQ(pw.setup, t.write_setup);
    EXPECT_EQ(pw.strobe, t.write_strobe);
    EXPECT_EQ(pw.hold, t.write_hold);
    EXPECT_EQ(b.ce2.word(0x41), 0x44332211u);
    std::printf("CECTL 0x%08X: read %lld+%lld+%lld = %llu ECLK, write %lld+%lld+%lld = %llu ECLK\n",
                cectl, (long long)pr.setup, (long long)pr.strobe, (long long)pr.hold,
                (unsigned long long)(r.done_edge - r.grant_edge), (long long)pw.setup,
                (long long)pw.strobe, (long long)pw.hold,
                (unsigned long long)(w.done_edge - w.grant_edge));
    expect_checker_clean(b.checker);
}

TEST_P(emif_cycle_counts, turnaround_between_directions_and_between_ce_spaces) {
    const uint32_t cectl = GetParam();
    const async_timing t = decode_cectl(cectl);
    bus b(cectl, cectl == cectl_zero ? 0 : 2);
    uint8_t buf[6][4] = {};
    // Queued together: read CE2, write CE2 (direction change), write CE2
    // (same: back to back), read CE3 (CE and direction change), read CE3.
    emif_access a[5] = {single(false, 0xA0000000, buf[0]), single(true, 0xA0000004, buf[1]),
                        single(true, 0xA0000008, buf[2]), single(false, 0xB0000000, buf[3]),
                        single(false, 0xB0000000, buf[4])};
    for (auto& x : a) ASSERT_TRUE(b.engine.submit(x));
    ASSERT_TRUE(b.loop.run_until_idle(1000));
    const uint64_t ta = t.turnaround, rd = t.read_cycles(), wr = t.write_cycles();
    EXPECT_EQ(a[0].done_edge - a[0].grant_edge, rd);
    EXPECT_EQ(a[1].done_edge - a[0].done_edge, ta + wr);
    EXPECT_EQ(a[1].turnaround_cycles, ta);
    EXPECT_EQ(a[2].done_edge - a[1].done_edge, wr);
    EXPECT_EQ(a[2].turnaround_cycles, 0u);
    EXPECT_EQ(a[3].done_edge - a[2].done_edge, ta + rd);
    EXPECT_EQ(a[4].done_edge - a[3].done_edge, rd);
    const uint64_t total = a[4].done_edge - a[0].grant_edge;
    EXPECT_EQ(total, 3 * rd + 2 * wr + 2 * ta);
    // During TA no CE is low.
    for (uint64_t e = a[0].done_edge; e < a[0].done_edge + ta; ++e)
        EXPECT_EQ(b.trace.at[e].active_ce(), -1) << e;
    std::printf(
        "CECTL 0x%08X: R W W (CE2) R R (CE3) = %llu ECLK (3 x %llu + 2 x %llu + 2 TA x %llu)\n",
        cectl, (unsigned long long)total, (unsigned long long)rd, (unsigned long long)wr,
        (unsigned long long)ta);
    expect_checker_clean(b.checker);
}

TEST_P(emif_cycle_counts, burst_words_follow_each_other_with_ce_held_low) {
    const uint32_t cectl = GetParam();
    const async_timing t = decode_cectl(cectl);
    bus b(cectl, cectl == cectl_zero ? 0 : 2);
    for (uint32_t i = 0; i < 64; ++i) b.ce3.word(i) = 0x1000u + i;
    std::vector<uint8_t> data(4 * 40);
    emif_access burst;
    burst.who = requester::edma;
    burst.address = 0xB0000000;
    burst.words = 40;
    burst.data = data.data();
    ASSERT_TRUE(b.engine.submit(burst));
    ASSERT_TRUE(b.loop.run_until_idle(10000));
    EXPECT_EQ(burst.done_edge - burst.grant_edge, 40ull * t.read_cycles());
    for (uint32_t i = 0; i < 40; ++i) {
        const uint32_t w = data[4 * i] | data[4 * i + 1] << 8 | data[4 * i + 2] << 16 |
                           uint32_t(data[4 * i + 3]) << 24;
        EXPECT_EQ(w, 0x1000u + i);
    }
    for (uint64_t e = burst.grant_edge; e < burst.done_edge; ++e)
        ASSERT_FALSE(b.trace.at[e].ce_n[3]) << "CE3 rose inside the burst at " << e;
    expect_checker_clean(b.checker);
}

INSTANTIATE_TEST_SUITE_P(cectl, emif_cycle_counts,
                         ::testing::Values(cectl_dsk_v1, cectl_dsk_v2, cectl_mixed, cectl_zero),
                         [](const ::testing::TestParamInfo<uint32_t>& i) {
                             char name[16];
                             std::snprintf(name, sizeof name, "x%08X", i.param);
                             return std::string(name);
                         });

TEST(emif_engine, one_vga_frame_over_the_dsk_v1_setting_takes_10_752_ms) {
    // 640 x 480 8-bit pixels = 76,800 words from the left pixel port (fixed
    // address), one EDMA burst: 76,800 x 14 ECLK at 100 MHz (docs/design-brief.md: ~10.8 ms).
    bus b(cectl_dsk_v1);
    constexpr uint32_t words = 640 * 480 / 4;
    std::vector<uint8_t> frame(4 * words);
    emif_access burst;
    burst.who = requester::edma;
    burst.address = 0xB0000000;
    burst.words = words;
    burst.increment = false;
    burst.data = frame.data();
    b.engine.set_observer(nullptr);  // speed: no trace of a million edges
    ASSERT_TRUE(b.engine.submit(burst));
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_TRUE(b.loop.run_until_idle(2000000));
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const uint64_t edges = burst.done_edge - burst.grant_edge;
    EXPECT_EQ(edges, uint64_t{words} * 14);
    const double ms = static_cast<double>(b.engine.edge_tick(edges)) / 18e6;
    EXPECT_DOUBLE_EQ(ms, 10.752);
    EXPECT_EQ(b.ce3.reads(), words);
    std::printf(
        "VGA frame: %u words, %llu ECLK = %.3f ms at 100 MHz, %.2f MB/s; engine+SRAM %.1f M "
        "edges/s\n",
        words, (unsigned long long)edges, ms, 4.0 * words / (ms * 1e3),
        static_cast<double>(edges) / wall / 1e6);
    RecordProperty("vga_frame_ms", std::to_string(ms));
}
