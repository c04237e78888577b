// stereosim: the command a firmware or hardware engineer types (docs/cli.md).
//   stereosim run [options]       one co-simulation, report.json, frames.csv
//   stereosim scenarios           the built-in scenarios, one line each
//   stereosim config --list       every config key: type, range, default, doc
//   stereosim faults ...          fault kinds and the fault campaign
//   stereosim sweep ...           a grid of config keys, every point co-simulated
//   stereosim merge DIR...        the shards of a sweep or campaign as one
//   stereosim firmware info PATH  what a firmware plugin declares
// Exit codes: 0 within budget, 1 over budget, 2 bad input, 3 the run failed.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <systemc>

#include "tb/app/cli/config_keys.h"
#include "tb/app/cli/firmware_command.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/app/cli/replay_init.h"
#include "tb/app/cli/run_command.h"
#include "tb/app/cli/scenarios.h"
#include "tb/app/faults/faults_command.h"
#include "tb/app/run_extensions.h"
#include "tb/app/sweep/merge_command.h"
#include "tb/app/sweep/sweep_command.h"

namespace {

// SystemC's messages: info is dropped, warnings are one line on stderr,
// errors keep their actions (throw) so the run command reports them.
void report_handler(const sc_core::sc_report& report, const sc_core::sc_actions& actions) {
    if (report.get_severity() == sc_core::SC_INFO) return;
    if (report.get_severity() == sc_core::SC_WARNING) {
        std::fprintf(stderr, "stereosim: SystemC warning: %s\n", report.get_msg());
        return;
    }
    sc_core::sc_report_handler::default_handler(report,
                                                actions & ~(sc_core::SC_DISPLAY | sc_core::SC_LOG));
}

void print_scenarios() {
    for (const cli::builtin_scenario& s : cli::builtin_scenarios())
        std::printf("%-13s %s\n", s.name, s.description);
}

}  // namespace

// Our own main instead of libsystemc's: SystemC prints its banner on stderr
// as it starts (before sc_main), unless this variable is set first.
int main(int argc, char* argv[]) {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 1);
    return sc_core::sc_elab_and_sim(argc, argv);
}

int sc_main(int argc, char* argv[]) {
    sc_core::sc_set_time_resolution(1, sc_core::SC_FS);
    sc_core::sc_report_handler::set_handler(report_handler);

    CLI::App app{"stereosim: co-simulation of the C6416 DSK stereo vision platform (docs/cli.md)"};
    app.require_subcommand(1);
    cli::run_command run(app, ::app::make_run_extensions());
    CLI::App* scenarios = app.add_subcommand("scenarios", "the built-in scenarios, one line each");
    CLI::App* config = app.add_subcommand("config", "the config keys (docs/config.md)");
    bool list = false, markdown = false;
    config->add_flag("--list", list, "every key: type, range, default, doc line");
    config->add_flag("--markdown", markdown, "the same as a Markdown table (docs/config.md)");
    std::string config_firmware;
    config
        ->add_option("--firmware", config_firmware,
                     "also the keys this firmware plugin declares (firmware.KEY, "
                     "docs/firmware-abi.md)")
        ->type_name("PATH")
        ->excludes("--markdown");
    // Further subcommands (e.g. `stereosim faults`) are added here.
    faults::faults_command faults(app, ::app::make_run_extensions);
    sweep::sweep_command sweep(app);
    sweep::merge_command merge(app);
    cli::replay_command replay(app);
    cli::firmware_command firmware(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string what = e.what();
        for (char& c : what)
            if (c == '\n') c = ' ';
        cli::print_error(what + " (stereosim --help)");
        return cli::exit_bad_input;
    }
    if (*scenarios) {
        print_scenarios();
        return 0;
    }
    if (*faults.subcommand()) return faults.execute();
    if (*sweep.subcommand()) return sweep.execute();
    if (*merge.subcommand()) return merge.execute();
    if (*replay.subcommand()) return replay.execute();
    if (*firmware.subcommand()) return firmware.execute();
    if (*config) {
        std::string error;
        if (markdown)
            std::printf("%s\n%s", cli::config_table_markdown().c_str(),
                        cli::firmware_table_markdown().c_str());
        else if (!cli::print_firmware_keys(config_firmware, &error)) {
            cli::print_error(error);
            return cli::exit_bad_input;
        }
        return 0;
    }
    return run.execute();
}
