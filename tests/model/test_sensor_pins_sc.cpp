// The SystemC pin module and the plain core alone give identical pin sequences,
// to the femtosecond: two sensors on one tick-exact master clock, OE restarts,
// seeded start-up delays, noise and faults (the proof that the fast island's
// sensor is cycle-accurate). Also: a 3-line start skew puts the two sensors'
// VSYNC edges exactly 3 line periods apart on the pins.
#include <gtest/gtest.h>

#include <cstdio>
#include <systemc>

#include "model/sensor/sensor_sc.h"
#include "sensor_sc_bench.h"
#include "sensor_test_util.h"

using namespace sensor;
using namespace sensor_test;

namespace {

constexpr uint64_t cycles = 9000;  // 7.5 frames of the small profile

bool oe_level(uint64_t n) {
    return (n >= 5 && n < 3000) || (n >= 3100 && n < 3150) || n >= 3400;
}

sensor_profile bench_profile() {
    sensor_profile p = small_profile();
    p.extra_delay_probability = 0.25;  // seeded: some starts out of step
    return p;
}

sensor_config left_config() {
    sensor_config c;
    c.seed = 3;
    c.noise = true;
    return c;
}

sensor_config right_config() {
    sensor_config c;
    c.seed = 4;
    return c;
}

void add_left_faults(sensor_core& core) {
    core.add_fault(fault::href_glitch(fault_trigger::at_frame(1, 7, 39), 4));
    core.add_fault(fault::stuck_data_bit(fault_trigger::at_time(2500 * 1050 + 300), 6, true));
    core.add_fault(fault::dark_leak(fault_trigger::at_frame(3), 180));
    core.add_fault(fault::dropped_line(fault_trigger::at_frame(4, 12)));
}

void add_right_faults(sensor_core& core) {
    core.add_fault(fault::start_skew(fault_trigger::at_frame(1), 3, 0, core.profile().line_pclks));
}

struct bench : sc_core::sc_module {
    sc_core::sc_signal<bool> mclk{"mclk"}, oe{"oe"};
    sc_core::sc_signal<bool> pclk_l{"pclk_l"}, vsync_l{"vsync_l"}, href_l{"href_l"},
        valid_l{"valid_l"}, fodd_l{"fodd_l"};
    sc_core::sc_signal<bool> pclk_r{"pclk_r"}, vsync_r{"vsync_r"}, href_r{"href_r"},
        valid_r{"valid_r"}, fodd_r{"fodd_r"};
    sc_core::sc_signal<uint32_t> data_l{"data_l"}, data_r{"data_r"};
    pattern_source source_l, source_r;
    tick_clock_sc master;
    sensor_sc left, right;
    oe_driver driver;
    pin_monitor mon_l, mon_r;

    explicit bench(sc_core::sc_module_name name)
        : sc_core::sc_module(name),
          source_l(16, 12),
          source_r(16, 12),
          master("master", simtime::tick_clock(bench_profile().mclk_period)),
          left("left", bench_profile(), scene::camera_id::left, source_l, left_config()),
          right("right", bench_profile(), scene::camera_id::right, source_r, right_config()),
          driver("driver", simtime::tick_clock(bench_profile().pclk_period()), cycles, oe_level),
          mon_l("mon_l"),
          mon_r("mon_r") {
        master.clk(mclk);
        driver.oe(oe);
        for (auto [s, pc, vs, hr, va, fo, da, mon] :
             {std::tuple{&left, &pclk_l, &vsync_l, &href_l, &valid_l, &fodd_l, &data_l, &mon_l},
              std::tuple{&right, &pclk_r, &vsync_r, &href_r, &valid_r, &fodd_r, &data_r, &mon_r}}) {
            s->mclk(mclk);
            s->oe(oe);
            s->pclk(*pc);
            s->vsync(*vs);
            s->href(*hr);
            s->valid(*va);
            s->fodd(*fo);
            s->data(*da);
            mon->pclk(*pc);
            mon->vsync(*vs);
            mon->href(*hr);
            mon->valid(*va);
            mon->fodd(*fo);
            mon->data(*da);
        }
        add_left_faults(left.core());
        add_right_faults(right.core());
    }
};

std::vector<pin_event> reference(scene::camera_id cam, const sensor_config& cfg,
                                 void (*faults)(sensor_core&)) {
    pattern_source source(16, 12);
    sensor_core core(bench_profile(), cam, source, cfg);
    faults(core);
    return core_events(core, cycles, oe_level);
}

std::vector<int64_t> vsync_rise_times(const std::vector<pin_event>& ev) {
    std::vector<int64_t> out;
    bool prev = false;
    for (const pin_event& e : ev) {
        const bool v = (e.pins & pin_word::vsync_bit) != 0;
        if (v && !prev) out.push_back(e.fs);
        prev = v;
    }
    return out;
}

}  // namespace

