// Dark-pixel sync check of the two sensor streams (docs/card.md, "Sync check").
//
// Both streams are sampled on the master pixel clock and placed in ONE common
// frame: its line 0, column 0 is the first VSYNC rise of either stream after
// OE (origin), and from there it free-runs LINE_TOTAL x FRAME_LINES pixel
// clocks per frame. Framing each stream by its own VSYNC would hide a pure
// time skew; the common frame turns any skew of >= 1 pixel clock into
// pixels, dark pixels or VSYNC edges at the wrong place.
//
// Per stream and per pixel clock of a common frame it flags:
//   window: a pixel (HREF and VALID) where the layout has none, or none where
//           it has one (catches any skew, dropped or extra lines);
//   dark:   a pixel at a dark position (dark columns on every readout line,
//           dark rows) that reads >= dark_threshold;
//   vsync:  a VSYNC rise anywhere but at line 0 column 0, or none there;
//   frame identity (when frame_id_check is set): the stream's FODD, sampled
//           at its VSYNC rise at line 0 column 0, equal to its previous
//           frame's (the sensor sent a frame twice: timing and dark pixels
//           cannot show it), or, in the first frame after the origin, to
//           the other stream's (both streams flagged: no history to blame).
// The causes accumulate over the frame; frame_end marks the last pixel clock
// of a common frame, where frame_causes is the verdict covering that frame.
//
// Layout (all from the configuration registers): a readout line starts
// h_start clocks after the line start: dark left | border left | active |
// border right | dark right; a readout frame starts v_start lines after the
// VSYNC rise: dark top | border top | active | border bottom | dark bottom.
// Requires line_total >= 1 and frame_lines >= 1 (checked by the firmware).
`timescale 1ns / 1fs
module sync_check (
    input  logic        pclk,
    input  logic        rst_n,
    // Sensor pins, sampled here on the master pixel clock.
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
    // From the OE controller.
    input  logic        run,          // WAIT_VSYNC or RUN: counters and checks live
    input  logic        wait_origin,  // WAIT_VSYNC: the next VSYNC rise starts the common frame
    // Configuration (quasi-static while run is high).
    input  logic        frame_id_check,
    input  logic [ 7:0] dark_threshold,
    input  logic [15:0] h_start,
    input  logic [15:0] dark_cols_left,
    input  logic [15:0] border_cols_left,
    input  logic [15:0] active_cols,
    input  logic [15:0] border_cols_right,
    input  logic [15:0] dark_cols_right,
    input  logic [15:0] line_total,
    input  logic [15:0] v_start,
    input  logic [15:0] dark_rows_top,
    input  logic [15:0] border_rows_top,
    input  logic [15:0] active_rows,
    input  logic [15:0] border_rows_bottom,
    input  logic [15:0] dark_rows_bottom,
    input  logic [15:0] frame_lines,
    input  logic [15:0] start_timeout,  // lines to wait for the origin
    // Results for the current sample.
    output logic        origin,        // first common frame starts with this sample
    output logic        frame_start,   // line 0 column 0 of a common frame
    output logic        frame_end,     // last sample of a common frame
    output logic        timeout,       // no VSYNC within start_timeout lines
    output logic [15:0] frame_index,   // common frames since the origin
    // {r_frame_id, l_frame_id, r_vsync, l_vsync, r_dark, l_dark, r_window, l_window}
    output logic [ 7:0] frame_causes,
    output logic [15:0] mm_line,       // first mismatch of the frame so far
    output logic [15:0] mm_col,
    output logic        active_px,     // an active pixel position of the layout
    output logic [ 1:0] active_phase,  // its column within a 4-pixel word
    output logic [ 7:0] l_pixel,
    output logic [ 7:0] r_pixel,
    output logic        l_vs_rise,
    output logic        r_vs_rise
);
    // ---- input sampling ---------------------------------------------------------------
    logic l_vsync_q, l_vsync_qq, l_href_q, l_valid_q, l_fodd_q;
    logic r_vsync_q, r_vsync_qq, r_href_q, r_valid_q, r_fodd_q;
    logic [7:0] l_data_q, r_data_q;

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            {l_vsync_q, l_vsync_qq, l_href_q, l_valid_q} <= '0;
            {r_vsync_q, r_vsync_qq, r_href_q, r_valid_q} <= '0;
            l_data_q <= '0;
            r_data_q <= '0;
            l_fodd_q <= 1'b0;
            r_fodd_q <= 1'b0;
        end else begin
            {l_vsync_q, l_vsync_qq, l_href_q, l_valid_q} <= {l_vsync, l_vsync_q, l_href, l_valid};
            {r_vsync_q, r_vsync_qq, r_href_q, r_valid_q} <= {r_vsync, r_vsync_q, r_href, r_valid};
            l_data_q <= l_data;
            r_data_q <= r_data;
            l_fodd_q <= l_fodd;
            r_fodd_q <= r_fodd;
        end
    end

    assign l_vs_rise = l_vsync_q && !l_vsync_qq;
    assign r_vs_rise = r_vsync_q && !r_vsync_qq;
    assign l_pixel   = l_data_q;
    assign r_pixel   = r_data_q;

    // ---- layout boundaries (registered: the configuration is quasi-static) -----------
    logic [16:0] c1_q, c2_q, c3_q, c4_q, c5_q;  // column boundaries
    logic [16:0] r1_q, r2_q, r3_q, r4_q, r5_q;  // line boundaries

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            {c1_q, c2_q, c3_q, c4_q, c5_q} <= '0;
            {r1_q, r2_q, r3_q, r4_q, r5_q} <= '0;
        end else begin
            c1_q <= 17'(h_start) + 17'(dark_cols_left);
            c2_q <= c1_q + 17'(border_cols_left);
            c3_q <= c2_q + 17'(active_cols);
            c4_q <= c3_q + 17'(border_cols_right);
            c5_q <= c4_q + 17'(dark_cols_right);
            r1_q <= 17'(v_start) + 17'(dark_rows_top);
            r2_q <= r1_q + 17'(border_rows_top);
            r3_q <= r2_q + 17'(active_rows);
            r4_q <= r3_q + 17'(border_rows_bottom);
            r5_q <= r4_q + 17'(dark_rows_bottom);
        end
    end

    // ---- common frame position ------------------------------------------------------
    logic        running_q;
    logic [15:0] col_q, line_q;  // position of the next sample (or the start timer)
    logic [15:0] frame_index_q;

    assign origin = wait_origin && !running_q && (l_vs_rise || r_vs_rise);
    // run gates it: the cycle after the controller leaves RUN, running_q is still set.
    wire        in_frame = run && (running_q || origin);
    wire [15:0] cur_col = origin ? 16'd0 : col_q;
    wire [15:0] cur_line = origin ? 16'd0 : line_q;
    wire        last_col = (cur_col == line_total - 16'd1);
    wire        last_line = (cur_line == frame_lines - 16'd1);

    assign frame_start = in_frame && cur_col == 16'd0 && cur_line == 16'd0;
    assign frame_end   = in_frame && last_col && last_line;
    assign frame_index = origin ? 16'd0 : frame_index_q;
    assign timeout     = wait_origin && !in_frame && line_q == start_timeout;

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            running_q     <= 1'b0;
            col_q         <= '0;
            line_q        <= '0;
            frame_index_q <= '0;
        end else if (!run) begin
            running_q     <= 1'b0;
            col_q         <= '0;
            line_q        <= '0;
            frame_index_q <= '0;
        end else if (in_frame) begin
            running_q <= 1'b1;
            col_q     <= last_col ? 16'd0 : cur_col + 16'd1;
            // cur_line, not line_q: at the origin line_q still holds the start timer.
            if (last_col) line_q <= last_line ? 16'd0 : cur_line + 16'd1;
            else line_q <= cur_line;
            if (frame_end) frame_index_q <= frame_index + 16'd1;
        end else begin
            // Waiting for the origin: the same counters time the start.
            col_q <= last_col ? 16'd0 : col_q + 16'd1;
            if (last_col) line_q <= line_q + 16'd1;
        end
    end

    // ---- expected layout at the current position ------------------------------------------
    wire [16:0] col = 17'(cur_col);
    wire [16:0] line = 17'(cur_line);
    wire in_h = col >= 17'(h_start) && col < c5_q;
    wire in_v = line >= 17'(v_start) && line < r5_q;
    wire h_dark = col < c1_q || col >= c4_q;
    wire v_dark = line < r1_q || line >= r4_q;
    wire h_active = col >= c2_q && col < c3_q;
    wire v_active = line >= r2_q && line < r3_q;
    wire exp_pixel = in_frame && in_h && in_v;
    wire exp_dark = exp_pixel && (h_dark || v_dark);

    assign active_px = exp_pixel && h_active && v_active;
    // Only the low bits of (col - c2) are needed: the word phase.
    assign active_phase = col[1:0] - c2_q[1:0];

    // ---- frame identity -------------------------------------------------------------------
    // A stream's frame begins where the common frame does; its FODD then
    // names the exposure it carries. In step, both toggle every frame.
    // Per stream: the last frame's FODD, and whether one was seen since the
    // origin.
    logic l_id_prev, r_id_prev, l_id_seen, r_id_seen;
    wire l_id_at = frame_start && l_vs_rise;
    wire r_id_at = frame_start && r_vs_rise;
    wire id_pair_differs = l_id_at && r_id_at && (l_fodd_q != r_fodd_q);
    wire l_id_bad = frame_id_check && l_id_at &&
                    (l_id_seen ? l_fodd_q == l_id_prev : id_pair_differs);
    wire r_id_bad = frame_id_check && r_id_at &&
                    (r_id_seen ? r_fodd_q == r_id_prev : id_pair_differs);

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            {l_id_prev, r_id_prev, l_id_seen, r_id_seen} <= '0;
        end else if (!run) begin
            {l_id_seen, r_id_seen} <= '0;
        end else if (frame_start) begin
            // No rise here (a VSYNC cause): the next frame has no history.
            l_id_seen <= l_vs_rise;
            r_id_seen <= r_vs_rise;
            if (l_vs_rise) l_id_prev <= l_fodd_q;
            if (r_vs_rise) r_id_prev <= r_fodd_q;
        end
    end

    // ---- per-stream checks --------------------------------------------------------------
    wire l_px = l_href_q && l_valid_q;
    wire r_px = r_href_q && r_valid_q;
    wire [7:0] err_now = {
        r_id_bad,
        l_id_bad,
        in_frame && (r_vs_rise != frame_start),
        in_frame && (l_vs_rise != frame_start),
        exp_dark && r_px && (r_data_q >= dark_threshold),
        exp_dark && l_px && (l_data_q >= dark_threshold),
        in_frame && (r_px != exp_pixel),
        in_frame && (l_px != exp_pixel)
    };

`ifdef VERILATOR  // functional coverage (--coverage-user, make coverage): each cause, each stream
    always_ff @(posedge pclk) begin
        cov_cause_l_window : cover (err_now[0]);
        cov_cause_r_window : cover (err_now[1]);
        cov_cause_l_dark : cover (err_now[2]);
        cov_cause_r_dark : cover (err_now[3]);
        cov_cause_l_vsync : cover (err_now[4]);
        cov_cause_r_vsync : cover (err_now[5]);
        cov_cause_l_frame_id : cover (err_now[6]);
        cov_cause_r_frame_id : cover (err_now[7]);
        cov_frame_id_pair_differs : cover (frame_id_check && id_pair_differs);
        cov_start_timeout : cover (timeout);
        cov_origin_left_first : cover (origin && l_vs_rise && !r_vs_rise);
        cov_origin_right_first : cover (origin && r_vs_rise && !l_vs_rise);
        cov_origin_together : cover (origin && l_vs_rise && r_vs_rise);
    end
`endif

    logic [7:0] causes_q;
    logic [15:0] mm_line_q, mm_col_q;
    wire [7:0] causes_before = frame_start ? 8'd0 : causes_q;
    wire first_error = causes_before == 8'd0 && err_now != 8'd0;

    assign frame_causes = causes_before | err_now;
    assign mm_line = first_error ? cur_line : mm_line_q;
    assign mm_col = first_error ? cur_col : mm_col_q;

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            causes_q  <= '0;
            mm_line_q <= '0;
            mm_col_q  <= '0;
        end else if (!in_frame) begin
            causes_q <= '0;
        end else begin
            causes_q  <= frame_causes;
            mm_line_q <= mm_line;
            mm_col_q  <= mm_col;
        end
    end
endmodule
