// `stereosim sweep` and `stereosim merge` as a user runs them (docs/sweep.md,
// docs/cluster.md): bad grids are one-line errors that write nothing; a
// point's figures are the ones `stereosim run` writes for the same keys;
// the closed form's capture time is docs/budget.md's hand derivation and its
// P_max is near the co-simulation's; the frontier is the smallest
// fitting CPU clock; shards merge into exactly the unsharded sweep; the
// screen co-simulates the boundary; --emit-slurm writes a job array.
#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/shell.h"

namespace {

using nlohmann::json;
using testsupport::read_text;

const std::string binary = STEREOSIM_BINARY;

testsupport::command_result stereosim(const std::string& args) {
    return testsupport::run_command(binary + " " + args);
}

json read_json(const std::string& path) {
    return json::parse(read_text(path), nullptr, false);
}

// The document without what differs run to run or with the job count.
json without_wall(json doc) {
    doc.erase("wall_s");
    doc.erase("jobs");
    for (json& p : doc["points"]) p.erase("wall_s");
    return doc;
}

size_t lines_of(const std::string& text) {
    size_t n = 0;
    for (char c : text) n += c == '\n';
    return n;
}

struct bad_case {
    const char* args;
    const char* message;  // part of the one-line error
};

TEST(Sweep, BadInputIsOneLineExit2AndWritesNothing) {
    const bad_case cases[] = {
        {"--grid rig.baselin_mm=100,200", "did you mean 'rig.baseline_mm'"},
        {"--grid dsk.cpu_mhz=", "no values"},
        {"--grid dsk.cpu_mhz=600,fast", "dsk.cpu_mhz"},
        {"--grid dsk.cpu_mhz=600,,700", "empty value"},
        {"--grid dsk.cpu_mhz=5000", "dsk.cpu_mhz"},
        {"--grid dsk.cpu_mhz=600:300:100", "LO <= HI"},
        {"--grid dsk.cpu_mhz=300:600:0", "STEP > 0"},
        {"--grid firmware.stereo_method=sad:edge:1", "a range is LO:HI:STEP"},
        {"--grid rig.baseline_mm=sad:edge:1", "a range is LO:HI:STEP (three numbers)"},
        {"--grid sensor.noise=0:1:1", "needs a number key"},
        {"--grid dsk.cpu_mhz=300 --grid dsk.cpu_mhz=600", "given twice"},
        {"--grid run.seed=0:20000:1", "more than 10,000 points"},
        {"--grid dsk.cpu_mhz=150,600", "point 0 (dsk.cpu_mhz=150.0)"},
        {"--grid dsk.cpu_mhz=600 --shard 3/2", "--shard"},
        {"--grid dsk.cpu_mhz=600 --set bogus.key=1", "unknown config key 'bogus.key'"},
        {"--grid dsk.cpu_mhz=600 --frames 0", "--frames"},
        {"--grid dsk.cpu_mhz=600 --emit-slurm --slurm-tasks 0", "--slurm-tasks"},
        {"--grid dsk.cpu_mhz=600 --emit-slurm --slurm-time soon", "--slurm-time"},
    };
    for (const bad_case& c : cases) {
        const std::string dir = testsupport::temp_dir("sweep-bad") + "/out";
        const auto r = stereosim(std::string("sweep ") + c.args + " --out " + dir);
        EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.output;
        EXPECT_EQ(lines_of(r.output), 1u) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << ": " << r.output;
        EXPECT_FALSE(testsupport::file_exists(dir)) << c.args << " wrote " << dir;
    }
    const auto no_out = stereosim("sweep --grid dsk.cpu_mhz=600");
    EXPECT_EQ(no_out.exit_code, 2) << no_out.output;
    EXPECT_NE(no_out.output.find("--out"), std::string::npos) << no_out.output;
}

// 200 MHz with a 97 x 97 search window cannot process a tracked pair in a
// period (the closed form: 29.98 ms; docs/budget.md's 300 MHz / radius 96
// case is over for the same reason); 250 MHz can; radius 8 fits at both.
TEST(Sweep, PointsAreTheirRunsAndTheClosedFormAgrees) {
    const std::string dir = testsupport::temp_dir("sweep-points");
    const auto r = stereosim(
        "sweep --grid dsk.cpu_mhz=200,250 --grid firmware.search_radius=8,48 "
        "--frames 8 --jobs 2 --out " +
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const json sweep = read_json(dir + "/sweep.json");
    ASSERT_EQ(sweep["points"].size(), 4u);
    std::map<std::string, json> by_keys;
    for (const json& p : sweep["points"]) by_keys[p["keys"].dump()] = p;
    const json over =
        by_keys[json({{"dsk.cpu_mhz", 200.0}, {"firmware.search_radius", 48}}).dump()];
    ASSERT_TRUE(over.is_object());
    EXPECT_EQ(over["verdict"], "over");
    EXPECT_EQ(over["first_overrun"]["resource"], "cpu");
    EXPECT_EQ(over["closed_form"]["verdict"], "over");
    for (const json& p : sweep["points"]) {
        EXPECT_EQ(p["closed_form_agrees"], true) << p.dump();
        if (p["keys"]["firmware.search_radius"] == 8) EXPECT_EQ(p["verdict"], "within");
        // docs/budget.md: C = 2,255,621 ECLK at 100 MHz = 22.556 ms, whatever the CPU.
        EXPECT_NEAR(p["closed_form"]["capture_ms"].get<double>(), 22.55621, 1e-5);
    }
    // The closed form's P_max is the host's largest pair at the point's clock:
    // within 15 % of the co-simulation's (docs/sweep.md has the measured range).
    for (const json& p : sweep["points"]) {
        const double host = p["closed_form"]["processing_ms"], cosim = p["processing_ms_max"];
        EXPECT_NEAR(host / cosim, 1.0, 0.15) << p.dump();
    }
    // The point against `stereosim run` with the same keys (its report.json).
    const std::string run_dir = dir + "/run";
    const auto run = stereosim(
        "run --quiet --set run.frames=8 --set dsk.cpu_mhz=200 "
        "--set firmware.search_radius=48 --out " +
        run_dir);
    ASSERT_EQ(run.exit_code, 1) << run.output;  // over budget
    const json report = read_json(run_dir + "/report.json");
    const json& timing = report["summary"]["timing"];
    EXPECT_EQ(over["cpu_busy_ms_max"], timing["cpu_busy_ms_max"]);
    EXPECT_EQ(over["emif_busy_ms_max"], timing["emif_busy_ms_max"]);
    EXPECT_EQ(over["processing_ms_max"], timing["processing_ms_max"]);
    EXPECT_EQ(over["stage_ms_max"]["track"], timing["stage_ms"]["track"]["max"]);
    EXPECT_EQ(over["first_overrun"]["stage"], report["overruns"][0]["stage"]);
    double min_slack = 1e9;
    for (const json& f : report["frames"])
        if (f["budget"]["judged"] == true)
            min_slack = std::min(min_slack, f["budget"]["slack_ms"].get<double>());
    EXPECT_NEAR(over["min_slack_ms"].get<double>(), min_slack, 1e-9);
    // frontier.csv: per radius the smallest fitting CPU clock.
    const std::string frontier = read_text(dir + "/frontier.csv");
    EXPECT_NE(frontier.find("\n8,200.0,"), std::string::npos) << frontier;
    EXPECT_NE(frontier.find("\n48,250.0,"), std::string::npos) << frontier;
    // sweep.csv: a header and a row per point; fitmap.png a PNG.
    EXPECT_EQ(lines_of(read_text(dir + "/sweep.csv")), 5u);
    EXPECT_EQ(read_text(dir + "/fitmap.png").substr(1, 3), "PNG");
    // The map is drawn: the over-budget cell red, the others green (OpenCV's
    // reading of the PNG, BGR).
    const cv::Mat map = cv::imread(dir + "/fitmap.png", cv::IMREAD_COLOR);
    ASSERT_FALSE(map.empty());
    int red = 0, green = 0;
    for (int y = 0; y < map.rows; ++y)
        for (int x = 0; x < map.cols; ++x) {
            const cv::Vec3b p = map.at<cv::Vec3b>(y, x);
            red += p[2] > p[1] + 60 && p[2] > p[0] + 60;
            // The palette runs white (0) to green (+extent): a cell with a
            // twentieth of the largest |margin| is G - R = 5, G - B = 3.
            green += p[1] > p[2] + 5 && p[1] > p[0] + 3;
        }
    EXPECT_GT(red, 5000) << "pixels of the over-budget cell";
    EXPECT_GT(green, 5000) << "pixels of the cells that fit";
    EXPECT_FALSE(testsupport::file_exists(dir + "/points"));
}

// Points too short for the tracker to run judged nothing of it: 6 periods of
// the default scenario (the tracker starts after period 7) are "not_judged",
// never a fit in the map, the frontier or the summary; 9 are judged.
TEST(Sweep, APointThatJudgedNothingIsNoFit) {
    const std::string dir = testsupport::temp_dir("sweep-short");
    const auto r = stereosim("sweep --grid dsk.cpu_mhz=300,600 --frames 6 --jobs 2 --out " + dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const json sweep = read_json(dir + "/sweep.json");
    for (const json& p : sweep["points"]) {
        EXPECT_EQ(p["verdict"], "not_judged") << p.dump();
        EXPECT_NE(p["not_judged"].get<std::string>().find("track"), std::string::npos);
        EXPECT_NE(p["not_judged"].get<std::string>().find("ask for --frames 9 or more"),
                  std::string::npos);
    }
    EXPECT_EQ(sweep["summary"]["not_judged"], 2);
    EXPECT_EQ(sweep["summary"]["within"], 0);
    // The frontier names no fitting clock; the map marks the cells.
    const std::string frontier = read_text(dir + "/frontier.csv");
    EXPECT_EQ(frontier, "smallest_fitting_dsk.cpu_mhz,slack_ms,source,points\n,,,2\n");
    EXPECT_NE(read_text(dir + "/fitmap.dat").find("\"not judged\""), std::string::npos);
    EXPECT_NE(r.output.find("2 not judged"), std::string::npos) << r.output;
    const auto judged = stereosim("sweep --grid dsk.cpu_mhz=600 --frames 9 --out " + dir + "/9");
    ASSERT_EQ(judged.exit_code, 0) << judged.output;
    EXPECT_EQ(read_json(dir + "/9/sweep.json")["points"][0]["verdict"], "within");
}

TEST(Sweep, ShardsMergeIntoTheUnshardedSweep) {
    const std::string dir = testsupport::temp_dir("sweep-shards");
    const std::string grid =
        "sweep --grid dsk.cpu_mhz=300,600 --grid firmware.stereo_method=sad,edge --frames 3 ";
    ASSERT_EQ(stereosim(grid + "--jobs 2 --out " + dir + "/whole").exit_code, 0);
    for (int k = 1; k <= 3; ++k) {
        const auto r = stereosim(grid + "--jobs 1 --shard " + std::to_string(k) + "/3 --out " +
                                 dir + "/shard-" + std::to_string(k));
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    // A shard missing: named, with the points it held; nothing written.
    const auto partial =
        stereosim("merge " + dir + "/shard-1 " + dir + "/shard-3 --out " + dir + "/partial");
    EXPECT_EQ(partial.exit_code, 3) << partial.output;
    EXPECT_NE(partial.output.find("shard(s) 2 of 3 missing: points 1"), std::string::npos)
        << partial.output;
    EXPECT_FALSE(testsupport::file_exists(dir + "/partial"));
    const auto merged = stereosim("merge " + dir + "/shard-1 " + dir + "/shard-2 " + dir +
                                  "/shard-3 --out " + dir + "/merged");
    ASSERT_EQ(merged.exit_code, 0) << merged.output;
    const json whole = read_json(dir + "/whole/sweep.json");
    EXPECT_EQ(whole["points"].size(), 4u);
    EXPECT_EQ(without_wall(read_json(dir + "/merged/sweep.json")), without_wall(whole));
    for (const char* file : {"sweep.csv", "frontier.csv", "fitmap.dat"})
        EXPECT_EQ(read_text(dir + "/merged/" + file), read_text(dir + "/whole/" + file)) << file;
    // Shards of another grid do not merge with these.
    ASSERT_EQ(
        stereosim("sweep --grid dsk.cpu_mhz=300 --frames 3 --shard 2/3 --out " + dir + "/other")
            .exit_code,
        0);
    const auto mixed =
        stereosim("merge " + dir + "/shard-1 " + dir + "/other --out " + dir + "/mixed");
    EXPECT_EQ(mixed.exit_code, 2) << mixed.output;
}

TEST(Sweep, ScreenCoSimulatesTheBoundary) {
    const std::string dir = testsupport::temp_dir("sweep-screen");
    const auto r = stereosim(
        "sweep --screen --grid dsk.cpu_mhz=200,250,300,400,500,600,800,1000 "
        "--set firmware.search_radius=48 --frames 8 --out " +
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const json sweep = read_json(dir + "/sweep.json");
    ASSERT_EQ(sweep["points"].size(), 8u);
    int simulated = 0;
    for (const json& p : sweep["points"]) {
        const double mhz = p["keys"]["dsk.cpu_mhz"];
        EXPECT_TRUE(p["closed_form"]["verdict"].is_string());
        EXPECT_EQ(p["closed_form"]["verdict"], mhz < 225 ? "over" : "within") << p.dump();
        // The closed form changes its verdict between 200 and 250: both co-simulated.
        if (mhz == 200 || mhz == 250) EXPECT_EQ(p["screen"], "boundary") << p.dump();
        if (mhz >= 400) EXPECT_NE(p["screen"], "boundary") << p.dump();
        simulated += p["simulate"].get<bool>();
        EXPECT_EQ(p.contains("verdict"), p["simulate"].get<bool>()) << p.dump();
    }
    EXPECT_EQ(simulated, sweep["summary"]["simulated"].get<int>());
    EXPECT_LT(simulated, 8);
    EXPECT_NE(read_text(dir + "/frontier.csv").find("\n250.0,"), std::string::npos)
        << read_text(dir + "/frontier.csv");
}

TEST(Sweep, EmitSlurmWritesAJobArrayOfTheShards) {
    const std::string dir = testsupport::temp_dir("sweep-slurm");
    const auto r = stereosim(
        "sweep --grid dsk.cpu_mhz=300,600 --frames 4 --emit-slurm "
        "--slurm-tasks 3 --slurm-cpus 1 --slurm-time 00:30:00 --out " +
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("submit: sbatch '" + dir + "/job.sbatch'"), std::string::npos)
        << r.output;
    const std::string job = read_text(dir + "/job.sbatch");
    EXPECT_NE(job.find("#SBATCH --array=1-3\n"), std::string::npos) << job;
    EXPECT_NE(job.find("#SBATCH --cpus-per-task=1\n"), std::string::npos) << job;
    EXPECT_NE(job.find("#SBATCH --time=00:30:00\n"), std::string::npos) << job;
    EXPECT_NE(job.find("'sweep' '--grid' 'dsk.cpu_mhz=300,600' '--frames' '4' --jobs 1 --shard "
                       "\"$task/3\" --out '" +
                       dir + "/shard-'\"$task\""),
              std::string::npos)
        << job;
    EXPECT_FALSE(testsupport::file_exists(dir + "/sweep.json"));
    const auto campaign =
        stereosim("faults --campaign smoke --emit-slurm --out " + dir + "/campaign");
    ASSERT_EQ(campaign.exit_code, 0) << campaign.output;
    const std::string cjob = read_text(dir + "/campaign/job.sbatch");
    EXPECT_NE(cjob.find("'faults' '--campaign' 'smoke' --jobs 2 --shard \"$task/4\""),
              std::string::npos)
        << cjob;
}

}  // namespace
