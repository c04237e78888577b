// Timers in the C6416 model: timer 1 counts CPU clock / 8 and raises TINT1
// (INT15) every PRD timer clocks, exactly on CPU edges; CNT reads back the
// count at any time; HLD = 0 holds it. Timer 2's TINT2, mapped by MUXL to
// INT9, is also EDMA event 19: its period starts a transfer on channel 19
// (an L2 word, timer-paced DMA) that completes with INT8 at the same time.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <vector>

#include "c6416_test_util.h"
#include "model/c6416/c6416_regs.h"
#include "model/c6416/c6416_sc.h"

using namespace c6416_test;
namespace irq = c6416::irq;
namespace timer = c6416::timer;
namespace edma = c6416::edma;

TEST(C6416TimerSc, PeriodicInterruptsCountAndTimerPacedDma) {
    c6416::c6416_config config;
    config.dsk = c6416::dsk_v2();  // 720 MHz: 25 ticks per cycle, timer clock 90 MHz
    c6416::c6416_sc chip("chip", config);
    const int64_t hz = 720000000;

    std::vector<sc_core::sc_time> tint1;
    sc_core::sc_time start, read_at, held_at;
    uint32_t cnt_read = 0, cnt_held_1 = 0, cnt_held_2 = 0;
    std::vector<std::pair<int, sc_core::sc_time>> timer2_wakes;
    sc_core::sc_time start2;
    chip.set_firmware([&](c6416::cpu_port& h) {
        h.charge(stage::capture, 7);  // start off cycle 0
        h.set_interrupt_enable(1u << 15);
        h.write32(timer::base1 + timer::prd, 900);  // 900 x 8 cycles = 10 us at 720 MHz
        start = sc_core::sc_time_stamp();
        h.write32(timer::base1 + timer::ctl, timer::ctl_clksrc | timer::ctl_hld | timer::ctl_go);
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(h.wait_for_interrupt(), 15);
            tint1.push_back(sc_core::sc_time_stamp());
        }
        h.charge(stage::capture, 8 * 333 + 5);  // 333 timer clocks and 5 cycles on
        read_at = sc_core::sc_time_stamp();
        cnt_read = h.read32(timer::base1 + timer::cnt);
        h.write32(timer::base1 + timer::ctl, timer::ctl_clksrc);  // hold
        held_at = sc_core::sc_time_stamp();
        cnt_held_1 = h.read32(timer::base1 + timer::cnt);
        h.charge(stage::capture, 80000);
        cnt_held_2 = h.read32(timer::base1 + timer::cnt);

        // Timer 2: INT9 <- TINT2, EDMA channel 19 copies one L2 word per period.
        h.write32(irq::muxl, (irq::muxl_reset & ~(irq::intsel_mask << irq::intsel_shift(9))) |
                                 (irq::sel_tint2 << irq::intsel_shift(9)));
        const uint32_t opt = (edma::mode_inc << edma::opt_sum_shift) |
                             (edma::mode_inc << edma::opt_dum_shift) | edma::opt_tcint |
                             edma::opt_tcc(5) | edma::opt_fs;
        const uint32_t entry[6] = {opt, 0x100, edma::make_cnt(0, 1), 0x200, 0, 0};
        for (uint32_t i = 0; i < 6; ++i) h.write32(edma::entry(19) + 4 * i, entry[i]);
        h.write32(0x100, 0xC0FFEE00u);
        h.write32(edma::cier_l, 1u << 5);
        h.write32(edma::eer_l, 1u << 19);
        h.set_interrupt_enable((1u << 9) | (1u << 8));
        h.write32(timer::base2 + timer::prd, 90);  // 1 us
        start2 = sc_core::sc_time_stamp();
        h.write32(timer::base2 + timer::ctl, timer::ctl_clksrc | timer::ctl_hld | timer::ctl_go);
        for (int i = 0; i < 2; ++i) {
            const int n = h.wait_for_interrupt();
            timer2_wakes.push_back({n, sc_core::sc_time_stamp()});
        }
        h.write32(timer::base2 + timer::ctl, 0);
    });
    sc_core::sc_start(us(300.0));

    const uint64_t k0 = chip.cpu_cycle_at_or_after(start);
    EXPECT_EQ(k0, 7u);
    ASSERT_EQ(tint1.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(fs_of(tint1[i]), cpu_edge_fs(k0 + 7200u * (i + 1), hz)) << i;
    }
    EXPECT_EQ(tint1[0] - start, us(10.0));
    EXPECT_EQ(cnt_read, 333u);
    EXPECT_EQ(cnt_held_1, 333u);
    EXPECT_EQ(cnt_held_2, 333u);
    ASSERT_EQ(timer2_wakes.size(), 2u);
    const sc_core::sc_time tint2 = chip.time_of_cpu_cycle(chip.cpu_cycle_at_or_after(start2) + 720);
    // INT9 and EDMA_INT at the same time (in either delta order).
    EXPECT_EQ(timer2_wakes[0].first + timer2_wakes[1].first, 8 + 9);
    EXPECT_NE(timer2_wakes[0].first, timer2_wakes[1].first);
    EXPECT_EQ(timer2_wakes[0].second, tint2);
    EXPECT_EQ(timer2_wakes[1].second, tint2);
    uint32_t copied = 0;
    std::memcpy(&copied, chip.memory(0x200, 4), 4);
    EXPECT_EQ(copied, 0xC0FFEE00u);
    std::printf("TINT1 every %s from %s; CNT %u after 333 clocks; TINT2 + EDMA ch19 at %s\n",
                (tint1[1] - tint1[0]).to_string().c_str(), start.to_string().c_str(), cnt_read,
                tint2.to_string().c_str());
}
