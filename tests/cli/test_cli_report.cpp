// `stereosim run --out DIR` as a user runs it: report.json validates against
// docs/report-schema.json (with a plain validator for the JSON-Schema subset
// the schema uses, shown to reject broken reports), frames.csv holds the same
// rows, the exit status is the verdict, and a second run with the same inputs
// (with the progress hook on, which pauses the simulation every period)
// writes a byte-identical report apart from summary.sim. report.txt is the
// platform's text report (identical but for its wall-time line); timeline.csv
// is written only with --timeline-csv.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

struct run_output {
    int status = -1;
    std::string err;
};

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

run_output run_binary(const std::string& args) {
    // One file per test process: ctest -j runs this file's tests side by side.
    const std::string err =
        testing::TempDir() + "cli_report_stderr_" + std::to_string(getpid()) + ".txt";
    const std::string command = std::string(STEREOSIM_BINARY) + " " + args + " 2>" + err;
    const int raw = std::system(command.c_str());
    run_output out;
    out.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    out.err = read_file(err);
    return out;
}

// ---- a validator for the JSON-Schema subset docs/report-schema.json uses ------------------
// type (name or list), const, enum, minimum, properties, required,
// additionalProperties (false or a schema), items, anyOf, $ref "#/$defs/<name>".
class schema_validator {
  public:
    explicit schema_validator(json root) : m_root(std::move(root)) {}
    std::vector<std::string> validate(const json& doc) {
        m_errors.clear();
        check(m_root, doc, "");
        return m_errors;
    }

  private:
    static bool has_type(const json& v, const std::string& t) {
        if (t == "object") return v.is_object();
        if (t == "array") return v.is_array();
        if (t == "string") return v.is_string();
        if (t == "integer") return v.is_number_integer();
        if (t == "number") return v.is_number();
        if (t == "boolean") return v.is_boolean();
        if (t == "null") return v.is_null();
        ADD_FAILURE() << "schema uses unknown type " << t;
        return false;
    }
    void fail(const std::string& where, const std::string& what) {
        m_errors.push_back((where.empty() ? "/" : where) + ": " + what);
    }
    void check(const json& s, const json& v, const std::string& where) {
        static const std::vector<std::string> known = {
            "$schema", "$id",        "title",    "description",          "type",  "const", "enum",
            "minimum", "properties", "required", "additionalProperties", "items", "anyOf", "$ref",
            "$defs"};
        for (auto it = s.begin(); it != s.end(); ++it)
            if (std::find(known.begin(), known.end(), it.key()) == known.end())
                ADD_FAILURE() << "schema keyword the validator does not know: " << it.key();
        if (s.contains("$ref")) {
            const std::string ref = s["$ref"];
            const std::string prefix = "#/$defs/";
            ASSERT_EQ(ref.rfind(prefix, 0), 0u) << ref;
            check(m_root["$defs"][ref.substr(prefix.size())], v, where);
        }
        if (s.contains("anyOf")) {
            bool any = false;
            for (const json& option : s["anyOf"]) {
                schema_validator sub(m_root);
                sub.check(option, v, where);
                any |= sub.m_errors.empty();
            }
            if (!any) fail(where, "matches no anyOf option");
        }
        if (s.contains("type")) {
            bool ok = false;
            if (s["type"].is_string())
                ok = has_type(v, s["type"]);
            else
                for (const json& t : s["type"]) ok |= has_type(v, t);
            if (!ok)
                return fail(where, "wrong type " + std::string(v.type_name()) + ", want " +
                                       s["type"].dump());
        }
        if (s.contains("const") && v != s["const"]) fail(where, "not " + s["const"].dump());
        if (s.contains("enum")) {
            bool found = false;
            for (const json& e : s["enum"]) found |= v == e;
            if (!found) fail(where, v.dump() + " not in " + s["enum"].dump());
        }
        if (s.contains("minimum") && v.is_number() && v.get<double>() < s["minimum"].get<double>())
            fail(where, v.dump() + " below minimum " + s["minimum"].dump());
        if (v.is_object()) {
            if (s.contains("required"))
                for (const json& r : s["required"])
                    if (!v.contains(r.get<std::string>()))
                        fail(where, "missing " + r.get<std::string>());
            const json props = s.value("properties", json::object());
            for (auto it = v.begin(); it != v.end(); ++it) {
                if (props.contains(it.key()))
                    check(props[it.key()], *it, where + "/" + it.key());
                else if (s.contains("additionalProperties") && s["additionalProperties"] == false)
                    fail(where, "unexpected property " + it.key());
                else if (s.contains("additionalProperties") &&
                         s["additionalProperties"].is_object())
                    check(s["additionalProperties"], *it, where + "/" + it.key());
            }
        }
        if (v.is_array() && s.contains("items"))
            for (size_t i = 0; i < v.size(); ++i)
                check(s["items"], v[i], where + "/" + std::to_string(i));
    }
    json m_root;
    std::vector<std::string> m_errors;
};

