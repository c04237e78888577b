// The C6416 register map (model/c6416/c6416_regs.h) against the numbers of its
// sources, typed here from them (docs/hardware-facts.md sections 1, 3, 4; TI CSL
// csl_edmahal.h / csl_irqhal.h / csl_timerhal.h; DSK6416.gel), and the plain
// C++ parts of the model that interpret it: the interrupt selector, the
// EDMA channel controller (events, enables, PaRAM update, link, chaining,
// completion interrupt) and the timer counter.
#include <gtest/gtest.h>

#include <cstdio>

#include "model/c6416/c6416_regs.h"
#include "model/c6416/edma_core.h"
#include "model/c6416/interrupt_selector.h"
#include "model/c6416/timer_unit.h"

namespace regs = c6416;
namespace edma = c6416::edma;
namespace irq = c6416::irq;

TEST(C6416Regs, AddressesMatchTheDataSheetAndCsl) {
    // Memory map [DS Table 3]; SDRAM [TR].
    EXPECT_EQ(regs::l2_bytes, 1024u * 1024u);
    EXPECT_EQ(regs::sdram_base, 0x80000000u);
    EXPECT_EQ(regs::sdram_bytes, 16u * 1024u * 1024u);
    EXPECT_EQ(regs::emifa_ce2_base, 0xA0000000u);
    EXPECT_EQ(regs::emifa_ce3_base, 0xB0000000u);
    EXPECT_EQ(regs::emifa_ce_of(0xB0100000u), 3);
    EXPECT_EQ(regs::emifa_ce_of(0x80FFFFFCu), 0);
    EXPECT_TRUE(regs::in_emifa(0xBFFFFFFCu));
    EXPECT_FALSE(regs::in_emifa(0xC0000000u));
    EXPECT_FALSE(regs::in_emifa(0x7FFFFFFCu));
    // EMIFA [CSL; GEL init_emif].
    EXPECT_EQ(regs::emifa::gblctl, 0x01800000u);
    EXPECT_EQ(regs::emifa::cectl1, 0x01800004u);
    EXPECT_EQ(regs::emifa::cectl0, 0x01800008u);
    EXPECT_EQ(regs::emifa::cectl2, 0x01800010u);
    EXPECT_EQ(regs::emifa::cectl3, 0x01800014u);
    EXPECT_EQ(regs::emifa::sdctl, 0x01800018u);
    EXPECT_EQ(regs::emifa::sdtim, 0x0180001Cu);
    EXPECT_EQ(regs::emifa::sdext, 0x01800020u);
    EXPECT_EQ(regs::emifa::cesec0, 0x01800048u);
    EXPECT_EQ(regs::emifa::cectl(2), 0x01800010u);
    // Interrupt selector [CSL csl_irqhal.h].
    EXPECT_EQ(irq::muxh, 0x019C0000u);
    EXPECT_EQ(irq::muxl, 0x019C0004u);
    EXPECT_EQ(irq::extpol, 0x019C0008u);
    // EDMA [CSL csl_edmahal.h; GEL OnRestart: CIERH 0x01A0FFA8, EERH FFB4, ECRH FFB8, CIERL FFE8,
    // EERL FFF4, ECRL FFF8].
    EXPECT_EQ(edma::pram_base, 0x01A00000u);
    EXPECT_EQ(edma::entry(4), 0x01A00060u);
    EXPECT_EQ(edma::entry(63), 0x01A005E8u);
    EXPECT_EQ(edma::null_entry, 0x01A00600u);
    EXPECT_EQ(edma::link_base, 0x01A00630u);
    EXPECT_EQ(edma::link_entries, 19);
    EXPECT_LE(edma::link_entry(18) + edma::entry_bytes, edma::pram_base + edma::pram_bytes);
    EXPECT_EQ(edma::cipr_l, 0x01A0FFE4u);
    EXPECT_EQ(edma::cier_l, 0x01A0FFE8u);
    EXPECT_EQ(edma::ccer_l, 0x01A0FFECu);
    EXPECT_EQ(edma::er_l, 0x01A0FFF0u);
    EXPECT_EQ(edma::eer_l, 0x01A0FFF4u);
    EXPECT_EQ(edma::ecr_l, 0x01A0FFF8u);
    EXPECT_EQ(edma::esr_l, 0x01A0FFFCu);
    EXPECT_EQ(edma::cipr_h, 0x01A0FFA4u);
    EXPECT_EQ(edma::cier_h, 0x01A0FFA8u);
    EXPECT_EQ(edma::ccer_h, 0x01A0FFACu);
    EXPECT_EQ(edma::er_h, 0x01A0FFB0u);
    EXPECT_EQ(edma::eer_h, 0x01A0FFB4u);
    EXPECT_EQ(edma::ecr_h, 0x01A0FFB8u);
    EXPECT_EQ(edma::esr_h, 0x01A0FFBCu);
    EXPECT_EQ(edma::epr_h, 0x01A0FF9Cu);
    EXPECT_EQ(edma::pqsr, 0x01A0FFE0u);
    EXPECT_EQ(edma::pqar0, 0x01A0FFC0u);
    // OPT field masks [CSL].
    EXPECT_EQ(edma::opt_pri_mask, 0xE0000000u);
    EXPECT_EQ(edma::opt_esize_mask, 0x18000000u);
    EXPECT_EQ(edma::opt_2ds, 0x04000000u);
    EXPECT_EQ(edma::opt_sum_mask, 0x03000000u);
    EXPECT_EQ(edma::opt_2dd, 0x00800000u);
    EXPECT_EQ(edma::opt_dum_mask, 0x00600000u);
    EXPECT_EQ(edma::opt_tcint, 0x00100000u);
    EXPECT_EQ(edma::opt_tcc_mask, 0x000F0000u);
    EXPECT_EQ(edma::opt_tccm_mask, 0x00006000u);
    EXPECT_EQ(edma::opt_atcint, 0x00001000u);
    EXPECT_EQ(edma::opt_atcc_mask, 0x000007E0u);
    EXPECT_EQ(edma::opt_link, 0x00000002u);
    EXPECT_EQ(edma::opt_fs, 0x00000001u);
    for (uint32_t code = 0; code < 64; ++code)
        EXPECT_EQ(edma::opt_tcc_code(edma::opt_tcc(code)), code);
    // Timers [CSL csl_timerhal.h].
    EXPECT_EQ(regs::timer::base0, 0x01940000u);
    EXPECT_EQ(regs::timer::base1, 0x01980000u);
    EXPECT_EQ(regs::timer::base2, 0x01AC0000u);
    EXPECT_EQ(regs::timer::ctl_go, 0x40u);
    EXPECT_EQ(regs::timer::ctl_hld, 0x80u);
    EXPECT_EQ(regs::timer::ctl_clksrc, 0x200u);
    EXPECT_EQ(regs::timer::ctl_tstat, 0x800u);
}

