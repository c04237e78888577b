// Shared by the system tests (label system): one platform simulation per
// process, run on first use and kept for every test of the executable
// (SystemC elaborates once per process; CTest runs each test in its own
// process, so each runs the simulation once). The report is printed so the
// figures can be quoted.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "dsp/kernel_costs.h"
#include "model/c6416/c6416_regs.h"
#include "tb/platform/budget.h"
#include "tb/platform/closed_form.h"
#include "tb/platform/platform.h"
#include "tb/platform/report.h"
#include "tb/platform/scoreboard.h"
#include "tests/support/host/reference_config.h"
#include "tests/support/host/stereo_runner.h"

namespace system_test {

struct system_run {
    std::unique_ptr<platform::platform_top> top;
    platform::scoreboard_report score;
    platform::budget_report budget;
};

inline system_run simulate(const platform::platform_config& config) {
    system_run r;
    r.top = std::make_unique<platform::platform_top>(config);
    r.top->run();
    r.score = platform::score(*r.top);
    r.budget = platform::check_budget(*r.top, r.score);
    platform::print_report(stdout, *r.top, r.score, r.budget);
    std::fflush(stdout);
    return r;
}

inline double ticks_to_ms(simtime::ticks t) {
    return static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1e6);
}

// The closed-form estimate's processing time, taken independently of the
// platform: the same firmware on the same scenario in the host harness (no
// hardware, tests/support/host), its largest pair's modelled cycles plus the capture
// stage's, at the platform's CPU clock (the cost model is the platform's).
inline double host_max_processing_ms(const platform::platform_config& config, int frames) {
    const dsp::control_program_config program = host::program_config(config);
    host::stereo_runner runner(config.scenario, program.pipeline);
    uint64_t max_cycles = 0;
    for (int n = 0; n < frames; ++n) {
        const platform::frame_record record = runner.step(n);
        uint64_t cycles = program.capture_cycles;
        for (int s = 0; s < dsp::stage_count; ++s) cycles += record.out.stage_cycles[s];
        max_cycles = std::max(max_cycles, cycles);
    }
    return 1e3 * static_cast<double>(max_cycles) / static_cast<double>(config.dsk.cpu_hz);
}

// The closed-form capture time of the configuration (DSK v1 card CECTL).
inline platform::capture_figures closed_form_capture(const platform::platform_top& top) {
    return platform::capture_closed_form(top);
}

// The firmware's SDRAM lines per pair on the bus (docs/budget.md).
inline platform::traffic_figures closed_form_traffic(const platform::platform_top& top) {
    const platform::platform_config& c = top.config();
    return platform::firmware_traffic(
        c.profile.active_cols, c.profile.active_rows,
        c.dsk.version >= 2 ? c6416::emifa::dsk_cectl_card_v2 : c6416::emifa::dsk_cectl_card_v1,
        top.engine().config());
}

}  // namespace system_test
