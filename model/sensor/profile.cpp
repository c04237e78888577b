#include "model/sensor/profile.h"

#include <stdexcept>

namespace sensor {

std::string sensor_profile::validate() const {
    const auto positive = [](int v) { return v > 0; };
    if (!positive(line_pclks) || !positive(frame_lines))
        return "line_pclks and frame_lines must be > 0";
    if (!positive(active_cols) || !positive(active_rows)) return "active size must be > 0";
    if (dark_cols_left < 0 || dark_cols_right < 0 || dark_rows_top < 0 || dark_rows_bottom < 0 ||
        border_cols_before < 0 || border_cols_after < 0 || border_rows_before < 0 ||
        border_rows_after < 0 || href_start < 0 || first_row_line < 0)
        return "negative layout field";
    // Border pixels repeat the image's outermost CFA cell: they need a whole cell.
    if (active_cols < 2 || active_rows < 2) return "active size must be at least 2x2";
    if (href_start + readout_cols() > line_pclks)
        return "readout columns do not fit in the line (href_start + readout > line_pclks)";
    if (first_row_line + readout_rows() > frame_lines)
        return "readout rows do not fit in the frame (first_row_line + readout > frame_lines)";
    if (vsync_pclks <= 0) return "vsync_pclks must be > 0";
    if (static_cast<int64_t>(vsync_pclks) > static_cast<int64_t>(first_row_line) * line_pclks)
        return "VSYNC must end before the first readout row";
    if (mclk_period.num <= 0 || mclk_period.den <= 0 || mclk_per_pclk <= 0)
        return "clock periods must be > 0";
    if (startup_latency_pclks < 1) return "startup_latency_pclks must be >= 1";
    if (extra_delay_probability < 0.0 || extra_delay_probability > 1.0)
        return "extra_delay_probability must be in [0, 1]";
    if (extra_delay_probability > 0.0 && extra_delay_max_pclks < 1)
        return "extra_delay_max_pclks must be >= 1 when extra delays can occur";
    if (black_level < 0 || black_level > 255) return "black_level must be 0..255";
    if (exposure_lines < 1) return "exposure_lines must be >= 1";
    return {};
}

// Start-up rule of docs/design-brief.md for every profile: fixed latency, then with
// probability 0.25 an extra delay of 1 pclk .. 2 lines.
static void set_startup(sensor_profile& p) {
    p.startup_latency_pclks = 2 * p.line_pclks;  // ASSUMED: 2 line periods
    p.extra_delay_probability = 0.25;            // [DESIGN]
    p.extra_delay_max_pclks = 2 * p.line_pclks;  // [DESIGN] up to 2 lines
}

sensor_profile default_profile() {
    sensor_profile p;
    p.name = "default";
    p.line_pclks = 800;            // [DESIGN]
    p.href_start = 0;              // ASSUMED: a line starts with HREF rising
    p.dark_cols_left = 16;         // [DESIGN] 16 dark columns, placed first: ASSUMED left
    p.active_cols = 640;           // [DESIGN]
    p.frame_lines = 525;           // [DESIGN]
    p.vsync_pclks = 2 * 800;       // ASSUMED: 2 lines, as VGA's vertical sync
    p.first_row_line = 27;         // ASSUMED: VSYNC 2 + back porch 25 lines (VGA-like)
    p.dark_rows_top = 8;           // [DESIGN] 8 dark rows, placed first: ASSUMED top
    p.active_rows = 480;           // [DESIGN]; front porch 525 - 27 - 488 = 10 lines
    p.cfa = dsp::cfa_order::bggr;  // ASSUMED: the firmware's default (dsp/controller.h)
    p.mclk_period = {simtime::pclk_default_period, 1};  // [DESIGN] 120/7 MHz, shared
    p.mclk_per_pclk = 1;  // ASSUMED: the master clock is the pixel clock
    set_startup(p);
    p.black_level = 16;      // ASSUMED
    p.exposure_lines = 480;  // ASSUMED
    return p;
}

sensor_profile ov7620_profile() {
    sensor_profile p;
    p.name = "ov7620";
    p.line_pclks = 858;  // ASSUMED: CCIR-601 525-line timing, 858 samples per line (NOT FOUND)
    p.href_start = 0;    // ASSUMED
    // Array 664 x 492, valid 640 x 480 [HF6]; "black level substitutes the pixel
    // data outside the active window" [HF6]: the 24 columns and 12 rows outside
    // it read black. Their split left/right, top/bottom: ASSUMED even.
    p.dark_cols_left = 12;
    p.active_cols = 640;
    p.dark_cols_right = 12;
    p.frame_lines = 525;      // [HF6] "Video Timing - 525 line, 30 fps"
    p.vsync_pclks = 3 * 858;  // ASSUMED: 3 lines (NOT FOUND)
    p.first_row_line = 20;    // ASSUMED (525 - 492 = 33 blanking lines, NOT FOUND where)
    p.dark_rows_top = 6;
    p.active_rows = 480;
    p.dark_rows_bottom = 6;
    p.cfa = dsp::cfa_order::bggr;  // ASSUMED: OV6620's raw order, row 1 B G, row 2 G R [HF6]
    p.mclk_period = simtime::period_of_hz(27000000);  // ASSUMED 27 MHz crystal (NOT FOUND)
    p.mclk_per_pclk = 2;  // ASSUMED: 13.5 MHz pclk -> 858 x 525 = 29.97 fps, matching "30 fps"
    set_startup(p);
    p.black_level = 16;      // ASSUMED
    p.exposure_lines = 480;  // ASSUMED
    return p;
}

sensor_profile mt9v011_profile() {
    sensor_profile p;
    p.name = "mt9v011";
    // Linux mt9v011 driver [HF6]: row_time = (width + 113 + hblank) * (speed + 2)
    // master clocks, hblank = 771 - width; frame = (height + vblank + 1) rows,
    // vblank = 508 - height; xtal 27 MHz; SGRBG8.
    p.line_pclks = 640 + 113 + (771 - 640);  // DERIVED: 884
    p.href_start = 0;                        // ASSUMED
    p.active_cols = 640;                     // [HF6] width 640
    // Dark pixels in the output window: NOT FOUND (the driver's column start 20
    // and row start 8 put the window past them). ASSUMED none: the card's
    // dark-pixel check cannot work with this profile.
    p.frame_lines = 480 + (508 - 480) + 1;            // DERIVED: 509
    p.vsync_pclks = 884;                              // ASSUMED: 1 line
    p.first_row_line = 29;                            // ASSUMED: all 29 blanking rows first
    p.active_rows = 480;                              // [HF6] height 480
    p.cfa = dsp::cfa_order::grbg;                     // [HF6] SGRBG8
    p.mclk_period = simtime::period_of_hz(27000000);  // [HF6] xtal 27 MHz
    p.mclk_per_pclk = 2;  // DERIVED: speed = 0 -> (speed + 2) = 2 master clocks per pixel
    set_startup(p);
    p.black_level = 16;      // ASSUMED
    p.exposure_lines = 480;  // ASSUMED
    return p;
}

sensor_profile mt9v012_profile() {
    sensor_profile p;
    p.name = "mt9v012";
    // Array 695 x 504: first 34 columns and 14 rows black, last 12 columns and
    // last row black; VGA image starts row 18, col 38 [HF6]. DERIVED: a 4-pixel
    // border before and 695-38-640-12 = 5 columns / 504-18-480-1 = 5 rows after.
    // ASSUMED: the whole array is read out.
    p.line_pclks = 880;  // ASSUMED (NOT FOUND): 695 readout + 185 blanking
    p.href_start = 0;    // ASSUMED
    p.dark_cols_left = 34;
    p.border_cols_before = 4;
    p.active_cols = 640;
    p.border_cols_after = 5;
    p.dark_cols_right = 12;
    p.frame_lines = 525;      // ASSUMED (NOT FOUND)
    p.vsync_pclks = 2 * 880;  // ASSUMED
    p.first_row_line = 10;    // ASSUMED
    p.dark_rows_top = 14;
    p.border_rows_before = 4;
    p.active_rows = 480;
    p.border_rows_after = 5;
    p.dark_rows_bottom = 1;
    p.cfa = dsp::cfa_order::grbg;  // [HF6] even rows G1 R, odd rows B G2; window at even row/col
    p.mclk_period = {simtime::pclk_default_period, 1};  // ASSUMED: the card's 120/7 MHz
    p.mclk_per_pclk = 1;                                // ASSUMED
    set_startup(p);
    p.black_level = 16;      // ASSUMED
    p.exposure_lines = 480;  // ASSUMED
    return p;
}

sensor_profile pas302_profile() {
    sensor_profile p;
    p.name = "pas302";
    // VGA readout 644 x 488: line = 644 valid + 175 blank = 819 pixclks; 488
    // lines = 4 dark lines + 484 valid lines; Bayer G R / B G [HF6].
    p.line_pclks = 819;
    p.href_start = 0;          // ASSUMED
    p.border_cols_before = 2;  // ASSUMED: VGA centred in the 644 valid columns
    p.active_cols = 640;
    p.border_cols_after = 2;
    p.frame_lines = 500;       // ASSUMED: 12 blanking lines beside the 488 (NOT FOUND)
    p.vsync_pclks = 2 * 819;   // ASSUMED
    p.first_row_line = 8;      // ASSUMED
    p.dark_rows_top = 4;       // [HF6] 4 dark lines; at the top: ASSUMED
    p.border_rows_before = 2;  // ASSUMED: VGA centred in the 484 valid lines
    p.active_rows = 480;
    p.border_rows_after = 2;
    p.cfa = dsp::cfa_order::grbg;  // [HF6] G R G R / B G B G; VGA window at even offsets
    p.mclk_period = simtime::period_of_hz(12000000);  // ASSUMED 12 MHz (NOT FOUND)
    p.mclk_per_pclk = 1;                              // ASSUMED
    set_startup(p);
    p.black_level = 16;      // ASSUMED
    p.exposure_lines = 480;  // ASSUMED
    return p;
}

std::string window_error(const sensor_profile& p, int cols, int rows) {
    const auto bad = [](int size, int active) {
        return size < 16 || size % 4 != 0 || size > active || (active - size) % 4 != 0;
    };
    if (bad(cols, p.active_cols) || bad(rows, p.active_rows))
        return "window " + std::to_string(cols) + " x " + std::to_string(rows) +
               " does not fit the " + p.name + " profile's " + std::to_string(p.active_cols) +
               " x " + std::to_string(p.active_rows) +
               " (at least 16, multiples of 4, centred on whole CFA cells)";
    return {};
}

sensor_profile windowed(const sensor_profile& p, int cols, int rows) {
    const std::string error = window_error(p, cols, rows);
    if (!error.empty()) throw std::invalid_argument(error);
    sensor_profile w = p;
    w.href_start += (p.active_cols - cols) / 2;
    w.active_cols = cols;
    w.first_row_line += (p.active_rows - rows) / 2;
    w.active_rows = rows;
    return w;
}

sensor_profile profile_by_name(const std::string& name) {
    if (name == "default") return default_profile();
    if (name == "ov7620") return ov7620_profile();
    if (name == "mt9v011") return mt9v011_profile();
    if (name == "mt9v012") return mt9v012_profile();
    if (name == "pas302") return pas302_profile();
    throw std::invalid_argument("unknown sensor profile '" + name +
                                "' (known: default, ov7620, mt9v011, mt9v012, pas302)");
}

}  // namespace sensor
