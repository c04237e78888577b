/* The shipped firmware with one report left out: a plugin that loads the
 * reference plugin (REFERENCE_FIRMWARE, its path) and hands it the
 * platform's services with report() or report_result() filtered. Its one
 * key of its own, `omit`, names what it leaves out ("none": nothing). It
 * stands for a user's firmware that forgets a report: the contract must
 * name the missing report (docs/firmware-abi.md, "The reporting protocol"),
 * not pass it or blame something else.
 *
 * Built with RENAMED_STAGES (renaming_firmware.so) it leaves nothing out but
 * declares 15 stages: 8 it never runs ("pad0".."pad7", optional in its
 * policy), then the reference's 7 renamed "x_" + name, and its tracker
 * states renamed; each stage index and each result's per-stage cycles are
 * moved by 8. A firmware whose stages are not the reference's: the budget,
 * report.json, frames.csv and the waveform must follow its descriptor. */
#define _POSIX_C_SOURCE 200809L
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stereosim/firmware.h"

/* What `omit` can name: an event kind, or every result. */
static const char* const omit_names[] = {
    "none",           "oe_raised",  "in_step",       "sync_error",    "overflow",
    "card_rearmed",   "watchdog",   "pair_captured", "pair_rejected", "pair_dropped",
    "pair_processed", "hard_error", "frames_used",   "result"};
#define OMIT_COUNT (sizeof omit_names / sizeof omit_names[0])
#define OMIT_RESULT (OMIT_COUNT - 1)
static const uint32_t omit_kinds[OMIT_COUNT] = {0, /* none */
                                                STEREOSIM_EV_OE_RAISED,
                                                STEREOSIM_EV_IN_STEP,
                                                STEREOSIM_EV_SYNC_ERROR,
                                                STEREOSIM_EV_OVERFLOW,
                                                STEREOSIM_EV_CARD_REARMED,
                                                STEREOSIM_EV_WATCHDOG,
                                                STEREOSIM_EV_PAIR_CAPTURED,
                                                STEREOSIM_EV_PAIR_REJECTED,
                                                STEREOSIM_EV_PAIR_DROPPED,
                                                STEREOSIM_EV_PAIR_PROCESSED,
                                                STEREOSIM_EV_HARD_ERROR,
                                                STEREOSIM_EV_FRAMES_USED,
                                                0 /* result */};

#define MAX_KEYS 128u

#ifdef RENAMED_STAGES
#define STAGE_SHIFT 8u
static const char* const renamed_stages[STEREOSIM_FW_MAX_STAGES] = {
    "pad0",      "pad1",   "pad2",     "pad3",    "pad4",         "pad5",          "pad6", "pad7",
    "x_capture", "x_gray", "x_detect", "x_track", "x_stereo_sad", "x_stereo_edge", "x_xyz"};
static const char* const renamed_states[] = {"X_DETECT", "X_TRACK", "X_LOST"};
#else
#define STAGE_SHIFT 0u
#endif

typedef struct omitting {
    stereosim_services filtered; /* what the reference sees */
    const stereosim_services* platform;
    uint32_t omit; /* index into omit_names */
    void* inner;
} omitting;

static const stereosim_fw_descriptor* reference;
static stereosim_fw_key keys[MAX_KEYS];
static stereosim_fw_descriptor descriptor;

static void report(void* ctx, const stereosim_event* event) {
    const omitting* self = (const omitting*)ctx;
    if (self->omit != 0 && self->omit != OMIT_RESULT && event->kind == omit_kinds[self->omit])
        return;
    self->platform->report(self->platform->ctx, event);
}

static void report_result(void* ctx, const stereosim_result* result) {
    const omitting* self = (const omitting*)ctx;
    if (self->omit == OMIT_RESULT) return;
    stereosim_result moved = *result;
    memset(moved.stage_cycles, 0, sizeof moved.stage_cycles);
    for (uint32_t s = 0; s + STAGE_SHIFT < STEREOSIM_FW_MAX_STAGES; ++s)
        moved.stage_cycles[s + STAGE_SHIFT] = result->stage_cycles[s];
    self->platform->report_result(self->platform->ctx, &moved);
}

