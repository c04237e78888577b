// Pixel-clock side of the card: samples both sensors, runs the sync check and
// the OE controller, packs the active pixels of checked frames into the two
// FIFOs and keeps the status counters (docs/card.md).
//
// Forwarding and rejected frames. A frame's pixels go to the FIFOs while the
// frame is being checked (there is no room to hold a frame back), so when a
// frame pair fails (sync cause, overflow, or ENABLE cleared mid-frame) the
// card stops writing at the first mismatch and publishes the FIFO region its
// words occupy, [begin, end) per FIFO; the bus side drops those words once
// the reader reaches them (fifo_discard). While such a discard is pending no
// new frame is forwarded, so at most one region is ever outstanding and the
// words in the FIFOs are always whole good frames plus the one being checked.
`timescale 1ns / 1fs
module card_capture #(
    parameter int AW = 17  // FIFO depth 2^AW words
) (
    input  logic        pclk,
    input  logic        rst_n,
    // Sensor pins
    input  logic        l_vsync,
    input  logic        l_href,
    input  logic        l_valid,
    input  logic [ 7:0] l_data,
    input  logic        l_fodd,
    input  logic        r_vsync,
    input  logic        r_href,
    input  logic        r_valid,
    input  logic [ 7:0] r_data,
    input  logic        r_fodd,
    output logic        sensor_oe,
    // Configuration (from the bus side, quasi-static)
    input  logic        cfg_enable,
    input  logic        cfg_frame_id_check,
    input  logic [ 7:0] cfg_dark_threshold,
    input  logic [15:0] cfg_h_start,
    input  logic [15:0] cfg_dark_cols_left,
    input  logic [15:0] cfg_border_cols_left,
    input  logic [15:0] cfg_active_cols,
    input  logic [15:0] cfg_border_cols_right,
    input  logic [15:0] cfg_dark_cols_right,
    input  logic [15:0] cfg_line_total,
    input  logic [15:0] cfg_v_start,
    input  logic [15:0] cfg_dark_rows_top,
    input  logic [15:0] cfg_border_rows_top,
    input  logic [15:0] cfg_active_rows,
    input  logic [15:0] cfg_border_rows_bottom,
    input  logic [15:0] cfg_dark_rows_bottom,
    input  logic [15:0] cfg_frame_lines,
    input  logic [ 7:0] cfg_retry_limit,
    input  logic [15:0] cfg_oe_low_cycles,
    input  logic [15:0] cfg_start_timeout,
    input  logic [ 7:0] discard_done_seq,  // last region the bus side finished
    // FIFO write sides
    output logic        l_wr_en,
    output logic [31:0] l_wr_data,
    input  logic        l_wr_full,
    input  logic [AW:0] l_wr_ptr,
    output logic        r_wr_en,
    output logic [31:0] r_wr_data,
    input  logic        r_wr_full,
    input  logic [AW:0] r_wr_ptr,
    output logic        fifo_clear,  // a run starts: clear sticky overflow and peaks
    // Status (to the bus side)
    output logic [ 2:0] state,
    output logic [31:0] frames_l,
    output logic [31:0] frames_r,
    output logic [31:0] pairs_ok,
    output logic [31:0] mismatches,
    output logic [31:0] retries,
    output logic [31:0] overflows,
    output logic [31:0] discarded,
    output logic [31:0] skipped,
    output logic [ 9:0] verdict_causes,  // VERDICT bits 9..0
    output logic [15:0] verdict_frame,
    output logic [15:0] mm_line,
    output logic [15:0] mm_col,
    output logic [ 7:0] discard_seq,     // changes when a new region is published
    output logic [AW:0] discard_begin_l,
    output logic [AW:0] discard_end_l,
    output logic [AW:0] discard_begin_r,
    output logic [AW:0] discard_end_r,
    output logic [AW:0] ready_end_l,     // FIFO end of the last good pair
    output logic [AW:0] ready_end_r
);
    localparam logic [2:0] S_RUN = 3'd3;

    // ---- sync check and OE controller ---------------------------------------------------
    logic origin, frame_start, frame_end, timeout, active_px;
    logic run, wait_origin, fail_evt, retry_evt, start_evt;
    logic l_vs_rise, r_vs_rise;
    logic [7:0] frame_causes;
    logic [15:0] frame_index, cur_mm_line, cur_mm_col;
    logic [1:0] active_phase;
    logic [7:0] l_pixel, r_pixel;

    sync_check u_check (
        .pclk(pclk),
        .rst_n(rst_n),
        .l_vsync(l_vsync),
        .l_href(l_href),
        .l_valid(l_valid),
        .l_data(l_data),
        .l_fodd(l_fodd),
        .r_vsync(r_vsync),
        .r_href(r_href),
        .r_valid(r_valid),
        .r_data(r_data),
        .r_fodd(r_fodd),
        .run(run),
        .wait_origin(wait_origin),
        .frame_id_check(cfg_frame_id_check),
        .dark_threshold(cfg_dark_threshold),
        .h_start(cfg_h_start),
        .dark_cols_left(cfg_dark_cols_left),
        .border_cols_left(cfg_border_cols_left),
        .active_cols(cfg_active_cols),
        .border_cols_right(cfg_border_cols_right),
        .dark_cols_right(cfg_dark_cols_right),
        .line_total(cfg_line_total),
        .v_start(cfg_v_start),
        .dark_rows_top(cfg_dark_rows_top),
        .border_rows_top(cfg_border_rows_top),
        .active_rows(cfg_active_rows),
        .border_rows_bottom(cfg_border_rows_bottom),
        .dark_rows_bottom(cfg_dark_rows_bottom),
        .frame_lines(cfg_frame_lines),
        .start_timeout(cfg_start_timeout),
        .origin(origin),
        .frame_start(frame_start),
        .frame_end(frame_end),
        .timeout(timeout),
        .frame_index(frame_index),
        .frame_causes(frame_causes),
        .mm_line(cur_mm_line),
        .mm_col(cur_mm_col),
        .active_px(active_px),
        .active_phase(active_phase),
        .l_pixel(l_pixel),
        .r_pixel(r_pixel),
        .l_vs_rise(l_vs_rise),
        .r_vs_rise(r_vs_rise)
    );

    wire sync_bad_now = frame_causes != 8'd0;

    oe_control u_oe (
        .pclk(pclk),
        .rst_n(rst_n),
        .enable(cfg_enable),
        .origin(origin),
        .frame_end(frame_end),
        .frame_sync_bad(sync_bad_now),
        .timeout(timeout),
        .retry_limit(cfg_retry_limit),
        .oe_low_cycles(cfg_oe_low_cycles),
        .state(state),
        .oe(sensor_oe),
        .run(run),
        .wait_origin(wait_origin),
        .fail_evt(fail_evt),
        .retry_evt(retry_evt),
        .start_evt(start_evt)
    );

    assign fifo_clear = start_evt;

    // ---- forwarding ---------------------------------------------------------------------
    logic fwd_frame_q, ovf_frame_q;
    logic [AW:0] begin_l_q, begin_r_q;
    logic [7:0] discard_seq_q;

    wire discard_pending = discard_seq_q != discard_done_seq;
    wire fwd_now = frame_start ? !discard_pending : fwd_frame_q;
    wire ovf_before = frame_start ? 1'b0 : ovf_frame_q;
    wire px_en = active_px && fwd_now && !sync_bad_now && !ovf_before;

    pixel_packer u_pack_l (
        .pclk(pclk),
        .rst_n(rst_n),
        .px_en(px_en),
        .phase(active_phase),
        .pixel(l_pixel),
        .wr_en(l_wr_en),
        .wr_data(l_wr_data)
    );
    pixel_packer u_pack_r (
        .pclk(pclk),
        .rst_n(rst_n),
        .px_en(px_en),
        .phase(active_phase),
        .pixel(r_pixel),
        .wr_en(r_wr_en),
        .wr_data(r_wr_data)
    );

    wire ovf_hit = (l_wr_en && l_wr_full) || (r_wr_en && r_wr_full);
    wire ovf_now = ovf_before || ovf_hit;
    // FIFO write pointers after this cycle's writes: the end of the frame so far.
    wire [AW:0] l_end = l_wr_ptr + (AW + 1)'(l_wr_en && !l_wr_full);
    wire [AW:0] r_end = r_wr_ptr + (AW + 1)'(r_wr_en && !r_wr_full);
    wire [AW:0] l_begin = frame_start ? l_wr_ptr : begin_l_q;
    wire [AW:0] r_begin = frame_start ? r_wr_ptr : begin_r_q;

    // A frame closes at its end, or when ENABLE is cleared in the middle of it.
    wire abort = state == S_RUN && !cfg_enable;
    wire closing = frame_end || abort;
    wire frame_bad = sync_bad_now || ovf_now || abort;
    wire wrote = l_end != l_begin || r_end != r_begin;
    wire publish_discard = closing && fwd_now && frame_bad && wrote;
    wire pair_good = frame_end && !frame_bad;

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            fwd_frame_q     <= 1'b0;
            ovf_frame_q     <= 1'b0;
            begin_l_q       <= '0;
            begin_r_q       <= '0;
            discard_seq_q   <= '0;
            discard_begin_l <= '0;
            discard_end_l   <= '0;
            discard_begin_r <= '0;
            discard_end_r   <= '0;
            ready_end_l     <= '0;
            ready_end_r     <= '0;
        end else begin
            if (frame_start) begin
                fwd_frame_q <= fwd_now;
                begin_l_q   <= l_wr_ptr;
                begin_r_q   <= r_wr_ptr;
            end
            ovf_frame_q <= run && ovf_now;
            if (publish_discard) begin
                discard_seq_q   <= discard_seq_q + 8'd1;
                discard_begin_l <= l_begin;
                discard_end_l   <= l_end;
                discard_begin_r <= r_begin;
                discard_end_r   <= r_end;
`ifndef SYNTHESIS  // immediate assertions with an action block: simulation only
                assert (!discard_pending) else $error("second discard region while one is pending");
