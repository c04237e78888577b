// Bus-side (ECLKOUT) register file of the card: the read/write registers that
// configure the capture side, the interrupt status and enables, the read-back
// of the capture side's status snapshot and the bus side's own counters.
// Offsets, reset values and fields come from card_regs.vh, generated from
// rtl/card_regs.csv like the firmware's dsp/card_regs.h and the docs table.
//
// Events: FRAME_READY when the snapshot's PAIRS_OK count moves AND both
// FIFOs' read sides see the pair's last word (so the firmware can read the
// whole pair the moment the interrupt arrives); SYNC_ERROR when MISMATCHES
// moves; OVERFLOW when OVERFLOWS moves. Each event sets its IRQ_STATUS bit
// and, if enabled, pulses its EXT_INT pin.
`timescale 1ns / 1fs
module card_regfile #(
    parameter int AW = 17
) (
    input  logic        clk,
    input  logic        rst_n,
    // From the EMIF slave
    input  logic [ 5:0] rd_idx,
    output logic [31:0] rd_data,
    input  logic        wr_en,
    input  logic [ 5:0] wr_idx,
    input  logic [31:0] wr_data,
    input  logic [ 3:0] wr_be,
    input  logic        underflow,
    // Capture-side status snapshot
    input  logic [ 2:0] st_state,
    input  logic [31:0] st_frames_l,
    input  logic [31:0] st_frames_r,
    input  logic [31:0] st_pairs_ok,
    input  logic [31:0] st_mismatches,
    input  logic [31:0] st_retries,
    input  logic [31:0] st_overflows,
    input  logic [31:0] st_discarded,
    input  logic [31:0] st_skipped,
    input  logic [ 9:0] st_verdict_causes,
    input  logic [15:0] st_verdict_frame,
    input  logic [15:0] st_mm_line,
    input  logic [15:0] st_mm_col,
    input  logic        st_oe,
    input  logic        st_overflow_l,
    input  logic        st_overflow_r,
    input  logic [AW:0] st_peak_l,
    input  logic [AW:0] st_peak_r,
    input  logic [AW:0] st_ready_end_l,
    input  logic [AW:0] st_ready_end_r,
    // Bus-side FIFO state
    input  logic        discard_busy,
    input  logic        empty_l,
    input  logic        empty_r,
    input  logic [AW:0] level_l,
    input  logic [AW:0] level_r,
    input  logic [AW:0] rd_wptr_l,
    input  logic [AW:0] rd_wptr_r,
    // Configuration
    output logic        cfg_enable,
    output logic        cfg_frame_id_check,
    output logic [ 7:0] cfg_dark_threshold,
    output logic [15:0] cfg_h_start,
    output logic [15:0] cfg_dark_cols_left,
    output logic [15:0] cfg_border_cols_left,
    output logic [15:0] cfg_active_cols,
    output logic [15:0] cfg_border_cols_right,
    output logic [15:0] cfg_dark_cols_right,
    output logic [15:0] cfg_line_total,
    output logic [15:0] cfg_v_start,
    output logic [15:0] cfg_dark_rows_top,
    output logic [15:0] cfg_border_rows_top,
    output logic [15:0] cfg_active_rows,
    output logic [15:0] cfg_border_rows_bottom,
    output logic [15:0] cfg_dark_rows_bottom,
    output logic [15:0] cfg_frame_lines,
    output logic [ 7:0] cfg_retry_limit,
    output logic [15:0] cfg_oe_low_cycles,
    output logic [15:0] cfg_start_timeout,
    // Interrupt events (to the pulse generators)
    output logic        evt_frame_ready,
    output logic        evt_sync_error,
    output logic        evt_overflow
);
`include "card_regs.vh"

    localparam logic [AW:0] DEPTH_P = (AW + 1)'(1 << AW);

    // Byte-enable merge of a register write.
    function automatic logic [31:0] merge(input logic [31:0] old, input logic [31:0] data,
                                          input logic [3:0] be);
        logic [31:0] m;
        for (int i = 0; i < 4; i++) m[8*i+:8] = be[i] ? data[8*i+:8] : old[8*i+:8];
        merge = m;
    endfunction

    // ---- read/write configuration registers -----------------------------------------
    logic [31:0] ctrl_q, checks_q, irq_enable_q, irq_status_q, underflows_q;
    logic [31:0] dark_threshold_q, retry_limit_q, oe_low_q, start_timeout_q;
    logic [31:0] h_start_q, dark_cols_left_q, border_cols_left_q, active_cols_q;
    logic [31:0] border_cols_right_q, dark_cols_right_q, line_total_q;
    logic [31:0] v_start_q, dark_rows_top_q, border_rows_top_q, active_rows_q;
    logic [31:0] border_rows_bottom_q, dark_rows_bottom_q, frame_lines_q;

    logic [2:0] events;

    always_ff @(posedge clk or negedge rst_n) begin
        if (!rst_n) begin
            ctrl_q               <= REG_CTRL_RESET;
            checks_q             <= REG_CHECKS_RESET;
            irq_enable_q         <= REG_IRQ_ENABLE_RESET;
            irq_status_q         <= REG_IRQ_STATUS_RESET;
            underflows_q         <= REG_UNDERFLOWS_RESET;
            dark_threshold_q     <= REG_DARK_THRESHOLD_RESET;
            h_start_q            <= REG_H_START_RESET;
            dark_cols_left_q     <= REG_DARK_COLS_LEFT_RESET;
            border_cols_left_q   <= REG_BORDER_COLS_LEFT_RESET;
            active_cols_q        <= REG_ACTIVE_COLS_RESET;
            border_cols_right_q  <= REG_BORDER_COLS_RIGHT_RESET;
            dark_cols_right_q    <= REG_DARK_COLS_RIGHT_RESET;
            line_total_q         <= REG_LINE_TOTAL_RESET;
            v_start_q            <= REG_V_START_RESET;
            dark_rows_top_q      <= REG_DARK_ROWS_TOP_RESET;
            border_rows_top_q    <= REG_BORDER_ROWS_TOP_RESET;
            active_rows_q        <= REG_ACTIVE_ROWS_RESET;
            border_rows_bottom_q <= REG_BORDER_ROWS_BOTTOM_RESET;
            dark_rows_bottom_q   <= REG_DARK_ROWS_BOTTOM_RESET;
            frame_lines_q        <= REG_FRAME_LINES_RESET;
            retry_limit_q        <= REG_RETRY_LIMIT_RESET;
            oe_low_q             <= REG_OE_LOW_CYCLES_RESET;
            start_timeout_q      <= REG_START_TIMEOUT_RESET;
        end else begin
            if (underflow) underflows_q <= underflows_q + 32'd1;
            // Events set IRQ_STATUS bits; a W1C write in the same cycle loses to the event.
            irq_status_q[2:0] <= (irq_status_q[2:0] &
                                  ~((wr_en && wr_idx == REG_IRQ_STATUS) ? wr_data[2:0] & {3{wr_be[0]}} :
                                                                          3'b000)) | events;
            if (wr_en) begin
                case (wr_idx)
                    REG_CTRL: ctrl_q <= merge(ctrl_q, wr_data, wr_be) & 32'h1;
                    REG_IRQ_ENABLE: irq_enable_q <= merge(irq_enable_q, wr_data, wr_be) & 32'h7;
                    REG_DARK_THRESHOLD:
                    dark_threshold_q <= merge(dark_threshold_q, wr_data, wr_be) & 32'hFF;
                    REG_H_START: h_start_q <= merge(h_start_q, wr_data, wr_be) & 32'hFFFF;
                    REG_DARK_COLS_LEFT:
                    dark_cols_left_q <= merge(dark_cols_left_q, wr_data, wr_be) & 32'hFFFF;
                    REG_BORDER_COLS_LEFT:
                    border_cols_left_q <= merge(border_cols_left_q, wr_data, wr_be) & 32'hFFFF;
                    REG_ACTIVE_COLS:
                    active_cols_q <= merge(active_cols_q, wr_data, wr_be) & 32'hFFFF;
                    REG_BORDER_COLS_RIGHT:
                    border_cols_right_q <= merge(border_cols_right_q, wr_data, wr_be) & 32'hFFFF;
                    REG_DARK_COLS_RIGHT:
                    dark_cols_right_q <= merge(dark_cols_right_q, wr_data, wr_be) & 32'hFFFF;
                    REG_LINE_TOTAL: line_total_q <= merge(line_total_q, wr_data, wr_be) & 32'hFFFF;
                    REG_V_START: v_start_q <= merge(v_start_q, wr_data, wr_be) & 32'hFFFF;
                    REG_DARK_ROWS_TOP:
                    dark_rows_top_q <= merge(dark_rows_top_q, wr_data, wr_be) & 32'hFFFF;
                    REG_BORDER_ROWS_TOP:
                    border_rows_top_q <= merge(border_rows_top_q, wr_data, wr_be) & 32'hFFFF;
                    REG_ACTIVE_ROWS:
                    active_rows_q <= merge(active_rows_q, wr_data, wr_be) & 32'hFFFF;
                    REG_BORDER_ROWS_BOTTOM:
                    border_rows_bottom_q <= merge(border_rows_bottom_q, wr_data, wr_be) & 32'hFFFF;
                    REG_DARK_ROWS_BOTTOM:
                    dark_rows_bottom_q <= merge(dark_rows_bottom_q, wr_data, wr_be) & 32'hFFFF;
                    REG_FRAME_LINES: frame_lines_q <= merge(frame_lines_q, wr_data, wr_be) & 32'hFFFF;
                    REG_RETRY_LIMIT: retry_limit_q <= merge(retry_limit_q, wr_data, wr_be) & 32'hFF;
                    REG_OE_LOW_CYCLES: oe_low_q <= merge(oe_low_q, wr_data, wr_be) & 32'hFFFF;
                    REG_START_TIMEOUT:
                    start_timeout_q <= merge(start_timeout_q, wr_data, wr_be) & 32'hFFFF;
                    REG_CHECKS: checks_q <= merge(checks_q, wr_data, wr_be) & 32'h1;
                    default: ;  // read-only or unused: ignored
                endcase
            end
        end
    end

    assign cfg_enable             = ctrl_q[CTRL_ENABLE_LSB];
    assign cfg_frame_id_check     = checks_q[CHECKS_FRAME_ID_LSB];
    assign cfg_dark_threshold     = dark_threshold_q[7:0];
    assign cfg_h_start            = h_start_q[15:0];
    assign cfg_dark_cols_left     = dark_cols_left_q[15:0];
    assign cfg_border_cols_left   = border_cols_left_q[15:0];
    assign cfg_active_cols        = active_cols_q[15:0];
    assign cfg_border_cols_right  = border_cols_right_q[15:0];
    assign cfg_dark_cols_right    = dark_cols_right_q[15:0];
    assign cfg_line_total         = line_total_q[15:0];
    assign cfg_v_start            = v_start_q[15:0];
    assign cfg_dark_rows_top      = dark_rows_top_q[15:0];
    assign cfg_border_rows_top    = border_rows_top_q[15:0];
    assign cfg_active_rows        = active_rows_q[15:0];
    assign cfg_border_rows_bottom = border_rows_bottom_q[15:0];
    assign cfg_dark_rows_bottom   = dark_rows_bottom_q[15:0];
    assign cfg_frame_lines        = frame_lines_q[15:0];
    assign cfg_retry_limit        = retry_limit_q[7:0];
    assign cfg_oe_low_cycles      = oe_low_q[15:0];
    assign cfg_start_timeout      = start_timeout_q[15:0];

    // ---- events ---------------------------------------------------------------------------
    logic [31:0] pairs_seen_q, mismatches_seen_q, overflows_seen_q;
    logic frame_pending_q;
    logic [AW:0] pending_end_l_q, pending_end_r_q;

    // The read side has seen the write pointer reach `end_ptr` (modulo the pointer range).
    function automatic logic reached(input logic [AW:0] wptr, input logic [AW:0] end_ptr);
        logic [AW:0] ahead;
        ahead = wptr - end_ptr;
        reached = ahead <= DEPTH_P;
    endfunction

    wire pair_readable = frame_pending_q && reached(rd_wptr_l, pending_end_l_q) &&
        reached(rd_wptr_r, pending_end_r_q);
    // Raw events (bit order of IRQ_STATUS); the pins pulse only for enabled ones.
    assign events[IRQ_STATUS_FRAME_READY_LSB] = pair_readable;
    assign events[IRQ_STATUS_SYNC_ERROR_LSB]  = st_mismatches != mismatches_seen_q;
    assign events[IRQ_STATUS_OVERFLOW_LSB]    = st_overflows != overflows_seen_q;
    assign evt_frame_ready = events[IRQ_STATUS_FRAME_READY_LSB] &&
        irq_enable_q[IRQ_ENABLE_FRAME_READY_LSB];
    assign evt_sync_error = events[IRQ_STATUS_SYNC_ERROR_LSB] &&
        irq_enable_q[IRQ_ENABLE_SYNC_ERROR_LSB];
    assign evt_overflow = events[IRQ_STATUS_OVERFLOW_LSB] && irq_enable_q[IRQ_ENABLE_OVERFLOW_LSB];

    always_ff @(posedge clk or negedge rst_n) begin
        if (!rst_n) begin
            pairs_seen_q      <= '0;
            mismatches_seen_q <= '0;
            overflows_seen_q  <= '0;
            frame_pending_q   <= 1'b0;
            pending_end_l_q   <= '0;
            pending_end_r_q   <= '0;
        end else begin
            mismatches_seen_q <= st_mismatches;
            overflows_seen_q  <= st_overflows;
            if (st_pairs_ok != pairs_seen_q) begin
                pairs_seen_q    <= st_pairs_ok;
                frame_pending_q <= 1'b1;
                pending_end_l_q <= st_ready_end_l;
                pending_end_r_q <= st_ready_end_r;
            end else if (pair_readable) begin
                frame_pending_q <= 1'b0;
            end
        end
    end

    // ---- read multiplexer -------------------------------------------------------------------
    logic [31:0] status, verdict, mismatch_pos;
    always_comb begin
        status = '0;
        status[STATUS_STATE_MSB:STATUS_STATE_LSB] = st_state;
        status[STATUS_OE_LSB] = st_oe;
        status[STATUS_HARD_ERROR_LSB] = st_state == 3'd4;
        status[STATUS_DISCARD_BUSY_LSB] = discard_busy;
        status[STATUS_OVERFLOW_L_LSB] = st_overflow_l;
        status[STATUS_OVERFLOW_R_LSB] = st_overflow_r;
        status[STATUS_EMPTY_L_LSB] = empty_l;
        status[STATUS_EMPTY_R_LSB] = empty_r;
        verdict = '0;
        verdict[VERDICT_R_FRAME_ID_MSB:VERDICT_L_WINDOW_LSB] = st_verdict_causes;
        verdict[VERDICT_FRAME_MSB:VERDICT_FRAME_LSB] = st_verdict_frame;
        mismatch_pos = '0;
        mismatch_pos[MISMATCH_POS_LINE_MSB:MISMATCH_POS_LINE_LSB] = st_mm_line;
        mismatch_pos[MISMATCH_POS_COL_MSB:MISMATCH_POS_COL_LSB] = st_mm_col;
    end

    always_comb begin
        case (rd_idx)
            REG_ID: rd_data = REG_ID_RESET;
            REG_CTRL: rd_data = ctrl_q;
            REG_STATUS: rd_data = status;
            REG_IRQ_STATUS: rd_data = irq_status_q;
            REG_IRQ_ENABLE: rd_data = irq_enable_q;
            REG_VERDICT: rd_data = verdict;
            REG_MISMATCH_POS: rd_data = mismatch_pos;
            REG_FRAMES_L: rd_data = st_frames_l;
            REG_FRAMES_R: rd_data = st_frames_r;
            REG_PAIRS_OK: rd_data = st_pairs_ok;
            REG_MISMATCHES: rd_data = st_mismatches;
            REG_RETRIES: rd_data = st_retries;
            REG_OVERFLOWS: rd_data = st_overflows;
            REG_DISCARDED: rd_data = st_discarded;
            REG_SKIPPED: rd_data = st_skipped;
            REG_UNDERFLOWS: rd_data = underflows_q;
            REG_LEVEL_L: rd_data = 32'(level_l);
            REG_LEVEL_R: rd_data = 32'(level_r);
            REG_PEAK_L: rd_data = 32'(st_peak_l);
            REG_PEAK_R: rd_data = 32'(st_peak_r);
            REG_FIFO_DEPTH: rd_data = 32'(DEPTH_P);
            REG_DARK_THRESHOLD: rd_data = dark_threshold_q;
            REG_H_START: rd_data = h_start_q;
            REG_DARK_COLS_LEFT: rd_data = dark_cols_left_q;
            REG_BORDER_COLS_LEFT: rd_data = border_cols_left_q;
            REG_ACTIVE_COLS: rd_data = active_cols_q;
            REG_BORDER_COLS_RIGHT: rd_data = border_cols_right_q;
            REG_DARK_COLS_RIGHT: rd_data = dark_cols_right_q;
            REG_LINE_TOTAL: rd_data = line_total_q;
            REG_V_START: rd_data = v_start_q;
            REG_DARK_ROWS_TOP: rd_data = dark_rows_top_q;
            REG_BORDER_ROWS_TOP: rd_data = border_rows_top_q;
            REG_ACTIVE_ROWS: rd_data = active_rows_q;
            REG_BORDER_ROWS_BOTTOM: rd_data = border_rows_bottom_q;
            REG_DARK_ROWS_BOTTOM: rd_data = dark_rows_bottom_q;
            REG_FRAME_LINES: rd_data = frame_lines_q;
            REG_RETRY_LIMIT: rd_data = retry_limit_q;
            REG_OE_LOW_CYCLES: rd_data = oe_low_q;
            REG_START_TIMEOUT: rd_data = start_timeout_q;
            REG_CHECKS: rd_data = checks_q;
            default: rd_data = 32'd0;
        endcase
    end
endmodule
