/* The registers this firmware touches, as a firmware author takes them from
 * the documents: the C6416's from TI's data sheet (SPRS146) and its Chip
 * Support Library headers, the DSK's EMIF settings from its GEL file, the
 * daughter card's from docs/card-registers.md (rtl/card_regs.csv). The
 * repository's docs/c6416.md lists each with its source. */
#ifndef PAPER_FW_DSK_REGS_H
#define PAPER_FW_DSK_REGS_H

/* ---- memory map [SPRS146 Table 3; DSK technical reference] ---- */
#define L2_BASE 0x00000000u
#define SDRAM_BASE 0x80000000u /* EMIFA CE0 */

/* ---- EMIFA [csl_emifahal.h; DSK6416.gel init_emif()] ---- */
#define EMIFA_GBLCTL 0x01800000u
#define EMIFA_CECTL0 0x01800008u
#define EMIFA_CECTL2 0x01800010u
#define EMIFA_CECTL3 0x01800014u
#define EMIFA_SDCTL 0x01800018u
#define EMIFA_SDTIM 0x0180001Cu
#define EMIFA_SDEXT 0x01800020u
#define DSK_GBLCTL 0x00012070u
#define DSK_CECTL0_SDRAM 0xFFFFFFD3u
#define DSK_SDCTL 0x47115000u
#define DSK_CECTL_CARD_V1 0x22A28A22u /* 2/10/2 ASYNC32 */
#define DSK_CECTL_CARD_V2 0x23228C22u /* 2/12/2 ASYNC32 (v2, v3) */
#define DSK_SDTIM_V1 0x00000618u
#define DSK_SDTIM_V2 0x00000750u
#define DSK_SDEXT_V1 0x000A8529u
#define DSK_SDEXT_V2 0x001FAF4Du
/* CECTL timing fields (setup, strobe, hold of reads and writes). */
#define CECTL_WRSETUP(v) (((uint32_t)(v)&0xFu) << 28)
#define CECTL_WRSTRB(v) (((uint32_t)(v)&0x3Fu) << 22)
#define CECTL_WRHLD(v) (((uint32_t)(v)&0x3u) << 20)
#define CECTL_RDSETUP(v) (((uint32_t)(v)&0xFu) << 16)
#define CECTL_RDSTRB(v) (((uint32_t)(v)&0x3Fu) << 8)
#define CECTL_RDHLD(v) ((uint32_t)(v)&0x7u)

/* ---- interrupt selector [csl_irqhal.h; SPRS146 Table 26] ---- */
#define IRQ_MUXH 0x019C0000u
#define IRQ_MUXL 0x019C0004u
#define IRQ_EXTPOL 0x019C0008u
#define IRQ_MUXL_RESET 0x250718A4u /* INT4-7 = EXT_INT4-7, INT8 = EDMA_INT, INT9 */
#define IRQ_MUXH_RESET 0x08202D43u /* ..., INT15 = TINT1 */
#define INT_EXT5 5                 /* the card's SYNC_ERROR pulse */
#define INT_EXT6 6                 /* the card's OVERFLOW pulse */
#define INT_EDMA 8
#define INT_TINT1 15

/* ---- EDMA [csl_edmahal.h; SPRS146 Tables 8 and 25] ---- */
#define EDMA_ENTRY(ch) (0x01A00000u + 0x18u * (uint32_t)(ch))
#define EDMA_LINK_ENTRY(n) (0x01A00630u + 0x18u * (uint32_t)(n))
#define EDMA_CIPR_L 0x01A0FFE4u
#define EDMA_CIER_L 0x01A0FFE8u
#define EDMA_CIER_H 0x01A0FFA8u
#define EDMA_CCER_L 0x01A0FFECu
#define EDMA_CCER_H 0x01A0FFACu
#define EDMA_EER_L 0x01A0FFF4u
#define EDMA_EER_H 0x01A0FFB4u
#define EDMA_ECR_L 0x01A0FFF8u
#define EDMA_ECR_H 0x01A0FFB8u
#define EDMA_CIPR_H 0x01A0FFA4u
#define EDMA_CHANNEL_EXT_INT4 4 /* the card's FRAME_READY */
/* OPT fields */
#define OPT_ESIZE_32 (0u << 27)
#define OPT_SUM(m) ((uint32_t)(m) << 24)
#define OPT_2DD 0x00800000u
#define OPT_DUM(m) ((uint32_t)(m) << 21)
#define OPT_TCINT 0x00100000u
#define OPT_TCC(code) ((((uint32_t)(code)&0xFu) << 16) | ((((uint32_t)(code) >> 4) & 0x3u) << 13))
#define OPT_LINK 0x00000002u
#define OPT_FS 0x00000001u
#define MODE_FIXED 0u
#define MODE_INC 1u
#define EDMA_CNT(frames_minus_1, elements) \
    (((uint32_t)(frames_minus_1) << 16) | ((elements)&0xFFFFu))
