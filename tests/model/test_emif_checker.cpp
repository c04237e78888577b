// The EMIF protocol checker: silent on everything the engine drives (a
// random mix of CPU, EDMA, SDRAM, refresh and ARDY faults at three CECTL
// values), firing on every strobe of an engine programmed shorter than the
// checker was told, and firing exactly the expected rule, with the expected
// cycle counts, on hand-written pin sequences: short setup / strobe / hold, back-to-back words too
// close, select change inside a strobe, ARE and AWE together, ED driven during a read, CE change
// and direction change without turnaround, two CEs at once, a strobe without CE.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <set>
#include <vector>

#include "model/emif/emif_async_master.h"
#include "model/emif/emif_checker.h"
#include "model/emif/emif_pin_loop.h"
#include "tests/support/emif/async_sram_slave.h"

using namespace emif;

namespace {

constexpr uint32_t cectl_mixed = 0x3151C52E;  // WS 3 WST 5 WH 5 RS 1 TA 3 RST 5 RH 6

// ---- engine-driven traffic -------------------------------------------------------------------

struct traffic_result {
    uint64_t violations = 0, strobes = 0, words = 0, bad_reads = 0;
    std::vector<violation> list;
};

// cectl with its read and write strobes `shorten` cycles shorter (at least
// 1): programmed into the engine while the checker is told cectl, every
// strobe the engine drives is too short, a violation made on the test side.
uint32_t with_shorter_strobes(uint32_t cectl, uint32_t shorten) {
    if (shorten == 0) return cectl;
    const auto shorter = [shorten](uint32_t raw) {
        const uint32_t cycles = raw == 0 ? 1 : raw;  // a field of 0 acts as 1
        return cycles > shorten ? cycles - shorten : 1;
    };
    cectl_fields f = cectl_unpack(cectl);
    f.rdstrb = shorter(f.rdstrb);
    f.wrstrb = shorter(f.wrstrb);
    return cectl_pack(f);
}

// Random accesses queued at random edges; reads come from a region no write touches.
traffic_result run_traffic(uint32_t cectl, uint32_t shorten, uint32_t seed, uint64_t edges,
                           bool ardy_fault_on = true) {
    emif_config cfg;
    cfg.cectl[2] = cfg.cectl[3] = cectl;
    cfg.sdram.refresh_period = 700;
    emif_config engine_cfg = cfg;
    engine_cfg.cectl[2] = engine_cfg.cectl[3] = with_shorter_strobes(cectl, shorten);
    emif_async_master engine(engine_cfg);
    async_sram_slave ce2(sram_config{2, 1024, 2, true}), ce3(sram_config{3, 1024, 2, true});
    for (uint32_t i = 0; i < 512; ++i) {
        ce2.word(i) = 0x20000000u + i * 3;
        ce3.word(i) = 0x30000000u + i * 5;
    }
    std::vector<uint8_t> sdram(1 << 14, 0);
    engine.set_sdram_storage(sdram.data(), sdram.size());
    emif_checker checker(cfg.cectl);
    engine.set_observer(&checker);
    ardy_fault f;
    f.ce = 2;
    f.extra_cycles = 2;
    f.from_access = 7;
    f.access_count = 5;
    if (ardy_fault_on) engine.set_ardy_fault(f);
    emif_pin_loop loop(engine);
    loop.attach(2, &ce2);
    loop.attach(3, &ce3);

    struct slot {
        emif_access a;
        std::vector<uint8_t> data;
        bool busy = false;
    };
    std::vector<slot> slots(12);
    std::mt19937 rng(seed);
    traffic_result out;
    auto check = [&](slot& s) {
        if (s.a.write || ce_of_address(s.a.address) == 0) return;
        const bool left = ce_of_address(s.a.address) == 2;
        for (uint32_t k = 0; k < s.a.words; ++k) {
            const uint32_t index = ((s.a.address >> 2) & 0x3FF) + (s.a.increment ? k : 0);
            const uint32_t expect = left ? 0x20000000u + index * 3 : 0x30000000u + index * 5;
            const uint8_t* d = &s.data[4 * k];
            if ((d[0] | d[1] << 8 | d[2] << 16 | uint32_t(d[3]) << 24) != expect) ++out.bad_reads;
        }
    };
    for (uint64_t e = 0; e < edges; ++e) {
        for (slot& s : slots) {
            if (s.busy && s.a.status == access_status::ok) {
                check(s);
                out.words += s.a.words;
                s.busy = false;
            }
        }
        if (rng() % 9 == 0) {
            for (slot& s : slots) {
                if (s.busy) continue;
                const int ce =
                    static_cast<int>(rng() % 3) == 0 ? 0 : 2 + static_cast<int>(rng() % 2);
                const bool edma = rng() % 2 == 0;
                s.a = emif_access{};
                s.a.who = edma ? requester::edma : requester::cpu;
                s.a.write = rng() % 3 == 0;
                s.a.words = edma ? 1 + rng() % 24 : 1;
                s.a.increment = rng() % 4 != 0;
                // Reads from words 0..255, writes to 512..767: reads stay checkable.
                const uint32_t base = s.a.write ? 512 : 0;
                s.a.address = ce_base(ce) + 4 * (base + rng() % 200);
                s.a.be_n = static_cast<uint8_t>(rng() % 16);
                s.data.assign(4 * s.a.words, static_cast<uint8_t>(rng()));
                s.a.data = s.data.data();
                if (!engine.submit(s.a)) ADD_FAILURE() << "rejected";
                s.busy = true;
                break;
            }
        }
        loop.step();
    }
    EXPECT_TRUE(loop.run_until_idle(100000));  // drain: every strobe ends
    for (slot& s : slots) {
        if (s.busy && s.a.status == access_status::ok) {
            check(s);
            out.words += s.a.words;
        }
    }
    out.violations = checker.total();
    out.strobes = checker.strobes_checked();
    out.list = checker.violations();
    return out;
}

// ---- hand-written pin sequences --------------------------------------------------------------

emif_pins idle() {
    return emif_pins{};
}
emif_pins read_select(int ce, uint32_t ea) {
    emif_pins p;
    p.ce_n[ce] = false;
    p.ea = ea;
    p.be_n = 0;
    p.aoe_n = false;
    return p;
}
emif_pins read_strobe(int ce, uint32_t ea) {
    emif_pins p = read_select(ce, ea);
    p.are_n = false;
    return p;
}
emif_pins write_select(int ce, uint32_t ea, uint32_t data) {
    emif_pins p;
    p.ce_n[ce] = false;
    p.ea = ea;
    p.be_n = 0;
    p.ed_out = data;
    p.ed_oe = true;
    return p;
}
emif_pins write_strobe(int ce, uint32_t ea, uint32_t data) {
    emif_pins p = write_select(ce, ea, data);
    p.awe_n = false;
    return p;
}

struct sequence {
    std::vector<emif_pins> cycles;
    sequence& add(const emif_pins& p, int n = 1) {
        cycles.insert(cycles.end(), n, p);
        return *this;
    }
    // A whole read / write at v1 timing with the given phase lengths.
    sequence& read(int ce, uint32_t ea, int setup = 2, int strobe = 10, int hold = 2) {
        return add(read_select(ce, ea), setup)
            .add(read_strobe(ce, ea), strobe)
            .add(read_select(ce, ea), hold);
    }
    sequence& write(int ce, uint32_t ea, uint32_t d, int setup = 2, int strobe = 10, int hold = 2) {
        return add(write_select(ce, ea, d), setup)
            .add(write_strobe(ce, ea, d), strobe)
            .add(write_select(ce, ea, d), hold);
    }
};

// Runs a sequence through a checker at CECTL v1 on CE2/CE3 (CE0 SDRAM).
emif_checker check(const sequence& s) {
    const uint32_t cectl[ce_count] = {cectl_sdram_dsk, cectl_reset, cectl_dsk_v1, cectl_dsk_v1};
    emif_checker c(cectl);
    for (size_t i = 0; i < s.cycles.size(); ++i) c.observe(i, s.cycles[i]);
    return c;
}

// Exactly `n` violations, all of kind `k`; returns them.
std::vector<violation> expect_only(const emif_checker& c, violation_kind k, uint64_t n) {
    EXPECT_EQ(c.count(k), n) << violation_name(k);
    EXPECT_EQ(c.total(), n);
    for (const violation& v : c.violations())
        if (v.kind != k) ADD_FAILURE() << "unexpected " << to_string(v);
    return c.violations();
}

}  // namespace

