// Proves the Verilator + SystemC + GoogleTest integration: the verilated
// two-flop synchronizer, clocked by an sc_clock, delays its input by exactly
// two rising clock edges and resets asynchronously.
#include <gtest/gtest.h>

#include <systemc>

#include "Vcdc_sync_2ff.h"

namespace {

struct sync_bench : sc_core::sc_module {
    sc_core::sc_clock clk{"clk", 10, sc_core::SC_NS};  // rising edges at 0, 10, 20 ... ns
    sc_core::sc_signal<bool> rst_n{"rst_n"};
    sc_core::sc_signal<uint32_t> async_in{"async_in"};
    sc_core::sc_signal<uint32_t> sync_out{"sync_out"};
    Vcdc_sync_2ff dut{"dut"};

    explicit sync_bench(sc_core::sc_module_name name) : sc_core::sc_module(name) {
        dut.clk(clk);
        dut.rst_n(rst_n);
        dut.async_in(async_in);
        dut.sync_out(sync_out);
    }
};

}  // namespace

// One simulation per process (SystemC cannot elaborate twice): a single test.
TEST(CdcSync2ffSc, OutputFollowsInputTwoEdgesLaterAndResets) {
    sync_bench bench("bench");
    bench.rst_n.write(false);
    bench.async_in.write(0);
    sc_core::sc_start(12, sc_core::SC_NS);  // past the 10 ns edge, in reset
    EXPECT_EQ(bench.sync_out.read(), 0u);

    bench.rst_n.write(true);
    sc_core::sc_start(10, sc_core::SC_NS);  // t = 22 ns, edge at 20 ns passed out of reset
    // Drive away from the active edge (t = 22 ns), as the Verilator examples do.
    bench.async_in.write(0xA);
    sc_core::sc_start(10, sc_core::SC_NS);  // t = 32: edge at 30 captured into the first flop
    EXPECT_EQ(bench.sync_out.read(), 0u) << "one edge after the change the output must not move";
    sc_core::sc_start(10, sc_core::SC_NS);  // t = 42: edge at 40 moved it to the output
    EXPECT_EQ(bench.sync_out.read(), 0xAu) << "two edges after the change the output follows";

    bench.async_in.write(0x5);
    sc_core::sc_start(10, sc_core::SC_NS);
    EXPECT_EQ(bench.sync_out.read(), 0xAu);
    sc_core::sc_start(10, sc_core::SC_NS);
    EXPECT_EQ(bench.sync_out.read(), 0x5u);

    bench.rst_n.write(false);  // asynchronous reset: clears without an edge
    sc_core::sc_start(1, sc_core::SC_NS);
    EXPECT_EQ(bench.sync_out.read(), 0u);
    bench.dut.final();
}
