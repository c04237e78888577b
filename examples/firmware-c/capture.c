/* The capture side: boot (EMIF, interrupts, the card, EDMA), the card's
 * interrupts, re-arming the card, the watchdog and the give-up.
 *
 * EDMA (as the card's documents suggest, docs/card.md): the card's
 * FRAME_READY is EDMA event 4. Channel 4 copies VERDICT .. PAIRS_OK into the
 * armed buffer's header and chains to a channel that reads the left frame
 * from its pixel port line by line, which chains to the right frame; that
 * one's completion raises EDMA_INT. Three chains: into buffer A, into B, and
 * a drain that reads a pair into one sink word (a pair nobody has room for
 * is thrown away, never left in the card's FIFO). Channel 4 links back to
 * the drain, so a pair that comes while no buffer is armed is drained. */
#include <stddef.h>

#include "dsk_regs.h"
#include "paper_fw.h"

#define HEADER_BYTES 64u
#define STATUS_WORDS 5u /* VERDICT, MISMATCH_POS, FRAMES_L, FRAMES_R, PAIRS_OK */
#define HDR_VERDICT 0
#define HDR_PAIRS_OK 4
#define CONTROL_BASE 0x000FF000u /* L2: drain header, then the sink word at +64 */
#define DRAIN 2
#define REARM_IDLE_POLLS 64u

static const int left_channel[3] = {56, 58, 60};
static const int right_channel[3] = {57, 59, 61};
static const uint32_t done_code[3] = {8, 9, 10};

void fw_event(paper_fw* fw, uint32_t kind, uint32_t pair, uint32_t value, uint32_t detail) {
    stereosim_event e = {0, 0, 0, 0, 0, 0};
    e.kind = kind;
    e.pair = pair;
    e.value = value;
    e.detail = detail;
    fw->hw->report(fw->hw->ctx, &e);
}

static uint32_t rd(paper_fw* fw, uint32_t a) {
    return fw->hw->read32(fw->hw->ctx, a);
}
static void wr(paper_fw* fw, uint32_t a, uint32_t v) {
    fw->hw->write32(fw->hw->ctx, a, v);
}
static uint32_t card_rd(paper_fw* fw, uint32_t r) {
    return rd(fw, CARD_BASE + r);
}
static void card_wr(paper_fw* fw, uint32_t r, uint32_t v) {
    wr(fw, CARD_BASE + r, v);
}

uint32_t fw_buffer_address(const paper_fw* fw, int buffer) {
    const uint32_t stride = (HEADER_BYTES + 2u * fw->width * fw->height + 4095u) & ~4095u;
    return SDRAM_BASE + (uint32_t)buffer * stride;
}
uint32_t fw_left_address(const paper_fw* fw, int buffer) {
    return fw_buffer_address(fw, buffer) + HEADER_BYTES;
}
uint32_t fw_right_address(const paper_fw* fw, int buffer) {
    return fw_left_address(fw, buffer) + fw->width * fw->height;
}

/* ---- boot ---- */
static void program_emif(paper_fw* fw) {
    const int v1 = fw->board.dsk_version == 1;
    uint32_t cectl = v1 ? DSK_CECTL_CARD_V1 : DSK_CECTL_CARD_V2;
    const stereosim_board* b = &fw->board;
    if (b->card_setup)
        cectl = (cectl & ~(CECTL_WRSETUP(15) | CECTL_RDSETUP(15))) | CECTL_WRSETUP(b->card_setup) |
                CECTL_RDSETUP(b->card_setup);
    if (b->card_strobe)
        cectl = (cectl & ~(CECTL_WRSTRB(63) | CECTL_RDSTRB(63))) | CECTL_WRSTRB(b->card_strobe) |
                CECTL_RDSTRB(b->card_strobe);
    if (b->card_hold)
        cectl = (cectl & ~(CECTL_WRHLD(3) | CECTL_RDHLD(7))) | CECTL_WRHLD(b->card_hold) |
                CECTL_RDHLD(b->card_hold);
    wr(fw, EMIFA_GBLCTL, DSK_GBLCTL);
    wr(fw, EMIFA_CECTL0, DSK_CECTL0_SDRAM);
    wr(fw, EMIFA_SDCTL, DSK_SDCTL);
    wr(fw, EMIFA_SDTIM, v1 ? DSK_SDTIM_V1 : DSK_SDTIM_V2);
    wr(fw, EMIFA_SDEXT, v1 ? DSK_SDEXT_V1 : DSK_SDEXT_V2);
    wr(fw, EMIFA_CECTL2, cectl);
    wr(fw, EMIFA_CECTL3, cectl);
    fw_event(fw, STEREOSIM_EV_EMIF_PROGRAMMED, 0, cectl, v1 ? DSK_SDTIM_V1 : DSK_SDTIM_V2);
}

