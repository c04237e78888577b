// The C6416 model's CPU accesses: a read32 / write32 in an EMIFA CE space is
// one b_transport on emifa_cpu and the CPU stalls for the target's time
// (whether the target annotates it or consumes it inside b_transport); L2
// and, without an EMIF (sdram_over_emifa = false), SDRAM are served locally
// in zero time and seen through memory(); a C6416 register access costs
// peripheral_access_cycles; writes to the EMIFA control registers reach the
// EMIF through the register observer. Two chips in one simulation.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "c6416_test_util.h"
#include "model/c6416/c6416_regs.h"
#include "model/c6416/c6416_sc.h"

using namespace c6416_test;
namespace regs = c6416;

TEST(C6416BusSc, CpuAccessesTakeTheTargetsTimeAndEmifaWritesAreObserved) {
    const sc_core::sc_time word(140, sc_core::SC_NS);
    // Chip a: SDRAM over the bus, a consuming target on CE0..CE3 (EMIF style).
    c6416::c6416_sc a("a");
    bus_target bus_a("bus_a", 0x80000000u, 0x1000, word, true);
    a.emifa_cpu.bind(bus_a.cpu);
    // Chip b: local SDRAM, an annotating target on CE2, 20-cycle register accesses.
    c6416::c6416_config config_b;
    config_b.sdram_over_emifa = false;
    config_b.peripheral_access_cycles = 20;
    c6416::c6416_sc b("b", config_b);
    bus_target bus_b("bus_b", 0xA0000000u, 0x1000, word, false);
    b.emifa_cpu.bind(bus_b.cpu);

    std::vector<std::pair<uint32_t, uint32_t>> emifa_writes;
    b.set_emifa_register_observer([&](uint32_t address, uint32_t value) {
        emifa_writes.push_back({address, value});
    });

    std::vector<sc_core::sc_time> ta, tb;
    uint32_t read_a = 0, read_b = 0, l2_read = 0;
    a.set_firmware([&](c6416::cpu_port& h) {
        h.charge(stage::capture, 3);
        ta.push_back(sc_core::sc_time_stamp());
        h.write32(0x80000010u, 0x12345678u);  // SDRAM through the bus
        ta.push_back(sc_core::sc_time_stamp());
        read_a = h.read32(0x80000010u);
        ta.push_back(sc_core::sc_time_stamp());
        h.write32(0x00000040u, 0xCAFEF00Du);  // L2: no time
        l2_read = h.read32(0x00000040u);
        ta.push_back(sc_core::sc_time_stamp());
    });
    b.set_firmware([&](c6416::cpu_port& h) {
        tb.push_back(sc_core::sc_time_stamp());
        h.write32(regs::emifa::cectl2, regs::emifa::dsk_cectl_card_v1);  // 20 cycles
        tb.push_back(sc_core::sc_time_stamp());
        h.write32(0x80000020u, 0xA5A5A5A5u);  // local SDRAM: no time
        tb.push_back(sc_core::sc_time_stamp());
        read_b = h.read32(0xA0000008u);  // the card's space: one word
        tb.push_back(sc_core::sc_time_stamp());
    });
    sc_core::sc_start(us(10.0));

    ASSERT_EQ(ta.size(), 4u);
    EXPECT_EQ(ta[1] - ta[0], word);
    EXPECT_EQ(ta[2] - ta[1], word);
    EXPECT_EQ(ta[3], ta[2]);
    EXPECT_EQ(read_a, 0x12345678u);
    EXPECT_EQ(l2_read, 0xCAFEF00Du);
    uint32_t in_l2 = 0;
    std::memcpy(&in_l2, a.memory(0x40, 4), 4);
    EXPECT_EQ(in_l2, 0xCAFEF00Du);
    uint32_t in_target = 0;
    std::memcpy(&in_target, bus_a.data(0x80000010u), 4);
    EXPECT_EQ(in_target, 0x12345678u);
    EXPECT_EQ(a.cpu_bus_stall_time(), word * 2.0);
    ASSERT_EQ(bus_a.records.size(), 2u);
    EXPECT_EQ(bus_a.records[0].length, 4u);
    EXPECT_FALSE(bus_a.records[0].from_edma);

    ASSERT_EQ(tb.size(), 4u);
    EXPECT_EQ(fs_of(tb[1]), cpu_edge_fs(20, 600000000));
    EXPECT_EQ(tb[2], tb[1]);
    EXPECT_EQ(tb[3] - tb[2], word);
    uint32_t in_sdram = 0;
    std::memcpy(&in_sdram, b.memory(0x80000020u, 4), 4);
    EXPECT_EQ(in_sdram, 0xA5A5A5A5u);
    EXPECT_EQ(b.sdram_storage()[0x20], 0xA5u);
    EXPECT_EQ(b.sdram_storage_bytes(), regs::sdram_bytes);
    EXPECT_TRUE(bus_b.records.size() == 1u && bus_b.records[0].read);
    ASSERT_EQ(emifa_writes.size(), 1u);
    EXPECT_EQ(emifa_writes[0].first, regs::emifa::cectl2);
    EXPECT_EQ(emifa_writes[0].second, 0x22A28A22u);
    EXPECT_EQ(b.peek_register(regs::emifa::cectl2), 0x22A28A22u);
    EXPECT_EQ(b.peek_register(regs::emifa::cectl3), regs::emifa::cectl_reset);
    EXPECT_EQ(a.bus_errors() + b.bus_errors(), 0u);
    std::printf("CE0 word over the bus %s each way; register write %s; CE2 read %s\n",
                (ta[1] - ta[0]).to_string().c_str(), (tb[1] - tb[0]).to_string().c_str(),
                (tb[3] - tb[2]).to_string().c_str());
}
