// Packs a stream's forwarded pixels into 32-bit words for its FIFO: the pixel
// at word phase n (its column within a group of 4, counted from the first
// active column, which the layout makes a multiple of 4 per line) goes to bits
// 8n+7..8n, i.e. the first pixel of a line is the lowest byte of its first
// word, as the little-endian C6416 reads it back from memory (byte address
// 4k+n = pixel 4k+n). The word is presented (wr_en) with its 4th pixel.
`timescale 1ns / 1fs
module pixel_packer (
    input  logic        pclk,
    input  logic        rst_n,
    input  logic        px_en,   // forward this pixel
    input  logic [ 1:0] phase,
    input  logic [ 7:0] pixel,
    output logic        wr_en,
    output logic [31:0] wr_data
);
    logic [23:0] acc_q;  // pixels of phases 0..2 of the word being built

    always_ff @(posedge pclk or negedge rst_n) begin
        if (!rst_n) acc_q <= '0;
        else if (px_en) begin
            case (phase)
                2'd0: acc_q[7:0] <= pixel;
                2'd1: acc_q[15:8] <= pixel;
                2'd2: acc_q[23:16] <= pixel;
                default: ;
            endcase
        end
    end

    assign wr_en   = px_en && phase == 2'd3;
    assign wr_data = {pixel, acc_q};
endmodule