static uint32_t enabled_interrupts(const paper_fw* fw) {
    uint32_t ier = (1u << INT_EXT5) | (1u << INT_EXT6) | (1u << INT_EDMA);
    if (fw->watchdog_ms) ier |= 1u << INT_TINT1;
    return ier;
}

static void setup_interrupts(paper_fw* fw) {
    wr(fw, IRQ_MUXL, IRQ_MUXL_RESET);
    wr(fw, IRQ_MUXH, IRQ_MUXH_RESET);
    wr(fw, IRQ_EXTPOL, 0); /* the card pulses high */
    fw->hw->clear_interrupt_flags(fw->hw->ctx, 0xFFFFu);
    fw->hw->set_interrupt_enable(fw->hw->ctx, enabled_interrupts(fw));
}

static int probe_card(paper_fw* fw) {
    const uint32_t id = card_rd(fw, CARD_ID);
    if ((id & CARD_ID_MAGIC_MASK) != CARD_ID_MAGIC) {
        fw_event(fw, STEREOSIM_EV_CARD_MISSING, 0, id, 0);
        return 0;
    }
    fw_event(fw, STEREOSIM_EV_CARD_FOUND, 0, id, 0);
    return 1;
}

static void configure_card(paper_fw* fw) {
    const stereosim_board* b = &fw->board;
    const uint32_t enable = CARD_IRQ_FRAME_READY | CARD_IRQ_SYNC_ERROR | CARD_IRQ_OVERFLOW;
    card_wr(fw, CARD_CTRL, 0);
    card_wr(fw, CARD_IRQ_STATUS, enable);
    card_wr(fw, CARD_DARK_THRESHOLD, CARD_DARK_THRESHOLD_RESET);
    card_wr(fw, CARD_H_START, b->h_start);
    card_wr(fw, CARD_DARK_COLS_LEFT, b->dark_cols_left);
    card_wr(fw, CARD_BORDER_COLS_LEFT, b->border_cols_left);
    card_wr(fw, CARD_ACTIVE_COLS, b->active_cols);
    card_wr(fw, CARD_BORDER_COLS_RIGHT, b->border_cols_right);
    card_wr(fw, CARD_DARK_COLS_RIGHT, b->dark_cols_right);
    card_wr(fw, CARD_LINE_TOTAL, b->line_total);
    card_wr(fw, CARD_V_START, b->v_start);
    card_wr(fw, CARD_DARK_ROWS_TOP, b->dark_rows_top);
    card_wr(fw, CARD_BORDER_ROWS_TOP, b->border_rows_top);
    card_wr(fw, CARD_ACTIVE_ROWS, b->active_rows);
    card_wr(fw, CARD_BORDER_ROWS_BOTTOM, b->border_rows_bottom);
    card_wr(fw, CARD_DARK_ROWS_BOTTOM, b->dark_rows_bottom);
    card_wr(fw, CARD_FRAME_LINES, b->frame_lines);
    card_wr(fw, CARD_RETRY_LIMIT, b->card_retry_limit);
    card_wr(fw, CARD_OE_LOW_CYCLES, CARD_OE_LOW_CYCLES_RESET);
    card_wr(fw, CARD_START_TIMEOUT, fw->start_timeout);
    card_wr(fw, CARD_IRQ_ENABLE, enable);
    fw_event(fw, STEREOSIM_EV_CARD_CONFIGURED, 0, enable, 0);
}

/* ---- EDMA ---- */
static void write_entry(paper_fw* fw, uint32_t address, const uint32_t w[6]) {
    uint32_t i;
    for (i = 0; i < 6; ++i) wr(fw, address + 4u * i, w[i]);
}

static uint32_t header_of(const paper_fw* fw, int chain) {
    return chain == DRAIN ? CONTROL_BASE : fw_buffer_address(fw, chain);
}

/* Links: 0 the trigger's drain setting, 1 + chain the left, 4 + chain the right. */
static void trigger_entry(const paper_fw* fw, int chain, uint32_t w[6]) {
    w[0] = OPT_ESIZE_32 | OPT_SUM(MODE_INC) | OPT_DUM(MODE_INC) | OPT_TCINT |
           OPT_TCC(left_channel[chain]) | OPT_LINK | OPT_FS;
    w[1] = CARD_BASE + CARD_VERDICT;
    w[2] = EDMA_CNT(0, STATUS_WORDS);
    w[3] = header_of(fw, chain);
    w[4] = 0;
    w[5] = EDMA_RLD(EDMA_LINK_ENTRY(0));
}

