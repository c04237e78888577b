// The firmware's main program (docs/firmware.md): boots the DSK, sets up
// the daughter card, and runs the frame loop that feeds dsp::controller with
// the stereo pairs the card delivers. Plain C++, no allocation after init(),
// everything through dsp::hal as on the real C6416.
//
// Boot (in this order, each step reported through hal::report):
//   1. EMIFA: GBLCTL 0x00012070, CE0 SDRAM 0xFFFFFFD3 + SDCTL/SDTIM/SDEXT,
//      CE2/CE3 (card) 0x22A28A22 on DSK v1, 0x23228C22 on v2/v3 (the DSK's
//      GEL init_emif values, model/c6416/c6416_regs.h).
//   2. Interrupt selector at its reset mapping (INT4-7 = EXT_INT4-7, INT8 =
//      EDMA_INT, INT15 = TINT1), EXTPOL 0 (the card pulses high), IER =
//      INT5 (sync error) | INT6 (overflow) | INT8 (EDMA) | INT15 (watchdog).
//   3. Card: ID checked (magic 0x57E5), ENABLE 0, IRQ_STATUS cleared, the
//      geometry / threshold / retry registers of card_setup, IRQ_ENABLE 7.
//   4. EDMA (below), armed for the first pair.
//   5. Timer 1 as a watchdog; ENABLE 1 raises OE. The card checks the dark
//      pixels; the first pair it forwards is reported in_step, a mismatch
//      sync_error (the card restarts OE itself; the firmware re-arms with
//      ENABLE 0 -> 1 when the card gives up (HARD_ERROR) or, if configured,
//      after every mismatch).
//
// Capture (no CPU involvement): the card's FRAME_READY pulse on EXT_INT4 is
// EDMA event 4. Channel 4 copies the card's VERDICT .. PAIRS_OK registers
// (5 words) into the pair buffer's header and chains (completion code ->
// CCER) to a channel that reads the left frame from its pixel port (fixed
// address, one array per line), which chains to the right frame; its
// completion code (CIER) raises EDMA_INT = INT8. Three chains exist: into
// buffer A, into buffer B, and "drain" (same reads, every word into one
// sink word in L2: the pair is read out of the card's FIFO and thrown
// away). The chain channels reload themselves by PaRAM linking; channel 4
// is rewritten by the CPU to choose the chain, with its link pointing at the
// drain chain, so after each capture the next pair is drained unless the
// CPU arms a free buffer in time.
//
// Frame loop: sequential mode uses buffer A only: wait for its capture,
// process it, re-arm it. Overlapped mode ping-pongs A and B: while the CPU
// processes one buffer the other is armed and filled. A pair is used only
// if the VERDICT copied with it has no cause bit (in step, no overflow).
//
// Overrun policy: a FRAME_READY that arrives while no buffer is armed (in
// overlapped mode: both busy, one being processed and one full or being
// filled; in sequential mode: any pair during processing) is the NEW pair
// and is dropped: the drain chain reads it out of the FIFO so the card's
// FIFO never holds stale pairs, and the firmware keeps the older pairs it
// already has. Drops are counted exactly from the gap in the pair numbers
// (PAIRS_OK) copied with each captured pair and reported as pair_dropped.
//
// Card errors: sync error (EXT_INT5 = INT5) and FIFO overflow (EXT_INT6 =
// INT6): the card discards the failed pair itself (it never raises
// FRAME_READY for it, so it is never captured, let alone used for 3D); the
// firmware reads VERDICT / MISMATCH_POS / STATUS, clears the card's
// IRQ_STATUS bit, reports, and re-arms the card (ENABLE 0 -> 1) on an
// overflow (configurable) and on a hard sync error. The watchdog (timer 1,
// periodic) re-arms a card none of whose event counters (PAIRS_OK,
// MISMATCHES, OVERFLOWS) moved for a whole period.
//
// Memory (docs/firmware.md): pair buffers at config.buffer_base (default
// SDRAM 0x80000000; L2 is possible for one VGA buffer): each is a 64-byte
// header (VERDICT, MISMATCH_POS, FRAMES_L, FRAMES_R, PAIRS_OK) then the left
// and the right raw frame, 4 KB aligned. The drain header and sink word are
// at config.control_base in L2. The controller's own working buffers are
// allocated at init (host memory; the cost model charges their accesses).
//
// Cost: per pair, config.capture_cycles CPU cycles charged to stage capture
// (interrupt handling, header check, re-arming; ASSUMED 600) plus the bus
// time of its register accesses; the controller charges the pipeline.
#pragma once

#include <cstdint>

#include "dsp/card_regs.h"
#include "dsp/controller.h"
#include "dsp/hal.h"
#include "model/c6416/c6416_regs.h"