TEST(emif_checker, silent_on_random_engine_traffic_at_three_cectl_values) {
    for (uint32_t cectl : {cectl_dsk_v1, cectl_dsk_v2, cectl_mixed}) {
        const traffic_result r = run_traffic(cectl, 0, 11, 60000);
        EXPECT_EQ(r.violations, 0u) << std::hex << cectl;
        for (size_t i = 0; i < r.list.size() && i < 5; ++i) ADD_FAILURE() << to_string(r.list[i]);
        EXPECT_EQ(r.bad_reads, 0u);
        EXPECT_GT(r.strobes, 1000u);
        std::printf(
            "CECTL 0x%08X: %llu strobes checked, %llu words, 0 violations expected, %llu seen\n",
            cectl, (unsigned long long)r.strobes, (unsigned long long)r.words,
            (unsigned long long)r.violations);
    }
}

TEST(emif_checker, fires_on_every_strobe_the_engine_shortens) {
    // No ARDY fault here: its wait states would lengthen some strobes back to 10.
    const traffic_result r = run_traffic(cectl_dsk_v1, 1, 11, 20000, false);
    ASSERT_GT(r.strobes, 100u);
    // Every async strobe is one cycle short: exactly one violation per strobe, all strobe_short.
    EXPECT_EQ(r.violations, r.strobes);
    for (const violation& v : r.list) {
        ASSERT_EQ(v.kind, violation_kind::strobe_short) << to_string(v);
        EXPECT_EQ(v.required, 10u);
        EXPECT_EQ(v.actual, 9u);
    }
    std::printf("strobe shortened by 1: %llu strobes, %llu strobe_short violations (first: %s)\n",
                (unsigned long long)r.strobes, (unsigned long long)r.violations,
                r.list.empty() ? "-" : to_string(r.list.front()).c_str());
}

