// The verilated card alone on the default scenario's own inputs (issue 14;
// docs/performance.md "The card alone"): how fast the platform could run if
// everything but the card's evaluation cost nothing.
//
// A child runs the default scenario in the fast arrangement (traces off)
// while this program records every evaluation of its card (bench/card_trace.h):
// the linker routes the fast island's calls of Vcard::eval_step and of
// card_eval's generated regions through the wrappers below
// (bench/CMakeLists.txt, --wrap). The same child then replays the records
// into a fresh card: once checking every output against the run, then
// STEREOSIM_BENCH_REPS times (default 5) timed, each followed by a replay
// that only writes the inputs (the replay's own cost). The replay's calls
// pass through the wrappers too (about 1 % of its instructions). Other
// children run the same scenario without recording, before and after, for
// the platform's own time.
// STEREOSIM_BENCH_FRAMES sets the periods (default 4; a record is 28 bytes,
// 2.8 M evaluations in the first period and 3.1 M in each later one). The
// recording must hold as many evaluations as the island counted, and the
// checking replay compares the outputs before every evaluation and after
// the last.
//
// Counters (medians):
//   platform_pairs_per_s  the whole co-simulation, frame pairs per wall second
//   card_pairs_per_s      the card's evaluations alone per wall second: the
//                         replay's time less that of a replay that only writes
//                         the inputs
//   card_pairs_per_s_best the same from the fastest replays (the least disturbed)
//   card_share            the card's time over the platform's. About 80 % of the
//                         card's instructions are its generated RTL logic, out
//                         of any testbench change's reach; the rest is
//                         Verilator's scheduling as card_eval drives it.
//   card_share_gross      the replay's whole time over the platform's: the
//                         input writes overlap the evaluation on an out-of-order
//                         core, so the card's true share lies between the two
//   evals_per_period      the card's evaluations per 24.5 ms period
//   replay_ns_per_eval    the replay's wall time per evaluation
//   inputs_only_ns_per_eval  the same replay writing the inputs and evaluating
//                         nothing: the replay's own part of replay_ns_per_eval
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <systemc>
#include <vector>

#include "bench/arrangement_runs.h"
#include "bench/bench_support.h"
#include "bench/card_trace.h"
#include "bench/child_run.h"
#include "bench/sc_benchmark_main.h"
#include "tb/platform/platform.h"

// ---- the recorder: the wrapped calls of the fast island -------------------------------------
namespace {

std::vector<card_trace::record>* g_trace = nullptr;  // recording while set
Vcard* g_card = nullptr;                             // the recorded card
// Inside Verilator's own eval, already recorded: its _eval calls the trigger
// function in another object file, so through the wrapper too.
bool g_in_full_eval = false;
bool g_region_recorded = false;  // card_eval ran the input region: its record is taken

void record(Vcard* card, uint32_t kind) {
    g_card = card;
    g_trace->push_back(card_trace::record_of(*card, kind));
}

}  // namespace

void real_eval_step(Vcard* self) asm("__real__ZN5Vcard9eval_stepEv");
void real_eval_ico(Vcard___024root* r) asm(
    "__real__Z26Vcard___024root___eval_icoP15Vcard___024root");
void real_eval_triggers(Vcard___024root* r) asm(
    "__real__Z36Vcard___024root___eval_triggers__actP15Vcard___024root");

void wrap_eval_step(Vcard* self) asm("__wrap__ZN5Vcard9eval_stepEv");
void wrap_eval_ico(Vcard___024root* r) asm(
    "__wrap__Z26Vcard___024root___eval_icoP15Vcard___024root");
void wrap_eval_triggers(Vcard___024root* r) asm(
    "__wrap__Z36Vcard___024root___eval_triggers__actP15Vcard___024root");

void wrap_eval_step(Vcard* self) {
    if (!g_trace) return real_eval_step(self);
    record(self, card_trace::bit_full_eval);
    g_in_full_eval = true;
    real_eval_step(self);
    g_in_full_eval = false;
}

// card_eval runs the input region first, then the triggers.
void wrap_eval_ico(Vcard___024root* r) {
    if (g_trace && !g_in_full_eval) {
        record(r->vlSymsp->__Vm_modelp, card_trace::bit_input_region);
        g_region_recorded = true;
    }
    real_eval_ico(r);
}

// card_eval's first trigger evaluation starts an evaluation; it evaluates
// the triggers again within one only after an NBA pass that moved a reset
// synchronizer's output (card_eval's own test, internal_triggers_steady),
// and every evaluation ends with them steady.
void wrap_eval_triggers(Vcard___024root* r) {
    if (g_trace && !g_in_full_eval) {
        if (g_region_recorded) {
            g_region_recorded = false;
        } else if (fast::internal_triggers_steady(*r)) {
            record(r->vlSymsp->__Vm_modelp, 0);
        }
    }
    real_eval_triggers(r);
}

