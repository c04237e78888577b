#include "tb/app/sweep/sweep_files.h"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "tb/app/cli/staged_files.h"
#include "tb/app/sweep/sweep_grid.h"

namespace sweep {

namespace {

using json = nlohmann::json;

std::string csv_text(const json& v) {
    if (v.is_null()) return "";
    std::string s = v.is_string() ? v.get<std::string>() : v.dump();
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

const json& at_path(const json& j, const std::string& pointer) {
    static const json null_value;
    const json::json_pointer p(pointer);
    return j.contains(p) ? j.at(p) : null_value;
}

const char* const figure_columns[][2] = {
    {"simulated", "/simulate"},
    {"ran", "/ran"},
    {"verdict", "/verdict"},
    {"min_slack_ms", "/min_slack_ms"},
    {"overrun_ms_max", "/overrun_ms_max"},
    {"first_overrun_resource", "/first_overrun/resource"},
    {"first_overrun_stage", "/first_overrun/stage"},
    {"first_overrun_period", "/first_overrun/period"},
    {"cpu_busy_ms_max", "/cpu_busy_ms_max"},
    {"emif_busy_ms_max", "/emif_busy_ms_max"},
    {"capture_ms_max", "/capture_ms/max"},
    {"processing_ms_max", "/processing_ms_max"},
    {"preprocess_ms_max", "/stage_ms_max/preprocess"},
    {"detect_ms_max", "/stage_ms_max/detect"},
    {"track_ms_max", "/stage_ms_max/track"},
    {"stereo_sad_ms_max", "/stage_ms_max/stereo_sad"},
    {"stereo_edge_ms_max", "/stage_ms_max/stereo_edge"},
    {"xyz_ms_max", "/stage_ms_max/xyz"},
    {"closed_form_capture_ms", "/closed_form/capture_ms"},
    {"closed_form_processing_ms", "/closed_form/processing_ms"},
    {"closed_form_need_ms", "/closed_form/need_ms"},
    {"closed_form_verdict", "/closed_form/verdict"},
    {"closed_form_agrees", "/closed_form_agrees"},
    {"exit_code", "/exit_code"},
    {"error", "/error"},
};

void write_csv(std::ostream& out, const json& sweep) {
    out << "index";
    for (const json& axis : sweep.at("grid")) out << "," << axis.at("key").get<std::string>();
    for (const auto& c : figure_columns) out << "," << c[0];
    out << "\n";
    for (const json& p : sweep.at("points")) {
        out << p.at("index").get<size_t>();
        for (const json& axis : sweep.at("grid"))
            out << "," << csv_text(p.at("keys").at(axis.at("key").get<std::string>()));
        for (const auto& c : figure_columns) out << "," << csv_text(at_path(p, c[1]));
        out << "\n";
    }
}

// The other keys' values of a point, as text, in axis order from `from`.
std::string others_of(const json& point, const json& grid, size_t from) {
    std::string s;
    for (size_t a = from; a < grid.size(); ++a)
        s += csv_text(point.at("keys").at(grid[a].at("key").get<std::string>())) + ",";
    return s;
}

// For each combination of the keys after the first, the smallest value of
// the first key whose point fits (empty when none does).
void write_frontier(std::ostream& out, const json& sweep) {
    const json& grid = sweep.at("grid");
    const std::string first = grid.at(0).at("key");
    for (size_t a = 1; a < grid.size(); ++a) out << grid[a].at("key").get<std::string>() << ",";
    out << "smallest_fitting_" << first << ",slack_ms,source,points\n";
    std::map<std::string, std::vector<const json*>> groups;  // by the other keys' values
    std::vector<std::string> order;
    for (const json& p : sweep.at("points")) {
        const std::string others = others_of(p, grid, 1);
        if (!groups.count(others)) order.push_back(others);
        groups[others].push_back(&p);
    }
    for (const std::string& others : order) {
        const json* best = nullptr;
        for (const json* p : groups[others]) {
            const point_outcome o = outcome_of(*p);
            if (!o.known || !o.judged || !o.fits) continue;
            const json& v = p->at("keys").at(first);
            if (!best || (v.is_number() && v < best->at("keys").at(first))) best = p;
        }
        out << others;
        if (best) {
            const point_outcome o = outcome_of(*best);
            out << csv_text(best->at("keys").at(first)) << "," << o.slack_ms << "," << o.source;
        } else {
            out << ",,";
        }
        out << "," << groups[others].size() << "\n";
    }
}

}  // namespace

point_outcome outcome_of(const json& point) {
    point_outcome o;
    if (point.value("ran", false) && point.value("verdict", json()).is_string()) {
        o.known = true;
        o.judged = point["verdict"] != "not_judged";
        o.fits = point["verdict"] == "within";
        const json& slack = point.value("min_slack_ms", json());
        const json& overrun = point.value("overrun_ms_max", json());
        if (o.fits)
            o.slack_ms = slack.is_number() ? slack.get<double>() : 0.0;
        else  // over budget: minus the largest overrun (a drop or overflow counts 0)
            o.slack_ms = overrun.is_number() ? -overrun.get<double>() : 0.0;
        o.source = "cosim";
        return o;
    }
    const json& cf = point.value("closed_form", json::object());
    if (cf.value("verdict", json()).is_string()) {
        o.known = true;
        o.fits = cf["verdict"] == "within";
        o.slack_ms = cf.at("slack_ms").get<double>();
        o.source = "closed_form";
    }
    return o;
}

bool write_fitmap(const std::string& dir, const json& sweep, std::string* warning);

// Staged and renamed into place: a second signal or a full disk never leaves
// a half-written sweep.json for --resume to read.
bool write_sweep_files(const std::string& dir, const json& sweep, std::string* error,
                       std::string* warning) {
    cli::staged_files staged;
    if (!staged.open(dir, error)) return false;
    std::ofstream json_out(staged.staged_path("sweep.json")),
        csv_out(staged.staged_path("sweep.csv")), frontier_out(staged.staged_path("frontier.csv"));
    json_out << sweep.dump(2) << "\n";
    write_csv(csv_out, sweep);
    write_frontier(frontier_out, sweep);
    json_out.close();
    csv_out.close();
    frontier_out.close();
    if (!json_out || !csv_out || !frontier_out) {
        *error = "cannot write into " + dir;
        return false;
    }
    if (!staged.commit(error)) return false;
    write_fitmap(dir, sweep, warning);
    return true;
}

}  // namespace sweep