TEST(emif_checker, a_legal_hand_written_sequence_is_silent) {
    sequence s;
    s.add(idle(), 3).read(2, 0x10).read(2, 0x11).add(idle(), 2).write(2, 0x12, 7).write(2, 0x12, 8);
    s.add(idle(), 2).read(3, 0x40000).read(3, 0x40000).add(idle(), 5);
    const emif_checker c = check(s);
    EXPECT_EQ(c.total(), 0u);
    for (const violation& v : c.violations()) ADD_FAILURE() << to_string(v);
    EXPECT_EQ(c.strobes_checked(), 6u);
}

TEST(emif_checker, short_setup_strobe_and_hold) {
    {
        sequence s;
        s.add(idle(), 3).read(2, 0x10, 1, 10, 2).add(idle(), 3);
        const auto v = expect_only(check(s), violation_kind::setup_short, 1);
        EXPECT_EQ(v[0].required, 2u);
        EXPECT_EQ(v[0].actual, 1u);
        EXPECT_EQ(v[0].ce, 2);
    }
    {
        sequence s;
        s.add(idle(), 3).write(3, 0x10, 5, 2, 9, 2).add(idle(), 3);
        const auto v = expect_only(check(s), violation_kind::strobe_short, 1);
        EXPECT_EQ(v[0].required, 10u);
        EXPECT_EQ(v[0].actual, 9u);
        EXPECT_EQ(v[0].cycle, 3u + 2 + 9);
    }
    {
        sequence s;
        s.add(idle(), 3).read(2, 0x10, 2, 10, 1).add(idle(), 3);
        const auto v = expect_only(check(s), violation_kind::hold_short, 1);
        EXPECT_EQ(v[0].actual, 1u);
    }
    {
        // Incrementing words: the next EA comes one cycle into the hold.
        sequence s;
        s.add(idle(), 3).read(2, 0x10, 2, 10, 1).read(2, 0x11).add(idle(), 3);
        expect_only(check(s), violation_kind::hold_short, 1);
    }
}