TEST(SensorPinsSc, PinModuleEqualsCoreAloneToTheFemtosecond) {
    bench b("bench");
    const std::vector<pin_event> ref_l =
        reference(scene::camera_id::left, left_config(), add_left_faults);
    const std::vector<pin_event> ref_r =
        reference(scene::camera_id::right, right_config(), add_right_faults);
    // Run to just past the last reference edge.
    sc_core::sc_start(
        sc_core::sc_time::from_value(static_cast<sc_dt::uint64>(ref_l.back().fs + 1)));
    ASSERT_GE(b.mon_l.events.size(), ref_l.size());
    b.mon_l.events.resize(ref_l.size());
    b.mon_r.events.resize(std::min(b.mon_r.events.size(), ref_r.size()));
    EXPECT_EQ(first_difference(b.mon_l.events, ref_l), -1);
    EXPECT_EQ(first_difference(b.mon_r.events, ref_r), -1);
    std::printf("left: %zu pin events identical; right: %zu identical; starts: left extra",
                ref_l.size(), ref_r.size());
    for (const start_record& s : b.left.core().starts()) std::printf(" %d", s.extra_pclks);
    std::printf(", right extra");
    for (const start_record& s : b.right.core().starts()) std::printf(" %d", s.extra_pclks);
    std::printf("\n");

    // The sensors really were exercised: several frames, a restart, faults.
    EXPECT_EQ(b.left.core().starts().size(), 3u);
    EXPECT_GE(b.left.core().truth().size(), 5u);

    // 3-line skew at the right sensor's frame 1: from then on its VSYNC rises
    // exactly 3 line periods (+ the two start-up draws' difference) after the left's.
    const auto vl = vsync_rise_times(b.mon_l.events), vr = vsync_rise_times(b.mon_r.events);
    const auto& tl = b.left.core().truth();
    const auto& tr = b.right.core().truth();
    ASSERT_GE(tr.size(), 2u);
    EXPECT_EQ(tr[1].skew_before_pclks, 120);
    const int extra_diff =
        b.right.core().starts()[0].extra_pclks - b.left.core().starts()[0].extra_pclks;
    const int64_t t_l = simtime::to_fs(tl[1].vsync_tick);
    const int64_t t_r = simtime::to_fs(tr[1].vsync_tick);
    EXPECT_EQ(t_r - t_l, simtime::to_fs(tl[1].vsync_tick + (3 * 40 + extra_diff) * 1050) - t_l);
    EXPECT_NE(std::find(vl.begin(), vl.end(), t_l), vl.end()) << "truth time is a pin edge";
    EXPECT_NE(std::find(vr.begin(), vr.end(), t_r), vr.end()) << "truth time is a pin edge";
    std::printf("frame 1 VSYNC: left %lld fs, right %lld fs, apart %lld fs = 3 lines + %d clocks\n",
                static_cast<long long>(t_l), static_cast<long long>(t_r),
                static_cast<long long>(t_r - t_l), extra_diff);
}
