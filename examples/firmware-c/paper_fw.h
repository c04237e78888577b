/* A second firmware for the stereosim platform, written in plain C11 against
 * the installed SDK only (stereosim/firmware.h): the paper's chain at its
 * plainest (gray from the raw pair, three-frame differencing, SAD tracking,
 * SAD stereo, depth) under the card's sync protocol (OE restart on a bad
 * verdict by the card, re-arm on its hard error and on an overflow, a
 * watchdog, a give-up). See README.md. */
#ifndef PAPER_FW_H
#define PAPER_FW_H

#include <stddef.h>
#include <stdint.h>

#include "stereosim/firmware.h"

/* The stages and tracker states. The platform names them as the descriptor
 * does; they follow the reference firmware's names and order so that the
 * two firmware's tables line up side by side. The edge stage never runs
 * (the policy's optional_stages says so). */
enum { ST_CAPTURE, ST_GRAY, ST_DETECT, ST_TRACK, ST_STEREO, ST_UNUSED_EDGE, ST_XYZ, ST_COUNT };
enum { TRACKER_DETECT, TRACKER_TRACK, TRACKER_LOST };

/* CPU cycles per pair of the capture stage: interrupt entry, header
 * check, re-arm (this author's guess). */
#define CAPTURE_CYCLES 600u

/* The keys, in the descriptor's order. */
enum {
    KEY_MODE,
    KEY_WATCHDOG_MS,
    KEY_START_TIMEOUT,
    KEY_SEARCH_RADIUS,
    KEY_DETECT_THRESHOLD,
    KEY_HARD_ERROR_REARMS,
    KEY_COUNT
};

typedef struct vision {
    uint32_t w, h;
    uint8_t* gray[3]; /* the right camera's gray frames: [0] newest */
    uint8_t* left;    /* the left camera's gray frame of the current pair */
    uint32_t frames;  /* right gray frames seen since the last restart */
    uint8_t* moving;  /* per 8 x 8 block: 1 = moving */
    int32_t* queue;   /* flood fill of the moving blocks */
    uint8_t* labels;
    uint8_t* templ; /* the tracked object as detected, from the right image */
    uint8_t* patch; /* the box's look in the right image now, for stereo */
    stereosim_box box;
    uint32_t state;
    uint32_t threshold;
    int32_t search_radius;
} vision;

typedef struct paper_fw {
    const stereosim_services* hw;
    stereosim_board board;
    uint32_t overlapped, watchdog_ms, start_timeout, hard_error_rearms;
    uint32_t width, height;
    /* capture: pair buffers A (and B when overlapped) */
    uint32_t buffers;
    uint32_t state[2];
    uint32_t full_order[2];
    uint32_t captures;
    /* the sync protocol */
    uint32_t failures, oe_raises, watchdog_progress, awaiting_in_step;
    uint32_t have_pair, last_pair, pairs_processed, gave_up;
    uint64_t stage_cycles[ST_COUNT]; /* of the pair being processed */
    vision v;
} paper_fw;

enum { BUF_FREE, BUF_ARMED, BUF_FULL, BUF_BUSY };

/* capture.c: boot, EDMA capture, the card's interrupts, re-arm, give-up */
void fw_event(paper_fw* fw, uint32_t kind, uint32_t pair, uint32_t value, uint32_t detail);
int fw_boot(paper_fw* fw);
void fw_service_interrupts(paper_fw* fw);
void fw_handle_interrupt(paper_fw* fw, int n);
int fw_oldest_full(const paper_fw* fw);
void fw_release(paper_fw* fw, int buffer);
void fw_shutdown(paper_fw* fw);
uint32_t fw_buffer_address(const paper_fw* fw, int buffer);
uint32_t fw_left_address(const paper_fw* fw, int buffer);
uint32_t fw_right_address(const paper_fw* fw, int buffer);

/* firmware.c: an instance for a board and key values, and its end (the
 * descriptor's and the host entry's create and destroy) */
void* fw_create(const stereosim_services* services, const stereosim_board* board,
                const double* values, char* error, size_t error_size);
void fw_destroy(void* instance);

/* vision.c: the paper's chain, each step charged to its stage */
int vision_init(vision* v, uint32_t w, uint32_t h, uint32_t threshold, int32_t search_radius);
void vision_free(vision* v);
void vision_restart(vision* v);
void vision_pair(paper_fw* fw, const uint8_t* raw_left, const uint8_t* raw_right,
                 stereosim_result* result);

/* A kernel's cycles under the run's cost model, charged to its stage:
 * one loop of `iterations` issuing `ops` each, its data in `where`. */
void fw_charge_loop(paper_fw* fw, uint32_t stage, const char* name, uint64_t iterations,
                    stereosim_op_mix ops, uint32_t chain, uint64_t bytes_read,
                    uint64_t bytes_written, uint32_t where);

#endif
