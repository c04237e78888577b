// Pixel-clock drift in the SystemC pin module: the master clock is an
// off-grid 27 MHz crystal (2000/3 ticks) divided by 2, and from a time in the
// middle of a line the sensor leaves it for its own -250 ppm oscillator. The
// pin module's events equal the core's to the femtosecond before and after,
// and after the onset its PCLK edges are no longer master-clock edges.
#include <gtest/gtest.h>

#include <cstdio>
#include <systemc>

#include "model/sensor/sensor_sc.h"
#include "sensor_sc_bench.h"
#include "sensor_test_util.h"

using namespace sensor;
using namespace sensor_test;

namespace {

constexpr uint64_t cycles = 6000;
constexpr uint64_t onset_cycle = 1700;  // frame 1, line 12, mid-line

sensor_profile drift_profile() {
    sensor_profile p = small_profile();
    p.mclk_period = simtime::period_of_hz(27000000);
    p.mclk_per_pclk = 2;
    return p;
}

bool oe_level(uint64_t n) {
    return n >= 3;
}

fault drift_fault() {
    // 100 ticks before the onset clock's rising edge: acts from that clock.
    const simtime::tick_clock pclk(drift_profile().pclk_period());
    return fault::pclk_drift(fault_trigger::at_time(pclk.rise(onset_cycle) - 100), -250);
}

struct bench : sc_core::sc_module {
    sc_core::sc_signal<bool> mclk{"mclk"}, oe{"oe"}, pclk{"pclk"}, vsync{"vsync"}, href{"href"},
        valid{"valid"}, fodd{"fodd"};
    sc_core::sc_signal<uint32_t> data{"data"};
    pattern_source source;
    tick_clock_sc master;
    sensor_sc cam;
    oe_driver driver;
    pin_monitor mon;

    explicit bench(sc_core::sc_module_name name)
        : sc_core::sc_module(name),
          source(16, 12),
          master("master", simtime::tick_clock(drift_profile().mclk_period)),
          cam("cam", drift_profile(), scene::camera_id::left, source),
          driver("driver", simtime::tick_clock(drift_profile().pclk_period()), cycles, oe_level),
          mon("mon") {
        master.clk(mclk);
        driver.oe(oe);
        cam.mclk(mclk);
        cam.oe(oe);
        cam.pclk(pclk);
        cam.vsync(vsync);
        cam.href(href);
        cam.valid(valid);
        cam.fodd(fodd);
        cam.data(data);
        mon.pclk(pclk);
        mon.vsync(vsync);
        mon.href(href);
        mon.valid(valid);
        mon.fodd(fodd);
        mon.data(data);
        cam.core().add_fault(drift_fault());
    }
};

}  // namespace

TEST(SensorDriftSc, OwnOscillatorEdgesMatchTheCoreExactly) {
    bench b("bench");
    pattern_source source(16, 12);
    sensor_core core(drift_profile(), scene::camera_id::left, source);
    core.add_fault(drift_fault());
    const std::vector<pin_event> ref = core_events(core, cycles, oe_level);
    sc_core::sc_start(sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(ref.back().fs + 1)));
    ASSERT_GE(b.mon.events.size(), ref.size());
    b.mon.events.resize(ref.size());
    EXPECT_EQ(first_difference(b.mon.events, ref), -1);
    EXPECT_FALSE(b.cam.core().on_master_clock());

    // Before the onset every PCLK rise is a master-clock rise (every 2nd);
    // after it they drift away: at the end the sensor is behind the master's
    // grid by floor(j * P * 250e-6) ticks for j clocks since the onset.
    const simtime::tick_clock master(drift_profile().mclk_period);
    int64_t on_grid_before = 0, on_grid_after = 0;
    for (size_t i = 0; i < ref.size(); i += 2) {
        const uint64_t n = i / 2;
        const bool on_grid = ref[i].fs == simtime::to_fs(master.rise(2 * n));
        (n < onset_cycle ? on_grid_before : on_grid_after) += on_grid;
    }
    EXPECT_EQ(on_grid_before, static_cast<int64_t>(onset_cycle));
    const int64_t j = static_cast<int64_t>(cycles - 1 - onset_cycle);
    const simtime::ticks own =
        master.rise(2 * onset_cycle) + (j * 4000 * (1000000 - 250)) / 3000000;
    EXPECT_EQ(ref[2 * (cycles - 1)].fs, simtime::to_fs(own));
    std::printf(
        "%zu events identical; after the onset %lld of %lld rises still on the master grid; "
        "sensor ahead by %lld ticks after %lld clocks at -250 ppm\n",
        ref.size(), static_cast<long long>(on_grid_after),
        static_cast<long long>(cycles - onset_cycle),
        static_cast<long long>(master.rise(2 * (cycles - 1)) - own), static_cast<long long>(j));
    EXPECT_LT(on_grid_after, static_cast<int64_t>(cycles - onset_cycle) / 2);
}
