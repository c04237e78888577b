#include "model/emif/cectl.h"

namespace emif {

bool is_sdram(memory_type t) {
    return t == memory_type::sdram8 || t == memory_type::sdram16 || t == memory_type::sdram32 ||
           t == memory_type::sdram64;
}

bool is_async(memory_type t) {
    return t == memory_type::async8 || t == memory_type::async16 || t == memory_type::async32 ||
           t == memory_type::async64;
}

cectl_fields cectl_unpack(uint32_t v) {
    namespace r = c6416::emifa;
    const auto field = [v](uint32_t mask, uint32_t shift) { return (v & mask) >> shift; };
    cectl_fields f;
    f.wrsetup = field(r::cectl_wrsetup_mask, r::cectl_wrsetup_shift);
    f.wrstrb = field(r::cectl_wrstrb_mask, r::cectl_wrstrb_shift);
    // WRHLDMSB is the hold's bit 2
    f.wrhld = field(r::cectl_wrhld_mask, r::cectl_wrhld_shift) |
              (field(r::cectl_wrhldmsb_mask, r::cectl_wrhldmsb_shift) << 2);
    f.rdsetup = field(r::cectl_rdsetup_mask, r::cectl_rdsetup_shift);
    f.ta = field(r::cectl_ta_mask, r::cectl_ta_shift);
    f.rdstrb = field(r::cectl_rdstrb_mask, r::cectl_rdstrb_shift);
    f.mtype = field(r::cectl_mtype_mask, r::cectl_mtype_shift);
    f.rdhld = field(r::cectl_rdhld_mask, r::cectl_rdhld_shift);
    return f;
}

uint32_t cectl_pack(const cectl_fields& f) {
    return ((f.wrsetup & 0xF) << 28) | ((f.wrstrb & 0x3F) << 22) | ((f.wrhld & 0x3) << 20) |
           ((f.rdsetup & 0xF) << 16) | ((f.ta & 0x3) << 14) | ((f.rdstrb & 0x3F) << 8) |
           ((f.mtype & 0xF) << 4) | (((f.wrhld >> 2) & 1) << 3) | (f.rdhld & 0x7);
}

async_timing decode_cectl(uint32_t v) {
    const cectl_fields f = cectl_unpack(v);
    const auto at_least_1 = [](uint32_t x) { return x == 0 ? 1u : x; };  // ASSUMED, see cectl.h
    async_timing t;
    t.write_setup = at_least_1(f.wrsetup);
    t.write_strobe = at_least_1(f.wrstrb);
    t.write_hold = at_least_1(f.wrhld);
    t.read_setup = at_least_1(f.rdsetup);
    t.turnaround = at_least_1(f.ta);
    t.read_strobe = at_least_1(f.rdstrb);
    t.read_hold = at_least_1(f.rdhld);
    t.type = static_cast<memory_type>(f.mtype);
    return t;
}

}  // namespace emif