// CSV line -> cells (no quoting in frames.csv: no cell holds a comma).
std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> cells;
    std::string cell;
    std::stringstream in(line);
    while (std::getline(in, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    return cells;
}

// The JSON value under a CSV column, by the documented naming (docs/cli.md).
json value_at(const json& row, const std::string& pointer) {
    try {
        return row.at(json::json_pointer(pointer));
    } catch (const json::exception&) {
        return nullptr;
    }
}

// report.txt is the platform's text report, the same in two runs but for the
// wall-time line; timeline.csv is in `with_csv` only (--timeline-csv).
void expect_text_report_and_timeline(const std::string& with_csv, const std::string& without_csv,
                                     const json& verdict) {
    const std::string text = read_file(with_csv + "/report.txt");
    EXPECT_EQ(text.rfind("== stereosim platform: DSK v1 (CPU 600 MHz, EMIF 100 MHz)", 0), 0u)
        << text;
    EXPECT_NE(text.find("\n-- pairs (times ms): pair ready"), std::string::npos);
    EXPECT_NE(text.find(verdict == "within_budget" ? "\nVERDICT: within budget ("
                                                   : "\nVERDICT: OVER BUDGET ("),
              std::string::npos);
    const auto without_wall = [](const std::string& t) {
        const size_t run = t.find("\nrun: ");
        return t.substr(0, run) + t.substr(t.find('\n', run + 1));
    };
    EXPECT_EQ(without_wall(text), without_wall(read_file(without_csv + "/report.txt")));
    const std::string timeline = read_file(with_csv + "/timeline.csv");
    EXPECT_EQ(timeline.rfind("tick,time_ns,kind,name,a,b,c\n", 0), 0u);
    EXPECT_NE(timeline.find(",stage_begin,"), std::string::npos) << timeline.substr(0, 200);
    EXPECT_FALSE(fs::exists(without_csv + "/timeline.csv"));
}

TEST(cli_report, schema_csv_verdict_and_reproducibility) {
    const std::string a = testing::TempDir() + "cli_report_a";
    const std::string b = testing::TempDir() + "cli_report_b";
    fs::remove_all(a);
    fs::remove_all(b);
    const std::string args = "run --scenario default --frames 5 --seed 3 --quiet --timeline-csv";
    const run_output first = run_binary(args + " --out " + a);
    const run_output second =
        run_binary("run --scenario default --frames 5 --seed 3 --progress --out " + b);
    ASSERT_TRUE(fs::exists(a + "/report.json")) << first.err;
    ASSERT_TRUE(fs::exists(b + "/report.json")) << second.err;
    const json report = json::parse(read_file(a + "/report.json"));

    // ---- exit status = verdict; 5 periods are too short for the detector's
    // three frames, the tracker, the SAD stereo and the 3D stage to run: the
    // budget judged them not
    // ("not judged", the frames to ask for)
    EXPECT_EQ(first.status, report["verdict"] == "within_budget" ? 0 : 1);
    EXPECT_FALSE(report["judged"].get<bool>());
    EXPECT_EQ(
        report["not_judged"],
        "not judged: detect, track, stereo_sad, xyz never ran in 5 periods; ask for --frames 9 "
        "or more");
    EXPECT_EQ(second.status, first.status);
    // Off a terminal, --quiet: nothing on stderr at all (no SystemC banner).
    EXPECT_EQ(first.err.find("SystemC"), std::string::npos) << first.err;
    EXPECT_EQ(second.err.find("SystemC"), std::string::npos);
    // --progress drew the line up to the last period.
    EXPECT_NE(second.err.find("frame 5/5"), std::string::npos) << second.err;

    // ---- schema
    schema_validator validator(
        json::parse(read_file(std::string(STEREOSIM_SOURCE_DIR) + "/docs/report-schema.json")));
    std::vector<std::string> errors = validator.validate(report);
    for (const std::string& e : errors) ADD_FAILURE() << e;
    EXPECT_EQ(report["schema_version"], 1);
    // Every stage_ms has one key per stage the firmware declares (what the
    // schema cannot say: the names are the firmware's).
    std::set<std::string> stages;
    for (const json& s : report["tool"]["firmware"]["stages"]) stages.insert(s.get<std::string>());
    EXPECT_EQ(stages.size(), 7u);
    auto keys_of = [](const json& object) {
        std::set<std::string> keys;
        for (const auto& [key, value] : object.items()) keys.insert(key);
        return keys;
    };
    EXPECT_EQ(keys_of(report["summary"]["timing"]["stage_ms"]), stages);
    for (const json& row : report["frames"]) {
        if (!row["stage_ms"].is_null()) {
            EXPECT_EQ(keys_of(row["stage_ms"]), stages);
        }
    }
    EXPECT_EQ(report["frames"].size(), 5u);
    // The validator rejects broken reports (each a copy with one defect).
    std::vector<std::pair<std::string, json>> broken;
    json r = report;
    r.erase("schema_version");
    broken.push_back({"no schema_version", r});
    r = report;
    r["summary"]["sync"]["unsynced_pairs_used"] = "none";
    broken.push_back({"string count", r});
    r = report;
    r["summary"]["timing"]["stage_ms"]["stereo_sad"]["max"] = -1.0;
    broken.push_back({"negative stage time", r});
    r = report;
    r["frames"][2]["sync"]["card"] = "maybe";
    broken.push_back({"bad enum", r});
    r = report;
    r["frames"][0]["unexpected"] = 1;
    broken.push_back({"extra frame field", r});
    r = report;
    r["verdict"] = "fine";
    broken.push_back({"bad verdict", r});
    r = report;
    r["summary"]["timing"]["budget_ms"] = -1.0;
    broken.push_back({"negative budget", r});
    for (const auto& [what, doc] : broken)
        EXPECT_FALSE(validator.validate(doc).empty()) << "accepted a report with: " << what;

    // ---- frames.csv: the same rows
    std::ifstream csv(a + "/frames.csv");
    std::string header_line;
    ASSERT_TRUE(std::getline(csv, header_line));
    const std::vector<std::string> header = split(header_line);
    // Column name -> JSON pointer, as docs/cli.md documents it.
    auto pointer_of = [](const std::string& column) -> std::string {
        static const std::vector<std::pair<std::string, std::string>> fixed = {
            {"card_verdict", "/sync/card"},
            {"oe_restarts", "/sync/oe_restarts"},
            {"pair", "/sync/pair"},
            {"in_step", "/sync/in_step"},
            {"judged", "/budget/judged"},
            {"over_budget", "/budget/over_budget"},
            {"cpu_busy_ms", "/budget/cpu_busy_ms"},
            {"emif_busy_ms", "/budget/emif_busy_ms"},
            {"slack_ms", "/budget/slack_ms"},
            {"fifo_peak_left", "/budget/fifo_peak_words/left"},
            {"fifo_peak_right", "/budget/fifo_peak_words/right"},
            {"overflow", "/budget/overflow"},
            {"drops", "/budget/drops"},
            {"est_x_mm", "/estimate/x"},
            {"est_y_mm", "/estimate/y"},
            {"est_z_mm", "/estimate/z"},
            {"true_x_mm", "/truth/x"},
            {"true_y_mm", "/truth/y"},
            {"true_z_mm", "/truth/z"},
            {"true_z_visible_mm", "/truth/z_visible"},
            {"err_x_mm", "/errors/x_mm"},
            {"err_y_mm", "/errors/y_mm"},
            {"err_z_mm", "/errors/z_mm"},
            {"err_depth_pct", "/errors/depth_pct"},
            {"err_disparity_px", "/errors/disparity_px"},
            {"err_box_centre_px", "/errors/box_centre_px"}};
        for (const auto& [name, p] : fixed)
            if (name == column) return p;
        for (const char* pair_field :
             {"scene_frame", "captured", "processed", "capture_ms", "processing_ms", "latency_ms"})
            if (column == pair_field) return std::string("/pair/") + pair_field;
        if (column.rfind("stage_", 0) == 0)
            return "/stage_ms/" + column.substr(6, column.size() - 9);
        for (const char* box : {"box_right_", "box_left_"})
            if (column.rfind(box, 0) == 0)
                return "/" + std::string(box).substr(0, std::string(box).size() - 1) + "/" +
                       column.substr(std::string(box).size());
        return "/" + column;
    };
    size_t rows = 0, cells_compared = 0, non_empty = 0;
    for (std::string line; std::getline(csv, line); ++rows) {
        const std::vector<std::string> cells = split(line);
        ASSERT_EQ(cells.size(), header.size()) << "row " << rows;
        ASSERT_LT(rows, report["frames"].size());
        const json& row = report["frames"][rows];
        for (size_t c = 0; c < header.size(); ++c) {
            const json v = value_at(row, pointer_of(header[c]));
            ++cells_compared;
            if (v.is_null()) {
                EXPECT_EQ(cells[c], "") << header[c] << " row " << rows;
                continue;
            }
            ++non_empty;
            if (v.is_boolean())
                EXPECT_EQ(cells[c], v.get<bool>() ? "1" : "0") << header[c];
            else if (v.is_string())
                EXPECT_EQ(cells[c], v.get<std::string>()) << header[c];
            else
                EXPECT_NEAR(std::stod(cells[c]), v.get<double>(), 1e-9)
                    << header[c] << " row " << rows;
        }
    }
    EXPECT_EQ(rows, report["frames"].size());
    // Every stage column present (docs/design-brief.md stage names).
    for (const char* stage :
         {"capture", "preprocess", "detect", "track", "stereo_sad", "stereo_edge", "xyz"})
        EXPECT_NE(std::find(header.begin(), header.end(), std::string("stage_") + stage + "_ms"),
                  header.end());

    // ---- the summary agrees with the rows
    int over = 0, verdict_errors = 0, forwarded = 0;
    for (const json& f : report["frames"]) {
        over += f["budget"]["over_budget"].get<bool>();
        verdict_errors += f["sync"]["card"] == "sync_error";
        forwarded += !f["sync"]["pair"].is_null();
    }
    EXPECT_EQ(report["summary"]["timing"]["frames_over_budget"], over);
    EXPECT_EQ(report["summary"]["sync"]["mismatches_detected"], verdict_errors);
    EXPECT_EQ(report["summary"]["sync"]["pairs_forwarded"], forwarded);
    EXPECT_EQ(report["summary"]["sync"]["unsynced_pairs_used"], 0);
    EXPECT_NEAR(report["summary"]["sim"]["simulated_s"].get<double>(), 5 * 0.0245, 1e-9);

    // ---- reproducible: identical but for summary.sim
    json other = json::parse(read_file(b + "/report.json"));
    json mine = report;
    mine["summary"].erase("sim");
    other["summary"].erase("sim");
    EXPECT_EQ(mine.dump(2), other.dump(2));
    EXPECT_EQ(read_file(a + "/frames.csv"), read_file(b + "/frames.csv"));

    expect_text_report_and_timeline(a, b, report["verdict"]);
    // No staging folder left behind.
    for (const auto& entry : fs::directory_iterator(a))
        EXPECT_EQ(entry.path().filename().string().rfind(".stereosim-staging", 0),
                  std::string::npos);

    std::printf(
        "report: verdict %s (exit %d), %zu frames, %zu csv cells compared (%zu non-empty), "
        "%d periods over budget, %d sync errors, %d pairs forwarded, sim ratio %.4f, "
        "%zu broken reports rejected\n",
        report["verdict"].get<std::string>().c_str(), first.status, rows, cells_compared, non_empty,
        over, verdict_errors, forwarded, report["summary"]["sim"]["ratio"].get<double>(),
        broken.size());
}

}  // namespace

