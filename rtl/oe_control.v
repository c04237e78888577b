// OE controller (docs/card.md, "OE control"): enables both sensors, lets the
// sync check judge every common frame, restarts OE on a failed check and
// gives up after retry_limit consecutive restarts.
//
//   IDLE --enable--> WAIT_VSYNC --origin--> RUN
//   WAIT_VSYNC --start timeout--> fail;  RUN --frame_end with a sync cause--> fail
//   fail: retries so far < retry_limit ? OE_LOW (restart) : HARD_ERROR
//   OE_LOW --oe_low_cycles--> WAIT_VSYNC;  any state --!enable--> IDLE
//
// A frame that passes clears the consecutive-failure count, so a slip late in
// a run gets the full retry budget again. OE is a registered output: high in
// WAIT_VSYNC and RUN only.
`timescale 1ns / 1fs
module oe_control (
    input  logic        pclk,
    input  logic        rst_n,
    input  logic        enable,
    input  logic        origin,
    input  logic        frame_end,
    input  logic        frame_sync_bad,  // the verdict at frame_end has a sync cause
    input  logic        timeout,
    input  logic [ 7:0] retry_limit,
    input  logic [15:0] oe_low_cycles,
    output logic [ 2:0] state,
    output logic        oe,
    output logic        run,          // WAIT_VSYNC or RUN
    output logic        wait_origin,  // WAIT_VSYNC
    output logic        fail_evt,     // a check failed (mismatch or start timeout)
    output logic        retry_evt,    // OE restarts
    output logic        start_evt     // IDLE -> WAIT_VSYNC: a new run begins
);
    localparam logic [2:0] S_IDLE = 3'd0;
    localparam logic [2:0] S_OE_LOW = 3'd1;
    localparam logic [2:0] S_WAIT_VSYNC = 3'd2;
    localparam logic [2:0] S_RUN = 3'd3;
    localparam logic [2:0] S_HARD_ERROR = 3'd4;

    logic [2:0] state_q, state_next;
    logic [7:0] fails_q;      // consecutive failed checks that led to a restart
    logic [15:0] low_cnt_q;   // pixel clocks spent in OE_LOW
    logic oe_q;

    wire [15:0] low_cycles = (oe_low_cycles == 16'd0) ? 16'd1 : oe_low_cycles;

    always_comb begin
        state_next = state_q;
        fail_evt   = 1'b0;
        case (state_q)
            S_IDLE: if (enable) state_next = S_WAIT_VSYNC;
            S_OE_LOW:
            if (!enable) state_next = S_IDLE;
            else if (low_cnt_q + 16'd1 >= low_cycles) state_next = S_WAIT_VSYNC;
            S_WAIT_VSYNC:
            if (!enable) state_next = S_IDLE;
            else if (timeout) fail_evt = 1'b1;
            else if (origin) state_next = S_RUN;
            S_RUN:
            if (!enable) state_next = S_IDLE;
            else if (frame_end && frame_sync_bad) fail_evt = 1'b1;
            S_HARD_ERROR: if (!enable) state_next = S_IDLE;
            default: state_next = S_IDLE;
        endcase
        retry_evt = fail_evt && fails_q < retry_limit;
        if (fail_evt) state_next = retry_evt ? S_OE_LOW : S_HARD_ERROR;
    end

    assign start_evt = state_q == S_IDLE && state_next == S_WAIT_VSYNC;

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) begin
            state_q   <= S_IDLE;
            fails_q   <= '0;
            low_cnt_q <= '0;
            oe_q      <= 1'b0;
        end else begin
            state_q   <= state_next;
            oe_q      <= state_next == S_WAIT_VSYNC || state_next == S_RUN;
            low_cnt_q <= (state_q == S_OE_LOW) ? low_cnt_q + 16'd1 : 16'd0;
            if (state_q == S_IDLE) fails_q <= '0;
            else if (retry_evt) fails_q <= fails_q + 8'd1;
            else if (state_q == S_RUN && frame_end && !frame_sync_bad) fails_q <= '0;
`ifndef SYNTHESIS  // immediate assertions with an action block: simulation only
            assert (state_q <= S_HARD_ERROR) else $error("illegal OE controller state %0d", state_q);
`endif
        end
    end

`ifdef VERILATOR  // functional coverage (--coverage-user, make coverage): states and arcs
    always_ff @(posedge pclk) begin
        cov_st_idle : cover (state_q == S_IDLE);
        cov_st_oe_low : cover (state_q == S_OE_LOW);
        cov_st_wait_vsync : cover (state_q == S_WAIT_VSYNC);
        cov_st_run : cover (state_q == S_RUN);
        cov_st_hard_error : cover (state_q == S_HARD_ERROR);
        cov_arc_enable : cover (state_q == S_IDLE && state_next == S_WAIT_VSYNC);
        cov_arc_origin : cover (state_q == S_WAIT_VSYNC && state_next == S_RUN);
        cov_arc_timeout_restart : cover (state_q == S_WAIT_VSYNC && state_next == S_OE_LOW);
        cov_arc_timeout_hard_error : cover (state_q == S_WAIT_VSYNC && state_next == S_HARD_ERROR);
        cov_arc_mismatch_restart : cover (state_q == S_RUN && state_next == S_OE_LOW);
        cov_arc_mismatch_hard_error : cover (state_q == S_RUN && state_next == S_HARD_ERROR);
        cov_arc_restart_done : cover (state_q == S_OE_LOW && state_next == S_WAIT_VSYNC);
        cov_arc_disable_oe_low : cover (state_q == S_OE_LOW && state_next == S_IDLE);
        cov_arc_disable_wait_vsync : cover (state_q == S_WAIT_VSYNC && state_next == S_IDLE);
        cov_arc_disable_run : cover (state_q == S_RUN && state_next == S_IDLE);
        cov_arc_hard_error_cleared : cover (state_q == S_HARD_ERROR && state_next == S_IDLE);
        cov_pass_clears_failures : cover (state_q == S_RUN && frame_end && !frame_sync_bad &&
                                      fails_q != '0);
    end
`endif

    assign state       = state_q;
    assign oe          = oe_q;
    assign run         = state_q == S_WAIT_VSYNC || state_q == S_RUN;
    assign wait_origin = state_q == S_WAIT_VSYNC;
endmodule
