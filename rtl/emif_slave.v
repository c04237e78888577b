// EMIFA asynchronous slave of the card on CE2 (registers) and CE3 (pixel
// ports), synchronous to ECLKOUT: the C64x drives its async strobes from
// ECLKOUT edges (docs/hardware-facts.md section 3), so the pins are sampled on the
// same clock without synchronizers. docs/card.md lists the timing
// assumptions (those the facts mark NOT FOUND).
//
// Read (AOE low through setup, strobe and hold; ARE low during the strobe):
//   edge S+1 (first edge that samples ARE low): decode EA; a pixel-port read
//            pops its FIFO (block-RAM read, data next cycle);
//   edge S+2: ED register loaded (register value or FIFO word); ready.
// ED is driven while CE and AOE are low (like an SRAM's output enable), so it
// is released as soon as the EMIF ends the hold, and never outside the card's
// CE. ARDY is low while the card's CE and AOE are low and the read data is
// not yet in the ED register: with a strobe of >= 3 + L cycles (L = where the
// EMIF samples ARDY, 1 assumed: RST >= 4, the DSK uses 10 and 12) it never
// stretches an access; with shorter strobes it adds wait states.
// A new read starts only on a fresh ARE strobe, so back-to-back reads with CE
// and AOE held low pop exactly once each.
// Write: at the first edge that samples AWE low, ED is written to the register
// EA selects, honouring the byte enables. Writes to CE3 are ignored.
//
// Address decode: EA is the word address (AEA21..AEA2 on the J4 connector).
// CE2: register index = EA[7:2]; EA[21:8] must be 0, other addresses read 0.
// CE3: EA[21:20] = 00 left port, 01 right port, 1x nothing (reads 0).
`timescale 1ns / 1fs
module emif_slave (
    input  logic        clk,
    input  logic        rst_n,
    // EMIF pins (active low strobes)
    input  logic        ce2_n,
    input  logic        ce3_n,
    input  logic        aoe_n,
    input  logic        are_n,
    input  logic        awe_n,
    input  logic [21:2] ea,
    input  logic [ 3:0] be_n,
    input  logic [31:0] ed_in,
    output logic [31:0] ed_out,
    output logic        ed_oe,
    output logic        ardy,
    // Register file
    output logic [ 5:0] reg_rd_idx,
    input  logic [31:0] reg_rdata,
    output logic        reg_wr_en,
    output logic [ 5:0] reg_wr_idx,
    output logic [31:0] reg_wr_data,
    output logic [ 3:0] reg_wr_be,
    // Pixel ports
    output logic        pop_l,
    output logic        pop_r,
    input  logic        empty_l,
    input  logic        empty_r,
    input  logic [31:0] rd_data_l,
    input  logic [31:0] rd_data_r,
    output logic        underflow  // a pixel-port read found its FIFO empty (returns 0)
);
    localparam logic [1:0] SRC_REG = 2'd0;
    localparam logic [1:0] SRC_LEFT = 2'd1;
    localparam logic [1:0] SRC_RIGHT = 2'd2;
    localparam logic [1:0] SRC_ZERO = 2'd3;

    wire sel_reg = !ce2_n;
    wire sel_data = !ce3_n;
    wire sel = sel_reg || sel_data;
    wire reg_addr_ok = ea[21:8] == 14'd0;
    wire port_left = ea[21:20] == 2'b00;
    wire port_right = ea[21:20] == 2'b01;

    logic rd_busy_q, ready_q, wr_busy_q;
    logic [1:0] src_q;
    logic [5:0] idx_q;
    logic [31:0] ed_q;

    wire rd_start = sel && !are_n && !rd_busy_q;
    wire wr_start = sel && !awe_n && !wr_busy_q;

    assign pop_l = rd_start && sel_data && port_left && !empty_l;
    assign pop_r = rd_start && sel_data && port_right && !empty_r;
    assign underflow = rd_start && sel_data &&
        ((port_left && empty_l) || (port_right && empty_r));

    logic [1:0] src_next;
    always_comb begin
        if (sel_reg) src_next = reg_addr_ok ? SRC_REG : SRC_ZERO;
        else if (pop_l) src_next = SRC_LEFT;
        else if (pop_r) src_next = SRC_RIGHT;
        else src_next = SRC_ZERO;
    end

    always_ff @(posedge clk or negedge rst_n) begin
        if (!rst_n) begin
            rd_busy_q <= 1'b0;
            ready_q   <= 1'b0;
            wr_busy_q <= 1'b0;
            src_q     <= SRC_ZERO;
            idx_q     <= '0;
            ed_q      <= '0;
        end else begin
            wr_busy_q <= sel && !awe_n;
            if (rd_start) begin
                rd_busy_q <= 1'b1;
                src_q     <= src_next;
                idx_q     <= ea[7:2];
            end else if (rd_busy_q && !ready_q) begin
                case (src_q)
                    SRC_REG: ed_q <= reg_rdata;
                    SRC_LEFT: ed_q <= rd_data_l;
                    SRC_RIGHT: ed_q <= rd_data_r;
                    default: ed_q <= '0;
                endcase
                ready_q <= 1'b1;
            end
            if (are_n) begin  // the strobe is over: the next ARE low is a new read
                rd_busy_q <= 1'b0;
                ready_q   <= 1'b0;
            end
`ifndef SYNTHESIS  // immediate assertions with an action block: simulation only
            assert (!(sel_reg && sel_data)) else $error("CE2 and CE3 both asserted");
            assert (!(sel && !are_n && !awe_n)) else $error("ARE and AWE both asserted");
`endif
        end
    end

    assign reg_rd_idx  = idx_q;
    assign reg_wr_en   = wr_start && sel_reg && reg_addr_ok;
    assign reg_wr_idx  = ea[7:2];
    assign reg_wr_data = ed_in;
    assign reg_wr_be   = ~be_n;

    assign ed_out = ed_q;
    assign ed_oe  = sel && !aoe_n;
    assign ardy   = !(sel && !aoe_n && !ready_q);
endmodule
