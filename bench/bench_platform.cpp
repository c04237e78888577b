// Speed of the whole co-simulation (issue 5, "Speed"; docs/platform.md): the
// default scenario (VGA, DSK v1, overlapped mode, 12 sync periods) in the
// fast arrangement with traces off (no pin hash), once: SystemC elaborates
// once per process, so there is one iteration. Counters:
//   sim_per_wall      simulated seconds per wall second (PERFORMANCE.md's figure)
//   wall_per_period   wall seconds per 24.5 ms sync period (one frame pair)
//   firmware_share    the firmware's own host time over the wall time (target < 10 %)
//   island_share      the cycle island's host time (sensors, scene, card RTL, EMIF)
//   syncs_per_period  island <-> SystemC syncs per period
//   pairs_per_s       frame pairs (24.5 ms periods) per wall second (issue 14's figure)
//   card_evals_per_edge  evaluations of the verilated card per clock edge (pclk + ECLK)
// bench_arrangements has both arrangements side by side, bench_campaign the fault
// campaign with and without snapshots, docs/performance.md the history.
#include <benchmark/benchmark.h>

#include <systemc>

#include "tb/platform/platform.h"
#include "tb/platform/report.h"

namespace {

void default_scenario_traces_off(benchmark::State& state) {
    platform::platform_config config;
    config.hash_pins = false;
    for (auto _ : state) {
        platform::platform_top top(config);
        top.run();
        const platform::run_figures f = platform::figures_of(top);
        state.counters["sim_per_wall"] = f.sim_per_wall();
        state.counters["wall_per_period_s"] = f.wall_s / config.frames;
        state.counters["firmware_share"] = f.firmware_share();
        state.counters["island_share"] = f.wall_s > 0.0 ? f.island_wall_s / f.wall_s : 0.0;
        state.counters["syncs_per_period"] =
            static_cast<double>(top.cycle_island().stats().syncs) / config.frames;
        state.counters["pairs_processed"] = static_cast<double>(top.probe().results().size());
        state.counters["pairs_per_s"] = f.wall_s > 0.0 ? config.frames / f.wall_s : 0.0;
        const platform::island_stats& s = top.cycle_island().stats();
        state.counters["card_evals_per_edge"] =
            static_cast<double>(s.card_evals) / static_cast<double>(s.pclk_edges + s.eclk_edges);
    }
}
// One simulation per process: exactly one iteration, timed as wall time.
BENCHMARK(default_scenario_traces_off)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

int sc_main(int argc, char* argv[]) {
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
