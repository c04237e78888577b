// Multi-bit clock crossing by a two-phase (toggle) handshake (a
// "multi-cycle path" formulation): the source copies src_data into xfer_q and
// toggles req_q; the destination sees the toggle through a two-flop
// synchronizer, by which time xfer_q has been stable for two destination
// edges, copies it to dst_data and toggles ack back. The source reloads only
// after the ack arrived, so xfer_q never changes while it is being sampled.
//
// It runs continuously: dst_data is a coherent snapshot of src_data at most
// one round trip old (about 3 source + 3 destination cycles). Used for the
// card's configuration (bus -> pixel clock) and status (pixel clock -> bus).
`timescale 1ns / 1fs
module cdc_handshake #(
    parameter int WIDTH = 8
) (
    input  logic             src_clk,
    input  logic             src_rst_n,
    input  logic [WIDTH-1:0] src_data,
    input  logic             dst_clk,
    input  logic             dst_rst_n,
    output logic [WIDTH-1:0] dst_data,
    output logic             dst_update  // one dst cycle: dst_data was just reloaded
);
    logic             req_q;
    logic             ack_q;
    logic             req_sync;
    logic             ack_sync;
    logic [WIDTH-1:0] xfer_q;

    // Source side.
    cdc_sync_2ff #(.WIDTH(1)) u_sync_ack (
        .clk(src_clk),
        .rst_n(src_rst_n),
        .async_in(ack_q),
        .sync_out(ack_sync)
    );

    always_ff @(posedge src_clk or negedge src_rst_n) begin
        if (!src_rst_n) begin
            req_q  <= 1'b0;
            xfer_q <= '0;
        end else if (ack_sync == req_q) begin
            xfer_q <= src_data;
            req_q  <= ~req_q;
        end
    end

    // Destination side.
    cdc_sync_2ff #(.WIDTH(1)) u_sync_req (
        .clk(dst_clk),
        .rst_n(dst_rst_n),
        .async_in(req_q),
        .sync_out(req_sync)
    );

    always_ff @(posedge dst_clk or negedge dst_rst_n) begin
        if (!dst_rst_n) begin
            ack_q      <= 1'b0;
            dst_data   <= '0;
            dst_update <= 1'b0;
        end else begin
            dst_update <= 1'b0;
            if (req_sync != ack_q) begin
                dst_data   <= xfer_q;
                ack_q      <= req_sync;
                dst_update <= 1'b1;
            end
        end
    end
endmodule
