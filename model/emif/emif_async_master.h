// The C64x EMIFA as bus master: a plain C++ cycle engine stepped once per
// ECLKOUT rising edge (no SystemC). It queues accesses from the CPU (single
// words) and the EDMA (bursts), arbitrates between them and SDRAM refresh,
// runs the asynchronous memory cycle at the pins for async CE spaces (the
// daughter card on CE2/CE3) and charges SDRAM accesses on CE0 as bus time at
// transaction level (no pins but ACE0). docs/emif.md has the timing diagram,
// the arbitration rule and the list of assumptions.
//
// Async access, per 32-bit word, in ECLK edges (S = edge that lowers the strobe):
//   setup:  RS / WS cycles: CE, EA, BE (and AOE for reads, ED for writes)
//           valid, strobe high;
//   strobe: ARE / AWE low from S; it ends at the first edge E >= S + RST/WST
//           at which ARDY sampled at edge E - ardy_lead was high (ARDY low
//           extends the strobe: wait states). Read data is sampled at E, the
//           edge where ARE rises;
//   hold:   RH / WH cycles, strobe high, the rest held.
// So a read at CECTL 0x22A28A22 takes RS + RST + RH = 2 + 10 + 2 = 14 edges
// from the start of its setup to the end of its hold. Words of the same
// direction to the same CE follow each other directly (CE stays low); a
// change of direction or CE space inserts TA idle cycles (all CE high)
// unless the bus has been idle that long already.
//
// Cost: step() is a switch on the phase with no allocation and no virtual
// call (except an observer, if one is set). skip_idle_to() jumps over idle
// stretches in O(refreshes).
#pragma once

#include <cstddef>
#include <cstdint>

#include "model/emif/cectl.h"
#include "model/emif/emif_access.h"
#include "model/emif/emif_pins.h"
#include "model/time/ticks.h"

namespace emif {

// SDRAM on CE0 at transaction level (docs/emif.md lists which numbers are ASSUMED).
struct sdram_timing {
    // ECLK cycles between refresh requests: SDTIM PERIOD = 0x618 = 1560 at
    // 100 MHz (docs/hardware-facts.md section 3, [GEL]); 0 turns refresh off.
    uint32_t refresh_period = 1560;
    // ASSUMED: bus cycles one auto-refresh occupies (~tRC of a 64 Mbit PC100 part, 70 ns).
    uint32_t refresh_cycles = 7;
    // ASSUMED: bus cycles to open a row and reach the first data (ACTV, tRCD
    // 2 + CAS latency 3) plus closing it (precharge 2).
    uint32_t access_cycles = 7;
    // An SDRAM burst is arbitrated in chunks of this many 32-bit words; a
    // chunk moves 2 words per ECLK (SDRAM64 on the 64-bit EMIFA).
    uint32_t chunk_words = 32;
    // The open row: a chunk pays no access_cycles when the op right before it
    // on the bus was an SDRAM chunk that left the same row (bank and row) of
    // the SDRAM open; any other op (a card word, a refresh) closes it, and a
    // chunk pays access_cycles again for every row boundary it crosses.
    // Geometry (ASSUMED from the DSK's 16 MB = 2 x 64 Mbit parts, 32 bits
    // each, on the 64-bit bus: 4 banks x 2048 rows x 256 columns of 8 bytes,
    // docs/hardware-facts.md section 3): one row of one bank = 2 KB of
    // consecutive addresses, column address in the low bits, then the bank,
    // then the row. A row is identified by offset / row_bytes.
    uint32_t row_bytes = 2048;
};

struct emif_config {
    simtime::tick_clock eclk{simtime::rational_ticks{simtime::emif_100mhz_period, 1}};
    // CECTL0..3 (docs/hardware-facts.md section 3): CE0 SDRAM, CE1 at reset,
    // CE2/CE3 the DSK v1 daughter-card setting.
    uint32_t cectl[ce_count] = {cectl_sdram_dsk, cectl_reset, cectl_dsk_v1, cectl_dsk_v1};
    // ASSUMED (NOT FOUND in the facts; the card's docs and its test master use 1):
    // the strobe can end at edge E only if ARDY was high when sampled at edge E - ardy_lead.
    uint32_t ardy_lead = 1;
    sdram_timing sdram;
};

// Fault hook: ARDY held low `extra_cycles` more cycles at the end of the
// strobe of accesses (words) on CE space `ce`: from the first access whose
// setup starts at or after `from_tick` and that is at least the
// `from_access`-th access (0-based) on that CE, for `access_count` accesses.
struct ardy_fault {
    int ce = 3;
    uint32_t extra_cycles = 0;
    simtime::ticks from_tick = 0;
    uint64_t from_access = 0;
    uint64_t access_count = UINT64_MAX;
};

struct emif_stats {
    uint64_t words[requester_count] = {};     // words moved per requester
    uint64_t accesses[requester_count] = {};  // accesses completed per requester
    uint64_t busy_edges = 0;                  // edges with the bus in use or turning around
    uint64_t turnaround_edges = 0;            // of which idle turnaround
    uint64_t wait_edges = 0;                  // strobe edges added by ARDY / faults
    uint64_t refreshes = 0;
    uint64_t sdram_edges = 0;  // edges of SDRAM chunks and refreshes
};

class emif_async_master {
  public:
    using completion_fn = void (*)(void* context, emif_access& access);

