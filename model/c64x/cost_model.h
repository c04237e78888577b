// C64x cycle cost model: how many CPU cycles a hand-scheduled TMS320C64x
// kernel takes, from a description of how it is coded (docs/design-brief.md, "Firmware
// timing"). The firmware runs natively on the host; simulated time advances
// by these modelled cycles.
//
// A kernel call is an operation profile: a few sections, each a
// software-pipelined loop (or a straight-line block) described by the
// operations ONE iteration issues on each functional-unit class of the C64x
// (.L .S .M .D, two units each: side A and B; docs/hardware-facts.md section 1),
// its trip count, how often it is entered, the latency of its critical
// dependence chain and any loop-carried recurrence. Then
//
//   II(section)     = max(resource bound, recurrence, 1), where the resource
//                     bound is max over classes of ceil(ops on class / 2)
//                     after the flexible ops (ADD, AND, PACK...) have been put
//                     on the least loaded class that can run them;
//   cycles(section) = entries * (iterations * II + (chain - 1)
//                                + loop_overhead if it is a loop);
//   cycles(kernel)  = calls * call_overhead + sum of sections
//                     (x compiled_c_factor) + memory stall cycles.
//
// Why chain - 1: a pipelined loop issues an iteration every II cycles; the
// last iteration issues its ops over II cycles and its critical chain drains
// after its last issue slot, so N iterations take (N - 1) * II + II - 1 +
// chain = N * II + chain - 1 cycles (prologue + kernel + epilogue).
//
// Latencies (1 + delay slots): loads 5 (4 delay slots; the standard C6000
// load, marked unverified in docs/hardware-facts.md section 1), DOTPU4 4 (3 delay
// slots, [BINU] "4cycle"), 16-bit multiplies (MPY, MPY2, XPND4, the "1616_m"
// class) 2, .L/.S/.D ALU ops 1, stores 1 (nothing in the kernel waits on
// them).
//
// Memory: profiles carry the bytes they stream and where those bytes live.
// The fitting formulas of TI IMGLIB assume data already in L1D; frame data
// in L2 SRAM pays L1D misses, frame data in SDRAM (EMIFA CE0) pays the EMIF
// transfers through the L2 cache. The constants that no source at hand gives
// are marked ASSUMED in model_params.
//
// Not modelled: the one cross path per side (and its stall after a write
// in the previous cycle), register pressure, L1D bank conflicts, interrupts,
// L1P misses. They are part of what the fitted loop overhead absorbs.
//
// Cost: a few dozen integer operations per kernel call; no allocation.
#pragma once

#include <cstdint>

