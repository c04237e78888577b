// Test-build stand-in for cdc_sync_2ff (selected with +define+STEREOSIM_CDC_JITTER)
// that models metastability resolution: a bit that toggled in the source's
// last cycle and is still being captured may resolve to its old value, i.e.
// it reaches the output 0 or 1 destination cycle later, at random. A bit is
// never delayed twice in a row, and bits that settled earlier are captured
// as they are. async_prev is the source register's value one source cycle
// ago (the source keeps it for this model only).
//
// The assertion is the property a Gray-coded pointer crossing relies on:
// whatever the first flop captures is a value the source actually held (now
// or one source cycle ago). A multi-bit change (a binary pointer) breaks it.
`timescale 1ns / 1fs
// Linted with the card, it is a second top: it replaces cdc_sync_2ff only in
// test builds, so nothing instantiates it.
/* verilator lint_off MULTITOP */
module cdc_sync_2ff_jitter #(
    parameter int WIDTH = 1
) (
    input  logic             clk,
    input  logic             rst_n,
    input  logic [WIDTH-1:0] async_in,
    input  logic [WIDTH-1:0] async_prev,
    output logic [WIDTH-1:0] sync_out
);
    logic [WIDTH-1:0] meta_q;
    logic [WIDTH-1:0] delayed_q;  // bits held back at the previous edge
    logic [WIDTH-1:0] coin_q;     // fresh random bits every edge

    wire [WIDTH-1:0] toggled = async_in ^ async_prev;
    wire [WIDTH-1:0] eligible = toggled & (async_in ^ meta_q) & ~delayed_q;
    wire [WIDTH-1:0] delay = eligible & coin_q;
    wire [WIDTH-1:0] meta_next = (async_in & ~delay) | (meta_q & delay);

    always_ff @(posedge clk or negedge rst_n) begin
        if (!rst_n) begin
            meta_q    <= '0;
            sync_out  <= '0;
            delayed_q <= '0;
            coin_q    <= '0;
        end else begin
            meta_q    <= meta_next;
            sync_out  <= meta_q;
            delayed_q <= delay;
            coin_q    <= WIDTH'({$urandom, $urandom});
            assert (meta_next == async_in || meta_next == async_prev)
            else $error("captured %h: the source held %h and %h, never this", meta_next, async_prev,
                        async_in);
        end
    end
endmodule