`endif
            end
            if (pair_good && fwd_now) begin
                ready_end_l <= l_end;
                ready_end_r <= r_end;
            end
        end
    end

    assign discard_seq = discard_seq_q;

`ifdef VERILATOR  // functional coverage (--coverage-user, make coverage): forwarding decisions
    always_ff @(posedge pclk) begin
        cov_pair_forwarded : cover (pair_good && fwd_now);
        cov_pair_skipped : cover (pair_good && !fwd_now);
        cov_discard_for_sync : cover (publish_discard && sync_bad_now);
        cov_discard_for_overflow : cover (publish_discard && ovf_now && !sync_bad_now);
        cov_discard_for_abort : cover (publish_discard && abort);
        cov_overflow_hit : cover (ovf_hit && !ovf_before);
        cov_frame_start_while_discarding : cover (frame_start && discard_pending);
    end
`endif

    // ---- counters and verdict -----------------------------------------------------------
    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            frames_l       <= '0;
            frames_r       <= '0;
            pairs_ok       <= '0;
            mismatches     <= '0;
            retries        <= '0;
            overflows      <= '0;
            discarded      <= '0;
            skipped        <= '0;
            verdict_causes <= '0;
            verdict_frame  <= '0;
            mm_line        <= '0;
            mm_col         <= '0;
        end else begin
            if (l_vs_rise && sensor_oe) frames_l <= frames_l + 32'd1;
            if (r_vs_rise && sensor_oe) frames_r <= frames_r + 32'd1;
            if (pair_good && fwd_now) pairs_ok <= pairs_ok + 32'd1;
            if (pair_good && !fwd_now) skipped <= skipped + 32'd1;
            if (fail_evt) mismatches <= mismatches + 32'd1;
            if (retry_evt) retries <= retries + 32'd1;
            if (ovf_hit && !ovf_before) overflows <= overflows + 32'd1;
            if (publish_discard) discarded <= discarded + 32'd1;
            if (frame_end) begin
                verdict_causes <= {frame_causes[7:6], ovf_now, 1'b0, frame_causes[5:0]};
                verdict_frame  <= frame_index;
                if (sync_bad_now) begin
                    mm_line <= cur_mm_line;
                    mm_col  <= cur_mm_col;
                end
            end else if (timeout) begin
                verdict_causes <= 10'h040;
                verdict_frame  <= '0;
            end
        end
    end
endmodule
