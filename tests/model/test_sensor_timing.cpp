// Frame timing of the sensor core, measured from its pins: pixel clocks per
// line, lines per frame, VSYNC / HREF widths, frame period, data invalid while
// OE is low, restart after OE, and the step rate of the core.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include "model/sensor/sensor_core.h"
#include "sensor_test_util.h"

using namespace sensor;
using namespace sensor_test;

namespace {

struct measured {
    std::vector<uint64_t> vsync_rise, vsync_fall, href_rise, href_fall;
};

measured measure(const std::vector<cycle_record>& rec) {
    return {rises(rec, pin_word::vsync_bit), falls(rec, pin_word::vsync_bit),
            rises(rec, pin_word::href_bit), falls(rec, pin_word::href_bit)};
}

// Checks one profile's layout against its pins over `frames` whole frames.
void check_layout(sensor_profile p, int frames) {
    p.extra_delay_probability = 0.0;  // fixed start-up: the run length is known
    pattern_source source(p.active_cols, p.active_rows);
    sensor_config cfg;
    sensor_core core(p, scene::camera_id::right, source, cfg);
    const uint64_t oe_rise = 3;
    const auto rec = run(core,
                         oe_rise + core.profile().startup_latency_pclks +
                             static_cast<uint64_t>(p.frame_pclks()) * frames + 5,
                         oe_from(oe_rise));
    const measured m = measure(rec);
    ASSERT_EQ(m.vsync_rise.size(), static_cast<size_t>(frames + 1)) << p.name;
    ASSERT_FALSE(core.starts().empty());
    const uint64_t first_frame = oe_rise + static_cast<uint64_t>(core.starts()[0].latency_pclks);
    EXPECT_EQ(m.vsync_rise[0], first_frame) << p.name;

    for (int f = 0; f < frames; ++f) {
        // Frame period: VSYNC rise to VSYNC rise, in clocks and in ticks.
        EXPECT_EQ(m.vsync_rise[f + 1] - m.vsync_rise[f], static_cast<uint64_t>(p.frame_pclks()));
        // VSYNC is driven at falling edges: floor((2n + 1) N / 2D) ticks.
        const auto fall_tick = [&](uint64_t n) {
            const __int128 num = static_cast<__int128>(2 * n + 1) * p.pclk_period().num;
            return static_cast<simtime::ticks>(num / (2 * p.pclk_period().den));
        };
        EXPECT_EQ(rec[m.vsync_rise[f + 1]].fall - rec[m.vsync_rise[f]].fall,
                  fall_tick(m.vsync_rise[f + 1]) - fall_tick(m.vsync_rise[f]));
        EXPECT_EQ(m.vsync_fall[f] - m.vsync_rise[f], static_cast<uint64_t>(p.vsync_pclks));
    }
    // HREF: readout_rows pulses per frame, each readout_cols clocks wide,
    // line_pclks apart, the first at first_row_line lines + href_start after VSYNC.
    for (int f = 0; f < frames; ++f) {
        std::vector<uint64_t> frame_hrefs;
        for (size_t i = 0; i < m.href_rise.size(); ++i)
            if (m.href_rise[i] >= m.vsync_rise[f] && m.href_rise[i] < m.vsync_rise[f + 1])
                frame_hrefs.push_back(i);
        ASSERT_EQ(frame_hrefs.size(), static_cast<size_t>(p.readout_rows())) << p.name;
        EXPECT_EQ(m.href_rise[frame_hrefs[0]] - m.vsync_rise[f],
                  static_cast<uint64_t>(p.first_row_line) * p.line_pclks + p.href_start);
        for (size_t k = 0; k < frame_hrefs.size(); ++k) {
            const size_t i = frame_hrefs[k];
            EXPECT_EQ(m.href_fall[i] - m.href_rise[i], static_cast<uint64_t>(p.readout_cols()));
            if (k > 0) {
                EXPECT_EQ(m.href_rise[i] - m.href_rise[i - 1], static_cast<uint64_t>(p.line_pclks));
            }
        }
    }
    // VALID from the first frame on; VSYNC never overlaps HREF.
    for (uint64_t n = 0; n < rec.size(); ++n) {
        EXPECT_EQ(rec[n].pins.valid(), n >= first_frame) << n;
        if (rec[n].pins.vsync()) {
            ASSERT_FALSE(rec[n].pins.href()) << n;
        }
    }
}

}  // namespace

TEST(SensorTiming, SmallProfileLayoutOnThePins) {
    check_layout(small_profile(), 3);
}