// The DSK's SDRAM refresh setting (the CECTL values are decoded and tested
// by the EMIF model, tests/model/test_emif_timing.cpp, from these constants).
TEST(C6416Regs, DskSdramRefreshPeriod) {
    // SDRAM refresh: 1560 / 1872 ECLK = 15.6 us at 100 / 120 MHz ([TR]: one row every 15.6 us).
    EXPECT_EQ(regs::emifa::dsk_sdtim_v1 & regs::emifa::sdtim_period_mask, 1560u);
    EXPECT_EQ(regs::emifa::dsk_sdtim_v2 & regs::emifa::sdtim_period_mask, 1872u);
}

// Reset routing of Table 26 and how MUXL / MUXH / EXTPOL change it.
TEST(C6416Selector, ResetRoutingAndRemapping) {
    c6416::interrupt_selector s;
    for (int n = 4; n <= 7; ++n) EXPECT_EQ(s.cpu_interrupts_for(irq::sel_gpint4 + n - 4), 1u << n);
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_edma_int), 1u << 8);
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_sd_inta), 1u << 10);
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_dspint), 1u << 13);
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_tint0), 1u << 14);
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_tint1), 1u << 15);
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_tint2), 0u);
    uint32_t v = 0;
    ASSERT_TRUE(s.read(irq::muxl, v));
    EXPECT_EQ(v, 0x250718A4u);
    ASSERT_TRUE(s.read(irq::muxh, v));
    EXPECT_EQ(v, 0x08202D43u);
    // INT9 <- TINT2, INT12 <- EXT_INT4 too: one event may reach two CPU interrupts.
    ASSERT_TRUE(
        s.write(irq::muxl, (v = irq::muxl_reset & ~(0x1Fu << 26)) | (irq::sel_tint2 << 26)));
    ASSERT_TRUE(s.write(irq::muxh, (irq::muxh_reset & ~(0x1Fu << 10)) | (irq::sel_gpint4 << 10)));
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_tint2), 1u << 9);
    EXPECT_EQ(s.cpu_interrupts_for(irq::sel_gpint4), (1u << 4) | (1u << 12));
    EXPECT_EQ(s.selected_event(12), irq::sel_gpint4);
    // EXTPOL: rising edges by default; bit n = 1 selects the falling edge of EXT_INT(4+n).
    EXPECT_TRUE(s.active_edge(1, false, true));
    EXPECT_FALSE(s.active_edge(1, true, false));
    ASSERT_TRUE(s.write(irq::extpol, 0x2u));
    EXPECT_FALSE(s.active_edge(1, false, true));
    EXPECT_TRUE(s.active_edge(1, true, false));
    EXPECT_TRUE(s.active_edge(0, false, true));
    ASSERT_TRUE(s.write(irq::extpol, 0xFFFFFFFFu));
    ASSERT_TRUE(s.read(irq::extpol, v));
    EXPECT_EQ(v, 0xFu);  // XIP is 4 bits
    EXPECT_FALSE(s.read(0x019C000Cu, v));
}