// ---- the benchmark -----------------------------------------------------------------------
namespace {

struct replay_figures {
    double record_run_wall_s = 0.0;  // the platform while recording (not a figure of merit)
    double replay_wall_s = 0.0;      // median of the timed replays
    double replay_best_s = 0.0;      // the fastest: the least disturbed by other load
    double inputs_only_s = 0.0;      // median of the replays that evaluate nothing
    double inputs_only_best_s = 0.0;
    double evals = 0.0;
    bool recorded_every_eval = false;  // as many records as the island counted evaluations
    bool outputs_match = false;
};

// The trace's reservation: 2.8 M evaluations in the first period, 3.1 M in
// each later one (measured), with room to spare.
constexpr size_t records_per_period_bound = 3400000;

// The recorded run: as run_arrangement's fast one, traces off.
platform::platform_config default_config(int frames) {
    platform::platform_config config;
    config.arrangement = platform::arrangement_kind::fast;
    config.hash_pins = false;
    config.frames = frames;
    return config;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The platform's own time: the same run without recording, in a child
// (bench/arrangement_runs.h).
std::optional<double> platform_wall(int frames) {
    const std::optional<bench::run_time> r =
        bench::run_arrangement(platform::arrangement_kind::fast, frames, false);
    if (!r) return std::nullopt;
    return r->wall;
}

// Not inlined, so that callgrind can count each kind of replay alone:
// --toggle-collect='*replay_into<(card_trace::replay_mode)1>*' (timed) or
// ...)2>*' (inputs only).
template <card_trace::replay_mode mode>
__attribute__((noinline)) void replay_into(Vcard& card,
                                           const std::vector<card_trace::record>& trace) {
    card_trace::replay<mode>(card, trace);
}

// Wall seconds of one replay of `trace` into a fresh card.
template <card_trace::replay_mode mode>
double timed_replay(const std::vector<card_trace::record>& trace) {
    VerilatedContext context;
    Vcard card(&context, "card");
    const auto t0 = std::chrono::steady_clock::now();
    replay_into<mode>(card, trace);
    const double wall = seconds_since(t0);
    card.final();
    return wall;
}

std::optional<replay_figures> record_and_replay(int frames, int reps) {
    return bench::in_child<replay_figures>([=]() -> std::optional<replay_figures> {
        std::vector<card_trace::record> trace;
        trace.reserve(static_cast<size_t>(frames) * records_per_period_bound);
        replay_figures f;
        {
            g_trace = &trace;  // from the card's construction: its reset is recorded too
            platform::platform_top top(default_config(frames));
            const auto t0 = std::chrono::steady_clock::now();
            top.run();
            f.record_run_wall_s = seconds_since(t0);
            // reset_card's three evaluations are Verilator's, not the island's.
            const uint64_t island_evals = top.cycle_island().stats().card_evals + 3;
            f.recorded_every_eval = g_card && trace.size() == island_evals;
            if (!f.recorded_every_eval) {
                g_trace = nullptr;
                std::printf("  %zu evaluations recorded, %llu made\n", trace.size(),
                            static_cast<unsigned long long>(island_evals));
                std::fflush(stdout);
                return f;
            }
            f.evals = static_cast<double>(trace.size());
            record(g_card, card_trace::bit_end_of_run);  // the last evaluation's outputs
            g_trace = nullptr;
        }
        {
            VerilatedContext context;
            Vcard card(&context, "card");
            const size_t at = card_trace::replay<card_trace::replay_mode::verify>(card, trace);
            f.outputs_match = at == trace.size();
            if (!f.outputs_match) {
                std::printf("  the replay left the run at evaluation %zu of %zu\n", at,
                            trace.size());
                std::fflush(stdout);
            }
            card.final();
        }
        if (!f.outputs_match) return f;
        std::vector<double> walls, inputs_only;
        for (int rep = 0; rep < reps; ++rep) {
            walls.push_back(timed_replay<card_trace::replay_mode::timed>(trace));
            inputs_only.push_back(timed_replay<card_trace::replay_mode::inputs_only>(trace));
        }
        f.replay_wall_s = bench::median(walls);
        f.replay_best_s = *std::min_element(walls.begin(), walls.end());
        f.inputs_only_s = bench::median(inputs_only);
        f.inputs_only_best_s = *std::min_element(inputs_only.begin(), inputs_only.end());
        return f;
    });
}

void card_alone_default_scenario(benchmark::State& state) {
    const int frames = bench::env_int("STEREOSIM_BENCH_FRAMES", 4);
    const int reps = bench::env_int("STEREOSIM_BENCH_REPS", 5);
    for (auto _ : state) {
        const std::optional<double> before = platform_wall(frames);
        const std::optional<replay_figures> r = record_and_replay(frames, reps);
        const std::optional<double> after = platform_wall(frames);
        if (!before || !after || !r) {
            state.SkipWithError("a child simulation failed");
            return;
        }
        if (!r->recorded_every_eval) {
            state.SkipWithError("the recording missed evaluations of the card");
            return;
        }
        if (!r->outputs_match) {
            state.SkipWithError("the replay does not reproduce the run's outputs");
            return;
        }
        const double platform_s = bench::median({*before, *after});
        std::printf(
            "  platform %.3f s and %.3f s, recording run %.3f s, replay %.3f s (median of %d, "
            "fastest %.3f s; inputs only %.3f s)\n",
            *before, *after, r->record_run_wall_s, r->replay_wall_s, reps, r->replay_best_s,
            r->inputs_only_s);
        state.counters["frames"] = frames;
        state.counters["platform_pairs_per_s"] = frames / platform_s;
        // The card's own time: the replay less its own writing of the inputs.
        const double card_s = r->replay_wall_s - r->inputs_only_s;
        state.counters["card_pairs_per_s"] = frames / card_s;
        state.counters["card_pairs_per_s_best"] =
            frames / (r->replay_best_s - r->inputs_only_best_s);
        state.counters["card_share"] = card_s / platform_s;
        state.counters["card_share_gross"] = r->replay_wall_s / platform_s;
        state.counters["evals_per_period"] = r->evals / frames;
        state.counters["replay_ns_per_eval"] = 1e9 * r->replay_wall_s / r->evals;
        state.counters["inputs_only_ns_per_eval"] = 1e9 * r->inputs_only_s / r->evals;
    }
}
BENCHMARK(card_alone_default_scenario)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

int sc_main(int argc, char* argv[]) {
    return bench::run_sc_benchmarks(argc, argv);
}
