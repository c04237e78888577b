/* The firmware under test, behind a versioned C ABI (docs/firmware-abi.md).
 *
 * A firmware is a shared object that exports one symbol,
 * STEREOSIM_FIRMWARE_ENTRY, returning its descriptor: who it is, its stages,
 * tracker states and config keys, and create / run / destroy. The platform
 * hands it a table of services (the C6416 as the firmware sees it: cycles,
 * registers, memory, interrupts) and reads nothing of it but what it reports
 * through that table: the events and results below are the whole reporting
 * protocol, and every rule of the fault contract, the scoreboard and the
 * budget is judged on them alone.
 *
 * Plain C11, also valid C++17; no allocation is required of the platform's
 * side, no global state on either side: everything goes through the context
 * pointers. Compiled by tests/firmware_abi with -Wall -Wextra -pedantic
 * -Werror as C11 and as C++17.
 */
#ifndef STEREOSIM_FIRMWARE_H
#define STEREOSIM_FIRMWARE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bumped on every change a plugin built for the old header could misread.
 * A plugin whose descriptor names another version is refused at load, with
 * both numbers in the error. */
#define STEREOSIM_FIRMWARE_ABI_VERSION 1u

/* The symbol a plugin exports: `const stereosim_fw_descriptor*
 * stereosim_firmware(void)`. */
#define STEREOSIM_FIRMWARE_ENTRY "stereosim_firmware"

#define STEREOSIM_FW_MAX_STAGES 15u        /* the waveform's stage signal is 4 bits */
#define STEREOSIM_FW_MAX_TRACKER_STATES 8u /* the waveform's state signal is 3 bits */
#define STEREOSIM_FW_NO_INTERRUPT (-1)

/* ---- what the platform offers: the cost service's operation profile ----
 * The same op profile the C64x cost model of docs/c6416.md turns into
 * cycles: per section (a software-pipelined loop or a straight block) the
 * ops ONE iteration issues per functional-unit class, its trip count,
 * critical path and recurrence; per data stream where it lives. */

typedef struct stereosim_op_mix {
    uint32_t l;   /* .L only (SUBABS4, MINU4, CMPEQ, SUBC, ...) */
    uint32_t s;   /* .S only (CMPGTU4, SHRU, B, ...) */
    uint32_t m;   /* .M only (DOTPU4, MPY, AVGU4, ...) */
    uint32_t d;   /* .D only (loads and stores) */
    uint32_t ls;  /* .L or .S (PACK2, MVK, ...) */
    uint32_t lsd; /* .L, .S or .D (ADD, SUB, AND, MV, ...) */
} stereosim_op_mix;

typedef struct stereosim_section {
    const char* name;
    stereosim_op_mix ops; /* per iteration */
    uint64_t iterations;  /* trip count each time the loop is entered */
    uint64_t entries;     /* times it is entered (0 is taken as 1) */
    uint32_t chain;       /* one iteration's critical path, cycles */
    uint32_t recurrence;  /* loop-carried bound on the initiation interval, cycles */
    uint32_t is_loop;     /* 0: a straight-line block (no loop overhead) */
} stereosim_section;

typedef enum stereosim_placement {
    STEREOSIM_IN_L1D = 0,  /* already in L1D */
    STEREOSIM_IN_L2 = 1,   /* L2 SRAM: each 64-byte L1D line misses once */
    STEREOSIM_IN_SDRAM = 2 /* EMIFA CE0 SDRAM through the L2 cache */
} stereosim_placement;

typedef struct stereosim_stream {
    uint64_t bytes_read;
    uint64_t bytes_written;
    uint32_t where; /* stereosim_placement */
} stereosim_stream;

#define STEREOSIM_PROFILE_MAX_SECTIONS 16u
#define STEREOSIM_PROFILE_MAX_STREAMS 4u

typedef struct stereosim_kernel_profile {
    const char* name;
    uint64_t calls; /* this call and the library calls it makes (each pays the call overhead) */
    uint32_t section_count;
    stereosim_section sections[STEREOSIM_PROFILE_MAX_SECTIONS];
    uint32_t stream_count;
    stereosim_stream streams[STEREOSIM_PROFILE_MAX_STREAMS];
} stereosim_kernel_profile;

typedef struct stereosim_sdram_traffic {
    uint64_t bytes_read;
    uint64_t bytes_written;
} stereosim_sdram_traffic;

/* ---- what the firmware reports: events ----
 * `pair` is the card's pair number (its PAIRS_OK count when the pair became
 * ready) where one applies. The numbers are part of the ABI. */
