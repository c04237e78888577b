#include "tb/app/cli/run_command.h"
#include "tb/platform/firmware_crash.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <fstream>
#include <systemc>

#include "tb/app/cli/config_keys.h"
#include "tb/app/cli/console.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/app/cli/run_report.h"
#include "tb/app/cli/staged_files.h"
#include "tb/platform/budget.h"
#include "tb/platform/platform.h"
#include "tb/platform/report.h"
#include "tb/platform/scoreboard.h"

namespace cli {

namespace {

using nlohmann::json;

// A named option is a config key: the same checks and messages as --set.
bool add_assignment(const std::string& option, const std::string& key_name, const std::string& text,
                    std::vector<key_assignment>* out, std::string* error) {
    const config_key* key = find_key(key_name);
    if (!key) {  // a firmware's own key (--mode): checked once the firmware is known
        out->push_back({key_name, json(text)});
        return true;
    }
    json value;
    if (!parse_value(*key, text, &value, error)) {
        *error = option + ": " + *error;
        return false;
    }
    out->push_back({key_name, value});
    return true;
}

bool write_text(const std::string& path, const std::string& text, std::string* error) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        *error = "cannot write " + path;
        return false;
    }
    return true;
}

// report.txt: the platform's text report (tb/platform/report.h), per-pair
// table included.
bool write_text_report(const std::string& path, const run_result& run, std::string* error) {
    std::FILE* out = std::fopen(path.c_str(), "w");
    if (!out) {
        *error = "cannot write " + path;
        return false;
    }
    platform::print_report(out, run.top, run.score, run.budget, /*per_pair=*/true);
    const bool failed = std::ferror(out) != 0;
    if (std::fclose(out) != 0 || failed) {
        *error = "cannot write " + path;
        return false;
    }
    return true;
}

}  // namespace

void print_error(const std::string& message) {
    std::fprintf(stderr, "stereosim: error: %s\n", message.c_str());
}

run_command::run_command(CLI::App& app, std::vector<std::unique_ptr<run_extension>> extensions)
    : m_extensions(std::move(extensions)) {
    m_run = app.add_subcommand(
        "run", "one co-simulation: report.json, report.txt, frames.csv, the verdict");
    run_options& o = m_options;
    CLI::Option* scenario =
        m_run->add_option("--scenario", o.scenario, "built-in scenario (stereosim scenarios)");
    CLI::Option* config = m_run->add_option("--config", o.config_file,
                                            "config file (JSON, version 1, docs/config.md); a "
                                            "report.json replays its run");
    scenario->excludes(config);
    // Kept as text (the config keys check them), shown as what they take.
    m_run->add_option("--frames", o.frames, "sync periods of 24.5 ms to simulate (run.frames)")
        ->type_name("INT");
    m_run->add_option("--seed", o.seed, "seed (run.seed)")->type_name("INT");
    m_run->add_option("--dsk", o.dsk, "DSK version v1|v2|v3 (dsk.version)")->type_name("v1|v2|v3");
    m_run->add_option("--cpu-mhz", o.cpu_mhz, "CPU clock, MHz (dsk.cpu_mhz)")->type_name("FLOAT");
    m_run->add_option("--mode", o.mode, "sequential|overlapped (firmware.mode)")
        ->type_name("sequential|overlapped");
    m_run->add_option("--replay", o.replay, "replay manifest (scenario.replay)");
    m_run
        ->add_option("--firmware", o.firmware,
                     "the firmware under test, a plugin .so (run.firmware, docs/firmware-abi.md)")
        ->type_name("PATH");
    m_run->add_option("--set", o.sets,
                      "key=value for any config key (repeatable; stereosim config --list)");
    m_run->add_option("--out", o.out_dir,
                      "write report.json, report.txt, frames.csv, ... into this folder");
    m_run->add_flag("--quiet,-q", o.quiet, "no progress line and no summary");
    m_run->add_flag("--progress", o.force_progress,
                    "progress line even when stderr is not a terminal");
    m_run->add_flag("--summary", o.force_summary, "summary even when stdout is not a terminal");
    for (auto& e : m_extensions) e->add_options(*m_run);
}

bool run_command::setup_from_options(run_setup* setup, std::string* error) const {
    const run_options& o = m_options;
    // The file or the scenario, then the named options, then --set in order.
    std::vector<key_assignment> assignments;
    if (!o.config_file.empty() && !read_config_file(o.config_file, &assignments, error))
        return false;
    if (!o.scenario.empty()) assignments.push_back({"scenario.name", o.scenario});
    std::string dsk = o.dsk;
    if (dsk.size() == 2 && (dsk[0] == 'v' || dsk[0] == 'V')) dsk = dsk.substr(1);
    const struct {
        const char* option;
        const char* key;
        const std::string& text;
    } named[] = {{"--frames", "run.frames", o.frames},
                 {"--seed", "run.seed", o.seed},
                 {"--dsk", "dsk.version", dsk},
                 {"--cpu-mhz", "dsk.cpu_mhz", o.cpu_mhz},
                 {"--mode", "firmware.mode", o.mode},
                 {"--replay", "scenario.replay", o.replay},
                 {"--firmware", "run.firmware", o.firmware}};
    for (const auto& n : named) {
        if (!n.text.empty() && !add_assignment(n.option, n.key, n.text, &assignments, error))
            return false;
    }
    for (const std::string& set : o.sets) {
        const size_t eq = set.find('=');
        if (eq == std::string::npos) {
            *error = "--set '" + set + "': expected key=value";
            return false;
        }
        const std::string name = set.substr(0, eq);
        if (is_firmware_own_key(name)) {  // checked once the firmware is known
            assignments.push_back({name, json(set.substr(eq + 1))});
            continue;
        }
        if (!find_key(name)) {
            *error = unknown_key_message(name);
            return false;
        }
        if (!add_assignment("--set", name, set.substr(eq + 1), &assignments, error)) return false;
    }
    return apply_assignments(assignments, setup, error) && validate_setup(*setup, error);
}