static void frame_entry(const paper_fw* fw, int chain, int right, uint32_t w[6]) {
    const int drain = chain == DRAIN;
    const uint32_t code = right ? done_code[chain] : (uint32_t)right_channel[chain];
    w[0] = OPT_ESIZE_32 | OPT_SUM(MODE_FIXED) | (drain ? 0u : OPT_2DD) |
           OPT_DUM(drain ? MODE_FIXED : MODE_INC) | OPT_TCINT | OPT_TCC(code) | OPT_LINK | OPT_FS;
    w[1] = right ? CARD_DATA_RIGHT : CARD_DATA_LEFT;
    w[2] = EDMA_CNT(fw->height - 1u, fw->width / CARD_PIXELS_PER_WORD);
    w[3] = drain ? CONTROL_BASE + 64u
                 : (right ? fw_right_address(fw, chain) : fw_left_address(fw, chain));
    w[4] = EDMA_IDX(fw->width, 0);
    w[5] = EDMA_RLD(EDMA_LINK_ENTRY((right ? 4 : 1) + chain));
}

static void arm(paper_fw* fw, int buffer) {
    uint32_t w[6];
    trigger_entry(fw, buffer, w);
    wr(fw, EDMA_EER_L, 0); /* a FRAME_READY meanwhile stays latched */
    write_entry(fw, EDMA_ENTRY(EDMA_CHANNEL_EXT_INT4), w);
    fw->state[buffer] = BUF_ARMED;
    wr(fw, EDMA_EER_L, 1u << EDMA_CHANNEL_EXT_INT4);
}

static void arm_free_buffer(paper_fw* fw) {
    uint32_t b;
    for (b = 0; b < fw->buffers; ++b)
        if (fw->state[b] == BUF_ARMED) return;
    for (b = 0; b < fw->buffers; ++b) {
        if (fw->state[b] == BUF_FREE) {
            arm(fw, (int)b);
            return;
        }
    }
}

static void setup_edma(paper_fw* fw) {
    uint32_t w[6], ccer_h = 0;
    int chain;
    wr(fw, EDMA_EER_L, 0);
    wr(fw, EDMA_EER_H, 0);
    wr(fw, EDMA_ECR_L, 0xFFFFFFFFu);
    wr(fw, EDMA_ECR_H, 0xFFFFFFFFu);
    wr(fw, EDMA_CIPR_L, 0xFFFFFFFFu);
    wr(fw, EDMA_CIPR_H, 0xFFFFFFFFu);
    trigger_entry(fw, DRAIN, w);
    write_entry(fw, EDMA_LINK_ENTRY(0), w);
    for (chain = 0; chain < 3; ++chain) {
        frame_entry(fw, chain, 0, w);
        write_entry(fw, EDMA_LINK_ENTRY(1 + chain), w);
        write_entry(fw, EDMA_ENTRY(left_channel[chain]), w);
        frame_entry(fw, chain, 1, w);
        write_entry(fw, EDMA_LINK_ENTRY(4 + chain), w);
        write_entry(fw, EDMA_ENTRY(right_channel[chain]), w);
        ccer_h |= (1u << (left_channel[chain] - 32)) | (1u << (right_channel[chain] - 32));
    }
    wr(fw, EDMA_CCER_L, 0);
    wr(fw, EDMA_CCER_H, ccer_h);
    wr(fw, EDMA_CIER_L, (1u << done_code[0]) | (1u << done_code[1]));
    wr(fw, EDMA_CIER_H, 0);
    trigger_entry(fw, DRAIN, w);
    write_entry(fw, EDMA_ENTRY(EDMA_CHANNEL_EXT_INT4), w);
    fw->state[0] = fw->state[1] = BUF_FREE;
    arm(fw, 0);
}

/* ---- OE, watchdog, re-arm ---- */
static uint32_t card_progress(paper_fw* fw) {
    return card_rd(fw, CARD_PAIRS_OK) + card_rd(fw, CARD_MISMATCHES) + card_rd(fw, CARD_OVERFLOWS);
}

static void restart_watchdog(paper_fw* fw) {
    const uint64_t clocks =
        (uint64_t)fw->watchdog_ms * (fw->board.cpu_hz / 1000u) / TIMER_CPU_CYCLES_PER_CLOCK;
    wr(fw, TIMER1_CTL, 0);
    wr(fw, TIMER1_PRD, clocks > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)clocks);
    wr(fw, TIMER1_CTL, TIMER_CTL_CLKSRC | TIMER_CTL_HLD | TIMER_CTL_GO);
    fw->hw->clear_interrupt_flags(fw->hw->ctx, 1u << INT_TINT1);
}

