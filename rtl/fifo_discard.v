// Removes a rejected frame's words from a FIFO on the bus side. The capture
// side publishes the region [begin_ptr, end_ptr) the frame's words occupy
// (binary FIFO pointers); once the reader has consumed everything before it
// (rd_ptr reaches begin_ptr), this pops the region one word per cycle in
// cycles the DSP does not pop, so the next word the DSP reads is the first
// word of the next good frame. If the reader already went past the region
// (a firmware reading ahead of FRAME_READY), there is nothing left to drop.
// A frame is at most one FIFO of words, so a VGA frame pair is dropped in
// 76,800 cycles (0.77 ms at 100 MHz), well in_region the restart that follows.
`timescale 1ns / 1fs
module fifo_discard #(
    parameter int AW = 17
) (
    input  logic        clk,
    input  logic        rst_n,
    input  logic        start,      // a new region (begin_ptr/end_ptr valid)
    input  logic [AW:0] begin_ptr,
    input  logic [AW:0] end_ptr,
    input  logic [AW:0] rd_ptr,
    input  logic        empty,
    input  logic        dsp_pop,    // the bus pops this cycle: stay off
    output logic        pop,
    output logic        busy
);
    localparam logic [AW:0] DEPTH_P = (AW + 1)'(1 << AW);

    logic active_q;
    logic [AW:0] begin_q, end_q;

    wire [AW:0] offset = rd_ptr - begin_q;  // words of the region already consumed
    wire [AW:0] length = end_q - begin_q;
    wire behind = offset > DEPTH_P;  // the reader has not reached the region yet
    wire in_region = offset < length;

    assign pop  = active_q && in_region && !empty && !dsp_pop;
    assign busy = active_q;

    always_ff @(posedge clk or negedge rst_n) begin
        if (!rst_n) begin
            active_q <= 1'b0;
            begin_q  <= '0;
            end_q    <= '0;
        end else if (start) begin
            active_q <= 1'b1;
            begin_q  <= begin_ptr;
            end_q    <= end_ptr;
`ifndef SYNTHESIS  // immediate assertions with an action block: simulation only
            assert (!active_q) else $error("new discard region while one is active");
`endif
        end else if (active_q && !in_region && !behind) begin
            active_q <= 1'b0;
        end
    end
endmodule