typedef enum stereosim_event_kind {
    STEREOSIM_EV_BOOT = 0,            /* value: DSK version, detail: 1 overlapped, 0 sequential */
    STEREOSIM_EV_EMIF_PROGRAMMED = 1, /* value: CECTL2/3, detail: SDTIM */
    STEREOSIM_EV_CARD_FOUND = 2,      /* value: the card's ID register */
    STEREOSIM_EV_CARD_MISSING = 3,    /* value: what the ID register read */
    STEREOSIM_EV_CARD_CONFIGURED = 4, /* value: IRQ_ENABLE */
    STEREOSIM_EV_OE_RAISED = 5,       /* value: times the firmware raised OE (1 = boot) */
    STEREOSIM_EV_IN_STEP = 6,         /* pair: the first pair after OE that passed the check,
                                       * value: its VERDICT */
    STEREOSIM_EV_SYNC_ERROR = 7,      /* value: VERDICT, detail: MISMATCH_POS */
    STEREOSIM_EV_OVERFLOW = 8,        /* value: STATUS, detail: the card's OVERFLOWS count */
    STEREOSIM_EV_CARD_REARMED = 9,    /* ENABLE 0 -> 1; value: stereosim_rearm_cause */
    STEREOSIM_EV_WATCHDOG = 10,       /* no card event for a watchdog period; value: the
                                       * firmware's own (the reference's: timer clocks) */
    STEREOSIM_EV_PAIR_CAPTURED = 11,  /* pair, value: VERDICT copied with it, detail: buffer;
                                       * left / right: the frames' addresses in DSP memory */
    STEREOSIM_EV_PAIR_REJECTED = 12,  /* pair, value: its VERDICT (a cause bit set: not used) */
    STEREOSIM_EV_PAIR_DROPPED = 13,   /* pair: the one taken after the gap, value: how many
                                       * before it were dropped (overrun) */
    STEREOSIM_EV_PAIR_PROCESSED = 14, /* pair, value: buffer, detail: 1 if it gave a 3D point */
    STEREOSIM_EV_STOPPED = 15,        /* the loop ended; value: pairs processed */
    STEREOSIM_EV_HARD_ERROR = 16,     /* gave up: OE low, no capture; value: the last
                                       * rearm cause, detail: consecutive failures */
    STEREOSIM_EV_FRAMES_USED = 17     /* pair, left / right: the addresses the pipeline read
                                       * the pair's frames from, before PAIR_PROCESSED */
} stereosim_event_kind;

typedef enum stereosim_rearm_cause {
    STEREOSIM_REARM_HARD_ERROR = 1, /* the card reported HARD_ERROR */
    STEREOSIM_REARM_SYNC_ERROR = 2, /* a sync error, where the policy re-arms on every one */
    STEREOSIM_REARM_OVERFLOW = 3,
    STEREOSIM_REARM_WATCHDOG = 4
} stereosim_rearm_cause;

typedef struct stereosim_event {
    uint32_t kind; /* stereosim_event_kind */
    uint32_t pair;
    uint32_t value;
    uint32_t detail;
    uint32_t left;  /* PAIR_CAPTURED, FRAMES_USED: the left frame's address, else 0 */
    uint32_t right; /* PAIR_CAPTURED, FRAMES_USED: the right frame's address, else 0 */
} stereosim_event;

/* A box in image pixels: (x, y) its top-left pixel; w or h <= 0: none. */
typedef struct stereosim_box {
    int32_t x;
    int32_t y;
    int32_t w;
    int32_t h;
} stereosim_box;

/* The result of one processed pair, reported once per PAIR_PROCESSED. */
typedef struct stereosim_result {
    uint32_t pair;
    uint32_t state;      /* index into the descriptor's tracker_states: state after the pair */
    uint32_t detected;   /* 1: the track started on this pair */
    uint32_t has_object; /* 1: box_left / box_right hold the object */
    stereosim_box box_left;
    stereosim_box box_right;
    uint32_t has_point;   /* 1: disparity_q8 and x / y / z hold the 3D point */
    int32_t disparity_q8; /* the disparity the point came from, pixels x 256 */
    int32_t x_um;         /* the right camera's frame, micrometres */
    int32_t y_um;
    int32_t z_um;
    /* Every cycle charged for this pair, per stage: the budget reads the
     * pair's processing time from these alone. */
    uint64_t stage_cycles[STEREOSIM_FW_MAX_STAGES];
} stereosim_result;

/* ---- the board, as the run configured it ---- */
typedef enum stereosim_cfa {
    STEREOSIM_CFA_RGGB = 0,
    STEREOSIM_CFA_BGGR = 1,
    STEREOSIM_CFA_GRBG = 2,
    STEREOSIM_CFA_GBRG = 3
} stereosim_cfa;

