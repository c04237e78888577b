// stereosim_platform: one co-simulation of the stereo platform (docs/platform.md):
// two sensors -> card RTL -> EMIF -> C6416 running the firmware -> 3D track,
// with the scoreboard and the 24.5 ms budget check. Prints the report; exit
// status 0 when the run is within budget, 1 when over, 2 on a usage error.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <systemc>

#include "tb/platform/budget.h"
#include "tb/platform/platform.h"
#include "tb/platform/report.h"
#include "tb/platform/scoreboard.h"

namespace {

void usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: stereosim_platform [options]\n"
                 "  --frames N          sync periods to simulate (default 12)\n"
                 "  --mode M            sequential | overlapped (default overlapped)\n"
                 "  --seed S            sensor seeds 2S, 2S+1 (default 3)\n"
                 "  --dsk V             DSK version 1, 2 or 3 (default 1)\n"
                 "  --cpu-mhz F         CPU clock (custom DSK; EMIF as the version's)\n"
                 "  --search-radius R   SAD tracking search radius, pixels\n"
                 "  --still-frames N    still frames at the start of the default scenario (3)\n"
                 "  --quantum-ns Q      island sync quantum (default 46667: one line)\n"
                 "  --watchdog-ms W     the firmware's card watchdog period (default 500, 0 off)\n"
                 "  --frame-memory M    l2 | sdram: where the firmware's frames live (sdram)\n"
                 "  --no-sdram-bus      keep the firmware's SDRAM traffic off the EMIF bus\n"
                 "  --no-noise          sensors without noise\n"
                 "  --arrangement A     fast | pins (docs/arrangements.md; default fast)\n"
                 "  --no-pin-hash       do not hash pin changes\n"
                 "  --timeline PATH     write the timeline of pins and firmware as CSV\n"
                 "  --brief             no per-pair table\n");
}

bool parse_int(const char* text, long long* value) {
    char* end = nullptr;
    *value = std::strtoll(text, &end, 10);
    return end && *end == '\0' && end != text;
}

}  // namespace

int sc_main(int argc, char* argv[]) {
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    platform::platform_config config;
    std::string timeline_path;
    bool per_pair = true;
    long long cpu_mhz = 0, still_frames = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        long long v = 0;
        if (arg == "--help" || arg == "-h") {
            usage(stdout);
            return 0;
        } else if (arg == "--frames" && has_value && parse_int(argv[++i], &v) && v > 0) {
            config.frames = static_cast<int>(v);
        } else if (arg == "--mode" && has_value) {
            const std::string m = argv[++i];
            if (m == "sequential")
                config.mode = dsp::pipeline_mode::sequential;
            else if (m == "overlapped")
                config.mode = dsp::pipeline_mode::overlapped;
            else {
                std::fprintf(stderr, "unknown mode '%s'\n", m.c_str());
                return 2;
            }
        } else if (arg == "--seed" && has_value && parse_int(argv[++i], &v) && v >= 0) {
            config.seed = static_cast<uint64_t>(v);
        } else if (arg == "--dsk" && has_value && parse_int(argv[++i], &v) && v >= 1 && v <= 3) {
            config.dsk = c6416::dsk_version(static_cast<int>(v));
        } else if (arg == "--cpu-mhz" && has_value && parse_int(argv[++i], &v) && v > 0) {
            cpu_mhz = v;
        } else if (arg == "--search-radius" && has_value && parse_int(argv[++i], &v) && v > 0) {
            config.track_search_radius = static_cast<int>(v);
        } else if (arg == "--still-frames" && has_value && parse_int(argv[++i], &v) && v >= 0) {
            still_frames = v;
        } else if (arg == "--quantum-ns" && has_value && parse_int(argv[++i], &v) && v > 0) {
            config.quantum = v * simtime::ticks_per_ns;
        } else if (arg == "--watchdog-ms" && has_value && parse_int(argv[++i], &v) && v >= 0) {
            config.watchdog_ms = static_cast<uint32_t>(v);
        } else if (arg == "--frame-memory" && has_value) {
            const std::string m = argv[++i];
            if (m == "l2")
                config.frame_memory = dsp::cost::memory::l2;
            else if (m == "sdram")
                config.frame_memory = dsp::cost::memory::sdram;
            else {
                std::fprintf(stderr, "unknown frame memory '%s'\n", m.c_str());
                return 2;
            }
        } else if (arg == "--no-sdram-bus") {
            config.sdram_traffic_on_bus = false;
        } else if (arg == "--no-noise") {
            config.sensor_noise = false;
        } else if (arg == "--arrangement" && has_value) {
            const std::string a = argv[++i];
            if (a == "fast" || a == "pins") {
                config.arrangement = a == "pins" ? platform::arrangement_kind::pins
                                                 : platform::arrangement_kind::fast;
            } else {
                std::fprintf(stderr, "unknown arrangement '%s'\n", a.c_str());
                return 2;
            }
        } else if (arg == "--no-pin-hash") {
            config.hash_pins = false;
        } else if (arg == "--timeline" && has_value) {
            timeline_path = argv[++i];
        } else if (arg == "--brief") {
            per_pair = false;
        } else {
            std::fprintf(stderr, "unknown or incomplete option '%s'\n", arg.c_str());
            usage(stderr);
            return 2;
        }
    }
    if (cpu_mhz > 0) {
        const int version = config.dsk.version;
        config.dsk = c6416::dsk_custom(cpu_mhz * 1000000, config.dsk.emif_hz);
        config.dsk.version = version;  // the EMIF settings of that DSK
    }
    config.scenario = scene::default_scenario(static_cast<int>(still_frames));

    platform::platform_top top(config);
    top.run();
    if (top.firmware_init_failed()) {
        std::fprintf(stderr, "the firmware refused its configuration\n");
        return 2;
    }
    const platform::scoreboard_report score = platform::score(top);
    const platform::budget_report budget = platform::check_budget(top, score);
    platform::print_report(stdout, top, score, budget, per_pair);
    if (!timeline_path.empty() && !top.events().write_csv(timeline_path)) {
        std::fprintf(stderr, "cannot write %s\n", timeline_path.c_str());
        return 2;
    }
    return budget.fits ? 0 : 1;
}
