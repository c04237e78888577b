// Timing profile of a CMOS sensor: the frame layout on its pins and its clocks.
//
// Layout (docs/sensor.md has the drawing). One line = line_pclks pixel clocks;
// HREF is high for the readout columns, starting at column href_start:
//   [dark_cols_left][border_cols_before][active_cols][border_cols_after][dark_cols_right]
// then low for the rest of the line (horizontal blanking). One frame =
// frame_lines lines; line 0 is the frame start: VSYNC rises with its first
// pixel clock and stays high for vsync_pclks clocks. The readout rows are
// lines first_row_line .. first_row_line + readout_rows() - 1:
//   [dark_rows_top][border_rows_before][active_rows][border_rows_after][dark_rows_bottom]
// The other lines are vertical blanking (no HREF). VSYNC ends before the first
// readout row (validate() checks it). Both are active high.
//
// Dark (optically black) pixels read black_level (plus noise); border pixels
// are light-sensitive pixels outside the scene image: they repeat the
// outermost 2x2 CFA cell of the image. cfa is the colour order of the first
// ACTIVE pixel (docs/design-brief.md: the Bayer order depends on the window start).
//
// Every field of the named profiles says where its value comes from:
// [DESIGN] docs/design-brief.md decisions, [HF6] docs/hardware-facts.md section 6 (with its
// source), DERIVED (arithmetic on those), ASSUMED (no source: our choice).
#pragma once

#include <cstdint>
#include <string>

#include "dsp/bayer_demosaic.h"
#include "model/time/ticks.h"

namespace sensor {

struct sensor_profile {
    std::string name;

    // Horizontal, in pixel clocks.
    int line_pclks = 0;
    int href_start = 0;  // column of the line where HREF rises
    int dark_cols_left = 0;
    int border_cols_before = 0;
    int active_cols = 0;
    int border_cols_after = 0;
    int dark_cols_right = 0;

    // Vertical, in lines.
    int frame_lines = 0;
    int vsync_pclks = 0;     // VSYNC width from the frame's first pixel clock
    int first_row_line = 0;  // line of the first readout row
    int dark_rows_top = 0;
    int border_rows_before = 0;
    int active_rows = 0;
    int border_rows_after = 0;
    int dark_rows_bottom = 0;

    dsp::cfa_order cfa = dsp::cfa_order::bggr;

    // Clocks: the master clock (shared by both sensors) and the pixel clock,
    // pclk = mclk / mclk_per_pclk.
    simtime::rational_ticks mclk_period{simtime::pclk_default_period, 1};
    int mclk_per_pclk = 1;

    // Start-up after OE rises: fixed latency, plus with probability
    // extra_delay_probability an extra delay uniform in 1 .. extra_delay_max_pclks.
    int startup_latency_pclks = 0;
    double extra_delay_probability = 0.25;
    int extra_delay_max_pclks = 0;

    // Pixel response: out = clamp(black_level + scene * gain * exposure / ref_exposure + noise).
    int black_level = 16;
    int exposure_lines = 0;  // default integration time, in line periods

    int readout_cols() const {
        return dark_cols_left + border_cols_before + active_cols + border_cols_after +
               dark_cols_right;
    }
    int readout_rows() const {
        return dark_rows_top + border_rows_before + active_rows + border_rows_after +
               dark_rows_bottom;
    }
    int64_t frame_pclks() const { return static_cast<int64_t>(line_pclks) * frame_lines; }
    simtime::rational_ticks pclk_period() const {
        return simtime::reduce({mclk_period.num * mclk_per_pclk, mclk_period.den});
    }
    // First active column / row inside the readout window.
    int active_col0() const { return dark_cols_left + border_cols_before; }
    int active_row0() const { return dark_rows_top + border_rows_before; }

    // Empty if consistent; otherwise what is wrong.
    std::string validate() const;
};

// docs/design-brief.md default profile: 800 pclk per line (16 dark + 640 active + 144
// blanking), 525 lines per frame (8 dark + 480 active + 37 blanking), pclk
// 120/7 MHz -> 420,000 pclk = 441,000,000 ticks = exactly 24.5 ms per frame.
sensor_profile default_profile();

// Real parts of the era (docs/hardware-facts.md section 6).
sensor_profile ov7620_profile();
sensor_profile mt9v011_profile();
sensor_profile mt9v012_profile();
sensor_profile pas302_profile();

// The profile read out through a centred window of cols x rows active
// pixels (the windowing registers of the era's parts, e.g. the OV7620's
// HSTART / HSTOP): the line and frame timing stay, HREF starts later and the
// readout rows later, by half the columns / rows left out. The dark and
// border pixels stay around the window. Empty string if the window fits;
// otherwise what is wrong: cols and rows at least 16, multiples of 4, at
// most the active size, and (active - window) a multiple of 4 so that both
// halves left out are whole CFA cells (the Bayer order stays).
std::string window_error(const sensor_profile& p, int cols, int rows);
sensor_profile windowed(const sensor_profile& p, int cols, int rows);

// By name ("default", "ov7620", "mt9v011", "mt9v012", "pas302"); throws
// std::invalid_argument for an unknown name.
sensor_profile profile_by_name(const std::string& name);

}  // namespace sensor
