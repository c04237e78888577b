/* A firmware in plain C11 for the loader's tests (tests/firmware): boots,
 * charges its one stage, waits for interrupts until the platform asks it to
 * stop, and reports each step. Built several times with one defect each
 * (BAD_ABI, NO_ENTRY, TOO_MANY_STAGES, BAD_KEY_DEFAULT, NO_DESCRIPTOR) to
 * show the loader refusing it, or with a bug (CRASH_IN_RUN: a null pointer
 * written 10 ms into stage think; HANG_IN_RUN: a busy loop 10 ms into stage
 * think that only asks whether to stop) to show the platform reporting its
 * crash or its hang; NONDETERMINISTIC: a first charge that depends on the
 * process id, which `stereosim firmware check` must catch; PARENT_DEPENDENT:
 * the same on the parent's process id, alike in two runs started by one
 * process, so only the check's forked runs against their runs from the
 * start catch it; MANY_STAGES: all 15 stages the ABI allows, the work
 * charged to the last; UNDECLARED_STAGE: work charged to stage 5 of the 2
 * it declares, which the platform must refuse. */
#if defined(NONDETERMINISTIC) || defined(PARENT_DEPENDENT)
#define _POSIX_C_SOURCE 200809L /* getpid */
#include <unistd.h>
#endif
#include <stdio.h>
#include <stdlib.h>

#include "stereosim/firmware.h"

/* The stage the work after each interrupt is charged to. */
#if defined(MANY_STAGES)
#define WORK_STAGE 14u
#elif defined(UNDECLARED_STAGE)
#define WORK_STAGE 5u
#else
#define WORK_STAGE 1u
#endif

typedef struct minimal {
    const stereosim_services* hw;
    uint64_t cycles_per_wait;
    uint32_t mode;
} minimal;

static const char* const stages[] = {"capture", "think", "s2",  "s3",  "s4",  "s5",  "s6",  "s7",
                                     "s8",      "s9",    "s10", "s11", "s12", "s13", "s14", "s15"};
static const char* const states[] = {"idle", "busy"};
static const char* const modes[] = {"quiet", "chatty"};

static const stereosim_fw_key keys[] = {
    {"cycles_per_wait", STEREOSIM_KEY_INT, 0, 1e6,
#ifdef BAD_KEY_DEFAULT
     2e6,
#else
     600,
#endif
     NULL, 0, "cycles charged to stage think after each interrupt"},
    {"mode", STEREOSIM_KEY_CHOICE, 0, 0, 0, modes, 2, "quiet: fewer reports"},
};

static void report(const minimal* m, uint32_t kind, uint32_t value) {
    stereosim_event e = {0, 0, 0, 0, 0, 0};
    e.kind = kind;
    e.value = value;
    m->hw->report(m->hw->ctx, &e);
}

static void* create(const stereosim_services* services, const stereosim_board* board,
                    const double* values, char* error, size_t error_size) {
    minimal* m;
    if (board->active_cols == 0) {
        snprintf(error, error_size, "the board has no active columns");
        return NULL;
    }
    m = (minimal*)calloc(1, sizeof *m);
    if (m == NULL) {
        snprintf(error, error_size, "out of memory");
        return NULL;
    }
    m->hw = services;
    m->cycles_per_wait = (uint64_t)values[0];
    m->mode = (uint32_t)values[1];
    return m;
}