#define EDMA_IDX(frame_index, element_index) \
    (((uint32_t)(frame_index) << 16) | ((uint32_t)(element_index)&0xFFFFu))
#define EDMA_RLD(link_address) ((uint32_t)(link_address)&0xFFFFu)

/* ---- timer 1 [csl_timerhal.h] ---- */
#define TIMER1_CTL 0x01980000u
#define TIMER1_PRD 0x01980004u
#define TIMER_CTL_GO 0x040u
#define TIMER_CTL_HLD 0x080u
#define TIMER_CTL_CLKSRC 0x200u /* CPU clock / 8 */
#define TIMER_CPU_CYCLES_PER_CLOCK 8u

/* ---- the daughter card [docs/card-registers.md] ---- */
#define CARD_BASE 0xA0000000u      /* CE2: registers */
#define CARD_DATA_LEFT 0xB0000000u /* CE3: pixel ports, 4 pixels a word */
#define CARD_DATA_RIGHT 0xB0100000u
#define CARD_ID 0x00u
#define CARD_CTRL 0x04u
#define CARD_STATUS 0x08u
#define CARD_IRQ_STATUS 0x0Cu
#define CARD_IRQ_ENABLE 0x10u
#define CARD_VERDICT 0x14u
#define CARD_MISMATCH_POS 0x18u
#define CARD_PAIRS_OK 0x24u
#define CARD_MISMATCHES 0x28u
#define CARD_OVERFLOWS 0x30u
#define CARD_DARK_THRESHOLD 0x54u
#define CARD_H_START 0x58u
#define CARD_DARK_COLS_LEFT 0x5Cu
#define CARD_BORDER_COLS_LEFT 0x60u
#define CARD_ACTIVE_COLS 0x64u
#define CARD_BORDER_COLS_RIGHT 0x68u
#define CARD_DARK_COLS_RIGHT 0x6Cu
#define CARD_LINE_TOTAL 0x70u
#define CARD_V_START 0x74u
#define CARD_DARK_ROWS_TOP 0x78u
#define CARD_BORDER_ROWS_TOP 0x7Cu
#define CARD_ACTIVE_ROWS 0x80u
#define CARD_BORDER_ROWS_BOTTOM 0x84u
#define CARD_DARK_ROWS_BOTTOM 0x88u
#define CARD_FRAME_LINES 0x8Cu
#define CARD_RETRY_LIMIT 0x90u
#define CARD_OE_LOW_CYCLES 0x94u
#define CARD_START_TIMEOUT 0x98u
#define CARD_ID_MAGIC 0x57E50000u
#define CARD_ID_MAGIC_MASK 0xFFFF0000u
#define CARD_CTRL_ENABLE 0x1u
#define CARD_STATUS_STATE_MASK 0x7u /* 0 IDLE */
#define CARD_STATUS_HARD_ERROR 0x10u
#define CARD_IRQ_FRAME_READY 0x1u
#define CARD_IRQ_SYNC_ERROR 0x2u
#define CARD_IRQ_OVERFLOW 0x4u
#define CARD_VERDICT_CAUSES 0xFFu
#define CARD_DARK_THRESHOLD_RESET 0x20u
#define CARD_OE_LOW_CYCLES_RESET 0x320u
#define CARD_PIXELS_PER_WORD 4u

#endif