static void raise_oe(paper_fw* fw) {
    if (fw->watchdog_ms) {
        fw->watchdog_progress = card_progress(fw);
        restart_watchdog(fw);
    }
    card_wr(fw, CARD_CTRL, CARD_CTRL_ENABLE);
    ++fw->oe_raises;
    fw->awaiting_in_step = 1;
    vision_restart(&fw->v); /* frames across a restart are not one sequence */
    fw_event(fw, STEREOSIM_EV_OE_RAISED, 0, fw->oe_raises, 0);
}

/* ENABLE 0 -> 1 restarts the card. A card that keeps failing with no good
 * pair between is given up after hard_error_rearms re-arms: OE low, no
 * capture, a reported hard error. */
static void rearm(paper_fw* fw, uint32_t cause) {
    uint32_t i;
    if (cause == STEREOSIM_REARM_HARD_ERROR || cause == STEREOSIM_REARM_WATCHDOG) {
        if (++fw->failures > fw->hard_error_rearms) {
            card_wr(fw, CARD_CTRL, 0);
            fw->gave_up = 1;
            fw_event(fw, STEREOSIM_EV_HARD_ERROR, 0, cause, fw->failures);
            return;
        }
    }
    card_wr(fw, CARD_CTRL, 0);
    for (i = 0; i < REARM_IDLE_POLLS; ++i)
        if ((card_rd(fw, CARD_STATUS) & CARD_STATUS_STATE_MASK) == 0) break;
    card_wr(fw, CARD_IRQ_STATUS, CARD_IRQ_SYNC_ERROR | CARD_IRQ_OVERFLOW);
    fw_event(fw, STEREOSIM_EV_CARD_REARMED, 0, cause, 0);
    raise_oe(fw);
}

int fw_boot(paper_fw* fw) {
    fw_event(fw, STEREOSIM_EV_BOOT, 0, fw->board.dsk_version, fw->overlapped);
    program_emif(fw);
    setup_interrupts(fw);
    if (!probe_card(fw)) return 0;
    configure_card(fw);
    setup_edma(fw);
    raise_oe(fw);
    return 1;
}

/* ---- interrupts ---- */
static void handle_edma(paper_fw* fw) {
    const uint32_t cipr = rd(fw, EDMA_CIPR_L);
    const uint32_t drain_bit = 1u << done_code[DRAIN];
    uint32_t b;
    if (cipr & drain_bit) wr(fw, EDMA_CIPR_L, drain_bit);
    for (b = 0; b < fw->buffers; ++b) {
        const uint32_t bit = 1u << done_code[b];
        if (!(cipr & bit)) continue;
        wr(fw, EDMA_CIPR_L, bit);
        if (fw->state[b] != BUF_ARMED) continue;
        fw->state[b] = BUF_FULL;
        fw->full_order[b] = fw->captures++;
    }
    arm_free_buffer(fw);
}

static void handle_sync_error(paper_fw* fw) {
    const uint32_t verdict = card_rd(fw, CARD_VERDICT);
    const uint32_t position = card_rd(fw, CARD_MISMATCH_POS);
    const uint32_t status = card_rd(fw, CARD_STATUS);
    card_wr(fw, CARD_IRQ_STATUS, CARD_IRQ_SYNC_ERROR);
    fw_event(fw, STEREOSIM_EV_SYNC_ERROR, 0, verdict, position);
    /* The card restarts OE by itself; only its give-up needs the firmware. */
    if (status & CARD_STATUS_HARD_ERROR) rearm(fw, STEREOSIM_REARM_HARD_ERROR);
}

static void handle_overflow(paper_fw* fw) {
    const uint32_t status = card_rd(fw, CARD_STATUS);
    const uint32_t count = card_rd(fw, CARD_OVERFLOWS);
    card_wr(fw, CARD_IRQ_STATUS, CARD_IRQ_OVERFLOW);
    fw_event(fw, STEREOSIM_EV_OVERFLOW, 0, status, count);
    rearm(fw, STEREOSIM_REARM_OVERFLOW);
}

/* Timer 1 every watchdog period: re-arm a card none of whose event
 * counters moved for the whole period. */
static void handle_watchdog(paper_fw* fw) {
    const uint32_t progress = card_progress(fw);
    if (progress != fw->watchdog_progress) {
        fw->watchdog_progress = progress;
        return;
    }
    fw_event(fw, STEREOSIM_EV_WATCHDOG, 0, rd(fw, TIMER1_PRD), 0);
    rearm(fw, STEREOSIM_REARM_WATCHDOG);
}

