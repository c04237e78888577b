// TMS320C6416 register addresses and bit fields: the ONE source used by the
// C6416 model (model/c6416), the platform's board wiring, and the reference
// firmware (dsp/control_program.cpp), which includes it as a real firmware
// includes TI's CSL headers: the map is the chip's.
// Plain constants, no dependencies. Sources (keys of docs/hardware-facts.md):
//   [DS]  C6416 data sheet SPRS146 (memory map Table 3, EDMA Table 8/25,
//         interrupt selector Table 26);
//   [CSL] TI Chip Support Library hal headers (csl_emifahal.h,
//         csl_edmahal.h, csl_irqhal.h, csl_irq.h, csl_timerhal.h) of the
//         C6000 CSL shipped with the DSK;
//   [GEL] DSK6416.gel init_emif() (the DSK's EMIF settings);
//   [TR]  Spectrum Digital DSK technical reference.
// A value no source at hand confirms is marked ASSUMED. docs/c6416.md has
// the table with each source.
#pragma once

#include <cstdint>

namespace c6416 {

// ---- memory map [DS] Table 3 -------------------------------------------------------------
constexpr uint32_t l2_base = 0x00000000u;   // internal L2 SRAM (all of it mapped, no L2 cache)
constexpr uint32_t l2_bytes = 0x00100000u;  // 1 MB [DS] p.1
constexpr uint32_t emifa_ce0_base = 0x80000000u;
constexpr uint32_t emifa_ce1_base = 0x90000000u;
constexpr uint32_t emifa_ce2_base = 0xA0000000u;  // daughter card [TR]
constexpr uint32_t emifa_ce3_base = 0xB0000000u;  // daughter card [TR]
constexpr uint32_t emifa_ce_bytes = 0x10000000u;  // 256 MB per CE space
constexpr uint32_t sdram_base = emifa_ce0_base;   // DSK SDRAM on EMIFA CE0 [TR]
constexpr uint32_t sdram_bytes = 0x01000000u;     // 16 MB [TR]

// True for an address in EMIFA CE0..CE3 (0x80000000-0xBFFFFFFF).
constexpr bool in_emifa(uint32_t address) {
    return address >= emifa_ce0_base && address < emifa_ce0_base + 4 * emifa_ce_bytes;
}
// True for [address, address + bytes) inside the DSK's SDRAM.
constexpr bool in_sdram(uint32_t address, uint32_t bytes = 1) {
    return address >= sdram_base &&
           uint64_t{address} + bytes <= uint64_t{sdram_base} + uint64_t{sdram_bytes};
}
// The CE space number (0..3) of an EMIFA address.
constexpr int emifa_ce_of(uint32_t address) {
    return static_cast<int>((address - emifa_ce0_base) / emifa_ce_bytes);
}

// ---- EMIFA control registers [CSL csl_emifahal.h; GEL] -----------------------------------
namespace emifa {
constexpr uint32_t base = 0x01800000u;
constexpr uint32_t gblctl = 0x01800000u;
constexpr uint32_t cectl1 = 0x01800004u;
constexpr uint32_t cectl0 = 0x01800008u;
constexpr uint32_t cectl2 = 0x01800010u;
constexpr uint32_t cectl3 = 0x01800014u;
constexpr uint32_t sdctl = 0x01800018u;
constexpr uint32_t sdtim = 0x0180001Cu;
constexpr uint32_t sdext = 0x01800020u;
constexpr uint32_t cesec1 = 0x01800044u;
constexpr uint32_t cesec0 = 0x01800048u;
constexpr uint32_t cesec2 = 0x01800050u;
constexpr uint32_t cesec3 = 0x01800054u;
constexpr uint32_t block_bytes = 0x58u;  // [GEL] memory map: "EMIFA CTL REGS" 0x58 bytes

// CECTLn address of CE space n (the offsets are not in CE order).
constexpr uint32_t cectl(int ce) {
    return ce == 0 ? cectl0 : ce == 1 ? cectl1 : ce == 2 ? cectl2 : cectl3;
}

// CECTL fields (C64x) [CSL]. Units: ECLKOUT1 cycles.
constexpr uint32_t cectl_wrsetup_shift = 28, cectl_wrsetup_mask = 0xF0000000u;
constexpr uint32_t cectl_wrstrb_shift = 22, cectl_wrstrb_mask = 0x0FC00000u;
constexpr uint32_t cectl_wrhld_shift = 20, cectl_wrhld_mask = 0x00300000u;
constexpr uint32_t cectl_rdsetup_shift = 16, cectl_rdsetup_mask = 0x000F0000u;
constexpr uint32_t cectl_ta_shift = 14, cectl_ta_mask = 0x0000C000u;
constexpr uint32_t cectl_rdstrb_shift = 8, cectl_rdstrb_mask = 0x00003F00u;
constexpr uint32_t cectl_mtype_shift = 4, cectl_mtype_mask = 0x000000F0u;
constexpr uint32_t cectl_wrhldmsb_shift = 3, cectl_wrhldmsb_mask = 0x00000008u;
constexpr uint32_t cectl_rdhld_shift = 0, cectl_rdhld_mask = 0x00000007u;
// Reset value: every field at its CSL default (WRSETUP 15, WRSTRB 63, WRHLD 3,
// RDSETUP 15, TA 3, RDSTRB 63, MTYPE 0, RDHLD 3).
constexpr uint32_t cectl_reset = 0xFFFFFF03u;

enum class mtype : uint8_t {
    async8 = 0x0,
    async16 = 0x1,
    async32 = 0x2,
    sdram32 = 0x3,
    sync32 = 0x4,
    sdram8 = 0x8,
    sdram16 = 0x9,
    sync8 = 0xA,
    sync16 = 0xB,
    async64 = 0xC,
    sdram64 = 0xD,
    sync64 = 0xE,
};

// The EMIF model decodes CECTL with these fields (model/emif/cectl.h).

// The DSK's settings [GEL init_emif(); BSL]. v1 = 100 MHz EMIF, v2/v3 = 120/125 MHz.
constexpr uint32_t dsk_gblctl = 0x00012070u;         // EK2EN=1, ECLKOUT2 = EMIF clock
constexpr uint32_t dsk_cectl0_sdram = 0xFFFFFFD3u;   // CE0: SDRAM64
constexpr uint32_t dsk_cectl_card_v1 = 0x22A28A22u;  // CE2/CE3: 2/10/2 ASYNC32, TA 2
constexpr uint32_t dsk_cectl_card_v2 = 0x23228C22u;  // CE2/CE3: 2/12/2 ASYNC32, TA 2
constexpr uint32_t dsk_sdctl = 0x47115000u;
constexpr uint32_t dsk_sdtim_v1 = 0x00000618u;  // refresh period 1560 ECLK = 15.6 us at 100 MHz
constexpr uint32_t dsk_sdtim_v2 = 0x00000750u;  // 1872 ECLK = 15.6 us at 120 MHz
constexpr uint32_t dsk_sdext_v1 = 0x000A8529u;
constexpr uint32_t dsk_sdext_v2 = 0x001FAF4Du;
constexpr uint32_t sdtim_period_mask = 0x00000FFFu;  // refresh PERIOD field
}  // namespace emifa

// ---- interrupt selector [CSL csl_irqhal.h, csl_irq.h; DS Table 26] -----------------------
namespace irq {
constexpr uint32_t muxh = 0x019C0000u;  // selects INT10..INT15
constexpr uint32_t muxl = 0x019C0004u;  // selects INT4..INT9
constexpr uint32_t extpol = 0x019C0008u;
constexpr uint32_t extpol_mask =
    0x0000000Fu;  // XIP bit n: EXT_INT(4+n) 0 = rising, 1 = falling edge

// 5-bit INTSEL field of CPU interrupt n (4..15): register and shift.
constexpr uint32_t intsel_register(int cpu_int) {
    return cpu_int >= 10 ? muxh : muxl;
}
constexpr uint32_t intsel_shift(int cpu_int) {
    // INTSEL4/10 at bit 0, 5/11 at 5, 6/12 at 10, 7/13 at 16, 8/14 at 21, 9/15 at 26.
    constexpr uint32_t shifts[6] = {0, 5, 10, 16, 21, 26};
    return shifts[(cpu_int - 4) % 6];
}
constexpr uint32_t intsel_mask = 0x1Fu;

// Interrupt selector codes (event numbers) [CSL csl_irq.h IRQ_EVT_*].
constexpr uint32_t sel_dspint = 0;
constexpr uint32_t sel_tint0 = 1;
constexpr uint32_t sel_tint1 = 2;
constexpr uint32_t sel_sd_inta = 3;
constexpr uint32_t sel_gpint4 = 4;  // = EXT_INT4
constexpr uint32_t sel_gpint5 = 5;
constexpr uint32_t sel_gpint6 = 6;
constexpr uint32_t sel_gpint7 = 7;
constexpr uint32_t sel_edma_int = 8;
constexpr uint32_t sel_emu_dtdma = 9;
constexpr uint32_t sel_emu_rtdxrx = 10;
constexpr uint32_t sel_emu_rtdxtx = 11;
constexpr uint32_t sel_gpint0 = 16;
constexpr uint32_t sel_tint2 = 19;
constexpr uint32_t sel_sd_intb = 20;

// Reset values [CSL field defaults; DS Table 26]: INT4-7 = EXT_INT4-7,
// INT8 = EDMA_INT, INT9 = EMU_DTDMA, INT10 = SD_INTA, INT11/12 = RTDX,
// INT13 = DSPINT, INT14 = TINT0, INT15 = TINT1.
constexpr uint32_t muxl_reset =
    (4u << 0) | (5u << 5) | (6u << 10) | (7u << 16) | (8u << 21) | (9u << 26);  // 0x250718A4
constexpr uint32_t muxh_reset =
    (3u << 0) | (10u << 5) | (11u << 10) | (0u << 16) | (1u << 21) | (2u << 26);  // 0x08202D43
constexpr uint32_t extpol_reset = 0;

// CPU interrupt numbers as the firmware uses them (the reset mapping).
constexpr int int_ext4 = 4, int_ext5 = 5, int_ext6 = 6, int_ext7 = 7;
constexpr int int_edma = 8;
constexpr int int_tint0 = 14, int_tint1 = 15;
}  // namespace irq

// ---- EDMA [CSL csl_edmahal.h; DS Table 8, Table 25] --------------------------------------
namespace edma {
constexpr int channels = 64;
constexpr uint32_t pram_base = 0x01A00000u;
constexpr uint32_t pram_bytes = 0x00000800u;
constexpr uint32_t entry_bytes = 0x18u;  // six 32-bit words
constexpr uint32_t entry_words = 6;
// Channel entries 0..63, then a null entry and a reserved one, then 19 link
// (reload) entries up to 0x01A007F7, then scratch [CSL _EDMA_LINK_START ...].
constexpr uint32_t null_entry = pram_base + entry_bytes * channels;  // 0x01A00600
constexpr uint32_t link_base = null_entry + 2 * entry_bytes;         // 0x01A00630
constexpr int link_entries = static_cast<int>(pram_bytes / entry_bytes) - (channels + 2);  // 19

constexpr uint32_t entry(int channel) {
    return pram_base + entry_bytes * static_cast<uint32_t>(channel);
}
constexpr uint32_t link_entry(int n) {
    return link_base + entry_bytes * static_cast<uint32_t>(n);
}
// Word offsets inside an entry.
constexpr uint32_t opt = 0x00, src = 0x04, cnt = 0x08, dst = 0x0C, idx = 0x10, rld = 0x14;

// OPT fields [CSL].
constexpr uint32_t opt_pri_shift = 29, opt_pri_mask = 0xE0000000u;
constexpr uint32_t opt_esize_shift = 27, opt_esize_mask = 0x18000000u;  // 0 32-bit 1 16-bit 2 8-bit
constexpr uint32_t opt_2ds = 0x04000000u;
constexpr uint32_t opt_sum_shift = 24, opt_sum_mask = 0x03000000u;  // 0 fixed 1 inc 2 dec 3 index
constexpr uint32_t opt_2dd = 0x00800000u;
constexpr uint32_t opt_dum_shift = 21, opt_dum_mask = 0x00600000u;
constexpr uint32_t opt_tcint = 0x00100000u;
constexpr uint32_t opt_tcc_shift = 16, opt_tcc_mask = 0x000F0000u;    // TCC[3:0]
constexpr uint32_t opt_tccm_shift = 13, opt_tccm_mask = 0x00006000u;  // TCC[5:4] (C64x)
constexpr uint32_t opt_atcint = 0x00001000u;
constexpr uint32_t opt_atcc_shift = 5, opt_atcc_mask = 0x000007E0u;
constexpr uint32_t opt_pdts = 0x00000008u;
constexpr uint32_t opt_pdtd = 0x00000004u;
constexpr uint32_t opt_link = 0x00000002u;
constexpr uint32_t opt_fs = 0x00000001u;

constexpr uint32_t esize_32 = 0, esize_16 = 1, esize_8 = 2;
constexpr uint32_t mode_fixed = 0, mode_inc = 1, mode_dec = 2, mode_index = 3;

// OPT of a transfer: the 6-bit completion code goes to TCC and TCCM.
constexpr uint32_t opt_tcc(uint32_t code) {
    return ((code & 0xFu) << opt_tcc_shift) | (((code >> 4) & 0x3u) << opt_tccm_shift);
}
constexpr uint32_t opt_tcc_code(uint32_t opt_value) {
    return ((opt_value & opt_tcc_mask) >> opt_tcc_shift) |
           (((opt_value & opt_tccm_mask) >> opt_tccm_shift) << 4);
}
// CNT = FRMCNT (frames/arrays - 1) : ELECNT; IDX = FRMIDX : ELEIDX (signed 16 bit);
// RLD = ELERLD : LINK (low 16 bits of the reload entry's address).
constexpr uint32_t make_cnt(uint32_t frame_count_minus_1, uint32_t element_count) {
    return (frame_count_minus_1 << 16) | (element_count & 0xFFFFu);
}
constexpr uint32_t make_idx(int32_t frame_index, int32_t element_index) {
    return (static_cast<uint32_t>(frame_index) << 16) |
           (static_cast<uint32_t>(element_index) & 0xFFFFu);
}
constexpr uint32_t make_rld(uint32_t element_reload, uint32_t link_address) {
    return (element_reload << 16) | (link_address & 0xFFFFu);
}

// Channel registers, low half (channels 0-31) and high half (32-63) [CSL].
constexpr uint32_t cipr_l = 0x01A0FFE4u, cipr_h = 0x01A0FFA4u;  // W1C
constexpr uint32_t cier_l = 0x01A0FFE8u, cier_h = 0x01A0FFA8u;
constexpr uint32_t ccer_l = 0x01A0FFECu, ccer_h = 0x01A0FFACu;
constexpr uint32_t er_l = 0x01A0FFF0u, er_h = 0x01A0FFB0u;  // read only
constexpr uint32_t eer_l = 0x01A0FFF4u, eer_h = 0x01A0FFB4u;
constexpr uint32_t ecr_l = 0x01A0FFF8u, ecr_h = 0x01A0FFB8u;  // write 1: clear ER bit
constexpr uint32_t esr_l = 0x01A0FFFCu, esr_h = 0x01A0FFBCu;  // write 1: set event (start)
constexpr uint32_t epr_l = 0x01A0FFDCu, epr_h = 0x01A0FF9Cu;  // event polarity (not modelled)
constexpr uint32_t pqsr = 0x01A0FFE0u;
constexpr uint32_t pqar0 = 0x01A0FFC0u;      // PQAR0..3 at +0, +4, +8, +C
constexpr uint32_t regs_base = 0x01A0FF9Cu;  // [GEL] "EDMA REGS" 0x01A0FF9C, 0x64 bytes
constexpr uint32_t regs_bytes = 0x64u;

// Event-to-channel mapping [DS Table 25]: ch 4-7 = EXT_INT4-7, ch 1/2/19 = TINT0/1/2.
constexpr int channel_ext_int4 = 4;
constexpr int channel_tint0 = 1, channel_tint1 = 2, channel_tint2 = 19;
}  // namespace edma

// ---- timers [CSL csl_timerhal.h] ---------------------------------------------------------
namespace timer {
constexpr uint32_t base0 = 0x01940000u, base1 = 0x01980000u, base2 = 0x01AC0000u;
constexpr uint32_t ctl = 0x0, prd = 0x4, cnt = 0x8;  // offsets
constexpr uint32_t block_bytes = 0x0Cu;
constexpr uint32_t base(int n) {
    return n == 0 ? base0 : n == 1 ? base1 : base2;
}
// CTL fields [CSL].
constexpr uint32_t ctl_func = 0x001u;
constexpr uint32_t ctl_invout = 0x002u;
constexpr uint32_t ctl_datout = 0x004u;
constexpr uint32_t ctl_datin = 0x008u;
constexpr uint32_t ctl_pwid = 0x010u;
constexpr uint32_t ctl_go = 0x040u;      // write 1: reset CNT and start (with HLD = 1)
constexpr uint32_t ctl_hld = 0x080u;     // 0 = hold (counter stopped), 1 = count
constexpr uint32_t ctl_cp = 0x100u;      // 0 pulse, 1 clock mode
constexpr uint32_t ctl_clksrc = 0x200u;  // 1 = internal clock, CPU clock / 8 on C64x [CSL]
constexpr uint32_t ctl_invinp = 0x400u;
constexpr uint32_t ctl_tstat = 0x800u;
constexpr uint32_t cpu_cycles_per_internal_clock = 8;  // [CSL TIMER_CTL_CLKSRC_CPUOVR8]
}  // namespace timer

}  // namespace c6416
