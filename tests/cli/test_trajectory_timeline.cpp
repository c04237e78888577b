// trajectory.png / trajectory.gp and timeline.json of a `stereosim run`
// (docs/waveforms.md), run as a user would: the PNG decoded by OpenCV and its
// plotted curves counted by colour, the script shown to read frames.csv by
// relative path (redrawn from an edited frames.csv it changes), the Chrome
// trace parsed as JSON and each stage's complete event matched with the
// stage times of report.json.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "tb/app/output/trajectory_plot.h"

namespace {

using nlohmann::json;

int run_command(const std::string& command, std::string* output = nullptr) {
    std::FILE* p = popen((command + " 2>&1").c_str(), "r");
    if (!p) return -1;
    char buffer[4096];
    size_t n;
    std::string out;
    while ((n = std::fread(buffer, 1, sizeof buffer, p)) > 0) out.append(buffer, n);
    const int status = pclose(p);
    if (output) *output = out;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string temp_dir() {
    char name[] = "/tmp/stereosim-test-plot-XXXXXX";
    const char* dir = mkdtemp(name);
    return dir ? dir : "";
}

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Pixels within a small distance of a series colour (anti-aliased edges
// blend with the white background; the line centres keep the colour).
int pixels_near(const cv::Mat& bgr, unsigned rgb, int max_distance = 40) {
    const int r = rgb >> 16 & 0xFF, g = rgb >> 8 & 0xFF, b = rgb & 0xFF;
    int count = 0;
    for (int y = 0; y < bgr.rows; ++y) {
        const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(y);
        for (int x = 0; x < bgr.cols; ++x) {
            const int db = row[x][0] - b, dg = row[x][1] - g, dr = row[x][2] - r;
            if (db * db + dg * dg + dr * dr <= max_distance * max_distance) ++count;
        }
    }
    return count;
}

}  // namespace

// Eight periods of the default scenario (the firmware's SDRAM traffic on the
// bus, the memory plan of docs/firmware.md): the ball is detected and tracked.
TEST(trajectory_timeline, plot_and_trace_of_a_tracked_run) {
    const std::string dir = temp_dir();
    ASSERT_FALSE(dir.empty());
    std::string out;
    const int code = run_command(std::string("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 ") +
                                     STEREOSIM_BINARY + " run --frames 8 --quiet --out " + dir,
                                 &out);
    ASSERT_LE(code, 1) << out;
    const json report = json::parse(read_text(dir + "/report.json"));
    int estimates = 0;
    for (const json& f : report.at("frames")) estimates += !f.at("estimate").is_null();
    ASSERT_GE(estimates, 2) << "the run should track the ball";

    // ---- trajectory.png: documented size, both series plotted
    const cv::Mat png = cv::imread(dir + "/trajectory.png", cv::IMREAD_COLOR);
    ASSERT_FALSE(png.empty());
    EXPECT_EQ(png.cols, output::trajectory_png_width);
    EXPECT_EQ(png.rows, output::trajectory_png_height);
    const int est = pixels_near(png, output::trajectory_estimate_rgb);
    const int tru = pixels_near(png, output::trajectory_truth_rgb);
    std::printf(
        "trajectory.png %dx%d: %d estimate-coloured pixels, %d truth-coloured pixels, "
        "%d frames with an estimate\n",
        png.cols, png.rows, est, tru, estimates);
    EXPECT_GT(est, 300);
    EXPECT_GT(tru, 1000);

    // ---- trajectory.gp reads frames.csv by relative path: redrawn elsewhere
    // from a frames.csv without estimates, the estimate colour disappears.
    const std::string script = read_text(dir + "/trajectory.gp");
    EXPECT_NE(script.find("'frames.csv'"), std::string::npos);
    const std::string copy = temp_dir();
    {
        std::ofstream(copy + "/trajectory.gp") << script;
        std::istringstream csv(read_text(dir + "/frames.csv"));
        std::string header, line;
        std::getline(csv, header);
        std::ofstream edited(copy + "/frames.csv");
        edited << header << "\n";
        // Blank every est_* column.
        std::vector<bool> blank;
        {
            std::istringstream h(header);
            std::string name;
            while (std::getline(h, name, ',')) blank.push_back(name.rfind("est_", 0) == 0);
        }
        while (std::getline(csv, line)) {
            std::istringstream l(line);
            std::string cell;
            for (size_t i = 0; std::getline(l, cell, ','); ++i)
                edited << (i ? "," : "") << (i < blank.size() && blank[i] ? "" : cell);
            edited << "\n";
        }
    }
    ASSERT_EQ(run_command("cd " + copy + " && gnuplot trajectory.gp"), 0);
    const cv::Mat redrawn = cv::imread(copy + "/trajectory.png", cv::IMREAD_COLOR);
    ASSERT_FALSE(redrawn.empty());
    const int est_redrawn = pixels_near(redrawn, output::trajectory_estimate_rgb);
    const int tru_redrawn = pixels_near(redrawn, output::trajectory_truth_rgb);
    std::printf("redrawn without estimates: %d estimate-coloured (key sample only), %d truth\n",
                est_redrawn, tru_redrawn);
    EXPECT_LT(est_redrawn, est / 2);
    EXPECT_GT(tru_redrawn, tru / 2);

    // ---- timeline.json: trace events, one complete event per stage that ran
    const json trace = json::parse(read_text(dir + "/timeline.json"));
    ASSERT_TRUE(trace.at("traceEvents").is_array());
    std::map<int, std::string> threads;
    // (pair, stage) -> summed duration in ms, and the event count
    std::map<std::pair<int, std::string>, double> stage_ms;
    std::map<std::pair<int, std::string>, int> stage_events;
    std::map<int, double> capture_ms;
    int interrupts = 0;
    for (const json& e : trace.at("traceEvents")) {
        const std::string ph = e.at("ph");
        ASSERT_TRUE(e.contains("pid") && e.contains("name"));
        if (ph == "M") {
            if (e.at("name") == "thread_name") threads[e.at("tid")] = e.at("args").at("name");
            continue;
        }
        ASSERT_TRUE(e.at("ts").is_number());
        if (ph == "X") {
            ASSERT_GE(e.at("dur").get<double>(), 0.0);
            if (e.at("cat") == "stage") {
                const auto key = std::make_pair(e.at("args").at("pair").get<int>(),
                                                e.at("name").get<std::string>());
                stage_ms[key] += e.at("dur").get<double>() / 1000.0;
                ++stage_events[key];
                EXPECT_EQ(e.at("tid"), 1);
            }
            if (e.at("cat") == "edma")
                capture_ms[e.at("args").at("pair")] = e.at("dur").get<double>() / 1000.0;
        } else if (ph == "i" && e.at("cat") == "interrupt") {
            ++interrupts;
        }
    }
    EXPECT_EQ(threads[1], "CPU (firmware)");
    EXPECT_EQ(threads[2], "EDMA");
    EXPECT_EQ(threads[3], "card");
    int matched = 0;
    double worst = 0.0;
    int late_left_pairs = 0;
    for (const json& f : report.at("frames")) {
        if (f.at("pair").is_null() || !f.at("pair").at("processed").get<bool>()) continue;
        const int pair = f.at("pair").at("number");
        for (const auto& s : f.at("stage_ms").items()) {
            const double ms = s.value().get<double>();
            const auto key = std::make_pair(pair, s.key());
            if (ms <= 0.0) {
                EXPECT_EQ(stage_events.count(key), 0u) << s.key() << " of pair " << pair;
                continue;
            }
            ASSERT_EQ(stage_events.count(key), 1u) << s.key() << " of pair " << pair;
            // Once per pair; preprocess twice where a DETECT pair that kept the
            // strided history in its left buffer detected and only then made
            // its left image (docs/firmware.md, "Slow detection").
            const json& stages = f.at("stage_ms");
            const bool late_left = s.key() == "preprocess" && stage_events[key] == 2 &&
                                   stages.at("detect").get<double>() > 0.0 &&
                                   stages.at("stereo_sad").get<double>() > 0.0;
            late_left_pairs += late_left;
            EXPECT_EQ(stage_events[key], late_left ? 2 : 1)
                << s.key() << " ran once for pair " << pair;
            EXPECT_NEAR(stage_ms[key], ms, 1e-4) << s.key() << " of pair " << pair;
            worst = std::max(worst, std::fabs(stage_ms[key] - ms));
            ++matched;
        }
        if (!f.at("pair").at("capture_ms").is_null()) {
            ASSERT_TRUE(capture_ms.count(pair));
            EXPECT_NEAR(capture_ms[pair], f.at("pair").at("capture_ms").get<double>(), 1e-4);
        }
    }
    std::printf(
        "timeline.json: %zu events, %d stage events matched report.json (worst %.2e ms), "
        "%zu capture chains, %d interrupt instants, %d pairs with a late left image\n",
        trace.at("traceEvents").size(), matched, worst, capture_ms.size(), interrupts,
        late_left_pairs);
    EXPECT_GE(matched, 10);
    EXPECT_GE(interrupts, 3);
}