void fw_handle_interrupt(paper_fw* fw, int n) {
    if (n == INT_EDMA) handle_edma(fw);
    if (n == INT_EXT5) handle_sync_error(fw);
    if (n == INT_EXT6) handle_overflow(fw);
    if (n == INT_TINT1) handle_watchdog(fw);
}

void fw_service_interrupts(paper_fw* fw) {
    const uint32_t pending =
        fw->hw->interrupt_flags(fw->hw->ctx) & enabled_interrupts(fw) & 0xFFF0u;
    int n;
    for (n = 4; n <= 15 && !fw->gave_up; ++n) {
        if (!((pending >> n) & 1u)) continue;
        fw->hw->clear_interrupt_flags(fw->hw->ctx, 1u << n);
        fw_handle_interrupt(fw, n);
    }
}

int fw_oldest_full(const paper_fw* fw) {
    int best = -1;
    uint32_t b;
    for (b = 0; b < fw->buffers; ++b)
        if (fw->state[b] == BUF_FULL && (best < 0 || fw->full_order[b] < fw->full_order[best]))
            best = (int)b;
    return best;
}

/* A captured pair: its header checked, reported, handed to the chain if in
 * step, and its buffer freed. */
static uint32_t le32(const uint8_t* p) {
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

void fw_release(paper_fw* fw, int buffer) {
    const uint8_t* header;
    uint32_t verdict, pair;
    stereosim_event e = {0, 0, 0, 0, 0, 0};
    fw->state[buffer] = BUF_BUSY;
    header = fw->hw->memory(fw->hw->ctx, fw_buffer_address(fw, buffer), HEADER_BYTES);
    verdict = le32(header + 4 * HDR_VERDICT);
    pair = le32(header + 4 * HDR_PAIRS_OK);
    fw->hw->stage_begin(fw->hw->ctx, ST_CAPTURE);
    fw->hw->charge(fw->hw->ctx, ST_CAPTURE, CAPTURE_CYCLES, NULL);
    fw->hw->stage_end(fw->hw->ctx, ST_CAPTURE);
    if (fw->have_pair && pair > fw->last_pair + 1)
        fw_event(fw, STEREOSIM_EV_PAIR_DROPPED, pair, pair - fw->last_pair - 1, 0);
    fw->have_pair = 1;
    fw->last_pair = pair;
    e.kind = STEREOSIM_EV_PAIR_CAPTURED;
    e.pair = pair;
    e.value = verdict;
    e.detail = (uint32_t)buffer;
    e.left = fw_left_address(fw, buffer);
    e.right = fw_right_address(fw, buffer);
    fw->hw->report(fw->hw->ctx, &e);
    if (verdict & CARD_VERDICT_CAUSES) {
        fw_event(fw, STEREOSIM_EV_PAIR_REJECTED, pair, verdict, 0);
    } else {
        stereosim_result r;
        const uint32_t bytes = fw->width * fw->height;
        fw->failures = 0; /* a good pair: the card works */
        if (fw->awaiting_in_step) {
            fw->awaiting_in_step = 0;
            fw_event(fw, STEREOSIM_EV_IN_STEP, pair, verdict, 0);
        }
        /* The frames the pipeline reads, named in FRAMES_USED: rule 7 checks
         * they are the pair's own and that these are the frames read. */
        const uint8_t* left = fw->hw->memory(fw->hw->ctx, e.left, bytes);
        const uint8_t* right = fw->hw->memory(fw->hw->ctx, e.right, bytes);
        e.kind = STEREOSIM_EV_FRAMES_USED;
        e.value = e.detail = 0;
        fw->hw->report(fw->hw->ctx, &e);
        vision_pair(fw, left, right, &r);
        r.pair = pair;
        r.stage_cycles[ST_CAPTURE] += CAPTURE_CYCLES;
        ++fw->pairs_processed;
        fw->hw->report_result(fw->hw->ctx, &r);
        fw_event(fw, STEREOSIM_EV_PAIR_PROCESSED, pair, (uint32_t)buffer, r.has_point);
    }
    fw->state[buffer] = BUF_FREE;
    arm_free_buffer(fw);
}

void fw_shutdown(paper_fw* fw) {
    wr(fw, EDMA_EER_L, 0);
    card_wr(fw, CARD_CTRL, 0);
    if (fw->watchdog_ms) wr(fw, TIMER1_CTL, 0);
    fw_event(fw, STEREOSIM_EV_STOPPED, 0, fw->pairs_processed, 0);
}