typedef struct stereosim_board {
    uint32_t dsk_version; /* 1, 2 or 3 */
    uint64_t cpu_hz;
    uint64_t emif_hz;
    /* The card's CE2/CE3 access in ECLK (0: the DSK's own setting). */
    uint32_t card_setup;
    uint32_t card_strobe;
    uint32_t card_hold;
    uint32_t card_retry_limit; /* the RETRY_LIMIT the run asks the firmware to program */
    /* The sensors' frame geometry: what the card's geometry registers hold
     * (docs/card-registers.md). */
    uint32_t h_start;
    uint32_t dark_cols_left;
    uint32_t border_cols_left;
    uint32_t active_cols;
    uint32_t border_cols_right;
    uint32_t dark_cols_right;
    uint32_t line_total;
    uint32_t v_start;
    uint32_t dark_rows_top;
    uint32_t border_rows_top;
    uint32_t active_rows;
    uint32_t border_rows_bottom;
    uint32_t dark_rows_bottom;
    uint32_t frame_lines;
    uint32_t cfa; /* the sensors' colour filter: stereosim_cfa */
    /* The calibrated rig (the right camera's frame, docs/design-brief.md). */
    int32_t baseline_um;
    int32_t focal_length_um;
    int32_t pixel_pitch_nm;
    int32_t cx_left_q8; /* principal points, pixels x 256 */
    int32_t cy_left_q8;
    int32_t cx_right_q8;
    int32_t cy_right_q8;
} stereosim_board;

/* ---- the platform's services ----
 * Every function takes `ctx` first. None may be called from another thread
 * than the one run() was called on. */
typedef struct stereosim_services {
    uint32_t abi_version; /* STEREOSIM_FIRMWARE_ABI_VERSION of the platform */
    void* ctx;

    /* CPU time of a stage, in C64x cycles; `traffic` (may be NULL): the
     * bytes those cycles' memory stalls moved over EMIFA to SDRAM, which the
     * platform puts on the bus during the charge. */
    void (*charge)(void* ctx, uint32_t stage, uint64_t cycles,
                   const stereosim_sdram_traffic* traffic);
    /* The cycles and the SDRAM traffic of one kernel call under the run's
     * cost model (DSK clocks, compiled-C factor). `traffic` may be NULL. */
    uint64_t (*kernel_cycles)(void* ctx, const stereosim_kernel_profile* kernel,
                              stereosim_sdram_traffic* traffic);
    void (*stage_begin)(void* ctx, uint32_t stage);
    void (*stage_end)(void* ctx, uint32_t stage);

    /* One aligned 32-bit access at a physical address (C6416 registers, the
     * card's registers and pixel ports, L2, SDRAM): bus time as modelled. */
    uint32_t (*read32)(void* ctx, uint32_t address);
    void (*write32)(void* ctx, uint32_t address, uint32_t value);
    /* [address, address + bytes) of modelled L2 or SDRAM, NULL if not memory. */
    uint8_t* (*memory)(void* ctx, uint32_t address, uint32_t bytes);

    /* IER / IFR / ICR, bits 4..15 = INT4..INT15; no ISR runs by itself. */
    void (*set_interrupt_enable)(void* ctx, uint32_t ier);
    uint32_t (*interrupt_flags)(void* ctx);
    void (*clear_interrupt_flags)(void* ctx, uint32_t mask);
    /* Sleeps until IFR & IER has one of INT4..15, clears the lowest and
     * returns its number; STEREOSIM_FW_NO_INTERRUPT when asked to stop. */
    int32_t (*wait_for_interrupt)(void* ctx);
    /* Non-zero: end the frame loop (checked between pairs). */
    int32_t (*stop_requested)(void* ctx);

    void (*report)(void* ctx, const stereosim_event* event);
    void (*report_result)(void* ctx, const stereosim_result* result);
} stereosim_services;

/* ---- what the firmware declares ---- */
typedef enum stereosim_key_type {
    STEREOSIM_KEY_INT = 0,
    STEREOSIM_KEY_FLOAT = 1,
    STEREOSIM_KEY_BOOL = 2,
    STEREOSIM_KEY_CHOICE = 3 /* the value is the index into `choices` */
} stereosim_key_type;

typedef struct stereosim_fw_key {
    const char* name; /* without the "firmware." prefix */
    uint32_t type;    /* stereosim_key_type */
    double min;       /* INT / FLOAT: inclusive range */
    double max;
    double default_value;
    const char* const* choices; /* CHOICE: choice_count names */
    uint32_t choice_count;
    const char* doc; /* one line */
} stereosim_fw_key;

