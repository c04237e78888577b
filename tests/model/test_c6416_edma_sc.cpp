// The C6416 model's EDMA end to end in SystemC: a rising edge on EXT_INT4
// (event of channel 4) starts a frame-synchronised 2-D transfer of 8 arrays
// x 16 words from a TLM memory target into L2 (one b_transport per array);
// its completion code chains channel 20 (8 words from a fixed FIFO-like
// address, streaming width 4), whose completion raises EDMA_INT = INT8 at
// exactly the edge time plus the target's 140 ns per word (14 ECLK at
// 100 MHz). An EXT_INT5 edge while EER disables channel 5 is latched in ER
// (and in IFR bit 5) and starts its transfer only when EER enables it.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "c6416_test_util.h"
#include "model/c6416/c6416_regs.h"
#include "model/c6416/c6416_sc.h"

using namespace c6416_test;
namespace edma = c6416::edma;

namespace {

constexpr uint32_t src_base = 0xB0000000u;
constexpr uint32_t fifo_port = 0xB0008000u;
constexpr uint32_t dst_a = 0x00010000u, dst_b = 0x00020000u, dst_c = 0x00030000u;

void write_entry(c6416::cpu_port& h, uint32_t address, const uint32_t (&w)[6]) {
    for (uint32_t i = 0; i < 6; ++i) h.write32(address + 4 * i, w[i]);
}

constexpr uint32_t opt32(uint32_t sum, uint32_t dum) {
    return (edma::esize_32 << edma::opt_esize_shift) | (sum << edma::opt_sum_shift) |
           (dum << edma::opt_dum_shift) | edma::opt_tcint | edma::opt_fs;
}

struct observed {
    sc_core::sc_time int8_first, int8_second, enabled_at;
    int n_first = 0, n_second = 0;
    uint32_t cipr_after_first = 0, er_before_enable = 0, ifr_before_enable = 0;
};

}  // namespace