namespace dsp {

enum class dsk_version : uint8_t { v1 = 1, v2 = 2, v3 = 3 };
enum class pipeline_mode : uint8_t { sequential = 0, overlapped = 1 };
const char* pipeline_mode_name(pipeline_mode m);

// Why the firmware re-armed the card (event card_rearmed, value).
enum class rearm_cause : uint8_t { hard_error = 1, sync_error = 2, overflow = 3, watchdog = 4 };

// The card registers the firmware writes at boot (docs/card-registers.md).
// Defaults: the card's reset values, i.e. the default sensor profile
// (docs/design-brief.md): 640 x 480 active, 16 dark columns, 8 dark rows, 800 x 525.
struct card_setup {
    uint32_t dark_threshold = card_regs::dark_threshold_reset;
    uint32_t h_start = card_regs::h_start_reset;
    uint32_t dark_cols_left = card_regs::dark_cols_left_reset;
    uint32_t border_cols_left = card_regs::border_cols_left_reset;
    uint32_t active_cols = card_regs::active_cols_reset;  // = image width
    uint32_t border_cols_right = card_regs::border_cols_right_reset;
    uint32_t dark_cols_right = card_regs::dark_cols_right_reset;
    uint32_t line_total = card_regs::line_total_reset;
    uint32_t v_start = card_regs::v_start_reset;
    uint32_t dark_rows_top = card_regs::dark_rows_top_reset;
    uint32_t border_rows_top = card_regs::border_rows_top_reset;
    uint32_t active_rows = card_regs::active_rows_reset;  // = image height
    uint32_t border_rows_bottom = card_regs::border_rows_bottom_reset;
    uint32_t dark_rows_bottom = card_regs::dark_rows_bottom_reset;
    uint32_t frame_lines = card_regs::frame_lines_reset;
    uint32_t retry_limit = card_regs::retry_limit_reset;
    uint32_t oe_low_cycles = card_regs::oe_low_cycles_reset;
    uint32_t start_timeout = card_regs::start_timeout_reset;
    // CHECKS: FRAME_ID on compares the sensors' frame identity (0: the
    // paper's card, dark pixels only).
    uint32_t checks = card_regs::checks_reset;
};

// The card's async timing on CE2 / CE3 in ECLK cycles, read and write alike
// (the DSK's own settings are symmetric, docs/hardware-facts.md section 3); a
// field of 0 keeps the DSK version's value (2/10/2 on v1, 2/12/2 on v2/v3).
struct card_bus_timing {
    uint32_t setup = 0;   // RDSETUP / WRSETUP, 1..15
    uint32_t strobe = 0;  // RDSTRB / WRSTRB, 1..63
    uint32_t hold = 0;    // RDHLD / WRHLD, 1..3 (WRHLD is 2 bits without WRHLDMSB)
};

struct control_program_config {
    controller_config pipeline;  // max_width / max_height >= the card's active size
    card_setup card;
    dsk_version dsk = dsk_version::v1;
    card_bus_timing card_timing;
    uint32_t cpu_mhz = 0;  // for the watchdog timer; 0: the DSK's (600, 720, 1000)
    pipeline_mode mode = pipeline_mode::overlapped;
    uint32_t buffer_base = c6416::sdram_base;  // pair buffers (A, then B in overlapped mode)
    uint32_t control_base = 0x000FF000u;       // L2: drain header + sink (128 bytes)
    uint32_t max_pairs = 0;  // return after this many processed pairs; 0: until stop_requested
    bool rearm_on_overflow = true;
    bool rearm_on_every_sync_error = false;  // false: only when the card reports HARD_ERROR
    uint32_t watchdog_ms = 500;      // no card event for a whole period: re-arm; 0: no watchdog
    uint64_t capture_cycles = 600;   // CPU cycles per pair charged to stage capture (ASSUMED)
    uint32_t rearm_idle_polls = 64;  // STATUS reads waiting for the card to reach IDLE
    // No hang (docs/fault-contract.md): the firmware re-arms the card after
    // this many consecutive failures (the card's HARD_ERROR or a watchdog
    // re-arm) with no good pair in between; the next one ends in a reported
    // hard_error: ENABLE 0 (OE low), capture and watchdog stopped, run()
    // returns. Bound: (hard_error_rearms + 1) x (RETRY_LIMIT + 1) failed
    // checks after the fault, or as many watchdog periods.
    uint32_t hard_error_rearms = 1;
};

// The CECTL2 / CECTL3 value the firmware programs: the DSK version's card
// setting with card_timing's non-zero fields in place of its own.
uint32_t card_cectl(const control_program_config& config);

struct control_stats {
    uint32_t pairs_captured = 0;   // pairs the EDMA moved into a buffer
    uint32_t pairs_processed = 0;  // pairs the pipeline ran on
    uint32_t pairs_rejected = 0;   // captured with a verdict cause: not used
    uint32_t pairs_dropped = 0;    // overrun drops (gaps in the pair numbers)
    uint32_t sync_errors = 0;
    uint32_t overflows = 0;
    uint32_t rearms = 0;
    uint32_t watchdogs = 0;
    uint32_t oe_raises = 0;
    uint32_t last_pair = 0;  // card pair number of the last captured pair
    bool gave_up = false;    // hard_error reported
};

// The EDMA resources the program uses (docs/firmware.md), public for tests.
struct control_program_edma {
    static constexpr int trigger_channel = c6416::edma::channel_ext_int4;
    static constexpr int buffer_a = 0, buffer_b = 1, drain = 2;
    static constexpr int left_channel[3] = {56, 58, 60};   // A, B, drain
    static constexpr int right_channel[3] = {57, 59, 61};  // A, B, drain
    static constexpr uint32_t done_code[3] = {8, 9, 10};   // CIPR bits of a finished chain
    static constexpr uint32_t header_bytes = 64;
    static constexpr uint32_t status_words = 5;  // VERDICT .. PAIRS_OK
    // Header word indices.
    static constexpr int hdr_verdict = 0, hdr_mismatch_pos = 1, hdr_frames_l = 2, hdr_frames_r = 3,
                         hdr_pairs_ok = 4;
};

class control_program {
  public:
    control_program() = default;
    control_program(const control_program&) = delete;
    control_program& operator=(const control_program&) = delete;