// No figure over an empty set: the `near` scenario's ball is nearer than
// 1 m, so no scored depth is in the paper's 1-3 m range; the maximum there is
// null ("none in range"), and the one over every scored point is given.
TEST(cli_report, a_maximum_over_no_frame_is_null) {
    const std::string dir = testing::TempDir() + "cli_report_near";
    fs::remove_all(dir);
    const run_output r = run_binary("run --scenario near --frames 12 --quiet --out " + dir);
    ASSERT_TRUE(fs::exists(dir + "/report.json")) << r.err;
    const json accuracy = json::parse(read_file(dir + "/report.json"))["summary"]["accuracy"];
    ASSERT_GT(accuracy["points_scored"].get<int>(), 0) << accuracy.dump();
    EXPECT_EQ(accuracy["depth_scored_1_3m"], 0) << accuracy.dump();
    EXPECT_TRUE(accuracy["depth_err_pct_max"].is_null()) << accuracy.dump();
    ASSERT_TRUE(accuracy["depth_err_pct_max_all"].is_number()) << accuracy.dump();
    EXPECT_GT(accuracy["depth_err_pct_max_all"].get<double>(), 0.0);
    const std::string text = read_file(dir + "/report.txt");
    EXPECT_NE(text.find("depth at 1-3 m none in range; all scored depths " +
                        accuracy["points_scored"].dump() + ", max "),
              std::string::npos)
        << text.substr(text.find("-- track:"), 300);
    fs::remove_all(dir);
}