TEST(emif_checker, back_to_back_words_at_one_address_closer_than_hold_plus_setup) {
    sequence s;  // CE and AOE held low, same EA: the gap between strobes is hold 1 + setup 2
    s.add(idle(), 3).read(2, 0x10, 2, 10, 1).read(2, 0x10, 2, 10, 2).add(idle(), 3);
    const auto v = expect_only(check(s), violation_kind::hold_setup_short, 1);
    EXPECT_EQ(v[0].required, 4u);
    EXPECT_EQ(v[0].actual, 3u);
}

TEST(emif_checker, select_change_inside_a_strobe) {
    sequence s;
    s.add(idle(), 3).add(read_select(2, 0x10), 2).add(read_strobe(2, 0x10), 5);
    s.add(read_strobe(2, 0x11), 5).add(read_select(2, 0x11), 2).add(idle(), 3);
    expect_only(check(s), violation_kind::select_in_strobe, 1);
}

TEST(emif_checker, are_and_awe_low_together) {
    sequence s;
    emif_pins both = read_strobe(2, 0x10);
    both.awe_n = false;
    s.add(idle(), 3).add(read_select(2, 0x10), 2).add(read_strobe(2, 0x10), 4).add(both, 1);
    s.add(read_strobe(2, 0x10), 5).add(read_select(2, 0x10), 2).add(idle(), 3);
    expect_only(check(s), violation_kind::are_awe_both_low, 1);
}

TEST(emif_checker, dsp_drives_ed_during_a_read) {
    sequence s;
    s.add(idle(), 3);
    for (emif_pins p : {read_select(2, 0x10), read_strobe(2, 0x10), read_select(2, 0x10)}) {
        p.ed_oe = true;
        p.ed_out = 0xDEAD;
        s.add(p, p.are_n ? 2 : 10);
    }
    s.add(idle(), 3);
    expect_only(check(s), violation_kind::ed_in_read, 14);  // every cycle AOE was low
}

TEST(emif_checker, ce_change_without_turnaround) {
    for (int gap = 0; gap <= 2; ++gap) {
        sequence s;
        s.add(idle(), 3).read(2, 0x10).add(idle(), gap).read(3, 0x10).add(idle(), 3);
        const emif_checker c = check(s);
        if (gap < 2) {
            const auto v = expect_only(c, violation_kind::ce_turnaround, 1);
            EXPECT_EQ(v[0].required, 2u);
            EXPECT_EQ(v[0].actual, static_cast<uint32_t>(gap));
        } else {
            EXPECT_EQ(c.total(), 0u);
        }
    }
    // SDRAM (CE0, no pins but CE) right after a card read needs the card's TA too.
    sequence s;
    emif_pins sdram;
    sdram.ce_n[0] = false;
    s.add(idle(), 3).read(3, 0x10).add(idle(), 1).add(sdram, 8).add(idle(), 2).read(3, 0x10);
    expect_only(check(s), violation_kind::ce_turnaround, 1);
}

TEST(emif_checker, direction_change_without_turnaround) {
    {
        sequence s;  // read then write on CE2, 1 idle cycle (TA 2)
        s.add(idle(), 3).read(2, 0x10).add(idle(), 1).write(2, 0x10, 1).add(idle(), 3);
        const auto v = expect_only(check(s), violation_kind::dir_turnaround, 1);
        EXPECT_EQ(v[0].actual, 1u);
    }
    {
        sequence s;  // write then read, CE held low, no idle cycle at all
        s.add(idle(), 3).write(2, 0x10, 1).read(2, 0x10).add(idle(), 3);
        const auto v = expect_only(check(s), violation_kind::dir_turnaround, 1);
        EXPECT_EQ(v[0].actual, 0u);
    }
}

TEST(emif_checker, two_ce_spaces_at_once_and_a_strobe_without_ce) {
    {
        sequence s;
        emif_pins two = read_select(2, 0x10);
        two.ce_n[3] = false;
        s.add(idle(), 3).add(two, 2).add(idle(), 3);
        const emif_checker c = check(s);
        EXPECT_EQ(c.count(violation_kind::multiple_ce), 2u);
    }
    {
        sequence s;
        emif_pins orphan;
        orphan.are_n = false;
        s.add(idle(), 3).add(orphan, 4).add(idle(), 3);
        expect_only(check(s), violation_kind::strobe_no_ce, 1);
    }
}
