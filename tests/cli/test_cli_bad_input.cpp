// Bad input to `stereosim run`: each gets ONE line on stderr naming the
// problem, exit status 2, and nothing written into --out (no report.json, no
// frames.csv, no staging folder). A good replay manifest beside the broken
// ones runs (the negative control: the errors are not spurious).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

namespace {

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

std::string temp(const std::string& name) {
    return testing::TempDir() + "cli_bad_" + name;
}

run_output run_binary(const std::string& args) {
    // One file per test process: ctest -j runs this file's tests side by side.
    const std::string err = temp("stderr_" + std::to_string(getpid()) + ".txt");
    const std::string command =
        std::string(STEREOSIM_BINARY) + " " + args + " 2>" + err + " >/dev/null";
    const int raw = std::system(command.c_str());
    run_output out;
    out.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    out.err = read_file(err);
    return out;
}

void write(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

// Runs with --out into a fresh folder; expects exit 2, one line containing
// `expected`, and nothing written.
void expect_bad(const std::string& args, const std::string& expected) {
    const std::string out = temp("out_" + std::to_string(getpid()));
    fs::remove_all(out);
    const run_output r = run_binary(args + " --out " + out);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\nstderr: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    EXPECT_EQ(r.err.rfind("stereosim: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(out + "/report.json")) << args;
    EXPECT_FALSE(fs::exists(out + "/frames.csv")) << args;
    if (fs::exists(out))
        for (const auto& e : fs::directory_iterator(out)) ADD_FAILURE() << "left " << e.path();
    std::printf("%-60s -> exit %d: %s", args.substr(0, 60).c_str(), r.status, r.err.c_str());
}

TEST(cli_bad_input, unknown_scenario) {
    expect_bad("run --scenario tornado",
               "unknown scenario 'tornado' (stereosim scenarios lists them)");
}

TEST(cli_bad_input, config_files) {
    const std::string malformed = temp("malformed.json");
    write(malformed, "{\"version\": 1, \"run\": {\"frames\": 4,}}");
    expect_bad("run --config " + malformed, "malformed JSON: parse error at line 1");
    const std::string misspelled = temp("misspelled.json");
    write(misspelled, "{\"version\": 1, \"rig\": {\"baselin_mm\": 100}}");
    expect_bad("run --config " + misspelled,
               "unknown config key 'rig.baselin_mm' (did you mean 'rig.baseline_mm'?)");
    const std::string version = temp("version.json");
    write(version, "{\"version\": 2, \"run\": {\"frames\": 4}}");
    expect_bad("run --config " + version, "unsupported version 2 (this stereosim reads version 1)");
    const std::string no_version = temp("no_version.json");
    write(no_version, "{\"run\": {\"frames\": 4}}");
    expect_bad("run --config " + no_version, "missing \"version\"");
    const std::string wrong_type = temp("wrong_type.json");
    write(wrong_type, "{\"version\": 1, \"run\": {\"frames\": \"four\"}}");
    expect_bad("run --config " + wrong_type,
               "config key 'run.frames': expected an integer, got \"four\"");
    expect_bad("run --config " + temp("does_not_exist.json"), "cannot read config file");
}

TEST(cli_bad_input, misspelled_set_key) {
    expect_bad("run --frames 4 --set rig.baselin_mm=100",
               "unknown config key 'rig.baselin_mm' (did you mean 'rig.baseline_mm'?)");
    expect_bad("run --set firmware.mode", "--set 'firmware.mode': expected key=value");
}

TEST(cli_bad_input, out_of_range_values) {
    expect_bad("run --frames -3",
               "--frames: config key 'run.frames': -3 is out of range 1..100000");
    expect_bad("run --frames 0", "out of range 1..100000");
    expect_bad("run --cpu-mhz 0", "config key 'dsk.cpu_mhz': 0 is out of range 50..2000");
    expect_bad("run --set dsk.cpu_mhz=0", "config key 'dsk.cpu_mhz': 0 is out of range 50..2000");
    expect_bad("run --set firmware.search_radius=300",
               "the search window 601 x 601 px is larger than the image (640 x 480)");
    expect_bad("run --dsk v7", "--dsk: config key 'dsk.version': 7 is out of range 1..3");
    // Whole numbers in full, not 2.14748e+09.
    expect_bad("run --seed 3000000000",
               "--seed: config key 'run.seed': 3000000000 is out of range 0..2147483647");
    expect_bad("run --mode parallel", "is not one of sequential|overlapped");
    expect_bad("run --frames 4 --bogus", "--bogus");  // CLI11: not an option
}

// The fault contract's rule 1 has no exception with the card's frame-identity
// check on; a run that turns it off must say it judges the paper's card.
TEST(cli_bad_input, frame_id_check_off_under_the_strict_contract) {
    expect_bad(
        "run --frames 4 --fault extra-frame:sensor=R@frame=2 "
        "--set firmware.card_frame_id_check=false",
        "firmware.card_frame_id_check=0 turns the card's frame-identity check off, but "
        "--fault asks the contract for rule 1 without exception: add --paper-card");
}

TEST(cli_bad_input, file_options_without_out) {
    const run_output r = run_binary("run --frames 1 --timeline-csv");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(r.err,
              "stereosim: error: --timeline-csv needs --out DIR (it writes "
              "DIR/timeline.csv)\n");
}

// A replay set of 640 x 480 PNGs made here (frames 0..4), its manifest, and
// broken variants: missing manifest, a corrupt image, too short for the run.
TEST(cli_bad_input, replay_manifests) {
    const std::string dir = temp("replay");
    fs::remove_all(dir);
    fs::create_directories(dir + "/left");
    fs::create_directories(dir + "/right");
    for (int n = 0; n < 5; ++n) {
        cv::Mat image(480, 640, CV_8UC3, cv::Scalar(60 + 10 * n, 90, 120));
        cv::imwrite(dir + "/left/f" + std::to_string(n) + ".png", image);
        cv::imwrite(dir + "/right/f" + std::to_string(n) + ".png", image);
    }
    const std::string manifest_text =
        "stereosim_replay 1\nsize 640 480\nframes 5\nleft left/f%d.png\nright right/f%d.png\n"
        "focal_px 789.5\nbaseline_m 0.12\nprincipal_left 319.5 239.5\nprincipal_right 319.5 "
        "239.5\n";
    write(dir + "/good.txt", manifest_text);

    expect_bad("run --frames 3 --replay " + dir + "/missing.txt", "missing.txt");
    expect_bad("run --frames 8 --replay " + dir + "/good.txt", "(the run needs frames 0..8)");
    // A corrupt image: the PNG header torn off the third right frame.
    fs::create_directories(dir + "/bad/left");
    fs::create_directories(dir + "/bad/right");
    for (int n = 0; n < 5; ++n) {
        fs::copy_file(dir + "/left/f" + std::to_string(n) + ".png",
                      dir + "/bad/left/f" + std::to_string(n) + ".png");
        fs::copy_file(dir + "/right/f" + std::to_string(n) + ".png",
                      dir + "/bad/right/f" + std::to_string(n) + ".png");
    }
    const std::string victim = dir + "/bad/right/f2.png";
    const std::string bytes = read_file(victim);
    write(victim, "garbage!" + bytes.substr(8, 200));
    write(dir + "/bad/manifest.txt", manifest_text);
    expect_bad("run --frames 3 --replay " + dir + "/bad/manifest.txt", "f2.png");

    // The control: the good manifest runs; no scene ball, so truth is null.
    const std::string out = temp("replay_out");
    fs::remove_all(out);
    const run_output r =
        run_binary("run --frames 3 --quiet --replay " + dir + "/good.txt --out " + out);
    EXPECT_TRUE(r.status == 0 || r.status == 1) << r.err;
    const std::string report = read_file(out + "/report.json");
    EXPECT_NE(report.find("\"replay\": \"" + dir + "/good.txt\""), std::string::npos);
    EXPECT_EQ(report.find("\"z_visible\""), std::string::npos);  // no truth anywhere
    std::printf("replay control: exit %d, report %zu bytes\n", r.status, report.size());
}

TEST(cli_bad_input, unwritable_out_folder) {
    const std::string file = temp("a_file");
    write(file, "x");
    // A folder cannot be made under a file (root may write anywhere else).
    const std::string out = file + "/sub";
    const run_output r = run_binary("run --frames 4 --out " + out);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("cannot create output folder '" + out + "'"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    std::printf("unwritable --out -> exit %d: %s", r.status, r.err.c_str());
}

// --resume keeps only rows of this campaign's own plan: a row another
// stereosim's plan ran under the same index is refused, not merged.
TEST(cli_bad_input, resume_of_another_plan) {
    const std::string dir = temp("resume");
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string document =
        R"({"campaign":"smoke","seeds":0,"shard":"1/1","match":"","rows":[{"index":0,)"
        R"("fault":"bogus","seed":3,"frames":8,"retry_limit":8,"ran":true}]})";
    write(dir + "/campaign.json", document);
    const struct {
        std::string args, message;
    } bad[] = {
        {"faults --campaign smoke --resume " + dir,
         "run 0 of " + dir + "/campaign.json is not this campaign's"},
        {"faults --campaign smoke --resume " + dir + " --emit-slurm", "no --emit-slurm"},
        {"sweep --grid dsk.eclk_mhz=100,133 --resume " + dir + " --emit-slurm", "no --emit-slurm"},
        {"sweep --grid dsk.eclk_mhz=100,133 --resume " + dir, "sweep.json not found"},
    };
    for (const auto& b : bad) {
        const run_output r = run_binary(b.args);
        EXPECT_EQ(r.status, 2) << b.args << "\n" << r.err;
        EXPECT_NE(r.err.find(b.message), std::string::npos) << b.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_EQ(read_file(dir + "/campaign.json"), document) << "--resume changed the folder";
    }
    fs::remove_all(dir);
}

}  // namespace
