/* The plugin's face: its descriptor (stages, tracker states, keys), create /
 * run / destroy and its recovery policy, and the cost service's use. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "paper_fw.h"

static const char* const stage_names[ST_COUNT] = {"capture",    "preprocess",  "detect", "track",
                                                  "stereo_sad", "stereo_edge", "xyz"};
static const char* const tracker_states[] = {"DETECT", "TRACK", "LOST"};
static const char* const modes[] = {"sequential", "overlapped"};

/* Named like the platform's firmware keys, so a run's settings reach them. */
static const stereosim_fw_key keys[KEY_COUNT] = {
    {"mode", STEREOSIM_KEY_CHOICE, 0, 0, 1, modes, 2,
     "one pair buffer (read, then process) or two (process one while the next is read)"},
    {"watchdog_ms", STEREOSIM_KEY_INT, 0, 10000, 500, NULL, 0,
     "re-arm a card silent for this long, ms (0: no watchdog)"},
    {"card_start_timeout", STEREOSIM_KEY_INT, 1, 65535, 1050, NULL, 0,
     "START_TIMEOUT: lines the card waits for the first VSYNC after OE rises"},
    {"search_radius", STEREOSIM_KEY_INT, 1, 1000, 24, NULL, 0,
     "SAD tracking search radius, pixels each way"},
    {"detect_threshold", STEREOSIM_KEY_INT, 1, 254, 20, NULL, 0,
     "three-frame differencing: a pixel moves above this gray difference"},
    {"hard_error_rearms", STEREOSIM_KEY_INT, 0, 16, 1, NULL, 0,
     "re-arms after a card HARD_ERROR or a watchdog, no good pair between, before giving up"},
};

void fw_charge_loop(paper_fw* fw, uint32_t stage, const char* name, uint64_t iterations,
                    stereosim_op_mix ops, uint32_t chain, uint64_t bytes_read,
                    uint64_t bytes_written, uint32_t where) {
    stereosim_kernel_profile p;
    stereosim_sdram_traffic traffic = {0, 0};
    uint64_t cycles;
    memset(&p, 0, sizeof p);
    p.name = name;
    p.calls = 1;
    p.section_count = 1;
    p.sections[0].name = name;
    p.sections[0].ops = ops;
    p.sections[0].iterations = iterations;
    p.sections[0].entries = 1;
    p.sections[0].chain = chain;
    p.sections[0].recurrence = 1;
    p.sections[0].is_loop = iterations > 1;
    p.stream_count = 1;
    p.streams[0].bytes_read = bytes_read;
    p.streams[0].bytes_written = bytes_written;
    p.streams[0].where = where;
    cycles = fw->hw->kernel_cycles(fw->hw->ctx, &p, &traffic);
    fw->hw->charge(fw->hw->ctx, stage, cycles, &traffic);
    fw->stage_cycles[stage] += cycles;
}

void* fw_create(const stereosim_services* services, const stereosim_board* board,
                const double* values, char* error, size_t error_size) {
    paper_fw* fw;
    if (board->active_cols % 8 != 0 || board->active_rows % 8 != 0 || board->active_cols < 64 ||
        board->active_rows < 64) {
        snprintf(error, error_size,
                 "the image must be a multiple of 8 pixels each way, at least 64");
        return NULL;
    }
    fw = (paper_fw*)calloc(1, sizeof *fw);
    if (!fw) {
        snprintf(error, error_size, "out of memory");
        return NULL;
    }
    fw->hw = services;
    fw->board = *board;
    fw->width = board->active_cols;
    fw->height = board->active_rows;
    fw->overlapped = (uint32_t)values[KEY_MODE];
    fw->buffers = fw->overlapped ? 2u : 1u;
    fw->watchdog_ms = (uint32_t)values[KEY_WATCHDOG_MS];
    fw->start_timeout = (uint32_t)values[KEY_START_TIMEOUT];
    fw->hard_error_rearms = (uint32_t)values[KEY_HARD_ERROR_REARMS];
    if (!vision_init(&fw->v, fw->width, fw->height, (uint32_t)values[KEY_DETECT_THRESHOLD],
                     (int32_t)values[KEY_SEARCH_RADIUS])) {
        free(fw);
        snprintf(error, error_size, "out of memory for the frames");
        return NULL;
    }
    return fw;
}

/* Boot, then: take the interrupts that are in, process the oldest full
 * buffer, or sleep until the next interrupt. */
static void run(void* instance) {
    paper_fw* fw = (paper_fw*)instance;
    if (!fw_boot(fw)) return;
    while (!fw->gave_up && !fw->hw->stop_requested(fw->hw->ctx)) {
        int full, n;
        fw_service_interrupts(fw);
        if (fw->gave_up) break;
        full = fw_oldest_full(fw);
        if (full >= 0) {
            fw_release(fw, full);
            continue;
        }
        n = fw->hw->wait_for_interrupt(fw->hw->ctx);
        if (n == STEREOSIM_FW_NO_INTERRUPT) break;
        fw_handle_interrupt(fw, n);
    }
    fw_shutdown(fw);
}

void fw_destroy(void* instance) {
    paper_fw* fw = (paper_fw*)instance;
    vision_free(&fw->v);
    free(fw);
}

static void policy(const void* instance, stereosim_fw_policy* out) {
    const paper_fw* fw = (const paper_fw*)instance;
    out->hard_error_rearms = fw->hard_error_rearms;
    out->rearm_on_overflow = 1;
    out->rearm_on_every_sync_error = 0;
    out->watchdog_ms = fw->watchdog_ms;
    out->overlapped = fw->overlapped;
    out->optional_stages = 1u << ST_UNUSED_EDGE; /* declared for the reference's order only */
}

static const stereosim_fw_descriptor descriptor = {STEREOSIM_FIRMWARE_ABI_VERSION,
                                                   "paper-c",
                                                   "0.1",
                                                   ST_COUNT,
                                                   stage_names,
                                                   3,
                                                   tracker_states,
                                                   KEY_COUNT,
                                                   keys,
                                                   fw_create,
                                                   run,
                                                   fw_destroy,
                                                   policy};

const stereosim_fw_descriptor* stereosim_firmware(void) {
    return &descriptor;
}
