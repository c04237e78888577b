// Speed of the two arrangements and of the card under Icarus (issue 8;
// docs/arrangements.md "Speed"), all measured in the same run.
//
// arrangements_traces_off / arrangements_waves_window: the default scenario
// (VGA, DSK v1, overlapped mode, the platform's defaults, 12 sync periods)
// in the fast arrangement (cores stepped in one SystemC thread) and in the
// literal pin-level one (sc_signals, verilator --sc); traces off (no pin
// hash), or with a 1 ms FST window (--waves fst: tb/app/output's writer, the
// traced card's whole hierarchy, 49-50 ms). SystemC
// elaborates once per process, so each simulation runs in a forked child
// that reports its wall time. The machine is shared: runs are interleaved
// (fast, pins, pins, fast, ...) over STEREOSIM_BENCH_REPS repetitions
// (default 3) and the MEDIAN of the per-repetition ratios is reported.
// Counters:
//   fast_pairs_per_s, pins_pairs_per_s  simulated frame pairs (24.5 ms periods) per wall second
//   (median) fast_sim_per_wall, pins_sim_per_wall simulated seconds per wall second (median)
//   fast_over_pins                      median of the per-repetition speed ratios (issue 8 asks >=
//   4) fast_over_pins_min / _max           their spread
//
// card_icarus_vs_verilator: the card alone (rtl/card_top.v) replaying one
// recorded pin stimulus (tests/rtl/test_icarus_reference.cpp's: 2 ms from
// reset, small sensor layout, register writes, a sync error, frame pairs
// read over the EMIF) in the verilated card (rtl_card, --cc) and under
// Icarus Verilog (iverilog -g2012, vvp): simulated us per wall second.
// STEREOSIM_BENCH_FRAMES overrides the 12 periods (shorter runs for a quick look).
#include <benchmark/benchmark.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <systemc>
#include <vector>

// verilated.h, seeing SystemC, expects sc_time_stamp in the global namespace.
using sc_core::sc_time_stamp;
#include "Vcard.h"
#include "bench/bench_support.h"
#include "tb/app/output/waves_writer.h"
#include "tb/platform/platform.h"
#include "tests/rtl/card_bench.h"
#include "tests/rtl/icarus/card_stimulus.h"

namespace {

using bench::env_int;
using bench::median;

constexpr simtime::ticks ticks_per_ms = 18000000;

double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

struct run_time {
    double wall = -1.0;
    double cpu = -1.0;  // the child's CPU time in the run: less sensitive to other load
};

// Wall and CPU seconds of one run in a child process (negative on failure).
run_time run_in_child(platform::arrangement_kind arrangement, int frames, bool waves_window) {
    int fd[2];
    if (pipe(fd) != 0) return {};
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        platform::platform_config config;
        config.arrangement = arrangement;
        config.frames = frames;
        config.hash_pins = false;
        const platform::tick_window window{49 * ticks_per_ms, 50 * ticks_per_ms};
        output::waves_writer writer(output::waves_format::fst, window);
        const std::string fst = "/tmp/bench_arrangements_" + std::to_string(getpid()) + ".fst";
        if (waves_window) {
            if (!writer.open(fst)) _exit(4);
            config.trace = &writer;
            config.trace_window = window;
        }
        run_time r;
        {
            platform::platform_top top(config);
            const auto wall0 = std::chrono::steady_clock::now();
            const double cpu0 = cpu_seconds();
            top.run();
            r.cpu = cpu_seconds() - cpu0;
            r.wall =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
        }
        std::filesystem::remove(fst);
        const ssize_t written = write(fd[1], &r, sizeof r);
        _exit(written == sizeof r ? 0 : 3);
    }
    close(fd[1]);
    run_time r;
    if (read(fd[0], &r, sizeof r) != sizeof r) r = run_time{};
    close(fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? r : run_time{};
}

void measure_arrangements(benchmark::State& state, bool waves_window) {
    const int frames = env_int("STEREOSIM_BENCH_FRAMES", 12);
    const int reps = env_int("STEREOSIM_BENCH_REPS", 3);
    const double simulated_s = frames * 0.0245;
    for (auto _ : state) {
        std::vector<double> fast, pins, ratio, cpu_ratio;
        for (int rep = 0; rep < reps; ++rep) {
            // Alternate the order so a load change favours neither.
            run_time f, p;
            if (rep % 2 == 0) {
                f = run_in_child(platform::arrangement_kind::fast, frames, waves_window);
                p = run_in_child(platform::arrangement_kind::pins, frames, waves_window);
            } else {
                p = run_in_child(platform::arrangement_kind::pins, frames, waves_window);
                f = run_in_child(platform::arrangement_kind::fast, frames, waves_window);
            }
            if (f.wall <= 0.0 || p.wall <= 0.0) {
                state.SkipWithError("a child simulation failed");
                return;
            }
            std::printf(
                "  repetition %d: fast %.2f s wall (%.2f s CPU), pins %.2f s wall (%.2f s CPU), "
                "ratio %.2f wall, %.2f CPU\n",
                rep + 1, f.wall, f.cpu, p.wall, p.cpu, p.wall / f.wall, p.cpu / f.cpu);
            std::fflush(stdout);
            fast.push_back(f.wall);
            pins.push_back(p.wall);
            ratio.push_back(p.wall / f.wall);
            cpu_ratio.push_back(p.cpu / f.cpu);
        }
        const double f = median(fast), p = median(pins);
        state.counters["frames"] = frames;
        state.counters["reps"] = reps;
        state.counters["fast_wall_s"] = f;
        state.counters["pins_wall_s"] = p;
        state.counters["fast_pairs_per_s"] = frames / f;
        state.counters["pins_pairs_per_s"] = frames / p;
        state.counters["fast_sim_per_wall"] = simulated_s / f;
        state.counters["pins_sim_per_wall"] = simulated_s / p;
        state.counters["fast_over_pins"] = median(ratio);
        state.counters["fast_over_pins_cpu"] = median(cpu_ratio);
        state.counters["fast_over_pins_min"] = *std::min_element(ratio.begin(), ratio.end());
        state.counters["fast_over_pins_max"] = *std::max_element(ratio.begin(), ratio.end());
    }
}

void arrangements_traces_off(benchmark::State& state) {
    measure_arrangements(state, false);
}
void arrangements_waves_window(benchmark::State& state) {
    measure_arrangements(state, true);
}
BENCHMARK(arrangements_traces_off)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
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
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