// docs/design-brief.md: 800 clocks per line (656 with HREF: 16 dark + 640 active), 525
// lines, 488 readout rows, frame = 420,000 clocks = 441,000,000 ticks = 24.5 ms.
TEST(SensorTiming, DefaultProfileIsExactly24p5Milliseconds) {
    const sensor_profile p = default_profile();
    EXPECT_EQ(p.readout_cols(), 656);
    EXPECT_EQ(p.readout_rows(), 488);
    EXPECT_EQ(p.frame_pclks(), 420000);
    check_layout(p, 2);

    pattern_source source(p.active_cols, p.active_rows);
    sensor_core core(p, scene::camera_id::left, source);
    const auto t0 = std::chrono::steady_clock::now();
    const uint64_t cycles = 1600 + 1600 + 2 * 420000 + 10;  // latency + the largest extra delay
    const auto rec = run(core, cycles, oe_from(0));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto vs = rises(rec, pin_word::vsync_bit);
    ASSERT_GE(vs.size(), 2u);
    const simtime::ticks period = rec[vs[1]].rise - rec[vs[0]].rise;
    EXPECT_EQ(period, 441000000);
    EXPECT_EQ(simtime::to_fs(rec[vs[1]].fall) - simtime::to_fs(rec[vs[0]].fall), 24500000000000);
    // Truth agrees with the pins.
    ASSERT_GE(core.truth().size(), 2u);
    EXPECT_EQ(core.truth()[0].start_cycle, vs[0]);
    EXPECT_EQ(core.truth()[1].vsync_tick - core.truth()[0].vsync_tick, 441000000);
    EXPECT_EQ(core.truth()[0].lines_with_href, 488);
    std::printf(
        "default profile: frame period %lld ticks = %.6f ms; %.1f ns per step (recording)\n",
        static_cast<long long>(period), period / 18e6, s * 1e9 / cycles);
}

// Raw step rate without recording (what the RTL island pays per clock).
TEST(SensorTiming, CoreStepRate) {
    const sensor_profile p = default_profile();
    pattern_source source(p.active_cols, p.active_rows);
    sensor_core core(p, scene::camera_id::left, source);
    const uint64_t cycles = 3 * 420000;
    uint32_t checksum = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (uint64_t i = 0; i < cycles; ++i) checksum += core.step(true).bits;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(core.truth().size(), 3u);
    std::printf("core: %.2f ns per pixel clock, %.1f ms per 24.5 ms frame (checksum %u)\n",
                s * 1e9 / cycles, s * 1e3 / 3, checksum);
    RecordProperty("ns_per_step", std::to_string(s * 1e9 / cycles));
}

TEST(SensorTiming, DataInvalidWhileOeLowAndRestartAfterLatency) {
    const sensor_profile p = small_profile();
    pattern_source source(p.active_cols, p.active_rows);
    sensor_core core(p, scene::camera_id::left, source);
    // OE high at 10, low at 1000 (mid frame 0), high again at 1500.
    const auto oe = [](uint64_t n) { return (n >= 10 && n < 1000) || n >= 1500; };
    const auto rec = run(core, 4000, oe);
    for (uint64_t n = 0; n < rec.size(); ++n) {
        const bool stopped = n < 10 + 7 || (n >= 1000 && n < 1500 + 7);
        if (stopped) {
            ASSERT_EQ(rec[n].pins.bits, 0) << "cycle " << n << ": all outputs 0 while stopped";
        } else {
            ASSERT_TRUE(rec[n].pins.valid()) << n;
        }
    }
    const auto vs = rises(rec, pin_word::vsync_bit);
    ASSERT_GE(vs.size(), 2u);
    EXPECT_EQ(vs[0], 17u);
    EXPECT_EQ(vs[1], 1507u) << "the frame timing restarts latency clocks after OE rises again";
    ASSERT_EQ(core.starts().size(), 2u);
    EXPECT_EQ(core.starts()[1].oe_cycle, 1500u);
    ASSERT_GE(core.truth().size(), 2u);
    EXPECT_FALSE(core.truth()[0].complete) << "OE cut frame 0 short";
    // Scene frames follow time across a restart: the frame at clock 1507
    // falls in slot round(1507 / 1200) = 1.
    EXPECT_EQ(core.truth()[1].scene_frame, 1u) << "scene frames go on across a restart";
    EXPECT_TRUE(core.truth()[1].complete);
    // PCLK never stops: every cycle has a rising edge one period after the last.
    for (uint64_t n = 1; n < rec.size(); ++n) ASSERT_EQ(rec[n].rise - rec[n - 1].rise, 1050);
}

// A profile with an off-grid master clock (27 MHz / 2 = 13.5 MHz pclk): each
// edge is exact rational arithmetic, the frame period in ticks is the closed form.
TEST(SensorTiming, OffGridPixelClockEdgesAreExact) {
    sensor_profile p = small_profile();
    p.mclk_period = simtime::period_of_hz(27000000);
    p.mclk_per_pclk = 2;
    pattern_source source(p.active_cols, p.active_rows);
    sensor_core core(p, scene::camera_id::left, source);
    const auto rec = run(core, 5000, oe_from(0));
    for (uint64_t n = 0; n < rec.size(); ++n) {
        // rise(n) = floor(n * 4000 / 3), fall = floor((2n + 1) * 4000 / 6)
        ASSERT_EQ(rec[n].rise, static_cast<int64_t>(n) * 4000 / 3) << n;
        ASSERT_EQ(rec[n].fall, static_cast<int64_t>(2 * n + 1) * 4000 / 6) << n;
    }
}