/* Every other service is the platform's, called with the platform's context. */
#define PLATFORM(ctx) (((const omitting*)(ctx))->platform)
static void charge(void* ctx, uint32_t stage, uint64_t cycles, const stereosim_sdram_traffic* t) {
    PLATFORM(ctx)->charge(PLATFORM(ctx)->ctx, stage + STAGE_SHIFT, cycles, t);
}
static uint64_t kernel_cycles(void* ctx, const stereosim_kernel_profile* k,
                              stereosim_sdram_traffic* t) {
    return PLATFORM(ctx)->kernel_cycles(PLATFORM(ctx)->ctx, k, t);
}
static void stage_begin(void* ctx, uint32_t stage) {
    PLATFORM(ctx)->stage_begin(PLATFORM(ctx)->ctx, stage + STAGE_SHIFT);
}
static void stage_end(void* ctx, uint32_t stage) {
    PLATFORM(ctx)->stage_end(PLATFORM(ctx)->ctx, stage + STAGE_SHIFT);
}
static uint32_t read32(void* ctx, uint32_t address) {
    return PLATFORM(ctx)->read32(PLATFORM(ctx)->ctx, address);
}
static void write32(void* ctx, uint32_t address, uint32_t value) {
    PLATFORM(ctx)->write32(PLATFORM(ctx)->ctx, address, value);
}
static uint8_t* memory(void* ctx, uint32_t address, uint32_t bytes) {
    return PLATFORM(ctx)->memory(PLATFORM(ctx)->ctx, address, bytes);
}
static void set_interrupt_enable(void* ctx, uint32_t ier) {
    PLATFORM(ctx)->set_interrupt_enable(PLATFORM(ctx)->ctx, ier);
}
static uint32_t interrupt_flags(void* ctx) {
    return PLATFORM(ctx)->interrupt_flags(PLATFORM(ctx)->ctx);
}
static void clear_interrupt_flags(void* ctx, uint32_t mask) {
    PLATFORM(ctx)->clear_interrupt_flags(PLATFORM(ctx)->ctx, mask);
}
static int32_t wait_for_interrupt(void* ctx) {
    return PLATFORM(ctx)->wait_for_interrupt(PLATFORM(ctx)->ctx);
}
static int32_t stop_requested(void* ctx) {
    return PLATFORM(ctx)->stop_requested(PLATFORM(ctx)->ctx);
}

static void* create(const stereosim_services* services, const stereosim_board* board,
                    const double* values, char* error, size_t error_size) {
    omitting* self = (omitting*)calloc(1, sizeof *self);
    if (self == NULL) {
        snprintf(error, error_size, "omitting firmware: out of memory");
        return NULL;
    }
    self->platform = services;
    self->omit = (uint32_t)values[reference->key_count];
    const stereosim_services filtered = {services->abi_version,
                                         self,
                                         charge,
                                         kernel_cycles,
                                         stage_begin,
                                         stage_end,
                                         read32,
                                         write32,
                                         memory,
                                         set_interrupt_enable,
                                         interrupt_flags,
                                         clear_interrupt_flags,
                                         wait_for_interrupt,
                                         stop_requested,
                                         report,
                                         report_result};
    self->filtered = filtered;
    self->inner = reference->create(&self->filtered, board, values, error, error_size);
    if (self->inner == NULL) {
        free(self);
        return NULL;
    }
    return self;
}

static void run(void* instance) {
    reference->run(((omitting*)instance)->inner);
}

static void destroy(void* instance) {
    omitting* self = (omitting*)instance;
    reference->destroy(self->inner);
    free(self);
}

static void policy(const void* instance, stereosim_fw_policy* out) {
    reference->policy(((const omitting*)instance)->inner, out);
    out->optional_stages = (out->optional_stages << STAGE_SHIFT) | ((1u << STAGE_SHIFT) - 1u);
}

static const stereosim_fw_descriptor* load_reference(void) {
    void* library = dlopen(REFERENCE_FIRMWARE, RTLD_NOW | RTLD_LOCAL);
    if (library == NULL) return NULL;
    void* symbol = dlsym(library, STEREOSIM_FIRMWARE_ENTRY);
    if (symbol == NULL) return NULL;
    stereosim_firmware_entry entry;
    memcpy(&entry, &symbol, sizeof entry); /* POSIX: a data pointer to a function */
    return entry();
}

STEREOSIM_FIRMWARE_EXPORT const stereosim_fw_descriptor* stereosim_firmware(void) {
    if (reference == NULL) {
        reference = load_reference();
        if (reference == NULL || reference->key_count + 1 > MAX_KEYS) return NULL;
        memcpy(keys, reference->keys, reference->key_count * sizeof keys[0]);
        const stereosim_fw_key omit = {"omit",
                                       STEREOSIM_KEY_CHOICE,
                                       0,
                                       0,
                                       0,
                                       omit_names,
                                       (uint32_t)OMIT_COUNT,
                                       "the report left out"};
        keys[reference->key_count] = omit;
        descriptor = *reference;
        descriptor.name = "omitting-reference";
        descriptor.key_count = reference->key_count + 1;
        descriptor.keys = keys;
        descriptor.create = create;
        descriptor.run = run;
        descriptor.destroy = destroy;
        descriptor.policy = policy;
#ifdef RENAMED_STAGES
        descriptor.name = "renamed-reference";
        descriptor.stage_count = STEREOSIM_FW_MAX_STAGES;
        descriptor.stage_names = renamed_stages;
        descriptor.tracker_state_names = renamed_states;
#endif
    }
    return &descriptor;
}
