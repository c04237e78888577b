// The C64x EMIF CE space control register (CECTLn) and the async timing it
// programs, in ECLKOUT cycles.
//
// Bit fields exactly as docs/hardware-facts.md section 3 gives them from TI's CSL
// (csl_emifahal.h): WRSETUP 31:28, WRSTRB 27:22, WRHLD 21:20 plus WRHLDMSB
// bit 3 (the C64x's third hold bit), RDSETUP 19:16, TA 15:14, RDSTRB 13:8,
// MTYPE 7:4, RDHLD 2:0.
//
// ASSUMED (the facts mark it NOT FOUND, docs/emif.md): a timing field of 0
// acts as 1, so every setup, strobe, hold and turnaround lasts at least one
// ECLK cycle. The card's test master (tests/rtl/emif_master.h) assumes the same.
#pragma once

#include <cstdint>

#include "model/c6416/c6416_regs.h"

namespace emif {

// MTYPE values (docs/hardware-facts.md section 3), one definition with the
// firmware's register header.
using memory_type = c6416::emifa::mtype;

bool is_sdram(memory_type t);
bool is_async(memory_type t);

// The decoded register: field values as programmed (raw) and the cycle
// counts the engine uses (effective: 0 acts as 1).
struct async_timing {
    uint32_t write_setup = 1;   // WS
    uint32_t write_strobe = 1;  // WST
    uint32_t write_hold = 1;    // WH (3 bits with WRHLDMSB)
    uint32_t read_setup = 1;    // RS
    uint32_t turnaround = 1;    // TA
    uint32_t read_strobe = 1;   // RST
    uint32_t read_hold = 1;     // RH
    memory_type type = memory_type::async8;

    // ECLK cycles of one access, setup + strobe + hold, without wait states.
    uint32_t read_cycles() const { return read_setup + read_strobe + read_hold; }
    uint32_t write_cycles() const { return write_setup + write_strobe + write_hold; }
};

// The raw fields (no 0 -> 1 substitution), for encode/decode round trips.
struct cectl_fields {
    uint32_t wrsetup = 0, wrstrb = 0, wrhld = 0, rdsetup = 0, ta = 0, rdstrb = 0, mtype = 0,
             rdhld = 0;
};

cectl_fields cectl_unpack(uint32_t cectl);
// Field values out of range are truncated to their width.
uint32_t cectl_pack(const cectl_fields& f);
async_timing decode_cectl(uint32_t cectl);

// Register values used on the DSK (docs/hardware-facts.md section 3, [GEL]/[BSL]).
inline constexpr uint32_t cectl_dsk_v1 = 0x22A28A22;  // CE2/CE3 at 100 MHz: 2/10/2, TA 2, ASYNC32
inline constexpr uint32_t cectl_dsk_v2 = 0x23228C22;  // CE2/CE3 at 120/125 MHz: 2/12/2, TA 2
inline constexpr uint32_t cectl_sdram_dsk = 0xFFFFFFD3;  // CE0: SDRAM64
// Reset value DERIVED from the facts' per-field reset defaults (0xF, 0x3F,
// 3, 0xF, 3, 0x3F, MTYPE 0, 3; WRHLDMSB taken as 0).
inline constexpr uint32_t cectl_reset = 0xFFFFFF03;

// EMIFA CE spaces: CE0 0x80000000, CE1 0x90000000, CE2 0xA0000000,
// CE3 0xB0000000, 256 MB each (docs/hardware-facts.md section 3; [TR] for CE2/CE3).
inline constexpr uint32_t ce_base(int ce) {
    return 0x80000000u + (static_cast<uint32_t>(ce) << 28);
}
// CE space of an EMIFA byte address, or -1 outside 0x80000000..0xBFFFFFFF.
inline constexpr int ce_of_address(uint32_t address) {
    return (address >> 30) == 2u ? static_cast<int>((address >> 28) & 3u) : -1;
}

}  // namespace emif