bool run_command::open_out_dir(staged_files& files, std::string* error) {
    if (m_options.out_dir.empty()) return true;
    if (!files.open(m_options.out_dir, error)) return false;
    for (auto& e : m_extensions)
        if (!e->open_outputs(files, error)) return false;
    return true;
}

bool run_command::write_outputs(const run_result& run, staged_files& files, std::string* error) {
    if (!write_text(files.staged_path("frames.csv"), frames_csv(run.report), error) ||
        !write_text_report(files.staged_path("report.txt"), run, error))
        return false;
    for (auto& e : m_extensions)
        if (!e->write(run, files, error)) return false;
    // report.json last, so a reader that sees it sees every other file too.
    return write_text(files.staged_path("report.json"), run.report.dump(2) + "\n", error) &&
           files.commit(error);
}

int run_command::simulate(const run_setup& setup, const platform::platform_config& config,
                          staged_files& files) {
    platform::platform_top top(config);
    return run_and_report(top, setup, config, files);
}

int run_command::run_and_report(platform::platform_top& top, const run_setup& setup,
                                const platform::platform_config& config, staged_files& files) {
    const run_options& o = m_options;
    const bool progress = !o.quiet && (o.force_progress || isatty(STDERR_FILENO));
    const bool summary = !o.quiet && (o.force_summary || isatty(STDOUT_FILENO));
    for (auto& e : m_extensions) e->attach(top);
    progress_line line(stderr, config.frames,
                       static_cast<double>(config.period) / (simtime::ticks_per_ns * 1e6));
    if (progress) top.set_progress([&line](int done) { line.update(done); });
    platform::install_firmware_crash_report();
    top.run();
    if (progress) line.finish();
    if (top.firmware_init_failed()) {
        print_error("the firmware refused its configuration: " + top.firmware_init_error() +
                    " (see docs/config.md for the ranges)");
        return exit_bad_input;
    }
    const platform::scoreboard_report score = platform::score(top);
    const platform::budget_report budget = platform::check_budget(top, score);
    json report = build_report(setup, top, score, budget);
    const run_result result{setup, config, top, score, budget, report, o.out_dir};
    for (auto& e : m_extensions) e->add_to_report(report, result);

    std::string error;
    if (!o.out_dir.empty() && !write_outputs(result, files, &error)) {
        print_error(error);
        return exit_run_failed;
    }
    if (summary) {
        std::vector<std::string> extra;
        for (auto& e : m_extensions)
            for (const std::string& text : e->summary_lines(result)) extra.push_back(text);
        print_summary(stdout, report, files.committed(), extra);
    }
    std::string broken;
    for (auto& e : m_extensions)
        if (broken.empty()) broken = e->broken_verdict(result);
    if (!broken.empty()) {
        std::fprintf(stderr, "stereosim: %s\n", broken.c_str());
        return exit_contract_broken;
    }
    return budget.fits ? exit_within_budget : exit_over_budget;
}

bool run_command::prepare(run_setup* setup, platform::platform_config* config, std::string* error) {
    if (!setup_from_options(setup, error)) return false;
    *config = platform_config_of(*setup);
    for (auto& e : m_extensions)
        if (!e->configure(*setup, *config, error)) return false;
    return true;
}

template <typename Body>
int run_command::guarded(Body body) {
    try {
        return body();
    } catch (const std::exception& e) {
        // sc_core::sc_report is a std::exception too; one line.
        std::string what = e.what();
        for (char& c : what)
            if (c == '\n') c = ' ';
        print_error("the simulation failed: " + what);
        return exit_run_failed;
    }
}

int run_command::execute() {
    std::string error;
    run_setup setup;
    platform::platform_config config;
    // The output folder is checked before the (long) run.
    staged_files files;
    if (!prepare(&setup, &config, &error) || !open_out_dir(files, &error)) {
        print_error(error);
        return exit_bad_input;
    }
    return guarded([&] { return simulate(setup, config, files); });
}

int run_command::execute_from_snapshot(platform::platform_top& top) {
    std::string error;
    run_setup setup;
    platform::platform_config config;
    staged_files files;
    if (!prepare(&setup, &config, &error) || !open_out_dir(files, &error)) {
        print_error(error);
        return exit_bad_input;
    }
    return guarded([&] {
        top.continue_with_faults(config);
        return run_and_report(top, setup, config, files);
    });
}

}  // namespace cli