    explicit emif_async_master(const emif_config& config = {});
    emif_async_master(const emif_async_master&) = delete;
    emif_async_master& operator=(const emif_async_master&) = delete;

    // ---- configuration ----
    // The firmware's write of CECTLn: takes effect for words started after it.
    void set_cectl(int ce, uint32_t value);
    uint32_t cectl(int ce) const { return m_cectl[ce]; }
    const async_timing& timing(int ce) const { return m_timing[ce]; }
    const emif_config& config() const { return m_config; }
    // Called (inside step) when an access completes, before the next arbitration.
    void set_completion_handler(completion_fn fn, void* context);
    void set_observer(emif_pin_observer* observer) { m_observer = observer; }
    // Backing store of the SDRAM on CE0 (byte offset = address - 0x80000000,
    // modulo size). Without one, SDRAM reads return 0 and writes are dropped.
    void set_sdram_storage(uint8_t* bytes, size_t size);
    void set_ardy_fault(const ardy_fault& fault);  // one per CE space, replaces it
    void clear_ardy_faults();

    // ---- requests ----
    // Queues `a`, eligible from the next edge stepped. Returns false (and sets
    // a.status, no completion call) if it can never run.
    bool submit(emif_access& a);
    // Queues `a` made at tick t: eligible from the first edge strictly after t
    // (an access made at the very tick of an edge waits for the next edge, so
    // the result never depends on the order of processes within one time).
    bool submit_at(emif_access& a, simtime::ticks t);

    // ---- stepping ----
    // One ECLKOUT rising edge: `in` is what the slave drove just before it.
    // Afterwards pins() is what the DSP drives until the next edge.
    void step(const emif_inputs& in);
    // Jumps to edge `edge` (the next step() processes it) over idle edges:
    // only refreshes due in between are stepped (with idle inputs).
    void skip_idle_to(uint64_t edge);

    const emif_pins& pins() const { return m_pins; }
    uint64_t next_edge() const { return m_next; }
    simtime::ticks edge_tick(uint64_t edge) const { return m_config.eclk.rise(edge); }
    // Nothing in progress, queued or due.
    bool idle() const;
    // The next step() may choose what uses the bus (a new access can start
    // there): a driver running ahead of SystemC time must sync before it.
    bool arbitrates_at_next_edge() const;
    const emif_stats& stats() const { return m_stats; }

  private:
    enum class phase : uint8_t { idle, turnaround, setup, strobe, hold, sdram, refresh };
    enum class op_kind : uint8_t { none, async_word, sdram_chunk, refresh };
    struct bus_op {
        op_kind kind = op_kind::none;
        int ce = 0;
        bool write = false;
        emif_access* access = nullptr;
        uint32_t words = 0;  // words of an SDRAM chunk
    };
    struct queue {
        emif_access* head = nullptr;
        emif_access* tail = nullptr;
    };

    bool validate(emif_access& a) const;
    void enqueue(emif_access& a);
    void arbitrate(uint64_t e);
    bus_op next_op_of(emif_access& a) const;
    uint32_t turnaround_between(const bus_op& last, const bus_op& next) const;
    void start_op(uint64_t e);
    void begin_strobe(uint64_t e);
    void strobe_edge(uint64_t e, const emif_inputs& in);
    void finish_op(uint64_t e);
    void complete(emif_access& a, uint64_t e);
    void release_pins();
    uint32_t word_address(const emif_access& a) const;

    emif_config m_config;
    uint32_t m_cectl[ce_count];
    async_timing m_timing[ce_count];
    completion_fn m_on_done = nullptr;
    void* m_on_done_context = nullptr;
    emif_pin_observer* m_observer = nullptr;
    uint8_t* m_sdram = nullptr;
    size_t m_sdram_size = 0;
    ardy_fault m_fault[ce_count];
    uint64_t m_fault_from_edge[ce_count] = {};

    queue m_queue[requester_count];
    uint64_t m_next = 0;  // index of the edge the next step() processes
    phase m_phase = phase::idle;
    uint64_t m_phase_end = 0;  // edge at which the current phase ends
    bus_op m_op;               // the op on the bus (or turning around to it)
    bus_op m_last;             // the op before it (for turnaround)
    uint64_t m_bus_free_edge = 0;
    uint64_t m_strobe_start = 0;
    uint32_t m_strobe_cycles = 0;  // programmed strobe of the current word
    uint32_t m_fault_left = 0;     // injected wait states still to add to this word
    uint64_t m_ce_accesses[ce_count] = {};
    uint64_t m_next_refresh = 0;
    uint32_t m_refresh_pending = 0;
    // SDRAM row (offset / row_bytes) left open by the last chunk; no_row when
    // the op before was not an SDRAM chunk.
    static constexpr uint64_t no_row = UINT64_MAX;
    uint64_t m_sdram_open_row = no_row;
    uint64_t sdram_row(uint32_t address) const;
    bool m_ardy_history[16] = {};
    emif_pins m_pins;
    emif_stats m_stats;
};

}  // namespace emif