TEST(C6416EdmaSc, ExtInt4EdgeMovesWordsIntoL2AndRaisesInt8OnTime) {
    const sc_core::sc_time word = sc_core::sc_time(140, sc_core::SC_NS);
    const sc_core::sc_time edge4 = us(10.0), edge5 = us(50.0);
    c6416::c6416_sc chip("chip");
    bus_target bus("bus", src_base, 0x10000, word, false);
    pin_driver pins("pins", {{edge4, 4, true},
                             {edge4 + sc_core::sc_time(40, sc_core::SC_NS), 4, false},
                             {edge5, 5, true},
                             {edge5 + sc_core::sc_time(40, sc_core::SC_NS), 5, false}});
    pins.bind(chip);
    chip.emifa_cpu.bind(bus.cpu);
    chip.emifa_edma.bind(bus.edma);
    for (uint32_t i = 0; i < 0x10000; ++i)
        *bus.data(src_base + i) = static_cast<uint8_t>(i * 7 + 3);

    observed o;
    chip.set_firmware([&](c6416::cpu_port& h) {
        // Channel 4: 8 arrays of 16 words, 2-D source with arrays 256 B
        // apart, 1-D destination (packed in L2); completion code 20 chains.
        write_entry(h, edma::entry(4),
                    {opt32(edma::mode_inc, edma::mode_inc) | edma::opt_2ds | edma::opt_tcc(20),
                     src_base, edma::make_cnt(7, 16), dst_a, edma::make_idx(256, 0), 0});
        write_entry(h, edma::entry(20),
                    {opt32(edma::mode_fixed, edma::mode_inc) | edma::opt_tcc(21), fifo_port,
                     edma::make_cnt(0, 8), dst_b, 0, 0});
        write_entry(h, edma::entry(5),
                    {opt32(edma::mode_inc, edma::mode_inc) | edma::opt_tcc(22), src_base + 0x4000,
                     edma::make_cnt(0, 4), dst_c, 0, 0});
        h.write32(edma::ccer_l, 1u << 20);
        h.write32(edma::cier_l, (1u << 21) | (1u << 22));
        h.write32(edma::eer_l, 1u << 4);
        h.set_interrupt_enable(1u << 8);
        o.n_first = h.wait_for_interrupt();
        o.int8_first = sc_core::sc_time_stamp();
        o.cipr_after_first = h.read32(edma::cipr_l);
        h.write32(edma::cipr_l, 0xFFFFFFFFu);
        h.charge(stage::capture, 36000);  // 60 us at 600 MHz: past the EXT_INT5 edge
        o.er_before_enable = h.read32(edma::er_l);
        o.ifr_before_enable = h.interrupt_flags();
        o.enabled_at = sc_core::sc_time_stamp();
        h.write32(edma::eer_l, (1u << 4) | (1u << 5));
        o.n_second = h.wait_for_interrupt();
        o.int8_second = sc_core::sc_time_stamp();
    });
    sc_core::sc_start(us(200.0));

    // 8 x 16 + 8 words at 140 ns after the edge.
    EXPECT_EQ(o.n_first, 8);
    EXPECT_EQ(o.int8_first, edge4 + word * 136.0);
    EXPECT_EQ(o.cipr_after_first, (1u << 20) | (1u << 21));
    // The data: array a of the source (256 B apart) packed into L2.
    bool equal = true;
    for (uint32_t a = 0; a < 8; ++a) {
        equal &=
            std::memcmp(chip.memory(dst_a + 64 * a, 64), bus.data(src_base + 256 * a), 64) == 0;
    }
    EXPECT_TRUE(equal);
    // Fixed source: 8 reads of the same word.
    for (uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(std::memcmp(chip.memory(dst_b + 4 * i, 4), bus.data(fifo_port), 4), 0) << i;
    }
    // Bursts: one per array (64 B, incrementing), then one of 32 B at a fixed address.
    std::vector<bus_record> edma_records;
    for (const bus_record& r : bus.records) {
        if (r.from_edma) edma_records.push_back(r);
    }
    ASSERT_EQ(edma_records.size(), 10u);
    for (size_t a = 0; a < 8; ++a) {
        EXPECT_EQ(edma_records[a].address, src_base + 256 * a);
        EXPECT_EQ(edma_records[a].length, 64u);
        EXPECT_EQ(edma_records[a].streaming_width, 64u);
        EXPECT_EQ(edma_records[a].start, edge4 + word * (16.0 * static_cast<double>(a)));
    }
    EXPECT_EQ(edma_records[8].address, fifo_port);
    EXPECT_EQ(edma_records[8].length, 32u);
    EXPECT_EQ(edma_records[8].streaming_width, 4u);
    // Channel 5: latched while disabled, started by EER.
    EXPECT_EQ(o.er_before_enable, 1u << 5);
    EXPECT_NE(o.ifr_before_enable & (1u << 5), 0u);  // GPINT5 -> INT5 as well
    EXPECT_EQ(o.n_second, 8);
    EXPECT_EQ(edma_records[9].start, o.enabled_at);
    EXPECT_EQ(o.int8_second, o.enabled_at + word * 4.0);
    EXPECT_EQ(std::memcmp(chip.memory(dst_c, 16), bus.data(src_base + 0x4000), 16), 0);
    EXPECT_EQ(chip.edma_bytes(), 512u + 32u + 16u);
    EXPECT_EQ(chip.edma_busy_time(), word * 140.0);
    EXPECT_EQ(chip.bus_errors(), 0u);
    std::printf(
        "EXT_INT4 at %s: INT8 at %s (136 words x 140 ns); EER-enabled ch5 at %s: INT8 at %s\n",
        edge4.to_string().c_str(), o.int8_first.to_string().c_str(),
        o.enabled_at.to_string().c_str(), o.int8_second.to_string().c_str());
}
