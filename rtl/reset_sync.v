// Reset synchronizer: asserts asynchronously with arst_n, releases on the
// second rising clk edge after arst_n rises, so every flop of the domain leaves
// reset on the same edge (no recovery/removal race with the clock).
`timescale 1ns / 1fs
module reset_sync (
    input  logic clk,
    input  logic arst_n,
    output logic rst_n
);
    logic meta_q;

    always_ff @(posedge clk or negedge arst_n) begin
        if (!arst_n) begin
            meta_q <= 1'b0;
            rst_n  <= 1'b0;
        end else begin
            meta_q <= 1'b1;
            rst_n  <= meta_q;
        end
    end
endmodule
