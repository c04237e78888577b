// Speed of the whole co-simulation (issues 5 and 14; docs/performance.md),
// everything issue 14 asks to be reported in one program:
//
// default_scenario_traces_off: the default scenario (VGA, DSK v1, overlapped
// mode, 12 sync periods) in the fast arrangement with traces off (no pin
// hash), once, in a child process. Counters:
//   pairs_per_s       frame pairs (24.5 ms periods) per wall second (issue 14's figure)
//   sim_per_wall      simulated seconds per wall second (PERFORMANCE.md's figure)
//   wall_per_period   wall seconds per 24.5 ms sync period (one frame pair)
//   firmware_share    the firmware's own host time over the wall time (target < 10 %)
//   island_share      the cycle island's host time (sensors, scene, card RTL, EMIF)
//   syncs_per_period  island <-> SystemC syncs per period
//   card_evals_per_edge  evaluations of the verilated card per clock edge (pclk + ECLK)
//
// arrangements_traces_off: both arrangements side by side and their ratio
// (bench/arrangement_runs.h; 3 interleaved repetitions, about 1.5 min).
//
// campaign_both_ways: the smoke fault campaign with and without snapshots
// (bench/campaign_runs.h; about 2 min; STEREOSIM_BENCH_CAMPAIGN=full for the
// full campaign, about 25 min).
//
// One at a time: --benchmark_filter=default_scenario (or arrangements,
// campaign). bench_arrangements has the waves window and the card under
// Icarus.
#include <benchmark/benchmark.h>

#include <optional>
#include <systemc>

#include "bench/arrangement_runs.h"
#include "bench/campaign_runs.h"
#include "bench/child_run.h"
#include "bench/sc_benchmark_main.h"
#include "tb/platform/platform.h"
#include "tb/platform/report.h"

namespace {

struct scenario_figures {
    double wall_s = 0.0;
    double sim_per_wall = 0.0;
    double firmware_share = 0.0;
    double island_share = 0.0;
    double syncs = 0.0;
    double pairs_processed = 0.0;
    double card_evals_per_edge = 0.0;
};

std::optional<scenario_figures> run_default_scenario(int frames) {
    return bench::in_child<scenario_figures>([frames] {
        platform::platform_config config;
        config.hash_pins = false;
        config.frames = frames;
        platform::platform_top top(config);
        top.run();
        const platform::run_figures f = platform::figures_of(top);
        const platform::island_stats& s = top.cycle_island().stats();
        scenario_figures r;
        r.wall_s = f.wall_s;
        r.sim_per_wall = f.sim_per_wall();
        r.firmware_share = f.firmware_share();
        r.island_share = f.wall_s > 0.0 ? f.island_wall_s / f.wall_s : 0.0;
        r.syncs = static_cast<double>(s.syncs);
        r.pairs_processed = static_cast<double>(top.probe().results().size());
        r.card_evals_per_edge =
            static_cast<double>(s.card_evals) / static_cast<double>(s.pclk_edges + s.eclk_edges);
        return std::optional<scenario_figures>(r);
    });
}

void default_scenario_traces_off(benchmark::State& state) {
    const int frames = bench::env_int("STEREOSIM_BENCH_FRAMES", 12);
    for (auto _ : state) {
        const std::optional<scenario_figures> f = run_default_scenario(frames);
        if (!f || f->wall_s <= 0.0) {
            state.SkipWithError("the simulation failed");
            return;
        }
        state.SetIterationTime(f->wall_s);
        state.counters["pairs_per_s"] = frames / f->wall_s;
        state.counters["sim_per_wall"] = f->sim_per_wall;
        state.counters["wall_per_period_s"] = f->wall_s / frames;
        state.counters["firmware_share"] = f->firmware_share;
        state.counters["island_share"] = f->island_share;
        state.counters["syncs_per_period"] = f->syncs / frames;
        state.counters["pairs_processed"] = f->pairs_processed;
        state.counters["card_evals_per_edge"] = f->card_evals_per_edge;
    }
}
// One simulation: exactly one iteration, timed as the simulation's own wall
// time (the platform's construction and the fork left out).
BENCHMARK(default_scenario_traces_off)->Iterations(1)->Unit(benchmark::kSecond)->UseManualTime();

void arrangements_traces_off(benchmark::State& state) {
    bench::measure_arrangements(state, false);
}
BENCHMARK(arrangements_traces_off)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void campaign_both_ways(benchmark::State& state) {
    bench::campaign_both_ways(state);
}
BENCHMARK(campaign_both_ways)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

int sc_main(int argc, char* argv[]) {
    return bench::run_sc_benchmarks(argc, argv);
}
