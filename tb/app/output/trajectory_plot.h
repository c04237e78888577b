// trajectory.png (docs/waveforms.md): the ball's estimated and true X, Y, Z
// against time and a 3D view of both paths, like the paper's Fig. 11, drawn
// by gnuplot (Debian gnuplot-nox, pngcairo terminal) from frames.csv.
//
// The script, trajectory.gp, is saved beside frames.csv and reads it by
// relative path, so `cd DIR && gnuplot trajectory.gp` redraws the plot.
// PNG: 1200 x 900 pixels, white background, four panels; estimated values
// in red (#e41a1c, points and lines), truth in blue (#377eb8, lines; in
// the Z panel also the visible-surface depth, dashed, which is what a
// stereo match measures).
// Time is the frame's sync period start (frames.csv start_ms) in seconds.
#pragma once

#include <string>

namespace output {

inline constexpr int trajectory_png_width = 1200;
inline constexpr int trajectory_png_height = 900;
inline constexpr unsigned trajectory_estimate_rgb = 0xe41a1c;
inline constexpr unsigned trajectory_truth_rgb = 0x377eb8;

// The script; a series whose column has no value in any row is left out
// (gnuplot refuses a plot in which no series has a point).
std::string trajectory_gnuplot_script(bool with_truth = true, bool with_estimates = true);

// Which series frames.csv at `csv_path` can draw: any row with a true /
// estimated position. False if the file cannot be read.
bool trajectory_series_present(const std::string& csv_path, bool* truth, bool* estimates);

// Runs gnuplot on DIR/SCRIPT in DIR (the script's data must be there:
// frames.csv for trajectory.gp); false and *error (one line) if gnuplot is
// missing or failed. The sweep's fit map uses it too.
bool run_gnuplot(const std::string& dir, std::string* error,
                 const std::string& script = "trajectory.gp");

}  // namespace output
