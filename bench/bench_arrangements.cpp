// Speed of the two arrangements with a waveform window and of the card under
// Icarus (issue 8; docs/arrangements.md "Speed"), all measured in the same
// run. Both arrangements with traces off are in bench_platform.
//
// arrangements_waves_window: the default scenario in both arrangements with
// a 1 ms FST window, interleaved (bench/arrangement_runs.h has the counters,
// STEREOSIM_BENCH_REPS and STEREOSIM_BENCH_FRAMES).
//
// card_icarus_vs_verilator: the card alone (rtl/card_top.v) replaying one
// recorded pin stimulus (tests/rtl/test_icarus_reference.cpp's: 2 ms from
// reset, small sensor layout, register writes, a sync error, frame pairs
// read over the EMIF) in the verilated card (rtl_card, --cc) and under
// Icarus Verilog (iverilog -g2012, vvp): simulated us per wall second.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <systemc>
#include <vector>

// verilated.h, seeing SystemC, expects sc_time_stamp in the global namespace.
using sc_core::sc_time_stamp;
#include "Vcard.h"
#include "bench/arrangement_runs.h"
#include "bench/sc_benchmark_main.h"
#include "tests/rtl/card_bench.h"
#include "tests/rtl/icarus/card_stimulus.h"

namespace {

using bench::ticks_per_ms;

// Both arrangements with traces off are bench_platform's arrangements_traces_off.
void arrangements_waves_window(benchmark::State& state) {
    bench::measure_arrangements(state, true);
}
BENCHMARK(arrangements_waves_window)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// ---- the card alone: verilated vs Icarus on one stimulus ------------------------------------
void card_icarus_vs_verilator(benchmark::State& state) {
    namespace regs = dsp::card_regs;
    const simtime::ticks window = 2 * ticks_per_ms;
    for (auto _ : state) {
        // The stimulus of tests/rtl/test_icarus_reference.cpp.
        rtl_test::bench_options o;
        o.layout = rtl_test::small_layout();
        icarus_ref::card_inputs before_reset;
        std::vector<icarus_ref::clock_event> events;
        {
            rtl_test::card_bench<Vcard> b(o);
            b.right.set_start_extra({o.layout.line_total});
            before_reset = icarus_ref::read_inputs(b.dut());
            const rtl_test::sensor_layout& l = o.layout;
            const int layout[][2] = {
                {static_cast<int>(regs::h_start), l.h_start},
                {static_cast<int>(regs::dark_cols_left), l.dark_left},
                {static_cast<int>(regs::border_cols_left), l.border_left},
                {static_cast<int>(regs::active_cols), l.active_cols},
                {static_cast<int>(regs::border_cols_right), l.border_right},
                {static_cast<int>(regs::dark_cols_right), l.dark_right},
                {static_cast<int>(regs::line_total), l.line_total},
                {static_cast<int>(regs::v_start), l.v_start},
                {static_cast<int>(regs::dark_rows_top), l.dark_top},
                {static_cast<int>(regs::border_rows_top), l.border_top},
                {static_cast<int>(regs::active_rows), l.active_rows},
                {static_cast<int>(regs::border_rows_bottom), l.border_bottom},
                {static_cast<int>(regs::dark_rows_bottom), l.dark_bottom},
                {static_cast<int>(regs::frame_lines), l.frame_lines},
                {static_cast<int>(regs::oe_low_cycles), 60},
                {static_cast<int>(regs::start_timeout), 100},
                {static_cast<int>(regs::ctrl), static_cast<int>(regs::ctrl_enable_mask)}};
            for (const auto& w : layout) {
                rtl_test::emif_access a;
                a.k = rtl_test::emif_access::kind::write;
                a.addr = regs::ce2_base + static_cast<uint32_t>(w[0]);
                a.data = static_cast<uint32_t>(w[1]);
                b.master.push(a);
            }
            b.reader_enabled = true;
            while (b.now() + b.opt.eclk_ticks < static_cast<uint64_t>(window)) {
                const uint64_t p0 = b.pclk_edges(), e0 = b.eclk_edges();
                b.step();
                icarus_ref::clock_event e;
                e.tick = static_cast<simtime::ticks>(b.now());
                e.edges = static_cast<uint8_t>((b.pclk_edges() != p0 ? icarus_ref::edge_pclk : 0) |
                                               (b.eclk_edges() != e0 ? icarus_ref::edge_eclk : 0));
                e.in = icarus_ref::read_inputs(b.dut());
                events.push_back(e);
            }
        }
        const double simulated_us = static_cast<double>(events.back().tick) / 18000.0;

        const auto t0 = std::chrono::steady_clock::now();
        {
            VerilatedContext context;
            Vcard card(&context, "card");
            benchmark::DoNotOptimize(icarus_ref::replay(card, before_reset, events));
            card.final();
        }
        const double verilator_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

        const std::string dir = "/tmp/bench_icarus_" + std::to_string(getpid());
        std::filesystem::create_directories(dir);
        // This file is bench/bench_arrangements.cpp under the repository.
        const std::string rtl =
            std::filesystem::path(__FILE__).parent_path().parent_path().string() + "/rtl";
        if (!icarus_ref::write_stimulus(dir + "/stimulus.txt", before_reset, events) ||
            std::system(("iverilog -g2012 -I" + rtl + " -s card_replay_tb -o " + dir +
                         "/card.vvp " + rtl + "/../tests/rtl/icarus/card_replay_tb.v " + rtl +
                         "/*.v > /dev/null 2>&1")
                            .c_str()) != 0) {
            state.SkipWithError("iverilog failed");
            return;
        }
        const auto t1 = std::chrono::steady_clock::now();
        const int rc = std::system(("vvp -n " + dir + "/card.vvp +stimulus=" + dir +
                                    "/stimulus.txt +outputs=" + dir + "/outputs.txt > /dev/null")
                                       .c_str());
        const double icarus_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
        std::filesystem::remove_all(dir);
        if (rc != 0) {
            state.SkipWithError("vvp failed");
            return;
        }
        state.counters["simulated_us"] = simulated_us;
        state.counters["clock_events"] = static_cast<double>(events.size());
        state.counters["verilator_wall_s"] = verilator_s;
        state.counters["icarus_wall_s"] = icarus_s;
        state.counters["verilator_us_per_s"] = simulated_us / verilator_s;
        state.counters["icarus_us_per_s"] = simulated_us / icarus_s;
        state.counters["verilator_over_icarus"] = icarus_s / verilator_s;
    }
}
BENCHMARK(card_icarus_vs_verilator)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

int sc_main(int argc, char* argv[]) {
    return bench::run_sc_benchmarks(argc, argv);
}
