// The CPU's time in the C6416 model: charge(stage, n) moves simulated time
// to the CPU edge n cycles on, every edge at its exact tick rounded once to
// femtoseconds (600 MHz: 30 ticks per cycle), for the three DSK profiles and
// an off-grid 850 MHz clock (360/17 ticks), also after 100,000 single-cycle
// charges (accumulating the rounded period would drift); and the "CPU too
// slow" hook scales cycles charged after its onset by num / den, rounded up,
// splitting a charge that straddles the onset. Four chips, one simulation.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <vector>

#include "c6416_test_util.h"
#include "model/c6416/c6416_sc.h"

using namespace c6416_test;

namespace {

struct cpu_run {
    int64_t hz = 0;
    std::vector<std::pair<uint64_t, int64_t>> checkpoints;  // (expected edge, fs observed)
};

constexpr uint64_t single_charges = 100000;

}  // namespace

TEST(C6416CpuSc, ChargeCyclesAdvancesTimeExactlyAndTheSlowCpuHookScalesIt) {
    const c6416::dsk_profile profiles[4] = {c6416::dsk_v1(), c6416::dsk_v2(), c6416::dsk_v3(),
                                            c6416::dsk_custom(850000000, 125000000)};
    std::vector<std::unique_ptr<c6416::c6416_sc>> chips;
    std::vector<cpu_run> runs(4);
    for (int i = 0; i < 4; ++i) {
        c6416::c6416_config config;
        config.dsk = profiles[i];
        chips.push_back(
            std::make_unique<c6416::c6416_sc>(("chip_" + std::to_string(i)).c_str(), config));
        runs[i].hz = profiles[i].cpu_hz;
        cpu_run& run = runs[i];
        chips[i]->set_firmware([&run](c6416::cpu_port& h) {
            uint64_t edge = 0;
            auto charge = [&](uint64_t n) {
                h.charge(stage::preprocess, n);
                edge += n;
                run.checkpoints.push_back({edge, fs_of(sc_core::sc_time_stamp())});
            };
            charge(1);
            charge(1000);
            for (uint64_t k = 0; k < single_charges; ++k) h.charge(stage::track, 1);
            edge += single_charges;
            run.checkpoints.push_back({edge, fs_of(sc_core::sc_time_stamp())});
        });
    }
    // The slow-CPU fault on the v1 chip: x 3/2 from edge 101,501 + 400.
    const uint64_t onset_edge = 1 + 1000 + single_charges + 400;
    chips[0]->set_cycle_scale(3, 2, chips[0]->time_of_cpu_cycle(onset_edge));
    std::vector<int64_t> scaled_fs;
    chips[0]->set_firmware([&runs, &scaled_fs](c6416::cpu_port& h) {
        cpu_run& run = runs[0];
        uint64_t edge = 0;
        h.charge(stage::preprocess, 1);
        h.charge(stage::preprocess, 1000);
        for (uint64_t k = 0; k < single_charges; ++k) h.charge(stage::track, 1);
        edge = 1 + 1000 + single_charges;
        run.checkpoints.push_back({edge, fs_of(sc_core::sc_time_stamp())});
        h.charge(stage::detect, 1000);  // 400 before the onset, 600 after -> 900
        scaled_fs.push_back(fs_of(sc_core::sc_time_stamp()));
        h.charge(stage::detect, 1001);  // -> 1502 (1501.5 rounded up)
        scaled_fs.push_back(fs_of(sc_core::sc_time_stamp()));
    });
    sc_core::sc_start(us(1000.0));

    for (int i = 1; i < 4; ++i) {
        ASSERT_EQ(runs[i].checkpoints.size(), 3u);
        for (const auto& [edge, got] : runs[i].checkpoints) {
            EXPECT_EQ(got, cpu_edge_fs(edge, runs[i].hz)) << profiles[i].name << " edge " << edge;
        }
    }
    // 600 MHz: one cycle is 30 ticks = 1,666,666.67 fs -> 1,666,667 fs.
    ASSERT_EQ(runs[0].checkpoints.size(), 1u);
    EXPECT_EQ(runs[0].checkpoints[0].second, cpu_edge_fs(101001, 600000000));
    EXPECT_EQ(cpu_edge_fs(1, 600000000), 1666667);
    EXPECT_EQ(fs_of(chips[0]->time_of_cpu_cycle(1)), 1666667);
    ASSERT_EQ(scaled_fs.size(), 2u);
    EXPECT_EQ(scaled_fs[0], cpu_edge_fs(101001 + 400 + 900, 600000000));
    EXPECT_EQ(scaled_fs[1], cpu_edge_fs(101001 + 400 + 900 + 1502, 600000000));
    EXPECT_EQ(chips[0]->charged_cycles(stage::detect), 900u + 400u + 1502u);
    EXPECT_EQ(chips[0]->charged_cycles(stage::track), single_charges);
    EXPECT_EQ(chips[0]->charged_cycles_total(), 101001u + 2802u);
    EXPECT_EQ(fs_of(chips[0]->cpu_busy_time()), cpu_edge_fs(101001 + 2802, 600000000));

    // Accumulating the rounded 720 MHz period (1,388,889 fs) would be off by
    // 0.11 fs per cycle: 11 fs after 100,000 single charges.
    const int64_t v2_end = runs[1].checkpoints.back().second;
    const int64_t accumulated = static_cast<int64_t>(runs[1].checkpoints.back().first) * 1388889;
    EXPECT_NE(v2_end, accumulated);
    std::printf(
        "v2 after %llu cycles: %lld fs (accumulated rounded period: %lld fs); "
        "850 MHz edge 101001 at %lld fs\n",
        static_cast<unsigned long long>(runs[1].checkpoints.back().first),
        static_cast<long long>(v2_end), static_cast<long long>(accumulated),
        static_cast<long long>(runs[3].checkpoints.back().second));
}
