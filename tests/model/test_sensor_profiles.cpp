// The named timing profiles: each one's sourced numbers (docs/hardware-facts.md
// section 6, docs/design-brief.md) hold, and a sensor running it shows them on its pins:
// HREF width and period, HREF pulses per frame, VSYNC width, frame period.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "model/sensor/sensor_core.h"
#include "sensor_test_util.h"

using namespace sensor;
using namespace sensor_test;

namespace {

struct pin_figures {
    uint64_t href_width = 0, href_period = 0, hrefs_per_frame = 0, vsync_width = 0;
    uint64_t frame_pclks = 0;
    simtime::ticks frame_ticks = 0;
};

pin_figures measure_one_frame(sensor_profile p) {
    p.extra_delay_probability = 0.0;
    still_source source(p.active_cols, p.active_rows, {128, 128, 128});
    sensor_core core(p, scene::camera_id::left, source);
    const auto rec = run(core, p.startup_latency_pclks + p.frame_pclks() + 2, oe_from(0));
    const auto vs = rises(rec, pin_word::vsync_bit), ve = falls(rec, pin_word::vsync_bit);
    const auto hr = rises(rec, pin_word::href_bit), hf = falls(rec, pin_word::href_bit);
    pin_figures m;
    if (vs.size() < 2 || ve.empty() || hr.size() < 2 || hf.empty()) return m;
    m.href_width = hf[0] - hr[0];
    m.href_period = hr[1] - hr[0];
    for (uint64_t h : hr) m.hrefs_per_frame += h >= vs[0] && h < vs[1];
    m.vsync_width = ve[0] - vs[0];
    m.frame_pclks = vs[1] - vs[0];
    m.frame_ticks = rec[vs[1]].rise - rec[vs[0]].rise;
    return m;
}

void expect_pins_match(const sensor_profile& p) {
    const pin_figures m = measure_one_frame(p);
    EXPECT_EQ(m.href_width, static_cast<uint64_t>(p.readout_cols())) << p.name;
    EXPECT_EQ(m.href_period, static_cast<uint64_t>(p.line_pclks)) << p.name;
    EXPECT_EQ(m.hrefs_per_frame, static_cast<uint64_t>(p.readout_rows())) << p.name;
    EXPECT_EQ(m.vsync_width, static_cast<uint64_t>(p.vsync_pclks)) << p.name;
    EXPECT_EQ(m.frame_pclks, static_cast<uint64_t>(p.frame_pclks())) << p.name;
    const double ms = m.frame_ticks / 18e6;
    std::printf(
        "%-8s line %4d pclk (HREF %3d), frame %3d lines (%3d HREF), VSYNC %4d pclk, "
        "pclk %.4f MHz, frame %lld ticks = %.4f ms = %.3f fps, %s\n",
        p.name.c_str(), p.line_pclks, p.readout_cols(), p.frame_lines, p.readout_rows(),
        p.vsync_pclks, 18e3 * p.pclk_period().den / p.pclk_period().num,
        static_cast<long long>(m.frame_ticks), ms, 1000.0 / ms, dsp::cfa_order_name(p.cfa));
}

}  // namespace

TEST(SensorProfiles, DefaultProfileIsDesignMd) {
    const sensor_profile p = default_profile();
    EXPECT_EQ(p.validate(), "");
    EXPECT_EQ(p.line_pclks, 800);
    EXPECT_EQ(p.dark_cols_left + p.active_cols, 16 + 640);
    EXPECT_EQ(p.frame_lines, 525);
    EXPECT_EQ(p.dark_rows_top + p.active_rows, 8 + 480);
    EXPECT_EQ(p.pclk_period().num, 1050);
    EXPECT_EQ(p.extra_delay_probability, 0.25);
    EXPECT_EQ(p.extra_delay_max_pclks, 2 * 800);
    expect_pins_match(p);
    EXPECT_EQ(measure_one_frame(p).frame_ticks, 441000000);  // 24.5 ms exactly
}

