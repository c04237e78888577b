// Two-flop synchronizer: brings a WIDTH-bit signal into the clk domain.
// Used for the Gray-coded FIFO pointers and the OE / status crossings of the
// daughter card. Output follows input exactly two rising clk edges later.
`timescale 1ns / 1fs
module cdc_sync_2ff #(
    parameter int WIDTH = 1
) (
    input  logic             clk,
    input  logic             rst_n,
    input  logic [WIDTH-1:0] async_in,
    output logic [WIDTH-1:0] sync_out
);
    logic [WIDTH-1:0] meta_q;

    always_ff @(posedge clk or negedge rst_n) begin
        if (!rst_n) begin
            meta_q   <= '0;
            sync_out <= '0;
        end else begin
            meta_q   <= async_in;
            sync_out <= meta_q;
        end
    end
endmodule
