// NEGATIVE CONTROL for tests/rtl/test_async_fifo_binary.cpp, not card RTL:
// rtl/async_fifo.v with its pointers crossing in BINARY instead of Gray code.
// When a binary pointer changes several bits at once (0111 -> 1000) and the
// synchronizer catches some bits old and some new, the other side sees a
// value the pointer never held (1111, 0000, ...). The FIFO stress test must
// catch that; if it passed this variant, the test would prove nothing.
`timescale 1ns / 1fs
module async_fifo_binary #(
    parameter int DW = 32,
    parameter int AW = 4
) (
    input  logic          wclk,
    input  logic          wrst_n,
    input  logic          wr_en,
    input  logic [DW-1:0] wr_data,
    input  logic          wr_clear,
    output logic          wr_full,
    output logic [  AW:0] wr_level,
    output logic [  AW:0] wr_peak,
    output logic          wr_overflow,
    output logic [  AW:0] wr_ptr,
    input  logic          rclk,
    input  logic          rrst_n,
    input  logic          rd_en,
    output logic [DW-1:0] rd_data,
    output logic          rd_empty,
    output logic [  AW:0] rd_level,
    output logic [  AW:0] rd_ptr,
    output logic [  AW:0] rd_wptr
);
    localparam int DEPTH = 1 << AW;
    localparam logic [AW:0] DEPTH_P = (AW + 1)'(DEPTH);

    logic [DW-1:0] mem[DEPTH];

    logic [AW:0] wbin_q, wbin_prev_q, rbin_sync;
    wire wr_accept = wr_en && !wr_full;
    assign wr_level = wbin_q - rbin_sync;
    assign wr_full  = (wr_level >= DEPTH_P);
    assign wr_ptr   = wbin_q;

    always_ff @(posedge wclk) begin
        if (wr_accept) mem[wbin_q[AW-1:0]] <= wr_data;
    end

    always_ff @(posedge wclk or negedge wrst_n) begin
        if (!wrst_n) begin
            wbin_q      <= '0;
            wbin_prev_q <= '0;
            wr_overflow <= 1'b0;
            wr_peak     <= '0;
        end else begin
            wbin_prev_q <= wbin_q;
            if (wr_accept) wbin_q <= wbin_q + 1'b1;
            if (wr_clear) begin
                wr_overflow <= 1'b0;
                wr_peak     <= wr_level;
            end else begin
                if (wr_en && wr_full) wr_overflow <= 1'b1;
                if (wr_level > wr_peak) wr_peak <= wr_level;
            end
        end
    end

    logic [AW:0] rbin_q, rbin_prev_q, wbin_sync;
    wire rd_accept = rd_en && !rd_empty;
    assign rd_level = wbin_sync - rbin_q;
    assign rd_empty = (rd_level == '0) || (rd_level > DEPTH_P);
    assign rd_ptr   = rbin_q;
    assign rd_wptr  = wbin_sync;

    always_ff @(posedge rclk) begin
        if (rd_accept) rd_data <= mem[rbin_q[AW-1:0]];
    end

    always_ff @(posedge rclk or negedge rrst_n) begin
        if (!rrst_n) begin
            rbin_q      <= '0;
            rbin_prev_q <= '0;
        end else begin
            rbin_prev_q <= rbin_q;
            if (rd_accept) rbin_q <= rbin_q + 1'b1;
        end
    end

    cdc_sync_2ff_jitter #(.WIDTH(AW + 1)) u_sync_wptr (
        .clk(rclk),
        .rst_n(rrst_n),
        .async_in(wbin_q),
        .async_prev(wbin_prev_q),
        .sync_out(wbin_sync)
    );
    cdc_sync_2ff_jitter #(.WIDTH(AW + 1)) u_sync_rptr (
        .clk(wclk),
        .rst_n(wrst_n),
        .async_in(rbin_q),
        .async_prev(rbin_prev_q),
        .sync_out(rbin_sync)
    );
endmodule