namespace c64x {

// DSK clocks (docs/hardware-facts.md section 2): v1 600 MHz CPU / 100 MHz EMIF,
// v2 720 / 120, v3 (C6416T DSK) 1 GHz / 125 (the BSL says 120: discrepancy).
constexpr uint64_t dsk_v1_cpu_hz = 600'000'000;
constexpr uint64_t dsk_v2_cpu_hz = 720'000'000;
constexpr uint64_t dsk_v3_cpu_hz = 1'000'000'000;
constexpr uint64_t dsk_v1_emif_hz = 100'000'000;
constexpr uint64_t dsk_v2_emif_hz = 120'000'000;
constexpr uint64_t dsk_v3_emif_hz = 125'000'000;

// Instruction latencies in cycles (1 + delay slots), see the top comment.
constexpr uint32_t latency_load = 5;
constexpr uint32_t latency_dotpu4 = 4;
constexpr uint32_t latency_mpy16 = 2;
constexpr uint32_t latency_alu = 1;
constexpr uint32_t latency_store = 1;

constexpr uint32_t units_per_class = 2;  // one per side (A, B)

// Operations ONE iteration issues, by the units that can execute them
// ([BINU] tic6x-opcode-table.h; C64x added .D forms of ADD/SUB/AND/OR).
struct op_mix {
    uint32_t l = 0;    // .L only: SUBABS4, MINU4, MAXU4, ABS2, CMPLT(U), CMPEQ, LMBD, SUBC
    uint32_t s = 0;    // .S only: CMPGTU4, CMPEQ4, SPACKU4, SHL/SHRU(2), EXTU, B, BDEC
    uint32_t m = 0;    // .M only: DOTPU4, DOTP2, MPY(2,U), AVGU4, XPND4, BITC4
    uint32_t d = 0;    // .D only: LDB/LDW/LDDW/LDNDW, STB/STW/STDW
    uint32_t ls = 0;   // .L or .S: PACK2, PACKLH2, PACKL4, SHRMB, UNPKLU4, MVK, ABS
    uint32_t lsd = 0;  // .L, .S or .D: ADD, SUB, ADD2, SUB2, AND, OR, XOR, MV, ZERO
};

// Ops per class after placing the flexible ones.
struct unit_load {
    uint32_t l = 0, s = 0, m = 0, d = 0;
};

// Puts every flexible op, one at a time, on the least loaded class that can
// run it (.L/.S ops first: they have fewer choices). For these nested choice
// sets this water-filling gives the smallest possible maximum load.
unit_load place_ops(const op_mix& ops);

// max over classes of ceil(load / 2): the resource-bound initiation interval.
uint32_t resource_ii(const op_mix& ops);

// One section of a kernel: a software-pipelined loop, or a straight-line
// block (iterations = 1, no loop overhead).
struct loop_profile {
    const char* name = "";
    op_mix ops;               // per iteration
    uint64_t iterations = 0;  // trip count each time the loop is entered
    uint64_t entries = 1;     // times it is entered (product of outer trip counts)
    uint32_t chain = 1;       // latency of one iteration's critical path, cycles
    uint32_t recurrence = 0;  // loop-carried dependence bound on II, cycles
    bool is_loop = true;
};

loop_profile loop(const char* name, const op_mix& ops, uint64_t iterations, uint32_t chain,
                  uint64_t entries = 1, uint32_t recurrence = 0);
loop_profile block(const char* name, const op_mix& ops, uint32_t chain, uint64_t count = 1);

// Where streamed data lives.
enum class placement : uint8_t {
    l1d,   // already in L1D (what IMGLIB's cycle formulas assume)
    l2,    // L2 SRAM: every 64-byte L1D line read misses once
    sdram  // EMIFA CE0 SDRAM, reached through the L2 cache
};

struct memory_traffic {
    uint64_t bytes_read = 0;
    uint64_t bytes_written = 0;
    placement where = placement::l1d;
};

// A kernel call: its sections, the subroutine calls it makes (each pays the
// call overhead) and the data it streams. Fixed capacity, no allocation.
struct kernel_profile {
    static constexpr int max_sections = 16;
    static constexpr int max_traffic = 4;

    const char* name = "";
    uint64_t calls = 1;  // this call plus library calls it makes (e.g. __divu)
    loop_profile sections[max_sections];
    int section_count = 0;
    memory_traffic traffic[max_traffic];
    int traffic_count = 0;

    explicit kernel_profile(const char* kernel_name) : name(kernel_name) {}
    // Both ignore (and return false) past the capacity.
    bool add(const loop_profile& section);
    bool add(const memory_traffic& stream);
    // Appends `other`'s sections, traffic and calls, as if called `times`
    // times (a subroutine such as __divu).
    bool add_call(const kernel_profile& other, uint64_t times = 1);
};

// The bytes a kernel's SDRAM streams move: what its stalls wait for, and
// what a platform with a bus model puts on EMIFA.
struct sdram_bytes {
    uint64_t read = 0;
    uint64_t written = 0;
};
sdram_bytes sdram_bytes_of(const kernel_profile& kernel);

// The per-loop-entry overhead fitted on the IMGLIB formulas (value and
// method in cost_model.cpp, "FIT").
constexpr uint32_t fitted_loop_overhead = 2;

struct model_params {
    // Fitted / documented CPU parameters (see cost_model.cpp for the fit).
    uint32_t call_overhead = 6;  // cycles per call: IMGLIB's "includes 6 cycles of call overhead"
    uint32_t loop_overhead = fitted_loop_overhead;  // cycles per loop entry
    // Compiled C vs hand-scheduled: cycles scale by this factor (Q8, 256 = 1.0).
    // 1.0 = the hand-scheduled kernels these profiles describe.
    uint32_t compiled_c_factor_q8 = 256;