/* The recovery policy the contract holds the firmware to, for the values it
 * was created with (docs/fault-contract.md rules 4, 10, 11). */
typedef struct stereosim_fw_policy {
    uint32_t hard_error_rearms; /* re-arms after a card HARD_ERROR before the give-up */
    uint32_t rearm_on_overflow; /* 1: every overflow is followed by a re-arm */
    uint32_t rearm_on_every_sync_error;
    uint32_t watchdog_ms; /* 0: no watchdog */
    uint32_t overlapped;  /* 1: two pair buffers, 0: one (sequential) */
    /* Bit s set: stage s may never run in this configuration (an alternative
     * it was not asked for). Any other declared stage that never runs leaves
     * the run's budget not judged (docs/budget.md). 0: all are expected. */
    uint32_t optional_stages;
} stereosim_fw_policy;

typedef struct stereosim_fw_descriptor {
    uint32_t abi_version; /* STEREOSIM_FIRMWARE_ABI_VERSION the plugin was built for */
    const char* name;
    const char* version;

    uint32_t stage_count; /* 1..STEREOSIM_FW_MAX_STAGES */
    const char* const* stage_names;
    uint32_t tracker_state_count; /* 1..STEREOSIM_FW_MAX_TRACKER_STATES */
    const char* const* tracker_state_names;
    uint32_t key_count;
    const stereosim_fw_key* keys;

    /* An instance for one run: `values` holds key_count values (defaults
     * where the user set none, range-checked by the platform). NULL on
     * failure, with one line in `error` (error_size bytes). */
    void* (*create)(const stereosim_services* services, const stereosim_board* board,
                    const double* values, char* error, size_t error_size);
    /* Boot, then the frame loop until stop_requested, a give-up or a missing card. */
    void (*run)(void* instance);
    void (*destroy)(void* instance);
    void (*policy)(const void* instance, stereosim_fw_policy* out);
} stereosim_fw_descriptor;

typedef const stereosim_fw_descriptor* (*stereosim_firmware_entry)(void);

/* ---- optional: the processing chain alone, on the host ----
 * A plugin may also export STEREOSIM_FIRMWARE_HOST_ENTRY returning this
 * table. The sweep's closed form (docs/sweep.md) then prices a point's pairs
 * without a co-simulation: the platform renders the scenario, mosaics each
 * frame in the board's CFA as the sensors deliver it, and hands the raw pair
 * to process_pair. Of the services only charge, kernel_cycles, stage_begin,
 * stage_end, report and report_result do anything there: there is no bus
 * (read32 returns 0, write32 does nothing), no memory (NULL), no interrupt
 * (NO_INTERRUPT) and stop_requested is 0. A plugin without the symbol gets
 * no closed-form processing estimate, which the sweep says per point.
 * Adding this symbol changed no structure above: the ABI version stays 1. */
#define STEREOSIM_FIRMWARE_HOST_ENTRY "stereosim_firmware_host"

typedef struct stereosim_fw_host {
    uint32_t abi_version; /* STEREOSIM_FIRMWARE_ABI_VERSION the plugin was built for */
    /* As the descriptor's create, for host runs. */
    void* (*create)(const stereosim_services* services, const stereosim_board* board,
                    const double* values, char* error, size_t error_size);
    /* One raw Bayer pair, active_cols x active_rows bytes each, row after
     * row: reports exactly one result for `pair`, whose stage_cycles hold
     * every cycle the pair costs in the co-simulation (its capture work
     * included). */
    void (*process_pair)(void* instance, uint32_t pair, const uint8_t* left, const uint8_t* right);
    void (*destroy)(void* instance);
} stereosim_fw_host;

typedef const stereosim_fw_host* (*stereosim_firmware_host_entry)(void);

/* The entry a plugin defines; exported even when the plugin is built with
 * hidden visibility (stereosim_add_firmware does). */
#if defined(__GNUC__)
#define STEREOSIM_FIRMWARE_EXPORT __attribute__((visibility("default")))
#else
#define STEREOSIM_FIRMWARE_EXPORT
#endif
STEREOSIM_FIRMWARE_EXPORT const stereosim_fw_descriptor* stereosim_firmware(void);
/* Optional (see stereosim_fw_host). */
STEREOSIM_FIRMWARE_EXPORT const stereosim_fw_host* stereosim_firmware_host(void);

#ifdef __cplusplus
}
#endif

#endif /* STEREOSIM_FIRMWARE_H */
