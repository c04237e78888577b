#include "tb/app/output/trajectory_plot.h"

#include <fstream>
#include <sstream>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

extern char** environ;

namespace output {

std::string trajectory_gnuplot_script(bool with_truth, bool with_estimates) {
    char size[64];
    std::snprintf(size, sizeof size, "%d,%d", trajectory_png_width, trajectory_png_height);
    char colours[128];
    std::snprintf(colours, sizeof colours, "est = '#%06x'\ntru = '#%06x'\n",
                  trajectory_estimate_rgb, trajectory_truth_rgb);
    // One panel's plot command from its series (x, y columns; 3D with z).
    const auto panel = [&](const char* command, const std::string& truth_series,
                           const std::string& estimate_series) {
        std::string line = command;
        line += ' ';
        if (with_truth) line += truth_series;
        if (with_truth && with_estimates) line += ",";
        if (with_estimates) line += estimate_series;
        return line + "\n";
    };
    const std::string est_style = " with linespoints lw 2 pt 7 ps 0.8 lc rgb est title 'estimated'";
    const std::string tru_style = " with lines lw 2 lc rgb tru title 'true'";
    std::string s;
    s += "# stereosim: the ball's estimated and true position against time and in 3D\n"
         "# (docs/waveforms.md). Reads frames.csv beside this script (empty cells:\n"
         "# no estimate / no truth that frame); redraw with: gnuplot trajectory.gp\n";
    if (!with_estimates) s += "# This run has no 3D estimate: only the truth is drawn.\n";
    if (!with_truth) s += "# This run has no ground truth: only the estimates are drawn.\n";
    s += "set datafile separator ','\n"
         "set datafile columnheaders\n"
         "set terminal pngcairo size ";
    s += size;
    s += " background '#ffffff' font 'sans,10' noenhanced\n"
         "set output 'trajectory.png'\n";
    s += colours;
    s += "data = 'frames.csv'\n"
         "t(c) = column('start_ms') / 1000.0\n"
         "set grid\n"
         "set key top left\n"
         "set multiplot layout 2,2 title 'stereosim: ball position, estimated and true (mm)'\n"
         "set xlabel 'time (s)'\n"
         "set ylabel 'X (mm)'\n";
    s += panel("plot", "data using (t(0)):(column('true_x_mm'))" + tru_style,
               " data using (t(0)):(column('est_x_mm'))" + est_style);
    s += "set ylabel 'Y (mm)'\n";
    s += panel("plot", "data using (t(0)):(column('true_y_mm'))" + tru_style,
               " data using (t(0)):(column('est_y_mm'))" + est_style);
    s += "set ylabel 'Z (mm)'\n";
    s += panel("plot",
               "data using (t(0)):(column('true_z_mm'))" + tru_style +
                   ", data using (t(0)):(column('true_z_visible_mm')) with lines lw 2 dt 2 lc "
                   "rgb tru title 'true, visible surface'",
               " data using (t(0)):(column('est_z_mm'))" + est_style);
    // The 3D panel: the whole box drawn, its floor at the lowest point (the
    // default floats it below), Y pointing down as in the camera frame.
    s += "set xlabel 'X (mm)' offset 0,-1\n"
         "set ylabel 'Z (mm)' offset 1,0\n"
         "set zlabel 'Y (mm), down' rotate parallel\n"
         "set xyplane relative 0\n"
         "set border 4095\n"
         "set zrange [*:*] reverse\n"
         "set format x '%.0f'\n"
         "set format y '%.0f'\n"
         "set format z '%.0f'\n"
         "set view 62, 32\n";
    s += panel(
        "splot",
        "data using (column('true_x_mm')):(column('true_z_mm')):(column('true_y_mm'))" + tru_style,
        " data using (column('est_x_mm')):(column('est_z_mm')):(column('est_y_mm'))" + est_style);
    s += "unset multiplot\n";
    return s;
}

bool trajectory_series_present(const std::string& csv_path, bool* truth, bool* estimates) {
    *truth = *estimates = false;
    std::ifstream in(csv_path);
    std::string line;
    if (!in || !std::getline(in, line)) return false;
    // Column indices of the two x columns in the header.
    const auto split = [](const std::string& text) {
        std::vector<std::string> cells;
        std::stringstream ss(text);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        return cells;
    };
    const std::vector<std::string> header = split(line);
    int truth_col = -1, estimate_col = -1;
    for (size_t i = 0; i < header.size(); ++i) {
        if (header[i] == "true_x_mm") truth_col = static_cast<int>(i);
        if (header[i] == "est_x_mm") estimate_col = static_cast<int>(i);
    }
    while (std::getline(in, line)) {
        const std::vector<std::string> cells = split(line);
        const auto has = [&](int col) {
            return col >= 0 && col < static_cast<int>(cells.size()) && !cells[col].empty();
        };
        *truth = *truth || has(truth_col);
        *estimates = *estimates || has(estimate_col);
    }
    return true;
}

bool run_gnuplot(const std::string& dir, std::string* error, const std::string& script) {
    // gnuplot runs in DIR (the script's relative paths); stdout and stderr
    // kept off the terminal (its warnings about series with no points, e.g.
    // a run with no 3D estimate, are not the user's concern: a run is quiet
    // unless it fails); its exit status is checked.
    const pid_t child = fork();
    if (child < 0) {
        if (error) *error = std::string("cannot start gnuplot: ") + std::strerror(errno);
        return false;
    }
    if (child == 0) {
        if (chdir(dir.c_str()) != 0) _exit(126);
        std::FILE* null = std::fopen("/dev/null", "w");
        if (null) {
            dup2(fileno(null), 1);
            dup2(fileno(null), 2);
        }
        char* const argv[] = {const_cast<char*>("gnuplot"), const_cast<char*>(script.c_str()),
                              nullptr};
        execvp("gnuplot", argv);
        _exit(127);
    }
    int status = 0;
    while (waitpid(child, &status, 0) < 0) {
        if (errno != EINTR) break;
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
    if (error) {
        if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
            *error = "gnuplot not found (scripts/install-deps installs gnuplot-nox)";
        else
            *error = "gnuplot failed on " + dir + "/" + script;
    }
    return false;
}

}  // namespace output