namespace {

void write_entry(c6416::edma_core& e, uint32_t address, uint32_t opt, uint32_t src, uint32_t cnt,
                 uint32_t dst, uint32_t idx, uint32_t rld) {
    const uint32_t w[6] = {opt, src, cnt, dst, idx, rld};
    for (int i = 0; i < 6; ++i) ASSERT_TRUE(e.write(address + 4u * static_cast<uint32_t>(i), w[i]));
}

uint32_t word(const c6416::edma_core& e, uint32_t address) {
    uint32_t v = 0;
    EXPECT_TRUE(e.read(address, v));
    return v;
}

constexpr uint32_t opt32(uint32_t sum, uint32_t dum) {
    return (edma::esize_32 << edma::opt_esize_shift) | (sum << edma::opt_sum_shift) |
           (dum << edma::opt_dum_shift);
}

}  // namespace

// Frame-synchronised 2-D transfer: one request with all arrays, the entry
// reloaded from its link at submission, completion code -> CIPR, CIER -> EDMA_INT.
TEST(C6416Edma, FrameSyncTransferLinksAndInterrupts) {
    c6416::edma_core e;
    const uint32_t opt = opt32(edma::mode_inc, edma::mode_inc) | edma::opt_2ds | edma::opt_2dd |
                         edma::opt_tcint | edma::opt_tcc(40) | edma::opt_link | edma::opt_fs;
    write_entry(e, edma::entry(4), opt, 0xB0000000u, edma::make_cnt(7, 16), 0x1000u,
                edma::make_idx(256, 0), edma::make_rld(0, edma::link_entry(2)));
    write_entry(e, edma::link_entry(2), 0x11u, 0x22u, 0x33u, 0x44u, 0x55u, 0x66u);
    ASSERT_TRUE(e.write(edma::cier_h, 1u << (40 - 32)));

    e.event(4);  // EER off: latched only
    EXPECT_EQ(e.er(), 1u << 4);
    EXPECT_FALSE(e.has_request());
    ASSERT_TRUE(e.write(edma::eer_l, 1u << 4));  // enabling submits the latched event
    EXPECT_EQ(e.er(), 0u);
    ASSERT_TRUE(e.has_request());
    const c6416::transfer_request r = e.take_request();
    EXPECT_EQ(r.channel, 4);
    EXPECT_EQ(r.arrays, 8u);
    EXPECT_EQ(r.elements, 16u);
    EXPECT_EQ(r.bytes(), 512u);
    EXPECT_EQ(r.src.start, 0xB0000000u);
    EXPECT_EQ(r.src.element_step, 4);
    EXPECT_EQ(r.src.array_step, 256);
    EXPECT_EQ(r.dst.array_step, 256);
    EXPECT_EQ(r.done, c6416::completion::final);
    // Reloaded from link entry 2 at submission.
    EXPECT_EQ(word(e, edma::entry(4) + edma::opt), 0x11u);
    EXPECT_EQ(word(e, edma::entry(4) + edma::rld), 0x66u);
    EXPECT_FALSE(e.take_interrupt());
    e.complete(r);
    EXPECT_EQ(e.cipr(), uint64_t{1} << 40);
    EXPECT_TRUE(e.take_interrupt());
    EXPECT_FALSE(e.take_interrupt());
    ASSERT_TRUE(e.write(edma::cipr_h, 1u << 8));  // W1C
    EXPECT_EQ(e.cipr(), 0u);
}