    // Memory. Facts: L1D line 64 B (docs/hardware-facts.md section 1); EMIFA
    // 64-bit, SDRAM on CE0 (section 3); EMIF and CPU clocks (section 2).
    uint32_t l1d_line_bytes = 64;
    uint32_t l1d_miss_l2_cycles = 6;  // ASSUMED: stall per L1D read miss served by L2 SRAM
    uint32_t l2_line_bytes = 128;     // ASSUMED: C64x L2 cache line (NOT FOUND in the sheet)
    // ASSUMED, = the EMIF engine's sdram_timing::access_cycles (ACTV + tRCD 2 + CAS
    // latency 3 + precharge 2): a line burst that finds its row closed, the
    // case whenever any other bus op came between two lines (docs/c6416.md).
    uint32_t sdram_access_eclk = 7;
    uint32_t emif_bus_bytes = 8;      // EMIFA data bus 64 bits (fact)
    uint64_t cpu_hz = dsk_v1_cpu_hz;  // only to turn EMIF time into CPU stall cycles
    uint64_t emif_hz = dsk_v1_emif_hz;
};

// Cycles of one section, broken down (for reports and tests).
struct section_cost {
    uint32_t ii = 0;
    uint32_t resource_ii = 0;
    uint64_t cycles = 0;
};

class cost_model {
  public:
    cost_model() = default;
    explicit cost_model(const model_params& params) : m_params(params) {}

    const model_params& params() const { return m_params; }
    // Names the model in every reported figure.
    const char* id() const { return "c64x-op-model-v1"; }

    section_cost section(const loop_profile& loop) const;
    // calls * call_overhead + sections, scaled by compiled_c_factor.
    uint64_t compute_cycles(const kernel_profile& kernel) const;
    // CPU stall cycles of the kernel's data streams.
    uint64_t memory_cycles(const kernel_profile& kernel) const;
    uint64_t memory_cycles(const memory_traffic& stream) const;
    // Time the EMIFA bus is busy with a stream's SDRAM bursts (0 unless sdram).
    uint64_t emif_busy_ps(const memory_traffic& stream) const;
    // compute_cycles + memory_cycles.
    uint64_t cycles(const kernel_profile& kernel) const;

  private:
    // EMIF clock cycles of the SDRAM line bursts a stream causes.
    uint64_t sdram_eclk_cycles(const memory_traffic& stream) const;

    model_params m_params;
};

// Cycles to time at a CPU clock: exact integer picoseconds (rounded to
// nearest) and 1/18 ns simulation ticks (docs/design-brief.md "Time"; exact for 600, 720
// and 1000 MHz: 30, 25 and 18 ticks per cycle).
uint64_t cycles_to_ps(uint64_t cycles, uint64_t cpu_hz);
uint64_t cycles_to_ticks(uint64_t cycles, uint64_t cpu_hz);
constexpr uint64_t ticks_per_second = 18'000'000'000ull;

// Software division as the C64x run-time library does it (no divide
// instruction): a call and a loop of one SUBC (.L) per quotient bit, each
// depending on the last; 64-bit operands (__divull) take 3 dependent ops
// per bit.
// LMBD normalisation makes only the quotient's significant bits iterate.
kernel_profile software_divide(uint32_t bits, bool wide_operands = false);
// Significant bits of a quotient known to be below `limit` (at least 1).
uint32_t quotient_bits(uint64_t limit);

// TI IMGLIB C64x kernels, described as they are coded, with the published
// cycle formulas (docs/hardware-facts.md section 5). The first four are the
// fitting set, the last four the check set.
namespace imglib {
kernel_profile sad_8x8();                // 31
kernel_profile mad_8x8(int sx, int sy);  // 8 sx sy + 66
kernel_profile pix_sat(int n);           // 3 n / 16 + 13
kernel_profile corr_3x3(int n_out);      // 1.5 n_out + 22
kernel_profile sad_16x16();              // 67
kernel_profile mad_16x16(int h, int v);  // 38 h v + 20
kernel_profile pix_expand(int n);        // 3 n / 16 + 15
kernel_profile perimeter(int cols);      // 10 cols / 16 + 55
}  // namespace imglib

}  // namespace c64x