TEST(SensorProfiles, Ov7620) {
    const sensor_profile p = ov7620_profile();
    EXPECT_EQ(p.validate(), "");
    EXPECT_EQ(p.readout_cols(), 664);  // array 664 x 492, valid 640 x 480
    EXPECT_EQ(p.readout_rows(), 492);
    EXPECT_EQ(p.active_cols, 640);
    EXPECT_EQ(p.active_rows, 480);
    EXPECT_EQ(p.frame_lines, 525);  // "525 line, 30 fps"
    expect_pins_match(p);
    // 858 x 525 clocks at 13.5 MHz (ASSUMED) = 29.97 fps.
    EXPECT_EQ(measure_one_frame(p).frame_ticks, 858LL * 525 * 4000 / 3);
}

TEST(SensorProfiles, Mt9v011FromItsLinuxDriverFormulas) {
    const sensor_profile p = mt9v011_profile();
    EXPECT_EQ(p.validate(), "");
    // row_time = (640 + 113 + hblank) * (speed + 2) master clocks, hblank = 771 - 640.
    EXPECT_EQ(p.line_pclks * p.mclk_per_pclk, (640 + 113 + 131) * 2);  // 1768
    EXPECT_EQ(p.frame_lines, 480 + (508 - 480) + 1);                   // 509
    EXPECT_EQ(p.frame_pclks() * p.mclk_per_pclk, 899912);              // master clocks per frame
    EXPECT_EQ(p.cfa, dsp::cfa_order::grbg);                            // SGRBG8
    expect_pins_match(p);
    // 899,912 clocks of 27 MHz: the frame is 599,941,333 1/3 ticks, so the
    // measured period is the floor or ceiling of it; 30.003 fps.
    const simtime::ticks t = measure_one_frame(p).frame_ticks;
    EXPECT_TRUE(t == 599941333 || t == 599941334) << t;
}

TEST(SensorProfiles, Mt9v012ExplicitDarkLayout) {
    const sensor_profile p = mt9v012_profile();
    EXPECT_EQ(p.validate(), "");
    EXPECT_EQ(p.readout_cols(), 695);
    EXPECT_EQ(p.readout_rows(), 504);
    EXPECT_EQ(p.dark_cols_left, 34);
    EXPECT_EQ(p.dark_cols_right, 12);
    EXPECT_EQ(p.dark_rows_top, 14);
    EXPECT_EQ(p.dark_rows_bottom, 1);
    EXPECT_EQ(p.active_col0(), 38);  // VGA image starts at column 38, row 18
    EXPECT_EQ(p.active_row0(), 18);
    EXPECT_EQ(p.cfa, dsp::cfa_order::grbg);
    expect_pins_match(p);
}

TEST(SensorProfiles, Pas302DarkLines) {
    const sensor_profile p = pas302_profile();
    EXPECT_EQ(p.validate(), "");
    EXPECT_EQ(p.line_pclks, 819);  // 644 valid + 175 blank
    EXPECT_EQ(p.readout_cols(), 644);
    EXPECT_EQ(p.readout_rows(), 488);  // 4 dark + 484 valid
    EXPECT_EQ(p.dark_rows_top, 4);
    EXPECT_EQ(p.dark_cols_left + p.dark_cols_right, 0);
    expect_pins_match(p);
}

TEST(SensorProfiles, ByNameAndValidation) {
    for (const char* name : {"default", "ov7620", "mt9v011", "mt9v012", "pas302"})
        EXPECT_EQ(profile_by_name(name).name, name);
    EXPECT_THROW(profile_by_name("ov7670"), std::invalid_argument);

    sensor_profile p = small_profile();
    p.href_start = 30;  // 30 + 22 readout columns > 40
    EXPECT_NE(p.validate().find("do not fit in the line"), std::string::npos) << p.validate();
    still_source source(16, 12, {0, 0, 0});
    EXPECT_THROW(sensor_core(p, scene::camera_id::left, source), std::invalid_argument);
    p = small_profile();
    p.vsync_pclks = 4 * 40 + 1;  // into the first readout row
    EXPECT_NE(p.validate().find("VSYNC"), std::string::npos);
    p = small_profile();
    p.first_row_line = 20;  // 20 + 16 rows > 30 lines
    EXPECT_NE(p.validate().find("do not fit in the frame"), std::string::npos);
}