// A run in which no period could be judged (two frames: no pair is
// forwarded yet) is no fit, exit 1, but no overrun: report.txt and the
// summary say NOT JUDGED, not OVER BUDGET.
TEST(cli_report, a_run_that_judged_no_period_says_not_judged) {
    const std::string dir = testing::TempDir() + "cli_report_unjudged";
    fs::remove_all(dir);
    const run_output r =
        run_binary("run --frames 2 --summary --out " + dir + " > " + dir + ".summary");
    EXPECT_EQ(r.status, 1) << r.err;
    const json report = json::parse(read_file(dir + "/report.json"));
    EXPECT_EQ(report["verdict"], "over_budget");
    EXPECT_EQ(report["judged"], false);
    const std::string text = read_file(dir + "/report.txt");
    EXPECT_NE(text.find("\nVERDICT: NOT JUDGED: no period could be judged (0 judged periods, 0 "
                        "overruns)\n"),
              std::string::npos)
        << text.substr(text.find("VERDICT"));
    const std::string summary = read_file(dir + ".summary");
    EXPECT_NE(summary.find("\nVERDICT  NOT JUDGED: no period could be judged: 0 of 0 judged"),
              std::string::npos)
        << summary;
    fs::remove_all(dir);
    fs::remove(dir + ".summary");
}
