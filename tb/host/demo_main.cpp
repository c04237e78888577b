// stereosim_host_demo: the firmware on the default rendered stereo sequence
// with no hardware (host harness), frame by frame, scored against the
// scene's ground truth.
//
//   stereosim_host_demo [--frames N] [--out DIR]
//
// Prints a per-frame table and a summary; with --out writes DIR/frames.csv
// (DIR is created if missing; the file is written under a temporary name and
// renamed). A bad option: one line on stderr, exit status 2.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "model/scene/sequence.h"
#include "tb/host/error_metrics.h"
#include "tb/host/report.h"
#include "tb/host/stereo_runner.h"

namespace {

constexpr int default_frames = 100;  // the default scenario's nominal length (2.45 s)
constexpr int max_frames = 100000;

const char* const usage = "usage: stereosim_host_demo [--frames N] [--out DIR]";

struct options {
    int frames = default_frames;
    std::string out_dir;
};

// One-line error and false on anything it does not understand.
bool parse(int argc, char** argv, options* opt) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            std::printf("%s\n", usage);
            std::exit(0);
        }
        if (arg != "--frames" && arg != "--out") {
            std::fprintf(stderr, "stereosim_host_demo: unknown option '%s' (%s)\n", arg.c_str(),
                         usage);
            return false;
        }
        if (i + 1 >= argc) {
            std::fprintf(stderr, "stereosim_host_demo: %s needs a value (%s)\n", arg.c_str(),
                         usage);
            return false;
        }
        const char* value = argv[++i];
        if (arg == "--frames") {
            char* end = nullptr;
            errno = 0;
            const long n = std::strtol(value, &end, 10);
            if (end == value || *end != '\0' || errno != 0 || n < 1 || n > max_frames) {
                std::fprintf(stderr,
                             "stereosim_host_demo: --frames wants an integer in 1..%d, "
                             "got '%s'\n",
                             max_frames, value);
                return false;
            }
            opt->frames = static_cast<int>(n);
        } else {
            if (*value == '\0') {
                std::fprintf(stderr, "stereosim_host_demo: --out wants a directory\n");
                return false;
            }
            opt->out_dir = value;
        }
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    options opt;
    if (!parse(argc, argv, &opt)) return 2;
    if (!opt.out_dir.empty()) {  // fail before the run, not after it
        std::error_code error;
        std::filesystem::create_directories(opt.out_dir, error);
        if (error || !std::filesystem::is_directory(opt.out_dir)) {
            std::fprintf(stderr, "stereosim_host_demo: --out %s is not a usable directory%s%s\n",
                         opt.out_dir.c_str(), error ? ": " : "",
                         error ? error.message().c_str() : "");
            return 2;
        }
    }

    const scene::scenario scenario = scene::default_scenario();
    const dsp::controller_config config = host::controller_config_for(scenario.scene.rig);
    host::stereo_runner runner(scenario, config);
    std::printf(
        "stereosim host demo: default scenario, %dx%d, %d frames, CFA "
        "%s, stereo method %s, "
        "disparity %d..%d px\n",
        scenario.scene.rig.width, scenario.scene.rig.height, opt.frames,
        dsp::cfa_order_name(config.cfa), dsp::stereo_method_name(config.method),
        runner.firmware().config().stereo.min_disparity,
        runner.firmware().config().stereo.max_disparity);

    const std::vector<host::frame_record> records = runner.run(0, opt.frames);
    host::print_frame_table(stdout, records);
    const host::run_summary summary =
        host::summarize(records, host::first_motion_frame(runner.sequence(), opt.frames));
    std::printf("\n");
    host::print_summary(stdout, summary);

    if (!opt.out_dir.empty()) {
        const std::string path = opt.out_dir + "/frames.csv";
        std::string error;
        if (!host::write_frames_csv(path, records, &error)) {
            std::fprintf(stderr, "stereosim_host_demo: %s\n", error.c_str());
            return 1;
        }
        std::printf("wrote %s\n", path.c_str());
    }
    return 0;
}
