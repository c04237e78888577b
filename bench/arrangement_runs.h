// Both arrangements side by side (issues 8 and 14; docs/arrangements.md
// "Speed"): the default scenario (VGA, DSK v1, overlapped mode, the
// platform's defaults, 12 sync periods) in the fast arrangement (cores
// stepped in one SystemC thread) and in the literal pin-level one
// (sc_signals, verilator --sc), traces off (no pin hash) or with a 1 ms FST
// window (--waves fst: tb/app/output's writer, the traced card's whole
// hierarchy, 49-50 ms). Each simulation runs in a forked child. The machine
// is shared: runs are interleaved (fast, pins, pins, fast, ...) over
// STEREOSIM_BENCH_REPS repetitions (default 3) and the MEDIAN of the
// per-repetition ratios is reported. STEREOSIM_BENCH_FRAMES overrides the 12
// periods (shorter runs for a quick look). Counters:
//   fast_pairs_per_s, pins_pairs_per_s  frame pairs (24.5 ms periods) per wall second (median)
//   fast_sim_per_wall, pins_sim_per_wall  simulated seconds per wall second (median)
//   fast_over_pins                      median of the per-repetition speed ratios (issue 8 asks
//                                       >= 4); fast_over_pins_min / _max their spread
//   fast_over_pins_cpu                  the same of the children's CPU times
#pragma once

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "bench/child_run.h"
#include "tb/app/output/waves_writer.h"
#include "tb/platform/platform.h"

namespace bench {

constexpr simtime::ticks ticks_per_ms = 18000000;

struct run_time {
    double wall = -1.0;
    double cpu = -1.0;  // the child's CPU time in the run
};

// Wall and CPU seconds of one run in a child process (nothing on failure).
inline std::optional<run_time> run_arrangement(platform::arrangement_kind arrangement, int frames,
                                               bool waves_window) {
    return in_child<run_time>([&]() -> std::optional<run_time> {
        platform::platform_config config;
        config.arrangement = arrangement;
        config.frames = frames;
        config.hash_pins = false;
        const platform::tick_window window{49 * ticks_per_ms, 50 * ticks_per_ms};
        output::waves_writer writer(output::waves_format::fst, window);
        const std::string fst = "/tmp/bench_arrangements_" + std::to_string(getpid()) + ".fst";
        if (waves_window) {
            if (!writer.open(fst)) return std::nullopt;
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
        return r;
    });
}

inline void measure_arrangements(benchmark::State& state, bool waves_window) {
    const int frames = env_int("STEREOSIM_BENCH_FRAMES", 12);
    const int reps = env_int("STEREOSIM_BENCH_REPS", 3);
    const double simulated_s = frames * 0.0245;
    for (auto _ : state) {
        std::vector<double> fast, pins, ratio, cpu_ratio;
        for (int rep = 0; rep < reps; ++rep) {
            // Alternate the order so a load change favours neither.
            std::optional<run_time> f, p;
            if (rep % 2 == 0) {
                f = run_arrangement(platform::arrangement_kind::fast, frames, waves_window);
                p = run_arrangement(platform::arrangement_kind::pins, frames, waves_window);
            } else {
                p = run_arrangement(platform::arrangement_kind::pins, frames, waves_window);
                f = run_arrangement(platform::arrangement_kind::fast, frames, waves_window);
            }
            if (!f || !p || f->wall <= 0.0 || p->wall <= 0.0) {
                state.SkipWithError("a child simulation failed");
                return;
            }
            std::printf(
                "  repetition %d: fast %.2f s wall (%.2f s CPU), pins %.2f s wall (%.2f s CPU), "
                "ratio %.2f wall, %.2f CPU\n",
                rep + 1, f->wall, f->cpu, p->wall, p->cpu, p->wall / f->wall, p->cpu / f->cpu);
            std::fflush(stdout);
            fast.push_back(f->wall);
            pins.push_back(p->wall);
            ratio.push_back(p->wall / f->wall);
            cpu_ratio.push_back(p->cpu / f->cpu);
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

}  // namespace bench
