// Op profiles of the firmware kernels as a C64x engineer would hand-code
// them, run through the C64x cost model. Counts are per loop iteration;
// "l s m d ls lsd" are the unit classes of c64x::op_mix. Loads are
// LDDW/LDNDW (8 bytes), stores STDW, unless said otherwise. Every loop ends
// in a B (.S) and most decrement a counter (one lsd op); pointer increments
// ride in the load/store addressing modes and cost nothing.
#include "dsp/kernel_costs.h"

#include <algorithm>

namespace dsp::cost {

namespace {

using c64x::block;
using c64x::kernel_profile;
using c64x::latency_alu;
using c64x::latency_dotpu4;
using c64x::latency_load;
using c64x::latency_mpy16;
using c64x::latency_store;
using c64x::loop;
using c64x::memory_traffic;
using c64x::op_mix;
using c64x::placement;

uint64_t non_negative(int v) {
    return v > 0 ? static_cast<uint64_t>(v) : 0;
}

uint64_t ceil_div(uint64_t a, uint64_t b) {
    return (a + b - 1) / b;
}

uint32_t ceil_log2(uint64_t n) {
    uint32_t bits = 0;
    while (bits < 63 && (uint64_t{1} << bits) < n) ++bits;
    return bits;
}

placement placed(memory where) {
    return where == memory::sdram ? placement::sdram : placement::l2;
}

memory_traffic stream(uint64_t read, uint64_t written, placement where) {
    memory_traffic t;
    t.bytes_read = read;
    t.bytes_written = written;
    t.where = where;
    return t;
}

// ASSUMED scene statistics the kernels' arguments do not carry:
constexpr uint64_t mean_run_length = 16;         // foreground pixels per run (connected components)
constexpr uint64_t pixels_per_boundary = 16;     // edge boundaries: one per 16 px of a line
constexpr uint64_t pixels_per_boundary_run = 2;  // a step edge lights two Sobel columns

}  // namespace

const c64x::cost_model& default_model() {
    static const c64x::cost_model model;
    return model;
}

kernel_profile demosaic_gray_profile(int width, int height, memory where) {
    return demosaic_gray_profile(width, height, where, where);
}

kernel_profile demosaic_gray_profile(int width, int height, memory gray_where, memory raw_where) {
    // Fused bilinear demosaic + gray + mean, 4 output pixels of a row (two
    // Bayer pairs) per iteration, exact rounding as dsp/bayer_demosaic.h:
    //   d 4:  LDNDW of rows y-1, y, y+1 at x-1 (8 bytes each), STW of 4 gray
    //   ls 6: SHRMB / PACKLH2 give each row's words at x and x+1
    //   m 2:  AVGU4 = (a+b+1)>>1 exactly: horizontal and vertical pairs
    //   lsd 8 + 6 + 2, s 2: the two 4-neighbour means (cross, diagonal) in
    //         16-bit lanes: AND 0x00FF00FF x4, ADD2 x3, ADD2 +2, SHRU2 each
    //   s 3, lsd 1: odd lanes of the pair means and raw samples (SHRU2),
    //         even raw samples (AND)
    //   m 6:  MPY2 of R, G, B lane pairs by the Q14 weights (2 px per MPY2)
    //   lsd 12, s 4: per pixel 2 ADDs, + 8192, SHRU 14
    //   ls 3: PACK2 x2 + PACKL4 pack 4 gray bytes
    //   m 1, lsd 1: DOTPU4 with 0x01010101 + ADD for the frame mean
    //   s 1, lsd 1: B, counter
    // Totals: l 0, s 10, m 9, d 4, ls 9, lsd 31 -> II 9 (L/S/D bound: 54
    // ops on 6 units), 2.25 cycles/pixel.
    // Per row: the two border columns (reflect-101) in scalar code and the
    // row pointers: d 6, s 2, m 6, lsd 12.
    const uint64_t w = non_negative(width), h = non_negative(height);
    kernel_profile p("demosaic_gray");
    p.add(loop("4 pixels", op_mix{/*l*/ 0, /*s*/ 10, /*m*/ 9, /*d*/ 4, /*ls*/ 9, /*lsd*/ 31},
               ceil_div(w, 4),
               latency_load + latency_alu + latency_alu + 2 * latency_alu + 2 * latency_alu +
                   latency_mpy16 + 3 * latency_alu + latency_alu + 2 * latency_alu + latency_store,
               h));
    p.add(block("row set-up, border columns", op_mix{0, /*s*/ 2, /*m*/ 6, /*d*/ 6, 0, /*lsd*/ 12},
                latency_load + 3 * latency_alu + latency_mpy16 + 3 * latency_alu + latency_store,
                h));
    // Raw read (each byte 3 times; L1D serves all but the first), gray written.
    if (gray_where == raw_where) {
        p.add(stream(w * h, w * h, placed(raw_where)));
    } else {
        p.add(stream(w * h, 0, placed(raw_where)));
        p.add(stream(0, w * h, placed(gray_where)));
    }
    return p;
}

kernel_profile brightness_profile(int width, int height, memory where) {
    // gain = 256 * target / mean: one __divu (gain <= 1024: 11 quotient bits).
    // Table, 256 entries, one per iteration: MPY p * gain (m), ADD 128,
    // SHRU 8 (s), CMPGTU 255 (l), conditional MVK 255 (ls), STB (d),
    // counter + value (lsd 2), B: II 2.
    // Apply, 8 pixels per iteration (lookups cannot be SIMD):
    //   d 10: LDDW, 8 LDBU from the table, STDW
    //   s 6, lsd 2: byte indices (EXTU x4, SHRU x2; AND x2)
    //   ls 4, s 2, lsd 2: PACK2 x4, SHL x2, OR x2 repack the 8 bytes
    //   s 1, lsd 1: B, counter
    // -> II 5 (D bound), 0.625 cycles/pixel. In place: reads and writes the
    // frame.
    const uint64_t w = non_negative(width), h = non_negative(height);
    kernel_profile p("brightness");
    p.add_call(c64x::software_divide(c64x::quotient_bits(1025)));
    p.add(loop("table entry", op_mix{/*l*/ 1, /*s*/ 2, /*m*/ 1, /*d*/ 1, /*ls*/ 1, /*lsd*/ 2}, 256,
               latency_mpy16 + 4 * latency_alu + latency_store));
    p.add(loop("8 pixels", op_mix{0, /*s*/ 9, 0, /*d*/ 10, /*ls*/ 4, /*lsd*/ 5}, ceil_div(w, 8),
               latency_load + latency_alu + latency_load + 3 * latency_alu + latency_store, h));
    p.add(stream(w * h, w * h, placed(where)));
    return p;
}

kernel_profile three_frame_difference_profile(int width, int height, memory where) {
    // object = (|f0-f1| > th) & (|f1-f2| > th) = MINU4(|f0-f1|, |f1-f2|) > th,
    // 8 pixels per iteration:
    //   d 4: 3 LDDW, STDW      l 6: 4 SUBABS4, 2 MINU4
    //   s 3: 2 CMPGTU4, B      m 2: XPND4 (4-bit mask -> 0/255 bytes)
    //   lsd 1: counter
    // -> II 3 (L bound), 0.375 cycles/pixel.
    const uint64_t w = non_negative(width), h = non_negative(height);
    kernel_profile p("three_frame_difference");
    p.add(loop("8 pixels", op_mix{/*l*/ 6, /*s*/ 3, /*m*/ 2, /*d*/ 4, /*ls*/ 0, /*lsd*/ 1},
               ceil_div(w, 8),
               latency_load + 3 * latency_alu + latency_mpy16 + latency_alu + latency_store, h));
    p.add(stream(3 * w * h, w * h, placed(where)));
    return p;
}

kernel_profile three_frame_difference_packed_profile(int width, int height, memory where) {
    // object = Dif(t-2,t-1) & (|f1-f2| > th), Dif(t-1,t) stored back packed,
    // 8 pixels per iteration:
    //   d 5: 2 LDDW, LDBU (stored bits), STB (new bits), STDW (object bytes)
    //   l 2: 2 SUBABS4     s 4: 2 CMPGTU4, SHL (high nibble), B
    //   m 2: 2 XPND4 (object bits -> 0/255 bytes)
    //   lsd 3: OR (new byte), AND (object), counter
    // -> II 3 (.D / .L bound), 0.375 cycles/pixel; 2 1/8 bytes read and
    // 1/8 written per pixel besides the object row (which stays in L1D: the
    // detector's row pipeline consumes it at once).
    const uint64_t w = non_negative(width), h = non_negative(height);
    const uint64_t packed = ceil_div(w, 8) * h;
    kernel_profile p("three_frame_difference_packed");
    p.add(loop("8 pixels", op_mix{/*l*/ 2, /*s*/ 4, /*m*/ 2, /*d*/ 5, /*ls*/ 0, /*lsd*/ 3},
               ceil_div(w, 8),
               latency_load + latency_alu + latency_alu + latency_alu + latency_alu +
                   latency_mpy16 + latency_store,
               h));
    p.add(stream(2 * w * h + packed, packed, placed(where)));
    return p;
}

namespace {

// Dif(a, b) thresholded, 8 pixels per iteration:
//   d 3: 2 LDDW, STB      l 2: 2 SUBABS4
//   s 4: 2 CMPGTU4, SHL, B      lsd 2: OR, counter
// -> II 2 (.S / .D bound), 0.25 cycles/pixel.
c64x::loop_profile difference_loop(const char* name, uint64_t iterations, uint64_t rows) {
    return loop(name, op_mix{/*l*/ 2, /*s*/ 4, /*m*/ 0, /*d*/ 3, /*ls*/ 0, /*lsd*/ 2}, iterations,
                latency_load + 3 * latency_alu + latency_store, rows);
}

}  // namespace

kernel_profile difference_packed_profile(int width, int height, memory where) {
    const uint64_t w = non_negative(width), h = non_negative(height);
    const uint64_t packed = ceil_div(w, 8) * h;
    kernel_profile p("difference_packed");
    p.add(difference_loop("8 pixels", ceil_div(w, 8), h));
    p.add(stream(2 * w * h, packed, placed(where)));
    return p;
}

kernel_profile key_difference_profile(int width, int height, int hole_width, int hole_height) {
    // Dif(key, t) over a key's ring (dsp/key_frame.h moved_extent): the loop
    // of difference_packed over the held pixels (a row beside the hole: its
    // two segments); the key's bytes come from SDRAM, f(t)'s from L2, and
    // each row's bits go straight into the block counts (the row stays in
    // L1D): the ring read over the EMIF once, nothing written.
    const uint64_t w = non_negative(width), h = non_negative(height);
    const uint64_t hw = std::min(non_negative(hole_width), w);
    const uint64_t hh = std::min(non_negative(hole_height), h);
    const uint64_t ring = w * h - hw * hh;
    kernel_profile p("key_difference");
    p.add(difference_loop("8 pixels", ceil_div(w, 8), h - hh));
    if (hh > 0) p.add(difference_loop("8 pixels beside the hole", ceil_div(w - hw, 8) + 1, hh));
    p.add(stream(ring, 0, placement::sdram));
    p.add(stream(ring, 0, placement::l2));
    return p;
}

kernel_profile morphology_profile(int width, int height, int passes) {
    // Binary 3x3 erosion (AND) or dilation (OR) of a 0/255 mask, separable:
    // each iteration makes 8 pixels of the horizontal 3-AND of input row
    // y+1 into a 3-row ring (LDNDW x-1, LDDW x, LDNDW x+1, 4 ANDs, STDW) and
    // 8 output pixels of row y from the ring (3 LDDW, 4 ANDs, STDW):
    //   d 8, lsd 8 + counter, s 1 (B) -> II 4 (D bound), 0.5 cycles/pixel.
    // Per row: the edge doublewords with the outside as background
    // (d 4, s 2, lsd 6). Masks live in L2.
    const uint64_t w = non_negative(width), h = non_negative(height);
    const uint64_t rows = h * non_negative(passes);
    kernel_profile p("morphology_3x3");
    p.add(loop("8 pixels", op_mix{0, /*s*/ 1, 0, /*d*/ 8, 0, /*lsd*/ 9}, ceil_div(w, 8),
               latency_load + 2 * latency_alu + latency_store, rows));
    p.add(block("row edges", op_mix{0, /*s*/ 2, 0, /*d*/ 4, 0, /*lsd*/ 6},
                latency_load + 2 * latency_alu + latency_store, rows));
    p.add(stream(w * rows, w * rows, placement::l2));
    return p;
}

kernel_profile connected_components_profile(int width, int height, int foreground) {
    // Run-based 8-connected labelling (two label rows, union-find):
    // - clear the row above: 2 labels (STDW of -1) per iteration, II 1.
    // - scan, 8 pixels per iteration: LDDW, OR of the two words, 4 STDW of
    //   background labels, B out on a set pixel: d 5, lsd 2, s 1 -> II 3.
    // - run pixels, one per iteration: LDW label above, STW label (d 2),
    //   CMPLT / CMPEQ with the previous above-label (l 2), lsd 1 -> II 1;
    //   entered once per run.
    // - per run, not pipelinable: LMBD finds the run end; find_root (up to
    //   2 dependent LDW + compare + branch), union, bbox/area update (4 LDW,
    //   min/max, 4 STW): d 10, l 6, s 4, lsd 8, chain 2 x (load + compare +
    //   taken branch 6) + load + 2.
    // - resolve: per label (<= runs) LDW parent, LDW parent[parent], STW,
    //   merge stats: d 12, l 5, s 1, lsd 4; recurrence load + compare
    //   (a parent may be the entry just written).
    // - sort the components: ~n log2 n compare-and-swap steps of 8 cycles.
    // ASSUMED: runs = foreground / 16 (mean run length), labels = runs.
    const uint64_t w = non_negative(width), h = non_negative(height);
    const uint64_t fg = non_negative(foreground);
    const uint64_t runs = ceil_div(fg, mean_run_length);
    constexpr uint32_t taken_branch = 6;  // B + 5 delay slots nothing fills
    kernel_profile p("connected_components");
    p.add(loop("clear 2 labels", op_mix{0, /*s*/ 1, 0, /*d*/ 1, 0, /*lsd*/ 1}, ceil_div(w, 2),
               latency_store));
    p.add(loop("scan 8 pixels", op_mix{0, /*s*/ 1, 0, /*d*/ 5, 0, /*lsd*/ 2}, ceil_div(w, 8),
               latency_load + latency_alu + latency_store, h));
    if (runs > 0) {
        p.add(loop("run pixel", op_mix{/*l*/ 2, 0, 0, /*d*/ 2, 0, /*lsd*/ 1}, ceil_div(fg, runs),
                   latency_load + latency_alu + latency_store, runs));
        p.add(
            block("run: root, union, stats", op_mix{/*l*/ 6, /*s*/ 4, 0, /*d*/ 10, 0, /*lsd*/ 8},
                  2 * (latency_load + latency_alu + taken_branch) + latency_load + 2 * latency_alu,
                  runs));
        p.add(loop("resolve label", op_mix{/*l*/ 5, /*s*/ 1, 0, /*d*/ 12, 0, /*lsd*/ 4}, runs,
                   2 * latency_load + latency_load + 2 * latency_alu + latency_store, 1,
                   latency_load + latency_alu));
        p.add(block("sort step", op_mix{/*l*/ 1, /*s*/ 1, 0, /*d*/ 4, 0, 0},
                    latency_load + latency_alu + latency_alu + latency_store,
                    runs * (ceil_log2(runs) > 0 ? ceil_log2(runs) : 1)));
    }
    p.add(stream(w * h, 0, placement::l2));
    return p;
}

kernel_profile sad_search_profile(int pattern_w, int pattern_h, int positions) {
    // Per position, a software-pipelined loop over the pattern rows; one
    // iteration = one row of k = ceil(w/8) doublewords:
    //   d 2k: LDNDW image + LDDW pattern (rows zero-padded to 8)
    //   l 2k: SUBABS4      m 2k: DOTPU4 x 0x01010101 (sum of 4 |diffs|)
    //   lsd 2k: ADD tree + accumulate, + 1 counter, + 2 AND masks when
    //           w % 8 != 0 (image bytes past the pattern -> 0)
    //   s 1: B
    // e.g. 40 px: k 5 -> II 6 per row (L/S/D bound); a 40x40 position
    // costs 40 x 6 + 14 fill + 2 + 2 = 258 cycles (0.16 cycles/pixel).
    // Chain: load, SUBABS4, DOTPU4, log2(2k) ADDs, accumulate.
    // Per position: CMPLTU with the best (l), 2 conditional MVs, next
    // position and its pointer (lsd 3): chain compare + MV.
    // The search window (a few KB) stays in L1D after its first use; its
    // compulsory misses (< 1% of the total) are not charged.
    const uint64_t w = non_negative(pattern_w), h = non_negative(pattern_h);
    const uint64_t n = non_negative(positions);
    const uint32_t k = static_cast<uint32_t>(ceil_div(w, 8));
    const uint32_t tail_masks = (w % 8 != 0) ? 2 : 0;
    kernel_profile p("sad_search");
    p.add(loop(
        "pattern row",
        op_mix{/*l*/ 2 * k, /*s*/ 1, /*m*/ 2 * k, /*d*/ 2 * k, 0,
               /*lsd*/ 2 * k + 1 + tail_masks},
        h,
        latency_load + latency_alu + latency_dotpu4 + ceil_log2(2 * k) * latency_alu + latency_alu,
        n, latency_alu));
    p.add(block("compare with best, next position", op_mix{/*l*/ 1, 0, 0, 0, 0, /*lsd*/ 5},
                2 * latency_alu, n));
    p.add(block("store result", op_mix{0, 0, 0, /*d*/ 3, 0, 0}, latency_store));
    return p;
}

kernel_profile motion_blocks_profile(int width, int height) {
    // Per 16 mask bytes of a row (one block): 2 LDDW, the count as DOTPU4 of
    // the 0/1 bytes with 0x01010101 (m 4) and ADD (lsd 3), first
    // and last set byte by LMBD on the packed compare (l 2, s 2), LDBU/STB of
    // count and spans, MIN/MAX (d 5, lsd 4): m 4, l 2, s 2, d 7, lsd 7 -> II 3.
    // Grouping, per block: 9 loads of the neighbours' counts, compare, OR,
    // store (d 10, lsd 9) -> II 5; then the labeller on the block rows
    // (~blocks / 4 runs, bounded by connected_components' profile).
    // ASSUMED, no TI kernel of this shape; an estimate.
    const uint64_t w = non_negative(width), h = non_negative(height);
    const uint64_t blocks_x = ceil_div(w, 16), blocks = blocks_x * ceil_div(h, 16);
    kernel_profile p("motion_blocks");
    p.add(loop("row of a block", op_mix{/*l*/ 2, /*s*/ 2, /*m*/ 4, /*d*/ 7, 0, /*lsd*/ 7},
               blocks_x * h, latency_load + latency_alu + latency_store));
    p.add(loop("dilated block", op_mix{0, 0, 0, /*d*/ 10, 0, /*lsd*/ 9}, blocks,
               latency_load + latency_alu + latency_store));
    p.add_call(connected_components_profile(static_cast<int>(blocks_x),
                                            static_cast<int>(ceil_div(h, 16)),
                                            static_cast<int>(blocks / 4)));
    return p;
}

kernel_profile pattern_copy_profile(int pattern_w, int pattern_h) {
    // One collapsed loop over all doublewords of the pattern: LDNDW + STDW
    // (d 2), counter + conditional row step (lsd 2), B -> II 1, 8 px/cycle.
    const uint64_t w = non_negative(pattern_w), h = non_negative(pattern_h);
    kernel_profile p("pattern_copy");
    p.add(loop("doubleword", op_mix{0, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 2}, ceil_div(w, 8) * h,
               latency_load + latency_store));
    return p;
}

kernel_profile subpixel_profile() {
    // (S- - S+) * 128 / (S- - 2 S0 + S+): 3 SUB/ADD, 2 shifts, ABS x2 and
    // the sign, one __divu (|offset| <= 128 in Q8: 8 quotient bits), then
    // sign restore and clamp to +-128.
    kernel_profile p("subpixel");
    p.add(block("parabola terms", op_mix{/*l*/ 3, /*s*/ 2, 0, 0, 0, /*lsd*/ 6}, 4 * latency_alu));
    p.add_call(c64x::software_divide(c64x::quotient_bits(257)));
    p.add(block("sign, clamp", op_mix{/*l*/ 1, 0, 0, 0, 0, /*lsd*/ 3}, 3 * latency_alu));
    return p;
}

kernel_profile half_pel_profile(int pattern_w, int pattern_h) {
    // Two positions, a half pixel either side of the minimum; per word of 4
    // pixels, in halfwords: LDNW of the pattern and of the two left columns
    // (d 3), UNPKLU4/UNPKHU4 of each (ls 6), ADD2 x2 of the left pair and
    // x2 of the pattern to itself, SUB2 x2 (lsd 6), ABS2 x2 (l 2), DOTP2 x2
    // with 1s into the sum (m 2). ASSUMED, no TI kernel of this shape; an
    // estimate. A masked pattern is charged as its whole box.
    const uint64_t w = non_negative(pattern_w), h = non_negative(pattern_h);
    kernel_profile p("half_pel");
    p.add(loop("pattern word", op_mix{/*l*/ 2, 0, /*m*/ 2, /*d*/ 3, /*ls*/ 6, /*lsd*/ 6},
               2 * ceil_div(w, 4) * h,
               latency_load + 4 * latency_alu + latency_dotpu4 + latency_alu));
    return p;
}

kernel_profile surface_outline_profile(int rows, int columns, int inside) {
    // Per object row: the ellipse's half width, an integer square root by
    // bits (31 steps of ADD, MPY, CMPGTU, conditional add: l 2, m 1, lsd 2,
    // each waiting on the last: not pipelined) and one division by the height;
    // per tile row: the span clipped to the tile and summed (MIN, MAX, SUB,
    // ADD: l 4, lsd 2). Per tile matched inside the range: its SAD scaled to
    // the whole tile (one division).
    const uint64_t r = non_negative(rows), c = non_negative(columns);
    kernel_profile p("surface_outline");
    p.add(block("square root step", op_mix{/*l*/ 2, 0, /*m*/ 1, 0, 0, /*lsd*/ 2},
                latency_mpy16 + 2 * latency_alu, 31 * r));
    p.add_call(c64x::software_divide(16, true), r);
    p.add(loop("tile row span", op_mix{/*l*/ 4, 0, 0, 0, 0, /*lsd*/ 2}, r * c, latency_alu));
    p.add_call(c64x::software_divide(16, true), non_negative(inside));
    return p;
}

kernel_profile surface_mean_profile(int inside, int matched) {
    // The gate's insertion sort of `inside` SADs: n^2 / 4 shifts on
    // average (load, compare, store, branch; not pipelined: the compare
    // decides the next step), then the gate (one MPY, one add).
    // Per tile kept: the checks, d - offset, 2^32 / that (__divull,
    // ~18 quotient bits: a Q8 disparity of 64-256 px) and its sum; then
    // n 2^32 / sum (~16 quotient bits) and the offset back.
    const uint32_t m = static_cast<uint32_t>(non_negative(inside));
    const uint32_t n = static_cast<uint32_t>(non_negative(matched));
    kernel_profile p("surface_mean");
    p.add(block("sort step", op_mix{/*l*/ 1, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 1},
                latency_load + latency_alu + latency_store, m * m / 4 + m));
    p.add(block("tile checks, sum", op_mix{/*l*/ 4, 0, 0, 0, 0, /*lsd*/ 4}, 4 * latency_alu, n));
    p.add_call(c64x::software_divide(18, true), n);
    p.add_call(c64x::software_divide(16, true));
    return p;
}

kernel_profile sobel_profile(int width, int rows) {
    // IMG_sobel semantics, 4 output pixels per iteration in 16-bit lanes:
    //   d 4: LDNDW of rows y-1, y, y+1 at x-1, STW of 4 outputs
    //   ls 9 + 2: UNPKLU4/UNPKHU4 of the 3 rows, PACKLH2 for the centre column
    //   lsd 3 + 6: D = bottom - top (SUB2), H = D(x-1) + 2 D(x) + D(x+1)
    //   lsd 9 + 2: S = top + 2 mid + bottom (ADD2), V = S(x+1) - S(x-1)
    //   l 4: ABS2 of H and V    lsd 2: |H| + |V|
    //   s 1: SPACKU4 (saturate to 255 and pack)    s 1, lsd 1: B, counter
    // Totals: l 4, s 2, d 4, ls 11, lsd 24 -> II 8, 2 cycles/pixel.
    // Per row: zero the 2 border pixels, row pointers (d 2, lsd 3).
    // Sobel reads each input row three times; L1D serves all but the first.
    const uint64_t w = non_negative(width), r = non_negative(rows);
    const uint64_t inner = w > 2 ? w - 2 : 0;
    kernel_profile p("sobel_3x3");
    p.add(loop("4 pixels", op_mix{/*l*/ 4, /*s*/ 2, 0, /*d*/ 4, /*ls*/ 11, /*lsd*/ 24},
               ceil_div(inner, 4),
               latency_load + latency_alu + latency_alu + latency_alu + 3 * latency_alu +
                   latency_alu + latency_alu + latency_alu + latency_store,
               r));
    p.add(block("row borders", op_mix{0, 0, 0, /*d*/ 2, 0, /*lsd*/ 3}, latency_store, r));
    p.add(stream((r > 0 ? r + 2 : 0) * w, r * w, placement::l2));
    return p;
}

kernel_profile edge_match_profile(int width, int lines, int max_disparity, int min_disparity) {
    // Per line and image (2 x lines):
    // - threshold, 8 magnitudes per iteration: LDDW, 2 CMPGTU4, SHL + OR
    //   into a byte mask, STB: d 2, s 4 (incl. B), lsd 2 -> II 2.
    // - per edge run (boundary): its centroid; per run pixel LDBU, MPY
    //   x * magnitude, 2 ADDs (weight, moment); the run found with LMBD,
    //   range check, STW; moment * 256 / weight by __divu (18 quotient bits).
    // Per line and shift: the two boundary lists are merged both ways, one
    // boundary per iteration: 2 LDW, ADD shift, 2 SUB, 2 ABS, compare and
    // conditional MV for the nearest, cap (CMPLT + MV), ADD score, residual
    // (CMPLT + 2 conditional ADDs): l 5, s 1, d 2, lsd 8 -> II 3;
    // recurrence 3 (cursor advance: compare + conditional ADD + the next
    // entry selected from speculatively loaded registers).
    // Then the best shift (compare/select, recurrence 2) and one __divu for
    // the mean residual.
    // ASSUMED: one boundary per 16 px of a line, 2 edge pixels per boundary.
    const uint64_t w = non_negative(width), n_lines = non_negative(lines);
    const uint64_t shifts = max_disparity >= min_disparity
                                ? static_cast<uint64_t>(max_disparity - min_disparity) + 1
                                : 0;
    const uint64_t boundaries = ceil_div(w, pixels_per_boundary);
    const uint64_t scans = 2 * n_lines;
    kernel_profile p("edge_match");
    p.add(loop("threshold 8 magnitudes", op_mix{0, /*s*/ 4, 0, /*d*/ 2, 0, /*lsd*/ 2},
               ceil_div(w, 8), latency_load + 3 * latency_alu + latency_store, scans));
    if (boundaries > 0 && scans > 0) {
        p.add(loop("run pixel moment", op_mix{0, 0, /*m*/ 1, /*d*/ 1, 0, /*lsd*/ 2},
                   pixels_per_boundary_run, latency_load + latency_mpy16 + latency_alu,
                   scans * boundaries, latency_alu));
        p.add(block("run end, range check, store", op_mix{/*l*/ 4, /*s*/ 2, 0, /*d*/ 1, 0, 2},
                    3 * latency_alu + latency_store, scans * boundaries));
        p.add_call(c64x::software_divide(c64x::quotient_bits(uint64_t{1} << 18)),
                   scans * boundaries);
    }
    if (shifts > 0 && n_lines > 0) {
        p.add(loop("merge step", op_mix{/*l*/ 5, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 8}, 2 * boundaries,
                   latency_load + 2 * latency_alu + 2 * latency_alu + 2 * latency_alu,
                   shifts * n_lines, 3 * latency_alu));
        p.add(block("line score", op_mix{0, 0, 0, /*d*/ 2, 0, /*lsd*/ 2},
                    latency_load + latency_alu + latency_store, shifts * n_lines));
        p.add(loop("best shift", op_mix{/*l*/ 1, /*s*/ 1, 0, /*d*/ 1, 0, /*lsd*/ 2}, shifts,
                   latency_load + 2 * latency_alu, 1, 2 * latency_alu));
        p.add_call(c64x::software_divide(c64x::quotient_bits(257)));
    }
    p.add(stream(scans * w, 0, placement::l2));
    return p;
}

kernel_profile window_step_profile(int extents) {
    // dsp/extent_window.h, window_step2: each extent's size against half
    // the box (a compare and a branch), then the 2 (n - 1) edge steps and
    // their insertion sort, as window_fit_profile's; nothing below three.
    const uint32_t n = static_cast<uint32_t>(non_negative(extents));
    kernel_profile p("window_step");
    if (n < 3) return p;
    const uint32_t steps = 2 * (n - 1);
    p.add(block("size check", op_mix{/*l*/ 1, /*s*/ 1, 0, /*d*/ 1, 0, /*lsd*/ 1},
                latency_load + latency_alu, n));
    p.add(block("sort step", op_mix{/*l*/ 1, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 1},
                latency_load + latency_alu + latency_store, steps * steps / 4 + steps));
    return p;
}

kernel_profile detection_steps_profile() {
    // dsp/detection_steps.h: the box kept (4 words), then each of the 4
    // edges' 3 steps, a subtract and two compares against the step.
    kernel_profile p("detection_steps");
    p.add(block("keep box", op_mix{0, 0, 0, /*d*/ 2, 0, 0}, latency_load + latency_store, 4));
    p.add(block("edge step", op_mix{/*l*/ 2, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 1},
                latency_load + latency_alu, 4 * 3));
    return p;
}

kernel_profile size_at_depth_profile(int divides) {
    // dsp/size_at_depth.h: each size carried or extent narrowed is one __divu
    // of a size times a disparity by a disparity (a quotient of at most
    // 11 bits: a size under 2048 px), its rounding (MPY, ADD) and its centring
    // (SUB, SHR, ADD); the 1 % checks before it a MPY and a compare.
    const uint32_t n = static_cast<uint32_t>(non_negative(divides));
    kernel_profile p("size_at_depth");
    for (uint32_t i = 0; i < n; ++i) p.add_call(c64x::software_divide(c64x::quotient_bits(2048)));
    p.add(block("round and centre", op_mix{/*l*/ 2, /*s*/ 2, /*m*/ 2, /*d*/ 0, 0, /*lsd*/ 2},
                latency_mpy16 + 3 * latency_alu, n));
    return p;
}

kernel_profile round_box_profile() {
    // dsp/round_box.h, each tracked pair: the box's centre offsets (SUB,
    // SHL), two integer square roots by bits as the outline's (31 steps of
    // ADD, MPY, CMPGTU, conditional add, each waiting on the last), the
    // sphere's height from the width and width from the height (a __divu
    // each, quotients under 11 bits: sides under 2048 px) and the checks
    // (compares against the border and the eighth: l 6, s 2).
    kernel_profile p("round_box");
    p.add(block("square root step", op_mix{/*l*/ 2, 0, /*m*/ 1, 0, 0, /*lsd*/ 2},
                latency_mpy16 + 2 * latency_alu, 2 * 31));
    p.add_call(c64x::software_divide(c64x::quotient_bits(2048)), 2);
    p.add(block("offsets and checks", op_mix{/*l*/ 6, /*s*/ 2, /*m*/ 2, 0, 0, /*lsd*/ 2},
                latency_mpy16 + 4 * latency_alu, 1));
    return p;
}

kernel_profile extent_end_profile() {
    // dsp/box_refit.h, held_at_extent_end, each followed pair: per axis the
    // sizes compared, both ends' overshoot and the SAD box's offset (SUBs,
    // an ABS each), their compares and the conditional start (l 4, s 2).
    kernel_profile p("extent_end");
    p.add(block("axis", op_mix{/*l*/ 4, /*s*/ 2, 0, /*d*/ 2, 0, /*lsd*/ 2},
                latency_load + 2 * latency_alu, 2));
    return p;
}

kernel_profile size_depth_profile() {
    // dsp/size_at_depth.h, size_still_stands, each pair with a difference:
    // the two boxes' sizes compared (l 4), the disparities' change and its
    // eighth (SUB, ABS, shift, l 3), the silhouette's sides against the box's
    // (l 2) and the conditional move of the depth kept (s 1).
    kernel_profile p("size_depth");
    p.add(block("compare", op_mix{/*l*/ 9, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 1},
                latency_load + 3 * latency_alu, 1));
    return p;
}

kernel_profile depth_line_profile(bool replaced) {
    // dsp/depth_line.h on the triangulated depth: the three depths' line and
    // the pair's distance from it (5 SUB/ADD, 2 ABS, 2 shift-compares, l 9),
    // the history's shift (l 3, d 4). A replaced depth's disparity,
    // s f_px / D (dsp/triangulate.h), is one 64-bit divide (ASSUMED 24
    // quotient bits, as triangulate's) and f_px's; its point is charged as
    // a second triangulation by the caller.
    kernel_profile p("depth_line");
    p.add(block("line, compare, history", op_mix{/*l*/ 12, /*s*/ 2, 0, /*d*/ 4, 0, /*lsd*/ 3},
                latency_load + 4 * latency_alu + latency_store, 1));
    if (replaced) {
        p.add_call(c64x::software_divide(c64x::quotient_bits(uint64_t{1} << 18)));
        p.add_call(c64x::software_divide(24, true));
    }
    return p;
}

kernel_profile window_fit_profile(int extents) {
    // dsp/extent_window.h: the median of the 2 (n - 1) edge steps (an
    // insertion sort, as surface_mean's); over a full window the 2 (n - 2)
    // second differences of the edges (three loads, two SUBs and a shift
    // each, two compares for their signs) and their median alike; then for
    // each of the 33 half-pixel velocities the bounds over the n extents
    // (per extent two ADDs, how far the extent stood behind accumulated by
    // one more, the velocity then, v - k a, by a SUB and clamped at 0 by a
    // MAX2 and a MIN2, and the running bounds' MAX2 and MIN2, carried from
    // one extent to the next) and the choice (the crossing, two
    // compares, three conditional moves); then the steady side and the
    // clamp.
    const uint32_t n = static_cast<uint32_t>(non_negative(extents));
    const uint32_t steps = n > 1 ? 2 * (n - 1) : 0;
    const uint32_t changes = n > 3 ? 2 * (n - 2) : 0;
    constexpr uint32_t velocities = 33;
    kernel_profile p("window_fit");
    p.add(block("sort step", op_mix{/*l*/ 1, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 1},
                latency_load + latency_alu + latency_store, steps * steps / 4 + steps));
    p.add(block("second difference", op_mix{/*l*/ 4, /*s*/ 1, 0, /*d*/ 3, 0, /*lsd*/ 2},
                latency_load + 3 * latency_alu, changes));
    p.add(block("sort change", op_mix{/*l*/ 1, /*s*/ 1, 0, /*d*/ 2, 0, /*lsd*/ 1},
                latency_load + latency_alu + latency_store, changes * changes / 4 + changes));
    p.add(loop("extent", op_mix{/*l*/ 5, 0, 0, 0, 0, /*lsd*/ 3}, n, 2 * latency_alu, velocities,
               latency_alu));
    p.add(
        block("choice", op_mix{/*l*/ 3, /*s*/ 1, 0, 0, 0, /*lsd*/ 4}, 3 * latency_alu, velocities));
    // The steady side: at the chosen velocity each extent's two bounds again
    // (two ADDs each) and the four running MIN2 / MAX2, then two spreads
    // and their compares.
    p.add(loop("steady side", op_mix{/*l*/ 4, 0, 0, 0, 0, /*lsd*/ 4}, n, 2 * latency_alu, 1,
               latency_alu));
    p.add(block("clamp", op_mix{/*l*/ 2, 0, 0, 0, 0, /*lsd*/ 3}, 3 * latency_alu));
    return p;
}

kernel_profile triangulate_profile() {
    // f_px = f / pitch (__divu, 18 quotient bits: 789.5 px in Q8), then
    // D = s f_px / (d - dcx), X = D x / f_px, Y = D y / f_px with 64-bit
    // numerators (__divull, ASSUMED 24 quotient bits: depths and offsets up
    // to 16 m in micrometres). The three 32x32->64 products take 4 MPYU
    // (16x16) + 5 ADDs + 2 shifts each; sign handling and the validity
    // checks a few compares.
    kernel_profile p("triangulate");
    p.add_call(c64x::software_divide(c64x::quotient_bits(uint64_t{1} << 18)));
    p.add_call(c64x::software_divide(24, true), 3);
    p.add(block("32x32->64 products", op_mix{0, /*s*/ 6, /*m*/ 12, 0, 0, /*lsd*/ 15},
                latency_mpy16 + 3 * latency_alu));
    p.add(block("signs, checks, store", op_mix{/*l*/ 4, 0, 0, /*d*/ 3, 0, /*lsd*/ 6},
                4 * latency_alu + latency_store));
    return p;
}

sdram_traffic sdram_traffic_of(const kernel_profile& kernel) {
    const c64x::sdram_bytes b = c64x::sdram_bytes_of(kernel);
    sdram_traffic t;
    t.bytes_read = b.read;
    t.bytes_written = b.written;
    return t;
}

sdram_traffic demosaic_gray_traffic(int width, int height, memory where) {
    return sdram_traffic_of(demosaic_gray_profile(width, height, where));
}

sdram_traffic demosaic_gray_traffic(int width, int height, memory gray_where, memory raw_where) {
    return sdram_traffic_of(demosaic_gray_profile(width, height, gray_where, raw_where));
}

sdram_traffic three_frame_difference_packed_traffic(int width, int height, memory where) {
    return sdram_traffic_of(three_frame_difference_packed_profile(width, height, where));
}

sdram_traffic difference_packed_traffic(int width, int height, memory where) {
    return sdram_traffic_of(difference_packed_profile(width, height, where));
}

sdram_traffic brightness_traffic(int width, int height, memory where) {
    return sdram_traffic_of(brightness_profile(width, height, where));
}

sdram_traffic three_frame_difference_traffic(int width, int height, memory where) {
    return sdram_traffic_of(three_frame_difference_profile(width, height, where));
}

uint64_t demosaic_gray_cycles(int width, int height, memory where) {
    return default_model().cycles(demosaic_gray_profile(width, height, where));
}

uint64_t demosaic_gray_cycles(int width, int height, memory gray_where, memory raw_where) {
    return default_model().cycles(demosaic_gray_profile(width, height, gray_where, raw_where));
}

uint64_t three_frame_difference_packed_cycles(int width, int height, memory where) {
    return default_model().cycles(three_frame_difference_packed_profile(width, height, where));
}

uint64_t difference_packed_cycles(int width, int height, memory where) {
    return default_model().cycles(difference_packed_profile(width, height, where));
}

uint64_t brightness_cycles(int width, int height, memory where) {
    return default_model().cycles(brightness_profile(width, height, where));
}

uint64_t three_frame_difference_cycles(int width, int height, memory where) {
    return default_model().cycles(three_frame_difference_profile(width, height, where));
}

uint64_t morphology_cycles(int width, int height, int passes) {
    return default_model().cycles(morphology_profile(width, height, passes));
}

uint64_t connected_components_cycles(int width, int height, int foreground) {
    return default_model().cycles(connected_components_profile(width, height, foreground));
}

uint64_t sad_search_cycles(int pattern_w, int pattern_h, int positions) {
    return default_model().cycles(sad_search_profile(pattern_w, pattern_h, positions));
}

uint64_t motion_blocks_cycles(int width, int height) {
    return default_model().cycles(motion_blocks_profile(width, height));
}

uint64_t pattern_copy_cycles(int pattern_w, int pattern_h) {
    return default_model().cycles(pattern_copy_profile(pattern_w, pattern_h));
}

uint64_t window_fit_cycles(int extents) {
    return default_model().cycles(window_fit_profile(extents));
}

uint64_t window_step_cycles(int extents) {
    return default_model().cycles(window_step_profile(extents));
}

uint64_t size_at_depth_cycles(int divides) {
    return default_model().cycles(size_at_depth_profile(divides));
}

uint64_t subpixel_cycles() {
    return default_model().cycles(subpixel_profile());
}

uint64_t surface_outline_cycles(int rows, int columns, int inside) {
    return default_model().cycles(surface_outline_profile(rows, columns, inside));
}

uint64_t surface_mean_cycles(int inside, int matched) {
    return default_model().cycles(surface_mean_profile(inside, matched));
}

uint64_t sobel_cycles(int width, int rows) {
    return default_model().cycles(sobel_profile(width, rows));
}

uint64_t edge_match_cycles(int width, int lines, int max_disparity, int min_disparity) {
    return default_model().cycles(edge_match_profile(width, lines, max_disparity, min_disparity));
}

uint64_t triangulate_cycles() {
    return default_model().cycles(triangulate_profile());
}

}  // namespace dsp::cost
