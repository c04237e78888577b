// The C64x EDMA channel controller (model/c6416/c6416_regs.h edma::; [CSL
// csl_edmahal.h], [DS] Tables 8 and 25), plain C++: the parameter RAM, the
// event / enable / clear / set registers, completion codes, chaining and
// linking. It turns synchronisation events into transfer requests; the
// c6416 module's transfer controller executes them over the bus and calls
// complete(). Semantics (docs/c6416.md, ASSUMED where SPRU234 was not at hand):
//   - A hardware event (EXT_INT4-7 on channels 4-7, timers on 1/2/19) sets
//     its ER bit, latched even when EER disables it; an enabled event is
//     submitted at once, a disabled one when EER enables it later.
//   - Writing ESR submits the channel at once, whatever EER says; chaining
//     (a completion code n with CCER bit n) submits channel n likewise.
//   - Submission copies the channel's parameters into a transfer request
//     and updates the entry immediately (as the C64x channel controller does
//     when it issues the request, not when the transfer ends): FS = 1 sends
//     the whole block (FRMCNT + 1 arrays or frames of ELECNT elements); FS =
//     0 sends one array (2-D) or one element (1-D). After the last part the
//     entry is reloaded from its LINK entry (OPT.LINK = 1) or its counts are
//     zeroed (a later event is a null transfer, counted).
//   - Address update: 1-D side: fixed / +ESIZE / -ESIZE / +ELEIDX per
//     element, +FRMIDX instead of ELEIDX at a frame end in index mode; 2-D
//     side: arrays of contiguous elements (fixed: same address), FRMIDX from
//     one array's start to the next.
//   - Completion: the last part with TCINT sets CIPR bit TCC (6 bits with
//     TCCM); an intermediate array / frame end with ATCINT sets bit ATCC.
//     A set bit with CIER on raises EDMA_INT; enabling CIER on a pending bit
//     raises it too. Priority queues are not modelled (requests run in
//     submission order).
#pragma once

#include <cstdint>
#include <deque>

#include "model/c6416/c6416_regs.h"

namespace c6416 {

struct transfer_side {
    uint32_t start = 0;        // address of the first element
    int64_t element_step = 0;  // bytes from one element to the next in an array
    int64_t array_step = 0;    // bytes from one array's first element to the next's
};

enum class completion : uint8_t { none, intermediate, final };

// What the transfer controller moves for one synchronisation event.
struct transfer_request {
    int channel = 0;
    uint32_t opt = 0;
    uint32_t element_bytes = 4;
    uint32_t elements = 0;  // per array
    uint32_t arrays = 0;
    transfer_side src;
    transfer_side dst;
    completion done = completion::final;
    uint64_t sequence = 0;  // submission order

    uint64_t bytes() const { return static_cast<uint64_t>(element_bytes) * elements * arrays; }
};

class edma_core {
  public:
    edma_core() { reset(); }

    void reset();

    // PaRAM and channel registers at their addresses; false if not one.
    bool read(uint32_t address, uint32_t& value) const;
    bool write(uint32_t address, uint32_t value);

    // A hardware synchronisation event on `channel`.
    void event(int channel);

    bool has_request() const { return !m_requests.empty(); }
    transfer_request take_request();
    // The transfer controller finished `request`.
    void complete(const transfer_request& request);

    // EDMA_INT since the last call (then cleared).
    bool take_interrupt();

    uint64_t er() const { return m_er; }
    uint64_t eer() const { return m_eer; }
    uint64_t cipr() const { return m_cipr; }
    uint64_t cier() const { return m_cier; }
    uint64_t ccer() const { return m_ccer; }
    uint64_t submitted() const { return m_submitted; }
    uint64_t completed() const { return m_completed; }
    uint64_t null_transfers() const { return m_null_transfers; }

  private:
    static constexpr uint32_t pram_words = c6416::edma::pram_bytes / 4;

    void submit(int channel);
    void set_completion(uint32_t code);
    void enable_events(uint64_t newly_enabled);

    uint32_t m_pram[pram_words] = {};
    uint64_t m_er = 0, m_eer = 0, m_cipr = 0, m_cier = 0, m_ccer = 0, m_epr = 0;
    uint32_t m_pqar[4] = {};
    std::deque<transfer_request> m_requests;
    bool m_interrupt = false;
    uint64_t m_submitted = 0, m_completed = 0, m_null_transfers = 0;
};

}  // namespace c6416