    // Checks the configuration and allocates the pipeline's buffers. False
    // (nothing allocated, run() returns at once) if the image size or the
    // buffer placement is not usable.
    bool init(const control_program_config& config, hal& hardware);
    // Boot, then the frame loop until config.max_pairs pairs are processed,
    // the HAL asks to stop, or the card is missing. Allocates nothing.
    void run();

    const control_stats& stats() const { return m_stats; }
    const control_program_config& config() const { return m_config; }
    // Address of pair buffer 0 (A) or 1 (B), and of its left / right frame.
    uint32_t buffer_address(int buffer) const;
    uint32_t left_address(int buffer) const { return buffer_address(buffer) + header_size(); }
    uint32_t right_address(int buffer) const { return left_address(buffer) + frame_bytes(); }
    uint32_t buffer_stride() const;
    controller& pipeline() { return m_controller; }

  private:
    enum class buffer_state : uint8_t { free, armed, full, busy };

    static constexpr uint32_t header_size() { return control_program_edma::header_bytes; }
    uint32_t frame_bytes() const { return m_width * m_height; }
    uint32_t drain_header() const { return m_config.control_base; }
    uint32_t drain_sink() const { return m_config.control_base + 64; }

    // Boot.
    void program_emif();
    void setup_interrupts();
    bool probe_card();
    void configure_card();
    void setup_edma();
    void raise_oe();

    // EDMA.
    void write_entry(uint32_t address, const uint32_t words[6]);
    void trigger_entry(int chain, uint32_t words[6]) const;
    void left_entry(int chain, uint32_t words[6]) const;
    void right_entry(int chain, uint32_t words[6]) const;
    void arm(int buffer);
    void arm_free_buffer();
    int armed_buffer() const;

    // Frame loop.
    bool finished() const;
    void service_pending_interrupts();
    void handle_interrupt(int n);
    void handle_edma();
    void handle_sync_error();
    void handle_overflow();
    void handle_watchdog();
    void rearm(rearm_cause cause);
    void restart_watchdog();
    uint32_t card_progress();
    void process_buffer(int buffer);
    int oldest_full_buffer() const;
    void lower_oe();

    void report(firmware_event kind, uint32_t pair = 0, uint32_t value = 0, uint32_t detail = 0);
    uint32_t card_read(uint32_t reg) { return m_hal->read32(card_regs::ce2_base + reg); }
    void card_write(uint32_t reg, uint32_t v) { m_hal->write32(card_regs::ce2_base + reg, v); }

    control_program_config m_config;
    hal* m_hal = nullptr;
    controller m_controller;
    bool m_ready = false;
    uint32_t m_width = 0, m_height = 0;
    int m_buffers = 1;
    buffer_state m_state[2] = {buffer_state::free, buffer_state::free};
    uint32_t m_full_order[2] = {0, 0};  // capture order of full buffers
    uint32_t m_captures = 0;
    bool m_awaiting_in_step = false;
    bool m_have_pair = false;
    uint32_t m_watchdog_progress = 0;
    uint32_t m_failures = 0;  // consecutive hard errors / watchdog re-arms, no good pair between
    control_stats m_stats;
};

}  // namespace dsp