// Array-synchronised 2-D transfer: one array per event, addresses and FRMCNT
// updated per event, intermediate completions on ATCC, the last on TCC; no
// link: the entry is spent and a further event is a null transfer.
TEST(C6416Edma, ArraySyncTransferStepsPerEvent) {
    c6416::edma_core e;
    const uint32_t opt = opt32(edma::mode_fixed, edma::mode_inc) | edma::opt_2dd | edma::opt_tcint |
                         edma::opt_tcc(9) | edma::opt_atcint | (7u << edma::opt_atcc_shift);
    write_entry(e, edma::entry(5), opt, 0xB0100000u, edma::make_cnt(2, 4), 0x2000u,
                edma::make_idx(64, 0), 0);
    ASSERT_TRUE(e.write(edma::eer_l, 1u << 5));
    for (uint32_t a = 0; a < 3; ++a) {
        e.event(5);
        ASSERT_TRUE(e.has_request());
        const c6416::transfer_request r = e.take_request();
        EXPECT_EQ(r.arrays, 1u);
        EXPECT_EQ(r.elements, 4u);
        EXPECT_EQ(r.src.start, 0xB0100000u);  // fixed: a FIFO port
        EXPECT_EQ(r.src.element_step, 0);
        EXPECT_EQ(r.dst.start, 0x2000u + 64 * a);
        EXPECT_EQ(r.done, a < 2 ? c6416::completion::intermediate : c6416::completion::final);
        e.complete(r);
        EXPECT_EQ(e.cipr(), a < 2 ? uint64_t{1} << 7 : (uint64_t{1} << 7) | (1u << 9));
    }
    EXPECT_EQ(word(e, edma::entry(5) + edma::cnt), 0u);
    e.event(5);
    EXPECT_FALSE(e.has_request());
    EXPECT_EQ(e.null_transfers(), 1u);
}

// Element-synchronised 1-D transfer with index mode: ELEIDX between elements,
// FRMIDX at a frame end, ELECNT reloaded from ELERLD.
TEST(C6416Edma, ElementSyncIndexMode) {
    c6416::edma_core e;
    const uint32_t opt =
        opt32(edma::mode_index, edma::mode_inc) | edma::opt_tcint | edma::opt_tcc(3);
    write_entry(e, edma::entry(6), opt, 0x100u, edma::make_cnt(1, 3), 0x800u,
                edma::make_idx(100, 8), edma::make_rld(3, 0));
    ASSERT_TRUE(e.write(edma::eer_l, 1u << 6));
    const uint32_t expected_src[6] = {0x100, 0x108, 0x110, 0x110 + 100, 0x110 + 108, 0x110 + 116};
    for (int i = 0; i < 6; ++i) {
        e.event(6);
        ASSERT_TRUE(e.has_request());
        const c6416::transfer_request r = e.take_request();
        EXPECT_EQ(r.src.start, expected_src[i]) << i;
        EXPECT_EQ(r.dst.start, 0x800u + 4u * static_cast<uint32_t>(i)) << i;
        EXPECT_EQ(r.done, i == 5   ? c6416::completion::final
                          : i == 2 ? c6416::completion::intermediate
                                   : c6416::completion::none);
        e.complete(r);
    }
    EXPECT_EQ(e.cipr(), 1u << 3);
}