static void run(void* instance) {
    minimal* m = (minimal*)instance;
    uint32_t interrupts = 0;
    report(m, STEREOSIM_EV_BOOT, 1);
#ifdef CRASH_IN_RUN
    {
        /* The bug: 10 ms of work in stage think (6,000,000 cycles at the
         * DSK v1's 600 MHz), then a null pointer written. */
        volatile int* nowhere = NULL;
        m->hw->stage_begin(m->hw->ctx, 1);
        m->hw->charge(m->hw->ctx, 1, 6000000u, NULL);
        *nowhere = 1;
    }
#endif
#ifdef NONDETERMINISTIC
    /* The bug: work sized by something of the host's, here the process id. */
    m->hw->stage_begin(m->hw->ctx, 1);
    m->hw->charge(m->hw->ctx, 1, 1000u + (uint64_t)(getpid() % 4096), NULL);
    m->hw->stage_end(m->hw->ctx, 1);
#endif
#ifdef PARENT_DEPENDENT
    m->hw->stage_begin(m->hw->ctx, 1);
    m->hw->charge(m->hw->ctx, 1, 1000u + (uint64_t)(getppid() % 4096), NULL);
    m->hw->stage_end(m->hw->ctx, 1);
#endif
#if defined(MANY_STAGES) || defined(UNDECLARED_STAGE)
    /* Work in WORK_STAGE at once: no interrupt comes to a card never enabled. */
    m->hw->stage_begin(m->hw->ctx, WORK_STAGE);
    m->hw->charge(m->hw->ctx, WORK_STAGE, m->cycles_per_wait, NULL);
    m->hw->stage_end(m->hw->ctx, WORK_STAGE);
#endif
#ifdef HANG_IN_RUN
    /* The bug: waits for a flag by polling, never giving time back, so the
     * flag can never change. */
    m->hw->stage_begin(m->hw->ctx, 1);
    m->hw->charge(m->hw->ctx, 1, 6000000u, NULL);
    while (!m->hw->stop_requested(m->hw->ctx)) {
    }
#endif
    m->hw->set_interrupt_enable(m->hw->ctx, 1u << 4);
    for (;;) {
        int32_t n = m->hw->wait_for_interrupt(m->hw->ctx);
        if (n == STEREOSIM_FW_NO_INTERRUPT || m->hw->stop_requested(m->hw->ctx)) break;
        ++interrupts;
        m->hw->stage_begin(m->hw->ctx, WORK_STAGE);
        m->hw->charge(m->hw->ctx, WORK_STAGE, m->cycles_per_wait, NULL);
        m->hw->stage_end(m->hw->ctx, WORK_STAGE);
        if (m->mode == 1) report(m, STEREOSIM_EV_WATCHDOG, (uint32_t)n);
    }
    report(m, STEREOSIM_EV_STOPPED, interrupts);
}

static void destroy(void* instance) {
    free(instance);
}

static void policy(const void* instance, stereosim_fw_policy* out) {
    (void)instance;
    out->hard_error_rearms = 0;
    out->rearm_on_overflow = 0;
    out->rearm_on_every_sync_error = 0;
    out->watchdog_ms = 0;
    out->overlapped = 0;
}

static const stereosim_fw_descriptor descriptor = {
#ifdef BAD_ABI
    99u,
#else
    STEREOSIM_FIRMWARE_ABI_VERSION,
#endif
    "minimal", "0.1",
#if defined(TOO_MANY_STAGES)
    16u,
#elif defined(MANY_STAGES)
    15u,
#else
    2u,
#endif
    stages,    2u,    states, 2u, keys, create, run, destroy, policy};

#ifdef NO_ENTRY
const stereosim_fw_descriptor* not_the_entry(void) {
    return &descriptor;
}
#elif defined(NO_DESCRIPTOR)
const stereosim_fw_descriptor* stereosim_firmware(void) {
    return descriptor.name ? NULL : &descriptor;
}
#else
const stereosim_fw_descriptor* stereosim_firmware(void) {
    return &descriptor;
}
#endif

#ifdef BAD_HOST_ABI
/* A host entry (optional) built for another ABI: the whole plugin is refused. */
static void* host_create(const stereosim_services* services, const stereosim_board* board,
                         const double* values, char* error, size_t error_size) {
    (void)services;
    (void)board;
    (void)values;
    (void)error;
    (void)error_size;
    return NULL;
}
static void host_process(void* instance, uint32_t pair, const uint8_t* left, const uint8_t* right) {
    (void)instance;
    (void)pair;
    (void)left;
    (void)right;
}
static void host_destroy(void* instance) {
    (void)instance;
}
static const stereosim_fw_host host = {7u, host_create, host_process, host_destroy};
const stereosim_fw_host* stereosim_firmware_host(void) {
    return &host;
}
#endif
