// Replays a recorded pin stimulus into the card RTL under Icarus Verilog, the
// outside reference for the verilated card (docs/arrangements.md "Icarus
// reference"; tests/rtl/test_icarus_reference.cpp writes the stimulus and
// compares the outputs with the verilated card's for the same stimulus).
//
// Stimulus (rtl/icarus/card_stimulus.h writes it), text, one line each:
//   line 1: the inputs before reset (19 hex fields, the order below)
//   then one line per clock event: <time fs> <edges hex: 1 pclk, 2 eclk> <19 inputs>
// The time is simtime::to_fs(tick) plus a fixed offset: every edge keeps its
// exact tick (1/18 ns) rounded once to the femtosecond.
//
// Per clock event, as the C++ driver does with two evals (rtl_sim.h):
//   T           the clocks of `edges` rise, the other inputs unchanged
//   T + 500 fs  outputs written (phase 1)
//   T + 1000 fs the event's new inputs are applied, both clocks fall
//   T + 1500 fs outputs written (phase 2), one line per event
// Distinct ticks are 55,555 fs apart, so the phases never overlap an event.
// Reset: inputs of line 1 at 0 fs, rst_n 1 -> 0 at 10 fs, 0 -> 1 at 20 fs.
//
// Output line: oe ed_oe ardy ed_out int4 int5 int6 (phase 1), the same
// (phase 2), %h: an x or z anywhere shows as such and fails the comparison.
`timescale 1fs / 1fs
module card_replay_tb;
    reg         rst_n, pclk, eclk;
    reg         l_vsync, l_href, l_valid, l_fodd, r_vsync, r_href, r_valid, r_fodd;
    reg  [ 7:0] l_data, r_data;
    reg         ce2_n, ce3_n, aoe_n, are_n, awe_n;
    reg  [19:0] ea;
    reg  [ 3:0] be_n;
    reg  [31:0] ed_in;
    wire        sensor_oe, ed_oe, ardy, ext_int4, ext_int5, ext_int6;
    wire [31:0] ed_out;

    card_top dut (
        .rst_n(rst_n), .pclk(pclk), .sensor_oe(sensor_oe),
        .l_vsync(l_vsync), .l_href(l_href), .l_valid(l_valid), .l_data(l_data), .l_fodd(l_fodd),
        .r_vsync(r_vsync), .r_href(r_href), .r_valid(r_valid), .r_data(r_data), .r_fodd(r_fodd),
        .eclk(eclk), .ce2_n(ce2_n), .ce3_n(ce3_n), .aoe_n(aoe_n), .are_n(are_n), .awe_n(awe_n),
        .ea(ea), .be_n(be_n), .ed_in(ed_in), .ed_out(ed_out), .ed_oe(ed_oe), .ardy(ardy),
        .ext_int4(ext_int4), .ext_int5(ext_int5), .ext_int6(ext_int6));

    // One event's inputs, read ahead of their application.
    reg         n_rst_n, n_l_vsync, n_l_href, n_l_valid, n_l_fodd, n_r_vsync, n_r_href, n_r_valid;
    reg         n_r_fodd;
    reg  [ 7:0] n_l_data, n_r_data;
    reg         n_ce2_n, n_ce3_n, n_aoe_n, n_are_n, n_awe_n;
    reg  [19:0] n_ea;
    reg  [ 3:0] n_be_n;
    reg  [31:0] n_ed_in;
    reg  [63:0] at_fs;
    reg  [ 3:0] edges;
    integer     fi, fo, n, events;
    reg  [8*4096-1:0] in_path, out_path;

    task apply_next;
        begin
            rst_n = n_rst_n;
            l_vsync = n_l_vsync; l_href = n_l_href; l_valid = n_l_valid; l_data = n_l_data;
            l_fodd = n_l_fodd;
            r_vsync = n_r_vsync; r_href = n_r_href; r_valid = n_r_valid; r_data = n_r_data;
            r_fodd = n_r_fodd;
            ce2_n = n_ce2_n; ce3_n = n_ce3_n; aoe_n = n_aoe_n; are_n = n_are_n; awe_n = n_awe_n;
            ea = n_ea; be_n = n_be_n; ed_in = n_ed_in;
        end
    endtask

    initial begin
        if (!$value$plusargs("stimulus=%s", in_path) || !$value$plusargs("outputs=%s", out_path)) begin
            $display("usage: vvp card_replay.vvp +stimulus=FILE +outputs=FILE");
            $finish;
        end
        fi = $fopen(in_path, "r");
        fo = $fopen(out_path, "w");
        if (fi == 0 || fo == 0) begin
            $display("card_replay_tb: cannot open the stimulus or the output file");
            $finish;
        end
        n = $fscanf(fi, "%h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h\n",
                    n_rst_n, n_l_vsync, n_l_href, n_l_valid, n_l_data, n_l_fodd,
                    n_r_vsync, n_r_href, n_r_valid, n_r_data, n_r_fodd,
                    n_ce2_n, n_ce3_n, n_aoe_n, n_are_n, n_awe_n, n_ea, n_be_n, n_ed_in);
        pclk = 0;
        eclk = 0;
        apply_next;
        rst_n = 1;
        #10 rst_n = 0;  // a falling edge: the asynchronous resets act
        #10 rst_n = 1;
        events = 0;
        forever begin
            n = $fscanf(fi, "%d %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h %h\n",
                        at_fs, edges, n_rst_n, n_l_vsync, n_l_href, n_l_valid, n_l_data, n_l_fodd,
                        n_r_vsync, n_r_href, n_r_valid, n_r_data, n_r_fodd,
                        n_ce2_n, n_ce3_n, n_aoe_n, n_are_n, n_awe_n, n_ea, n_be_n, n_ed_in);
            if (n != 21) begin
                $fclose(fi);
                $fclose(fo);
                $display("card_replay_tb: %0d events replayed, %0t fs", events, $time);
                $finish;
            end
            #(at_fs - $time);
            if (edges[0]) pclk = 1;
            if (edges[1]) eclk = 1;
            #500 $fwrite(fo, "%h %h %h %h %h %h %h ", sensor_oe, ed_oe, ardy, ed_out, ext_int4,
                         ext_int5, ext_int6);
            #500 begin
                apply_next;
                pclk = 0;
                eclk = 0;
            end
            #500 $fwrite(fo, "%h %h %h %h %h %h %h\n", sensor_oe, ed_oe, ardy, ed_out, ext_int4,
                         ext_int5, ext_int6);
            events = events + 1;
        end
    end
endmodule
