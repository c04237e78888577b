// Directed checks of fifo_discard (rtl/fifo_discard.v) alone, for any FIFO
// address width: the discard pops exactly the words of its region
// [begin_ptr, end_ptr), never a word before it (the reader may still be
// reading the previous, good frame when a rejected frame's region is
// published) and never one after it. Golden values are the module's
// specification (its header comment), not its own output. Written for the
// RTL mutants (docs/mutants.md): a region start with a bit tied to 0, an
// offset bit flipped only in long regions.
#pragma once

#include <cstdint>
#include <string>

#include "verilated.h"

namespace rtl_test {

struct discard_outcome {
    uint64_t early_pops = 0;  // pops while the reader was before the region
    uint64_t region_pops = 0;
    uint64_t late_pops = 0;  // pops once the reader had reached end_ptr
    bool busy_cleared = false;
    std::string first_error;  // empty when the region was dropped exactly
};

// One region: the reader starts `behind` words before begin_ptr; the DSP
// reads those words one every `dsp_gap` cycles (the discard must stay off
// while the reader is before the region), then the discard drops the region.
template <class Vdiscard, unsigned AW>
class fifo_discard_bench {
  public:
    static constexpr uint64_t pointer_mask = (uint64_t{2} << AW) - 1;  // AW+1 bit pointers

    fifo_discard_bench() : m_top(&m_context) {
        m_top.clk = 0;
        m_top.rst_n = 0;
        m_top.start = 0;
        m_top.empty = 0;
        m_top.dsp_pop = 0;
        m_top.eval();
        m_top.rst_n = 1;
        m_top.eval();
    }

    discard_outcome drop(uint64_t begin, uint64_t length, uint64_t behind, unsigned dsp_gap) {
        discard_outcome out;
        const uint64_t end = (begin + length) & pointer_mask;
        uint64_t rd = (begin - behind) & pointer_mask;
        m_top.begin_ptr = begin;
        m_top.end_ptr = end;
        bool start = true;
        uint64_t dsp_left = behind;
        const uint64_t limit = behind * (dsp_gap + 1) + length + 16;
        for (uint64_t cycle = 0; cycle < limit; ++cycle) {
            const bool dsp_pop = dsp_left > 0 && cycle % (dsp_gap + 1) == dsp_gap;
            m_top.start = start;
            m_top.rd_ptr = rd;
            m_top.dsp_pop = dsp_pop;
            m_top.clk = 0;
            m_top.eval();
            const bool pop = m_top.pop;
            const uint64_t offset = (rd - begin) & pointer_mask;
            if (pop) {
                if (dsp_left > 0) {
                    ++out.early_pops;
                    note(out, "popped a word " + std::to_string(dsp_left) +
                                  " before the region (the previous frame's)");
                } else if (offset < length) {
                    ++out.region_pops;
                } else {
                    ++out.late_pops;
                    note(out, "popped past end_ptr");
                }
            }
            if (!start && !m_top.busy && dsp_left == 0) {
                out.busy_cleared = true;
                break;
            }
            m_top.clk = 1;
            m_top.eval();
            start = false;
            if (pop || dsp_pop) rd = (rd + 1) & pointer_mask;
            if (dsp_pop) --dsp_left;
        }
        if (out.region_pops != length)
            note(out, std::to_string(out.region_pops) + " of " + std::to_string(length) +
                          " region words popped");
        if (!out.busy_cleared) note(out, "still busy after the region");
        return out;
    }

  private:
    static void note(discard_outcome& out, const std::string& what) {
        if (out.first_error.empty()) out.first_error = what;
    }

    VerilatedContext m_context;
    Vdiscard m_top;
};

}  // namespace rtl_test
