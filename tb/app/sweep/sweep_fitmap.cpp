// fitmap.png (docs/sweep.md): the margin over the first two keys of the grid
// as a heat map (the minimum slack per period where the point fits, minus
// its largest overrun where it does not: red over budget, green margin),
// each cell
// marked with its verdict ("fits" / "OVER"; in parentheses where only the
// closed form judged it), one panel per combination of further keys. The
// data (fitmap.dat) and script (fitmap.gp) stay beside it to restyle.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "tb/app/output/trajectory_plot.h"
#include "tb/app/sweep/sweep_files.h"
#include "tb/app/sweep/sweep_grid.h"

namespace sweep {

namespace {

using json = nlohmann::json;

std::string gp_quote(const std::string& s) {
    std::string q = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') q += '\\';
        q += c;
    }
    return q + "\"";
}

size_t value_index(const json& axis, const json& value) {
    const json& values = axis.at("values");
    for (size_t i = 0; i < values.size(); ++i)
        if (values[i] == value) return i;
    return 0;
}

std::string tics(const json& axis) {
    std::string s = "(";
    const json& values = axis.at("values");
    for (size_t i = 0; i < values.size(); ++i)
        s += (i ? ", " : "") + gp_quote(value_text(values[i])) + " " + std::to_string(i);
    return s + ")";
}

}  // namespace

bool write_fitmap(const std::string& dir, const json& sweep, std::string* warning) {
    const json& grid = sweep.at("grid");
    if (sweep.at("points").empty()) {  // a shard with no point (more shards than points)
        if (warning) *warning = "fitmap.png not drawn: no points";
        return false;
    }
    const json no_axis = {{"key", ""}, {"values", json::array({0})}};
    const json& x_axis = grid.at(0);
    const json& y_axis = grid.size() > 1 ? grid.at(1) : no_axis;
    // Panels: the combinations of keys 3.., in grid order.
    std::map<std::string, std::vector<const json*>> panels;
    std::vector<std::string> order;
    for (const json& p : sweep.at("points")) {
        std::string title;
        for (size_t a = 2; a < grid.size(); ++a) {
            const std::string key = grid[a].at("key");
            title += (a > 2 ? ", " : "") + key + "=" + value_text(p.at("keys").at(key));
        }
        if (!panels.count(title)) order.push_back(title);
        panels[title].push_back(&p);
    }
    double extent = 1.0;
    for (const json& p : sweep.at("points")) {
        const point_outcome o = outcome_of(p);
        if (o.known && o.judged) extent = std::max(extent, std::fabs(o.slack_ms));
    }
    std::ofstream dat(dir + "/fitmap.dat");
    for (const std::string& title : order) {
        dat << "# " << title << "\n";
        for (const json* p : panels[title]) {
            const point_outcome o = outcome_of(*p);
            const size_t x =
                value_index(x_axis, p->at("keys").at(x_axis.at("key").get<std::string>()));
            const size_t y =
                grid.size() > 1
                    ? value_index(y_axis, p->at("keys").at(y_axis.at("key").get<std::string>()))
                    : 0;
            std::string mark = !o.known ? "?" : !o.judged ? "not judged" : o.fits ? "fits" : "OVER";
            if (o.known && std::string(o.source) == "closed_form") mark = "(" + mark + ")";
            // NaN: no colour (gnuplot skips the cell), the mark stays.
            const bool coloured = o.known && o.judged;
            dat << x << " " << y << " " << (coloured ? std::to_string(o.slack_ms) : "NaN") << " "
                << gp_quote(mark) << "\n";
        }
        dat << "\n\n";
    }
    dat.close();  // complete on disk before gnuplot reads it
    const size_t n = order.size();
    const int cols = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    const int rows = static_cast<int>((n + cols - 1) / cols);
    std::ofstream gp(dir + "/fitmap.gp");
    gp << "set terminal pngcairo size " << 560 * cols << "," << 440 * rows << " font 'sans,9'\n"
       << "set output 'fitmap.png'\n"
       << "set palette defined (-1 '#c0392b', 0 '#f7f7f7', 1 '#1e8449')\n"
       << "set cbrange [" << -extent << ":" << extent << "]\n"
       << "set cblabel 'margin, ms: min slack per period, or minus the largest overrun'\n"
       << "set xlabel " << gp_quote(x_axis.at("key")) << "\nset ylabel "
       << gp_quote(y_axis.at("key")) << "\n"
       << "set xtics " << tics(x_axis) << " rotate by 45 right\nset ytics " << tics(y_axis) << "\n"
       << "set xrange [-0.5:" << x_axis.at("values").size() - 0.5
       << "]\nset yrange [-0.5:" << y_axis.at("values").size() - 0.5 << "]\n"
       << "set termoption noenhanced\nunset key\n";
    if (n > 1) gp << "set multiplot layout " << rows << "," << cols << "\n";
    for (size_t i = 0; i < n; ++i) {
        gp << "set title " << gp_quote(order[i].empty() ? "stereosim sweep: fit map" : order[i])
           << "\nplot 'fitmap.dat' index " << i
           << " using 1:2:($1-0.5):($1+0.5):($2-0.5):($2+0.5):3 with boxxy fs solid 1.0 "
              "lc palette, '' index "
           << i << " using 1:2:4 with labels font 'sans,8'\n";
    }
    if (n > 1) gp << "unset multiplot\n";
    gp.close();
    std::string why;
    if (!output::run_gnuplot(dir, &why, "fitmap.gp")) {
        if (warning) *warning = "fitmap.png not drawn: " + why;
        return false;
    }
    return true;
}

}  // namespace sweep