// Chaining: a completion code with CCER set submits that channel whatever
// EER says; ESR submits a channel directly; ECR clears a latched event;
// enabling CIER on a pending bit raises EDMA_INT.
TEST(C6416Edma, ChainingEventSetAndClear) {
    c6416::edma_core e;
    write_entry(e, edma::entry(4), opt32(1, 1) | edma::opt_tcint | edma::opt_tcc(56) | edma::opt_fs,
                0xA0000014u, edma::make_cnt(0, 5), 0x3000u, 0, 0);
    write_entry(e, edma::entry(56),
                opt32(1, 1) | edma::opt_tcint | edma::opt_tcc(12) | edma::opt_fs, 0xB0000000u,
                edma::make_cnt(0, 2), 0x3100u, 0, 0);
    ASSERT_TRUE(e.write(edma::ccer_h, 1u << (56 - 32)));
    ASSERT_TRUE(e.write(edma::esr_l, 1u << 4));
    ASSERT_TRUE(e.has_request());
    c6416::transfer_request r = e.take_request();
    EXPECT_EQ(r.channel, 4);
    e.complete(r);  // code 56 -> chain
    ASSERT_TRUE(e.has_request());
    r = e.take_request();
    EXPECT_EQ(r.channel, 56);
    e.complete(r);
    EXPECT_EQ(e.cipr(), (uint64_t{1} << 56) | (1u << 12));
    EXPECT_FALSE(e.take_interrupt());
    ASSERT_TRUE(e.write(edma::cier_l, 1u << 12));
    EXPECT_TRUE(e.take_interrupt());

    e.event(7);
    EXPECT_EQ(e.er(), 1u << 7);
    ASSERT_TRUE(e.write(edma::ecr_l, 1u << 7));
    EXPECT_EQ(e.er(), 0u);
    ASSERT_TRUE(e.write(edma::eer_l, 1u << 7));
    EXPECT_FALSE(e.has_request());
}

// Timer: CPU clock / 8, TINT every PRD timer clocks, CNT 0 .. PRD - 1,
// HLD = 0 holds the count, HLD = 1 without GO resumes it.
TEST(C6416Timer, PeriodCountHoldAndResume) {
    c6416::timer_unit t;
    t.reset();
    t.write_prd(100);
    const uint32_t go = regs::timer::ctl_go | regs::timer::ctl_hld | regs::timer::ctl_clksrc;
    t.write_ctl(go, 1000);
    EXPECT_TRUE(t.counting());
    EXPECT_EQ(t.read_ctl() & regs::timer::ctl_go, 0u);
    EXPECT_EQ(t.next_interrupt(1000), 1000u + 800u);
    EXPECT_EQ(t.next_interrupt(1801), 1000u + 1600u);
    EXPECT_EQ(t.read_cnt(1000 + 8 * 37 + 7), 37u);
    EXPECT_EQ(t.read_cnt(1000 + 800), 0u);
    EXPECT_EQ(t.read_cnt(1000 + 8 * 150), 50u);
    t.write_ctl(regs::timer::ctl_clksrc, 1000 + 8 * 150);  // hold
    EXPECT_FALSE(t.counting());
    EXPECT_EQ(t.read_cnt(50000), 50u);
    EXPECT_EQ(t.next_interrupt(50000), c6416::timer_unit::never);
    t.write_ctl(regs::timer::ctl_clksrc | regs::timer::ctl_hld, 60000);  // resume at 50
    EXPECT_EQ(t.next_interrupt(60000), 60000u + 8u * 50u);
    t.write_ctl(regs::timer::ctl_hld, 70000);  // external clock: not modelled, stands still
    EXPECT_FALSE(t.counting());
}
