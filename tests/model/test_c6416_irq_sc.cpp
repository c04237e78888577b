// Interrupts in the C6416 model: EXT_INT edges reach IFR through the
// interrupt selector (reset mapping INT4-7 = EXT_INT4-7), IER decides what
// wakes wait_for_interrupt (a disabled interrupt stays latched in IFR and
// is taken at once when enabled), MUXL remaps an event to another CPU
// interrupt, EXTPOL selects the falling edge, TINT0 reaches INT14, a charge
// after a wake-up between CPU edges starts on the next edge, and
// request_stop ends a wait with no_interrupt.
#include <gtest/gtest.h>

#include <cstdio>

#include "c6416_test_util.h"
#include "model/c6416/c6416_regs.h"
#include "model/c6416/c6416_sc.h"

using namespace c6416_test;
namespace irq = c6416::irq;
namespace timer = c6416::timer;

namespace {

struct wake {
    int n;
    sc_core::sc_time at;
};

}  // namespace

TEST(C6416IrqSc, SelectorRoutesEdgesByPolarityAndIerGatesTheWakeUp) {
    const sc_core::sc_time ns40(40, sc_core::SC_NS);
    const sc_core::sc_time odd = us(7.0) + fs(123456);  // between CPU edges
    c6416::c6416_sc chip("chip");
    pin_driver pins("pins", {{us(1.0), 4, true},
                             {us(1.0) + ns40, 4, false},
                             {us(2.0), 6, true},
                             {us(2.0) + ns40, 6, false},
                             {us(3.0), 5, true},
                             {us(3.0) + ns40, 5, false},
                             {us(5.0), 6, true},  // rising: not active after EXTPOL
                             {odd, 6, false},     // falling: active
                             {us(9.0), 7, true}});
    pins.bind(chip);

    std::vector<wake> wakes;
    uint32_t ifr_after_int5 = 0, ifr_after_ext7 = 0;
    sc_core::sc_time charge_end, timer_started;
    chip.set_firmware([&](c6416::cpu_port& h) {
        auto take = [&] {
            const int n = h.wait_for_interrupt();
            wakes.push_back({n, sc_core::sc_time_stamp()});
        };
        h.set_interrupt_enable((1u << 4) | (1u << 5));
        take();  // EXT_INT4 at 1 us
        take();  // EXT_INT6 at 2 us is not enabled: EXT_INT5 at 3 us
        ifr_after_int5 = h.interrupt_flags();
        h.set_interrupt_enable((1u << 4) | (1u << 5) | (1u << 6));
        take();  // the latched INT6, at once
        // INT4 <- GPINT6, EXT_INT6 active on its falling edge.
        h.write32(irq::muxl, (irq::muxl_reset & ~irq::intsel_mask) | irq::sel_gpint6);
        h.write32(irq::extpol, 1u << 2);
        h.clear_interrupt_flags(0xFFFFu);
        h.set_interrupt_enable(1u << 4);
        take();  // EXT_INT6 falling at `odd`
        h.charge(stage::capture, 1);
        charge_end = sc_core::sc_time_stamp();
        ifr_after_ext7 = h.interrupt_flags();  // EXT_INT7 at 9 us: not yet
        // Timer 0 -> TINT0 -> INT14 (reset MUXH): 75 timer clocks of 8 cycles = 1 us.
        h.set_interrupt_enable(1u << 14);
        h.write32(timer::base0 + timer::prd, 75);
        timer_started = sc_core::sc_time_stamp();
        h.write32(timer::base0 + timer::ctl, timer::ctl_clksrc | timer::ctl_hld | timer::ctl_go);
        take();
        h.write32(timer::base0 + timer::ctl, 0);
        h.set_interrupt_enable(1u << 4);
        take();  // nothing enabled comes: the stop at 20 us ends the wait
    });
    sc_core::sc_start(us(20.0));
    chip.request_stop();
    sc_core::sc_start(us(1.0));

    ASSERT_EQ(wakes.size(), 6u);
    EXPECT_EQ(wakes[0].n, 4);
    EXPECT_EQ(wakes[0].at, us(1.0));
    EXPECT_EQ(wakes[1].n, 5);
    EXPECT_EQ(wakes[1].at, us(3.0));
    EXPECT_NE(ifr_after_int5 & (1u << 6), 0u);  // latched while disabled
    EXPECT_EQ(wakes[2].n, 6);
    EXPECT_EQ(wakes[2].at, us(3.0));
    EXPECT_EQ(wakes[3].n, 4);
    EXPECT_EQ(wakes[3].at, odd);  // not at the rising edge at 5 us
    // A charge of one cycle from between two edges ends one edge after the next.
    const uint64_t next_edge = chip.cpu_cycle_at_or_after(odd);
    EXPECT_EQ(fs_of(charge_end), cpu_edge_fs(next_edge + 1, 600000000));
    EXPECT_EQ(ifr_after_ext7 & (1u << 7), 0u);
    EXPECT_EQ(wakes[4].n, 14);
    EXPECT_EQ(wakes[4].at, chip.time_of_cpu_cycle(chip.cpu_cycle_at_or_after(timer_started) + 600));
    EXPECT_EQ(wakes[5].n, c6416::cpu_port::no_interrupt);
    EXPECT_EQ(wakes[5].at, us(20.0));
    EXPECT_NE(chip.ifr() & (1u << 7), 0u);  // EXT_INT7 at 9 us latched, never enabled
    EXPECT_EQ(chip.selector().selected_event(4), irq::sel_gpint6);
    std::printf("wakes: INT4 %s, INT5 %s, INT6 %s, INT4<-EXT_INT6 falling %s, INT14 %s\n",
                wakes[0].at.to_string().c_str(), wakes[1].at.to_string().c_str(),
                wakes[2].at.to_string().c_str(), wakes[3].at.to_string().c_str(),
                wakes[4].at.to_string().c_str());
}
