// Dual-clock FIFO with Gray-coded pointers (Cummings, "Simulation and
// Synthesis Techniques for Asynchronous FIFO Design", SNUG 2002): each side
// keeps a binary pointer (memory address) and its Gray code in a register;
// only the Gray register crosses, through a two-flop synchronizer, so a
// pointer sampled mid-change is off by at most one position and is always a
// value the other side really held. Pointers are AW+1 bits: the extra bit
// tells full from empty.
//
// Write side: wr_en when full drops the word and sets the sticky wr_overflow.
// wr_level (words in the FIFO as the writer sees it) never under-estimates
// the occupancy, so full is safe; wr_peak is its maximum since wr_clear.
// Read side: synchronous read, rd_data is valid the cycle after rd_en (like
// a block RAM); rd_level never over-estimates, so empty is safe. Reading an
// empty FIFO is a caller bug (assertion) and does nothing.
//
// Cost: 2^AW x DW bits of dual-port RAM, 2 x (AW+1) synchronizer flops.
`timescale 1ns / 1fs
module async_fifo #(
    parameter int DW = 32,
    parameter int AW = 4  // depth 2^AW words
) (
    input  logic          wclk,
    input  logic          wrst_n,
    input  logic          wr_en,
    input  logic [DW-1:0] wr_data,
    input  logic          wr_clear,     // clears wr_overflow, restarts wr_peak
    output logic          wr_full,
    output logic [  AW:0] wr_level,
    output logic [  AW:0] wr_peak,
    output logic          wr_overflow,
    output logic [  AW:0] wr_ptr,       // binary write pointer (words written, mod 2^(AW+1))

    input  logic          rclk,
    input  logic          rrst_n,
    input  logic          rd_en,
    output logic [DW-1:0] rd_data,
    output logic          rd_empty,
    output logic [  AW:0] rd_level,
    output logic [  AW:0] rd_ptr,       // binary read pointer
    output logic [  AW:0] rd_wptr       // the write pointer as the read side sees it (binary)
);
    localparam int DEPTH = 1 << AW;
    localparam logic [AW:0] DEPTH_P = (AW + 1)'(DEPTH);

    function automatic logic [AW:0] bin2gray(input logic [AW:0] b);
        bin2gray = b ^ (b >> 1);
    endfunction

    // Bit i of the binary value is the XOR of Gray bits i..AW: a prefix XOR
    // in log2(AW+1) shift steps. The same function as a bit-serial chain,
    // with a few more gates and fewer levels; a simulator evaluating it on
    // every read-side edge no longer walks AW dependent steps.
    function automatic logic [AW:0] gray2bin(input logic [AW:0] g);
        logic [AW:0] b;
        b = g;
        for (int s = 1; s <= AW; s = s * 2) b = b ^ (b >> s);
        gray2bin = b;
    endfunction

    logic [DW-1:0] mem[DEPTH];

    // ---- write side (wclk) ------------------------------------------------------------
    logic [AW:0] wbin_q, wgray_q, rgray_sync;
    wire  [AW:0] rbin_sync = gray2bin(rgray_sync);
    wire  [AW:0] wbin_next = wbin_q + 1'b1;
    wire         wr_accept = wr_en && !wr_full;

    assign wr_level = wbin_q - rbin_sync;
    assign wr_full  = (wr_level == DEPTH_P);
    assign wr_ptr   = wbin_q;

    always_ff @(posedge wclk) begin
        if (wr_accept) mem[wbin_q[AW-1:0]] <= wr_data;
    end

    always_ff @(posedge wclk or negedge wrst_n) begin
        if (!wrst_n) begin
            wbin_q      <= '0;
            wgray_q     <= '0;
            wr_overflow <= 1'b0;
            wr_peak     <= '0;
        end else begin
            if (wr_accept) begin
                wbin_q  <= wbin_next;
                wgray_q <= bin2gray(wbin_next);
            end
            if (wr_clear) begin
                wr_overflow <= 1'b0;
                wr_peak     <= wr_level;
            end else begin
                if (wr_en && wr_full) wr_overflow <= 1'b1;
                if (wr_level > wr_peak) wr_peak <= wr_level;
            end
`ifndef SYNTHESIS  // immediate assertions with an action block: simulation only
            assert (wr_level <= DEPTH_P)
            else $error("write side level %0d above depth %0d", wr_level, DEPTH);
`endif
        end
    end

    // ---- read side (rclk) -------------------------------------------------------------
    logic [AW:0] rbin_q, rgray_q, wgray_sync;
    wire  [AW:0] wbin_sync = gray2bin(wgray_sync);
    wire  [AW:0] rbin_next = rbin_q + 1'b1;
    wire         rd_accept = rd_en && !rd_empty;

    assign rd_level = wbin_sync - rbin_q;
    assign rd_empty = (rd_level == '0);
    assign rd_ptr   = rbin_q;
    assign rd_wptr  = wbin_sync;

    always_ff @(posedge rclk) begin
        if (rd_accept) rd_data <= mem[rbin_q[AW-1:0]];
    end

    always_ff @(posedge rclk or negedge rrst_n) begin
        if (!rrst_n) begin
            rbin_q  <= '0;
            rgray_q <= '0;
        end else begin
            if (rd_accept) begin
                rbin_q  <= rbin_next;
                rgray_q <= bin2gray(rbin_next);
            end
`ifndef SYNTHESIS  // immediate assertions with an action block: simulation only
            assert (!(rd_en && rd_empty)) else $error("read of an empty FIFO");
            assert (rd_level <= DEPTH_P)
            else $error("read side level %0d above depth %0d", rd_level, DEPTH);
`endif
        end
    end

    // ---- pointer crossings ------------------------------------------------------------
`ifdef STEREOSIM_CDC_JITTER
    // The jitter model needs each Gray register's value one source cycle ago.
    logic [AW:0] wgray_prev_q, rgray_prev_q;
    always_ff @(posedge wclk or negedge wrst_n) begin
        if (!wrst_n) wgray_prev_q <= '0;
        else wgray_prev_q <= wgray_q;
    end
    always_ff @(posedge rclk or negedge rrst_n) begin
        if (!rrst_n) rgray_prev_q <= '0;
        else rgray_prev_q <= rgray_q;
    end
    cdc_sync_2ff_jitter #(.WIDTH(AW + 1)) u_sync_wptr (
        .clk(rclk),
        .rst_n(rrst_n),
        .async_in(wgray_q),
        .async_prev(wgray_prev_q),
        .sync_out(wgray_sync)
    );
    cdc_sync_2ff_jitter #(.WIDTH(AW + 1)) u_sync_rptr (
        .clk(wclk),
        .rst_n(wrst_n),
        .async_in(rgray_q),
        .async_prev(rgray_prev_q),
        .sync_out(rgray_sync)
    );
`else
    cdc_sync_2ff #(.WIDTH(AW + 1)) u_sync_wptr (
        .clk(rclk),
        .rst_n(rrst_n),
        .async_in(wgray_q),
        .sync_out(wgray_sync)
    );
    cdc_sync_2ff #(.WIDTH(AW + 1)) u_sync_rptr (
        .clk(wclk),
        .rst_n(wrst_n),
        .async_in(rgray_q),
        .sync_out(rgray_sync)
    );
`endif
endmodule
