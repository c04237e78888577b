// Interrupt pulse for a C64x EXT_INT pin. The C6416 needs EXT_INTx high for
// >= 4P and low for >= 4P (P = CPU period; docs/hardware-facts.md section 4), i.e.
// 8 ns at 500 MHz, the slowest CPU considered. HIGH_CYCLES and LOW_CYCLES ECLK
// cycles give 40 ns / 40 ns at 100 MHz and 30 ns at 133 MHz (defaults 4 / 4),
// a 3.75x margin. Active high (EXTPOL default: rising edge interrupts).
// An event during a pulse or its low gap is remembered (one pending) and
// fires right after the gap; several such events merge into one pulse (the
// IRQ_STATUS bits and the counters keep the exact count).
`timescale 1ns / 1fs
module irq_pulse #(
    parameter int HIGH_CYCLES = 4,
    parameter int LOW_CYCLES  = 4
) (
    input  logic clk,
    input  logic rst_n,
    input  logic event_in,
    output logic irq
);
    localparam int CW = $clog2(HIGH_CYCLES + LOW_CYCLES + 1);

    logic [CW-1:0] count_q;  // cycles left in the current high or low phase
    logic pending_q;
    wire idle = !irq && count_q == '0;

    always_ff @(posedge clk or negedge rst_n) begin
        if (!rst_n) begin
            irq       <= 1'b0;
            count_q   <= '0;
            pending_q <= 1'b0;
        end else if (idle) begin
            if (event_in || pending_q) begin
                irq       <= 1'b1;
                count_q   <= CW'(HIGH_CYCLES - 1);
                pending_q <= 1'b0;
            end
        end else begin
            if (event_in) pending_q <= 1'b1;
            if (count_q != '0) begin
                count_q <= count_q - 1'b1;
            end else begin  // end of the high phase (not idle, count 0: irq is high)
                irq     <= 1'b0;
                count_q <= CW'(LOW_CYCLES - 1);
            end
        end
    end
endmodule
